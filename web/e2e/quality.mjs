// The machines page's quality records (issue 14): an operator records an
// out-of-tolerance value from the form and sees it marked NOT OK in words;
// the form says what is wrong as it is typed and shows the server's 400;
// "More records" pages back through older records; a programmer reads the
// records, has no form, and sees a record made elsewhere come in live.
import { logInAs } from './flows.mjs';

const row = (page) => page.locator('#quality-romi-1-table tbody tr').first();
const hint = (page, key) => page.locator(`#q-romi-1-${key}-hint`).innerText();

async function openMachines(page) {
  await page.getByRole('link', { name: 'Machines' }).click();
  await page.getByRole('heading', { name: 'Quality records' }).waitFor();
}

// `n` records made by the API as `user`, one login for all.
async function recordMany(h, user, n, what = 'length') {
  const token = await h.logIn(user);
  for (let i = 0; i < n; i++) {
    const r = await fetch(`${h.base}/api/machines/romi-1/quality`, { method: 'POST', headers: { Authorization: `Bearer ${token}`, 'Content-Type': 'application/json' }, body: JSON.stringify({ characteristic: `${what} ${i}`, measured: 50 + ((i % 7) - 3) / 100, min: 49.9, max: 50.1, unit: 'mm' }) });
    if (r.status !== 201) throw new Error(`quality record ${i}: ${r.status} ${await r.text()}`);
  }
}

export async function qualityFlow(page, h, { check, shot }) {
  await recordMany(h, 'appr', 25);
  await logInAs(page, 'oper');
  await openMachines(page);
  await page.locator('#quality-romi-1-table tbody tr').nth(19).waitFor();
  const first = await page.locator('#quality-romi-1-table tbody tr').count();
  await page.getByRole('button', { name: 'More records' }).click();
  await page.locator('#quality-romi-1-table tbody tr').nth(24).waitFor();
  const all = await page.locator('#quality-romi-1-table tbody tr').count();
  const oldest = await page.locator('#quality-romi-1-table tbody tr').last().innerText();
  check(first === 20 && all === 25 && /^\S+ \S+\s+length 0\s/.test(oldest) && (await page.getByRole('button', { name: 'More records' }).isHidden()), `"More records" pages back to the oldest (${first}, then ${all}; no more after)`);

  const f = (label) => page.getByLabel(label, { exact: true });
  await page.getByRole('button', { name: 'Record', exact: true }).click();
  await page.locator('#q-romi-1-status[role="alert"]').waitFor();
  const empty = [await page.locator('#q-romi-1-status').innerText(), await hint(page, 'characteristic'), await hint(page, 'measured')];
  const focused = await f('Characteristic').evaluate((e) => e === document.activeElement);
  check(empty.join(' / ') === 'Not recorded: see the fields marked. / Say what was measured. / Give the measured value.' && focused, `an empty form is not sent: its required fields are marked and the first focused (${empty.join(' / ')})`);
  await f('Characteristic').fill('bore A diameter');
  await f('Measured').fill('20,O3');
  await f('Min').fill('20.1');
  await f('Max').fill('20.021');
  const typed = [await hint(page, 'measured'), await hint(page, 'max')];
  check(/^Not a number/.test(typed[0]) && typed[1] === 'The max is below the min.' && (await f('Max').getAttribute('aria-invalid')) === 'true', `the form says what is wrong as it is typed (${typed.join(' / ')})`);
  await f('Measured').fill('1e10');
  await f('Min').fill('20');
  await page.getByRole('button', { name: 'Record', exact: true }).click();
  await page.locator('#q-romi-1-status[role="alert"]', { hasText: /^Refused/ }).waitFor();
  const refused = await page.locator('#q-romi-1-status').innerText();
  check(/^Refused \(400\): \S/.test(refused) && (await hint(page, 'max')) === '', `the server's 400 is shown as it says it ("${refused}")`);

  await f('Measured').fill('20,03'); // a decimal comma
  await f('Nominal').fill('20');
  await f('Unit').fill('mm');
  await f('Part').fill('SN-7');
  await f('Part').press('Enter'); // the keyboard records
  await page.locator('#q-romi-1-status', { hasText: 'Recorded:' }).waitFor();
  const made = await row(page).innerText();
  const mark = await row(page).locator('.verdict').innerText();
  const server = (await h.api('oper', 'GET', '/api/machines/romi-1/quality?limit=1')).json.records[0];
  check(mark === 'NOT OK' && /bore A diameter\s+20\.03 mm\s+20 to 20\.021 mm \(nominal 20 mm\)\s+NOT OK\s+part SN-7\s+oper/.test(made) && server.measured === 20.03 && server.ok === false, `an out-of-tolerance value is marked NOT OK in words ("${made.replace(/\s+/g, ' ')}")`);
  await f('Measured').fill('20.012');
  await page.getByRole('button', { name: 'Record', exact: true }).click();
  await page.locator('#q-romi-1-status', { hasText: /20\.012 mm, OK\.$/ }).waitFor();
  const counted = await page.locator('#quality-romi-1 > p.status').innerText();
  check((await row(page).locator('.verdict').innerText()) === 'OK' && (await page.locator('#quality-romi-1-table tbody tr').count()) === 27 && counted === '27 records shown.', `a value within its limits is marked OK, above the one before ("${counted}")`);
  await page.evaluate(() => document.getElementById('quality-romi-1').scrollIntoView({ block: 'start' }));
  await shot(page, 'web-quality.png', false);
  const zoomed = await fitsAtZoom(page, 'the machines page with 27 quality records and the form');
  check(zoomed.ok, zoomed.text);

  // One characteristic's measurements, then all again.
  const counter = page.locator('#quality-romi-1 > p.status');
  await page.getByLabel('Show only the characteristic').fill('bore A diameter');
  await counter.filter({ hasText: 'of bore A diameter' }).waitFor();
  const only = await page.locator('#quality-romi-1-table tbody th').allInnerTexts();
  const onlySaid = await counter.innerText();
  // Its run chart: the two values in order, the one past max a square.
  const run = page.locator('#quality-romi-1-run');
  const values = await run.locator('.point').evaluateAll((ps) => ps.map((p) => `${p.tagName}:${p.dataset.value}`));
  const labels = await run.locator('text').allTextContents();
  const desc = await run.locator('desc').textContent();
  await page.evaluate(() => document.getElementById('quality-romi-1').scrollIntoView({ block: 'start' }));
  await shot(page, 'web-quality-run.png', false);
  await page.getByLabel('Show only the characteristic').fill('');
  await counter.filter({ hasText: /^20 records shown; more are older\.$/ }).waitFor();
  const gone = await run.count();
  check(only.length === 2 && only.every((c) => c === 'bore A diameter') && onlySaid === '2 records of bore A diameter shown.', `the records of one characteristic ("${onlySaid}"), and all again`);
  check(values.join(' ') === 'rect:20.03 circle:20.012' && labels.includes('max 20.021 mm') && labels.includes('nominal = min 20 mm') && /^2 measurements from .+; 1 outside the limits; the last 20\.012 mm\.$/.test(desc) && gone === 0, `its run chart: ${values.join(', ')} oldest first, the one past max a square, the limits drawn ("${desc}"); gone with the filter`);

  await h.addUser('progr', 'programmer');
  await logInAs(page, 'progr');
  await openMachines(page);
  await page.locator('#quality-romi-1-table tbody tr').nth(19).waitFor();
  const forms = await page.locator('form.quality-form').count();
  const note = await page.locator('#quality-note').innerText();
  check(forms === 0 && (await page.getByRole('button', { name: 'Record', exact: true }).count()) === 0 && /recording one is for operators, approvers and admins/.test(note), 'a programmer reads the records and sees no form');
  await recordMany(h, 'appr', 1, 'live flatness');
  await row(page).locator('th', { hasText: 'live flatness 0' }).waitFor();
  check((await page.locator('#quality-romi-1-table tbody tr').count()) === 21, 'a record made elsewhere comes in live at the top, once');
}

// At 200 % zoom (flows.mjs's zoomFlow) with records and the form shown.
export async function fitsAtZoom(page, what) {
  await page.setViewportSize({ width: 640, height: 430 });
  const [scroll, client] = await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.clientWidth]);
  await page.setViewportSize({ width: 1280, height: 860 });
  return { ok: scroll <= client, text: `at 200 % zoom ${what} fits its width (${scroll} of ${client} px)` };
}
