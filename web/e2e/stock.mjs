// The program page's stock (issue 17): the "Stock" toggle shows the stock
// the server simulated, the slider and the play button replay the removal
// frame by frame, and the picture changes with them (read back from the
// canvas, as the tool-path view's test does).
import { canvasPixels } from './harness.mjs';

// The canvas read back, every 7th pixel's colour: two pictures compared.
async function picture(page) {
  return page.evaluate(() => {
    const c = document.querySelector('#viewer canvas');
    const t = document.createElement('canvas');
    t.width = c.width;
    t.height = c.height;
    const g = t.getContext('2d');
    g.drawImage(c, 0, 0);
    const d = g.getImageData(0, 0, t.width, t.height).data;
    const out = [];
    for (let i = 0; i < d.length; i += 28) out.push(d[i], d[i + 1], d[i + 2]);
    return out;
  });
}

// The share of sampled pixels that differ by more than a little.
function changed(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i += 3) if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 30) n++;
  return n / (a.length / 3);
}

const frameNow = (page) => page.evaluate(() => Number(document.getElementById('viewer').dataset.stockFrame));

// The replay of the cut in time moves the stock with it: its start is the
// uncut stock, a time in the middle a frame made by then, its end the last.
async function replayMovesTheStock(page, check, frames) {
  const time = page.getByLabel('Replay, time');
  await time.focus();
  await time.press('Home');
  const atStart = await frameNow(page);
  for (let k = 0; k < 5; k++) await time.press('PageUp');
  const replaySeconds = await page.evaluate(() => Number(document.getElementById('viewer').dataset.replayTime));
  const middle = await frameNow(page);
  const said = await page.locator('#stock-status').innerText();
  const at = /, at (\d+):(\d\d\.\d) of /.exec(said);
  const frameSeconds = at ? Number(at[1]) * 60 + Number(at[2]) : NaN;
  await time.press('End');
  const atEnd = await frameNow(page);
  check(
    atStart === 0 && middle > 0 && middle < frames && frameSeconds <= replaySeconds + 0.05 && atEnd === frames,
    `the replay in time moves the stock (its start: frame ${atStart}; at ${replaySeconds.toFixed(1)} s: frame ${middle} of ${frames}, made by ${frameSeconds} s; its end: frame ${atEnd})`,
  );
}

export async function stockFlow(page, { check, shot }) {
  const before = await canvasPixels(page);
  await page.getByRole('checkbox', { name: 'Stock', exact: true }).check();
  await page.waitForFunction(() => {
    const v = document.getElementById('viewer').dataset;
    return Number(v.stockFrames) > 0 && v.stockFrame === v.stockFrames;
  });
  const frames = await page.evaluate(() => Number(document.getElementById('viewer').dataset.stockFrames));
  const said = await page.locator('#stock-status').innerText();
  check(new RegExp(`^Frame ${frames} of ${frames}: \\d+ of \\d+ moves, line \\d+, at \\d+:\\d\\d\\.\\d of \\d+:\\d\\d\\.\\d, [1-9][\\d.]* mm³ removed`).test(said), `the stock is shown at its last frame of ${frames} ("${said}")`);
  const withStock = await canvasPixels(page);
  check(withStock.drawn > before.drawn + 2000, `the stock's mesh is drawn (${withStock.drawn} pixels not background, ${before.drawn} with the path alone)`);
  await page.getByRole('checkbox', { name: 'Tool path' }).uncheck();
  await page.getByRole('button', { name: 'Top view' }).click();
  const last = await picture(page);
  // The slider from the keyboard: Home is the uncut stock.
  const slider = page.getByLabel('Removal, frame');
  await slider.focus();
  await slider.press('Home');
  check((await frameNow(page)) === 0 && /^Frame 0 of/.test(await page.locator('#stock-status').innerText()), 'Home on the slider shows frame 0, the uncut stock');
  const uncut = await picture(page);
  const shares = [];
  const pictures = [uncut];
  for (let k = 1; k <= Math.min(frames, 3); k++) {
    await slider.press('ArrowRight');
    pictures.push(await picture(page));
    shares.push(changed(pictures[k - 1], pictures[k]));
  }
  check((await frameNow(page)) === Math.min(frames, 3), `the arrow keys step the frames (now ${await frameNow(page)})`);
  check(changed(uncut, last) > 0.01 && shares.some((s) => s > 0), `the picture changes between frames (uncut to last: ${(100 * changed(uncut, last)).toFixed(1)} % of pixels; steps: ${shares.map((s) => (100 * s).toFixed(2)).join(', ')} %)`);
  // Play runs to the end by itself.
  await slider.press('Home');
  const stock = page.getByRole('group', { name: 'Stock' });
  await stock.getByRole('button', { name: 'Play' }).click();
  await page.waitForFunction((n) => Number(document.getElementById('viewer').dataset.stockFrame) === n, frames, { timeout: 60000 });
  const played = await picture(page);
  check(changed(played, last) < 0.001 && (await stock.getByRole('button', { name: 'Play' }).getAttribute('aria-pressed')) === 'false', 'Play replays the removal to the last frame and stops');
  await replayMovesTheStock(page, check, frames);
  await page.getByLabel('Colour the stock by').selectOption('tool');
  const byTool = await picture(page);
  check(changed(byTool, last) > 0.005, `coloured by the tool that cut last, the picture changes (${(100 * changed(byTool, last)).toFixed(1)} %)`);
  await page.getByRole('checkbox', { name: 'Tool path' }).check();
  await page.getByRole('button', { name: 'Iso view' }).click();
  await page.evaluate(() => document.querySelector('.stock-controls').scrollIntoView({ block: 'start' }));
  await shot(page, 'web-stock.png', false);
  await page.getByRole('checkbox', { name: 'Stock', exact: true }).uncheck();
  const after = await canvasPixels(page);
  check(Math.abs(after.drawn - before.drawn) < 0.05 * before.drawn + 200, `the toggle hides the stock again (${after.drawn} pixels, ${before.drawn} before)`);
}
