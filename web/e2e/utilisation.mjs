// The machines page's utilisation per day (machine_utilisation.ts), after
// the simulated control reported a part (flows.mjs): today's bar is the
// server's figure, the axes are labelled, the table alternative opens from
// the keyboard with today's running time and parts, and the last cycle is
// set against the check's estimate of the program last sent.
export async function utilisationFlow(page, h, t, rev) {
  const api = (await h.api('oper', 'GET', '/api/machines/romi-1/utilisation')).json;
  const today = api.days[api.days.length - 1];
  const want = 100 * today.utilisation;
  const bar = page.locator(`#util-romi-1-chart rect.bar[data-key="${today.date}"]`);
  try {
    await page.waitForFunction(([sel, v]) => Math.abs(Number(document.querySelector(sel)?.dataset.value) - v) < 1e-9, [`#util-romi-1-chart rect.bar[data-key="${today.date}"]`, want]);
  } catch {
    throw new Error(`today's bar is ${await bar.getAttribute('data-value')}, the server says ${want}`);
  }
  const bars = await page.locator('#util-romi-1-chart rect.bar').count();
  const height = Number(await bar.getAttribute('height'));
  const labels = await page.locator('#util-romi-1-chart text').allTextContents();
  const title = await page.locator('#util-romi-1-chart > title').textContent();
  t.check(today.running_seconds >= 83.5 && height > 0 && bars === 14 && labels.includes('Utilisation') && labels.includes('Day (UTC)') && labels.includes('0.10 %') && labels.includes('0.02 %') && /utilisation per day/.test(title), `the chart has a bar for today of the server's ${want.toFixed(4)} % (${today.running_seconds} s running; ${bars} days; axes labelled, ticks ${labels.filter((l) => l.endsWith(' %')).join(', ')})`);

  await page.locator('#util-romi-1 summary').focus();
  await page.keyboard.press('Enter');
  const row = page.locator(`#util-romi-1-table tr[data-date="${today.date}"]`);
  await row.waitFor({ state: 'visible' });
  const cells = await row.locator('th, td').allInnerTexts();
  t.check(cells[2] === `${want.toFixed(2)} %` && Number(cells[3]) === today.parts && today.parts >= 1 && /^1 min 2[34] s$/.test(cells[1]), `the table opens from the keyboard with today's figures (${cells.join(' | ')})`);

  const check = (await h.api('oper', 'GET', `/api/programs/seed-000/revisions/${rev}`)).json.checks.cycle_time_s;
  const estimate = await page.locator('#machine-romi-1 dd.estimate').innerText();
  const ratio = Math.round((100 * 83.5) / check);
  t.check(estimate.startsWith(`${check.toFixed(1)} s for seed-000`) && estimate.endsWith(`the last cycle took ${ratio} % of it`), `the last cycle against the estimate ("${estimate}")`);
  await page.locator('#util-romi-1').scrollIntoViewIfNeeded();
}
