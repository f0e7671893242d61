// The machines page's tool life (machine_tools.ts), after the simulated
// control reported a part of seed 000 (flows.mjs): a row per tool of the
// server's count; Reset asks for confirmation and a reason, Escape resets
// nothing, the reset starts the tool's count again, says who and why, and
// is in the audit log.
export async function toolLifeFlow(page, h, t) {
  const api = (await h.api('oper', 'GET', '/api/machines/romi-1/tools')).json;
  const rows = page.locator('#tools-romi-1-table tbody tr');
  try {
    await page.waitForFunction((n) => document.querySelectorAll('#tools-romi-1-table tbody tr').length === n && n > 0, api.tools.length);
  } catch {
    throw new Error(`the tool table has ${await rows.count()} rows, the server ${api.tools.length} tools`);
  }
  const shown = await rows.evaluateAll((trs) => trs.map((tr) => [...tr.querySelectorAll('th, td')].slice(0, 2).map((c) => c.textContent).join(' ')));
  const want = api.tools.map((x) => `T${x.tool}${x.tool === 0 ? ' (no tool)' : ''} ${x.parts}`);
  const t1 = api.tools.find((x) => x.tool === 1);
  t.check(JSON.stringify(shown) === JSON.stringify(want) && t1 && t1.parts >= 1 && t1.cutting_seconds > 0 && api.tools.some((x) => x.tool === 2), `a row per tool with the server's parts (${shown.join(', ')}; T1 ${t1?.cutting_seconds.toFixed(1)} s cutting)`);

  // Their lives (harness.mjs): T1 one part, T2 600 minutes of cutting.
  const used = (n) => page.locator(`#tools-romi-1-table tr[data-tool="${n}"] td.used`).innerText();
  const u1 = await used(1);
  const u2 = await used(2);
  const worn = await page.locator('#tools-romi-1-table tr[data-tool="1"]').getAttribute('class');
  t.check(u1 === '100 %: WORN OUT' && worn === 'worn' && u2 === `${Math.round((100 * api.tools.find((x) => x.tool === 2).cutting_seconds) / 36000)} %` && api.tools.find((x) => x.tool === 1).worn === true, `a tool past its life says so in words (T1 "${u1}", T2 "${u2}")`);

  const reset = page.getByRole('button', { name: 'Reset the life of T1' });
  await reset.click();
  let dialog = page.getByRole('dialog');
  const asks = await dialog.innerText();
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });
  const still = (await h.api('oper', 'GET', '/api/machines/romi-1/tools')).json.tools.find((x) => x.tool === 1);
  t.check(/Reset T1 on romi-1\?/.test(asks) && /starts again from now/.test(asks) && still.reset_at_us === null && still.parts === t1.parts, 'Reset asks first, and Escape resets nothing');

  await reset.click();
  dialog = page.getByRole('dialog');
  await dialog.getByLabel(/Reason/).fill('new insert');
  await page.keyboard.press('Enter'); // the reason's field has the focus: Enter confirms
  await dialog.waitFor({ state: 'detached' });
  const row = page.locator('#tools-romi-1-table tr[data-tool="1"]');
  try {
    await page.waitForFunction(() => /by oper: new insert/.test(document.querySelector('#tools-romi-1-table tr[data-tool="1"] td.reset')?.textContent ?? ''));
  } catch {
    throw new Error(`T1's row after the reset: ${await row.innerText()}; the page says ${await page.locator('#tools-romi-1 .status').innerText()}`);
  }
  const after = (await h.api('oper', 'GET', '/api/machines/romi-1/tools')).json.tools;
  const a1 = after.find((x) => x.tool === 1);
  const a2 = after.find((x) => x.tool === 2);
  const b2 = api.tools.find((x) => x.tool === 2);
  const parts = await row.locator('td.parts').innerText();
  const usedAfter = await row.locator('td.used').innerText();
  const log = (await h.api('boss', 'GET', '/api/audit?limit=100000')).json.entries.filter((e) => e.action === 'tool.reset');
  t.check(parts === '0' && usedAfter === '0 %' && a1.worn === false && a1.parts === 0 && a1.counted_from === 'reset' && a1.reset_by === 'oper' && a2.parts === b2.parts && log.length === 1 && log[0].actor === 'oper' && log[0].reason === 'new insert' && log[0].subject === 'romi-1/T1', `the reset starts T1's count again (row: ${parts} parts; T2 keeps ${a2.parts}) and the audit log holds it (${log.map((e) => `${e.actor} ${e.subject} "${e.reason}"`).join(', ')})`);
  await page.locator('#tools-romi-1').scrollIntoViewIfNeeded();
}
