// The program page's replay of the cut (issue 14): the time slider's end is
// the check's cycle time, the keyboard moves it, the picture draws less at
// the start than at the end, the line being cut is named and marked in the
// text, and Play runs the clock until Pause stops it.
import { canvasPixels } from './harness.mjs';

const dataset = (page) => page.evaluate(() => ({ ...document.getElementById('viewer').dataset }));

// "1:15.3" or "1:02:03.4" as seconds.
function seconds(clock) {
  return clock.split(':').reduce((s, part) => s * 60 + Number(part), 0);
}

export async function replayFlow(page, { check }) {
  const whole = await canvasPixels(page);
  const said = await page.locator('#replay-status').innerText();
  const summary = await page.locator('dl.summary').innerText();
  const cycle = Number(/Cycle time\s+([\d.]+) s/.exec(summary)?.[1]);
  const end = /The whole path: ([\d:.]+) on the machine/.exec(said);
  check(end !== null && Math.abs(seconds(end[1]) - cycle) <= 0.1, `the replay ends at the check's cycle time ("${said}", ${cycle} s)`);

  const slider = page.getByLabel('Replay, time');
  await slider.focus();
  await slider.press('Home');
  const start = await dataset(page);
  const empty = await canvasPixels(page);
  check(Number(start.replayTime) === 0 && start.replayVertex === '1' && empty.drawn < whole.drawn * 0.8, `at 0:00.0 the cut has not started (${empty.drawn} of ${whole.drawn} pixels drawn)`);

  for (let i = 0; i < 5; i++) await slider.press('PageUp');
  const mid = await dataset(page);
  const line = Number(mid.replayLine);
  const midSaid = await page.locator('#replay-status').innerText();
  const marked = await page.locator(`#L${line}.selected`).count();
  check(Number(mid.replayTime) > 0 && Number(mid.replayTime) < cycle && Number(mid.replayVertex) > 1 && marked === 1 && midSaid.endsWith(`line ${line}`), `the keyboard moves the replay to ${mid.replayTime} s, on line ${line}, marked in the text ("${midSaid}")`);
  const part = await canvasPixels(page);
  check(part.drawn > empty.drawn && part.drawn < whole.drawn, `half-way, part of the path is drawn (${empty.drawn} < ${part.drawn} < ${whole.drawn} pixels)`);

  const replay = page.getByRole('group', { name: 'Replay of the cut' });
  await replay.getByRole('button', { name: 'Play' }).click();
  await page.waitForFunction((t) => Number(document.getElementById('viewer').dataset.replayTime) > t, Number(mid.replayTime));
  await replay.getByRole('button', { name: 'Pause' }).click();
  const paused = (await dataset(page)).replayTime;
  await page.waitForTimeout(300);
  const still = (await dataset(page)).replayTime;
  check(Number(paused) > Number(mid.replayTime) && paused === still, `Play runs the clock (${mid.replayTime} → ${paused} s) and Pause stops it`);

  await slider.press('End');
  const back = await canvasPixels(page);
  check(Math.abs(back.drawn - whole.drawn) <= whole.drawn * 0.02, `at the end the whole path is drawn again (${back.drawn} of ${whole.drawn} pixels)`);
}
