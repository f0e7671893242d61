// The machines page's utilisation per day (machine_utilisation.ts), after
// the simulated control reported a part (flows.mjs). The machine has a
// shift calendar (harness.mjs: the whole day every day in ZONE, a holiday
// three days ago), so the days are the zone's and the bars are the shift
// utilisation: today's bar is the server's figure, the axes are labelled,
// the holiday says "no shift", the table alternative opens from the
// keyboard with today's running time, parts and both utilisations, and the
// last cycle is set against the check's estimate of the program last sent.
import { HOLIDAY, ZONE } from './harness.mjs';

export async function utilisationFlow(page, h, t, rev) {
  const api = (await h.api('oper', 'GET', '/api/machines/romi-1/utilisation?days=local')).json;
  const today = api.days[api.days.length - 1];
  const want = 100 * today.shift_utilisation;
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
  t.check(api.days_in === ZONE && today.running_seconds >= 83.5 && today.scheduled_seconds === 86400 && height > 0 && bars === 14 && labels.includes('Utilisation in shift') && labels.includes(`Day (${ZONE})`) && labels.includes('0.10 %') && labels.includes('0.02 %') && /utilisation in the shifts per day/.test(title), `the chart has a bar for today (${today.date} in ${ZONE}) of the server's ${want.toFixed(4)} % of the shifts (${today.running_seconds} s running; ${bars} days; axes labelled, ticks ${labels.filter((l) => l.endsWith(' %')).join(', ')})`);
  const basis = await page.locator('#util-romi-1-calendar').innerText();
  t.check(basis.includes(`2 shifts a week in ${ZONE}, 1 holiday`) && basis.includes("the machine's own"), `the calendar is named ("${basis}")`);

  await page.locator('#util-romi-1 summary').focus();
  await page.keyboard.press('Enter');
  const row = page.locator(`#util-romi-1-table tr[data-date="${today.date}"]`);
  await row.waitFor({ state: 'visible' });
  const cells = await row.locator('th, td').allInnerTexts();
  t.check(cells[2] === `${(100 * today.utilisation).toFixed(2)} %` && cells[8] === `${want.toFixed(2)} %` && Number(cells[3]) === today.parts && today.parts >= 1 && /^1 min 2[34] s$/.test(cells[1]) && cells[6] === '24 h 0 min', `the table opens from the keyboard with today's figures (${cells.join(' | ')})`);
  const holiday = await page.locator(`#util-romi-1-table tr[data-date="${HOLIDAY}"] td.shift`).innerText();
  const off = (await h.api('oper', 'GET', `/api/machines/romi-1/utilisation?days=local&from=${HOLIDAY}&to=${HOLIDAY}`)).json.days[0];
  t.check(holiday === 'no shift' && off.shift_utilisation === null && off.scheduled_seconds === 0, `the holiday ${HOLIDAY} has no shift ("${holiday}")`);

  const check = (await h.api('oper', 'GET', `/api/programs/seed-000/revisions/${rev}`)).json.checks.cycle_time_s;
  const estimate = await page.locator('#machine-romi-1 dd.estimate').innerText();
  const ratio = Math.round((100 * 83.5) / check);
  t.check(estimate.startsWith(`${check.toFixed(1)} s for seed-000`) && estimate.endsWith(`the last cycle took ${ratio} % of it`), `the last cycle against the estimate ("${estimate}")`);
  await page.locator('#util-romi-1').scrollIntoViewIfNeeded();
}
