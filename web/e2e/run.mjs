// The page's end-to-end test: a real `usina serve` with a fresh store, the
// page built into a scratch folder, Debian's chromium driven headless by
// Playwright (@playwright/test). Logs in, uploads the seed 000 program, checks its
// diagnostics and its 3D view, a click on a move, its 2D drawing
// (drawing.mjs), its stock replayed (stock.mjs), the machines page, a
// program made from the elliptical pocket's form (forms.mjs), a folder
// imported (import.mjs), a library of
// 10,000 programs searched by comment, tool and O number (library.mjs),
// setup sheets attached, downloaded and shown (sheets.mjs), quality records
// (quality.mjs), the admin's machine settings (machine_settings.mjs).
//   node e2e/run.mjs --usina BUILD/usina --seed tests/programs/romi/seed-000-example.nc
//                    [--screenshots DIR]
// Exit 0 passed, 1 failed, 77 skipped (no chromium or no node_modules).
import { mkdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { libraryFlow, listed, machineFlow, reviewFlow, zoomFlow } from './flows.mjs';
import { drawingFlow, drawingNotesFlow } from './drawing.mjs';
import { matchesGolden, MOST_DIFFERING } from './golden.mjs';
import { bigLibraryFlow } from './library.mjs';
import { formsFlow } from './forms.mjs';
import { importFlow } from './import.mjs';
import { machineSettingsFlow } from './machine_settings.mjs';
import { qualityFlow } from './quality.mjs';
import { replayFlow } from './replay.mjs';
import { sheetsFlow } from './sheets.mjs';
import { stockFlow } from './stock.mjs';
import { usersFlow } from './users.mjs';
import { arg, canvasPixels, Harness, PASSWORD, skipUnlessReady, web } from './harness.mjs';

skipUnlessReady();
const usina = resolve(arg('usina', join(web, '..', 'build', 'usina')));
const seed = resolve(arg('seed', join(web, '..', 'tests', 'programs', 'romi', 'seed-000-example.nc')));
const shots = arg('screenshots', '');
const harness = new Harness(usina);
let failed = false;

function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failed = true;
}

// The 409 of POST /api/users/boss (users.mjs): the only admin stays one.
// The 409 of POST /api/programs (import.mjs): a file named as a program of
// another machine class.
// The 422 of a drawing with nothing to draw (drawing.mjs).
// The 400 of a .pdf that is no PDF (sheets.mjs) and of a measured value
// past the server's range (quality.mjs).
// The 400s of a machine EIA cannot carry and of a retirement without a
// reason (machine_settings.mjs).
// The sandbox of a setup sheet's frame stopping its script (sheets.mjs).
function askedRefusal(m) {
  const url = m.location().url ?? '';
  return (
    (/status of 409/.test(m.text()) && /\/api\/(users\/boss|programs)$/.test(url)) ||
    (/status of 422/.test(m.text()) && /\/api\/programs\/draw-nothing\/revisions\/\w+\/drawing\?/.test(url)) ||
    (/status of 400/.test(m.text()) && /\/api\/(programs\/seed-000\/revisions\/\w+\/sheet|machines\/romi-1\/quality)$/.test(url)) ||
    (/status of 400/.test(m.text()) && /\/api\/machines(\/mill-9\/retire)?$/.test(url)) ||
    /^Blocked script execution in '.*\/sheet\/view\?.*sandboxed/.test(m.text())
  );
}

async function shot(page, name, top = true) {
  if (!shots) return;
  mkdirSync(shots, { recursive: true });
  if (top) await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(shots, name), fullPage: false });
}

// The top view against its golden picture; the front view against the same
// golden must not pass, or the comparison could pass anything.
async function goldenViews(page) {
  const canvas = page.locator('#viewer canvas');
  const top = await matchesGolden(page, await canvas.screenshot(), 'viewer-top-seed-000.png');
  check(top.ok, `the 3D top view matches its golden picture (${top.text})`);
  await page.getByRole('button', { name: 'Front view' }).click();
  const front = await matchesGolden(page, await canvas.screenshot(), 'viewer-top-seed-000.png', { control: true });
  check(front.share > 4 * MOST_DIFFERING, `the front view does not pass for the top view (${front.text})`);
  await page.getByRole('button', { name: 'Top view' }).click();
}

async function run() {
  const base = await harness.start();
  await harness.addUser('appr', 'approver');
  await harness.addUser('oper', 'operator');
  check(true, 'the page built, usina serve started on a fresh store (users boss, appr, oper)');
  const context = await harness.browser();
  const page = context.pages()[0] ?? (await context.newPage());
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  // The refusals the test asks for (a wrong password, an operator's
  // approval, demoting the only admin: users.mjs) are no errors of the page.
  page.on('console', (m) => m.type() === 'error' && !/status of 40[13]/.test(m.text()) && !formRefusal(m.text()) && !askedRefusal(m) && errors.push(m.text()));
  // A form's field or a calculator's input the server refuses (forms.mjs) is
  // a 400 of /api/forms/ or /api/calc/ only.
  let formRefusals = 0;
  page.on('response', (r) => r.status() === 400 && /\/api\/(forms|calc)\//.test(r.url()) && formRefusals++);
  const formRefusal = (text) => /status of 400/.test(text) && formRefusals > 0 && formRefusals-- > 0;
  const elsewhere = [];
  // Object URLs of the page's own origin (the drawing's blob:) hold what it fetched;
  // the browser's own PDF viewer (a setup sheet shown, sheets.mjs) loads its
  // files from chrome:// and chrome-extension://, never the network.
  const browsers = (u) => u.startsWith('chrome://') || u.startsWith('chrome-extension://');
  page.on('request', (r) => !r.url().startsWith(base) && !r.url().startsWith(`blob:${base}/`) && !r.url().startsWith('ws://127.0.0.1') && !r.url().startsWith('data:') && !browsers(r.url()) && elsewhere.push(r.url()));
  page.setDefaultTimeout(20000);

  // Login.
  await page.goto(`${base}/`);
  await page.getByRole('heading', { name: 'Log in' }).waitFor();
  await shot(page, 'web-login.png');
  await page.getByLabel('User').fill('boss');
  await page.getByLabel('Password').fill('wrong password');
  await page.getByRole('button', { name: 'Log in' }).click();
  await page.getByRole('alert').waitFor();
  check(/wrong|password|user/i.test(await page.getByRole('alert').innerText()), 'a wrong password is refused with a message');
  await page.getByLabel('Password').fill(PASSWORD);
  await page.getByLabel('Password').press('Enter'); // the keyboard submits the form
  await page.getByRole('heading', { name: 'Library' }).waitFor();
  check(true, 'logged in from the keyboard; the library opens');

  // Upload the seed 000 program (ROMI).
  await page.getByLabel('Program file').setInputFiles(seed);
  await page.getByText(/bytes read/).waitFor();
  await page.getByLabel('Name', { exact: true }).fill('seed-000');
  await page.getByLabel('Dialect', { exact: true }).selectOption('romi');
  await page.getByRole('button', { name: 'Upload' }).click();
  await page.getByRole('heading', { name: 'Program seed-000' }).waitFor();
  const seedLines = readFileSync(seed, 'utf8').split('\n').filter((l, i, a) => l !== '' || i < a.length - 1).length;
  await page.locator(`#L${seedLines}`).waitFor();
  const lines = await page.locator('ol.code > li').count();
  check(lines === seedLines, `the text is shown with its ${seedLines} lines (${lines})`);
  const inline = await page.locator('ol.code .diag').count();
  const firstDiag = inline ? await page.locator('ol.code .diag').first().innerText() : '';
  check(inline > 0 && /^[EWN]_[A-Z_]+ \S/.test(firstDiag), `the check's diagnostics are inline with code and message (${inline}: "${firstDiag}")`);

  // The 3D view drew the path.
  await page.locator('#viewer canvas').waitFor();
  await page.waitForFunction(() => Number(document.getElementById('viewer')?.dataset.vertices) > 1);
  const px = await canvasPixels(page);
  check(px.drawn > 500, `the 3D view drew the tool path (${px.drawn} of ${px.total} pixels not background)`);
  for (const view of ['Top', 'Front', 'Side', 'Iso']) await page.getByRole('button', { name: `${view} view` }).click();
  await page.getByRole('button', { name: 'Top view' }).click();
  const top = await canvasPixels(page);
  check(top.feed !== null, 'the top view shows a feed of tool 1');
  await goldenViews(page);
  if (top.feed) {
    await page.locator('#viewer canvas').click({ position: top.feed });
    const said = await page.locator('#picked-line').innerText();
    const selected = await page.locator('ol.code li.selected').count();
    check(/^Line \d+: [1-9]\d* move/.test(said) && selected === 1, `a click on a move highlights its line ("${said}")`);
  }
  await page.getByLabel('Highlight the moves of line').fill('8');
  await page.getByLabel('Highlight the moves of line').press('Enter');
  check(/^Line 8: [1-9]\d* move/.test(await page.locator('#picked-line').innerText()), "line 8's moves highlighted from the keyboard");
  await page.getByRole('link', { name: /^line 15: W_TYPOGRAPHIC_DASH/ }).click();
  check(
    (await page.getByRole('heading', { name: 'Program seed-000' }).count()) === 1 &&
      (await page.locator('#L15.selected').count()) === 1 &&
      /^Line 15: [1-9]\d* move/.test(await page.locator('#picked-line').innerText()),
    "a diagnostic's link shows its line and its moves",
  );
  await page.getByLabel('Highlight the moves of line').fill('8');
  await page.getByLabel('Highlight the moves of line').press('Enter');
  await page.getByRole('button', { name: 'Iso view' }).click();
  await replayFlow(page, { check }); // the replay of the cut in time (replay.mjs)
  await page.evaluate(() => window.scrollTo(0, 0));
  await shot(page, 'web-program.png');
  await page.locator('#stats table[aria-label="Per tool"]').waitFor();
  const figures = await page.locator('#stats').innerText();
  check(/Cycle/.test(figures) && /X\s+-?[\d.]+ mm\s+-?[\d.]+ mm/.test(figures) && /T1\s+\d+ min \d+ s(\s+\S+( min \d+)? s){3}\s+[1-9][\d.]* mm/.test(figures) && /T2\s+[\d.]+( min \d+)? s/.test(figures), `the figures: cycle time, bounds, the time and distances of T1 and T2 (${JSON.stringify(figures)})`);
  await page.evaluate(() => document.getElementById('stats').scrollIntoView({ block: 'start' }));
  await shot(page, 'web-figures.png', false);
  const seedRev = (await harness.api('boss', 'GET', '/api/programs/seed-000')).json.revisions[0].revision;
  await drawingFlow(page, { check, shot }, seedRev); // the 2D drawing, SVG and DXF (drawing.mjs)
  await stockFlow(page, { check, shot }); // the stock and its replay (stock.mjs)

  // The library lists and finds it.
  await page.getByRole('link', { name: 'Library' }).click();
  await page.getByLabel('Search by name').fill('seed');
  check(/^1 program$/.test(await listed(page)), 'the search finds the program by name');
  await page.getByLabel('Search by name').fill('nothing-like-it');
  check(/^0 programs$/.test(await listed(page)), 'the search leaves out other names');
  await page.getByLabel('Search by name').fill('');
  await listed(page);

  // The machines, live.
  await page.getByRole('link', { name: 'Machines' }).click();
  await page.getByRole('heading', { name: 'Machines' }).waitFor();
  await page.getByText('Live updates: connected').waitFor();
  const state = await page.locator('#machine-romi-1 .state').innerText();
  check(['idle', 'offline', 'receiving', 'sending'].includes(state), `the machines page shows romi-1 (${state}), live`);

  // Review by role, the diffs, the machine's jobs (flows.mjs).
  const t = { check, shot };
  const { second } = await reviewFlow(page, harness, t, seed);
  await machineFlow(page, harness, t, second);
  await libraryFlow(page, harness, t);
  await formsFlow(page, harness, t);
  await importFlow(page, harness, t);
  await drawingNotesFlow(page, harness, t);
  await zoomFlow(page, harness, t, second);
  await bigLibraryFlow(page, harness, t);
  await usersFlow(page, harness, t);
  await machineSettingsFlow(page, harness, t);
  await sheetsFlow(page, harness, t, seedRev);
  await qualityFlow(page, harness, t);

  // No page file is fetched from elsewhere, and the page logged no error.
  check(elsewhere.length === 0, `every request went to usina serve${elsewhere.length ? `; not: ${elsewhere.join(', ')}` : ''}`);
  check(errors.length === 0, `no errors in the page${errors.length ? `: ${errors.join('; ')}` : ''}`);
  await context.close();
}

try {
  await run();
} catch (e) {
  check(false, String(e.stack ?? e));
} finally {
  harness.stop();
}
process.exit(failed ? 1 : 0);
