// The "New program" page (page_forms.ts): seed 002's elliptical pocket
// filled in as a programmer, a value the page refuses as it is typed, one
// the server refuses (its message under the field), the preview's tool path
// drawn before anything is saved, the draft saved for romi-1 and found in
// the library; the cutting calculator filling the spindle speed.
import { logInAs } from './flows.mjs';
import { join } from 'node:path';
import { canvasPixels, web } from './harness.mjs';

// docs/gen.md's example of the seed 002 pocket.
const SEED_002 = [
  ['Centre X (mm)', '50'],
  ['Centre Y (mm)', '40'],
  ['Radius along X (mm)', '30'],
  ['Radius along Y (mm)', '18'],
  ['Depth (mm)', '5'],
  ['Tool diameter (mm)', '8'],
  ['Stepover (mm)', '3'],
  ['Step down (mm)', '2'],
  ['Finish allowance (mm)', '0.5'],
];

async function previewShown(page) {
  try {
    await page.locator('#form-status', { hasText: /^Preview: / }).waitFor();
  } catch (e) {
    const errors = await page.locator('.field-error').allInnerTexts();
    throw new Error(`no preview: "${await page.locator('#form-status').innerText()}" ${JSON.stringify(errors.filter((x) => x))}`);
  }
  return page.locator('#form-status').innerText();
}

export async function formsFlow(page, h, t) {
  await h.addUser('prog', 'programmer');
  await logInAs(page, 'prog');
  await page.getByRole('link', { name: 'New program' }).click();
  await page.getByRole('heading', { name: 'New program' }).waitFor();
  t.check((await page.getByLabel('Cycle', { exact: true }).inputValue()) === 'ellipse_pocket', 'the New program page opens on the elliptical pocket');
  await page.getByLabel('Machine', { exact: true }).selectOption('romi-1');
  t.check((await page.getByLabel('Control (dialect)').inputValue()) === 'romi', "choosing romi-1 sets its control, romi");
  for (const [label, value] of SEED_002) await page.getByLabel(label, { exact: true }).fill(value);

  // The page's own check, at once: a feed of 0.
  await page.getByLabel('Feed (mm/min)', { exact: true }).fill('0');
  const feedSaid = await page.locator('#form-feed-error').innerText();
  t.check(/the feed is 0 mm\/min; give a number above 0 and at most 1000000 mm\/min/.test(feedSaid) && (await page.getByLabel('Feed (mm/min)', { exact: true }).getAttribute('aria-invalid')) === 'true', `a feed of 0 is refused as it is typed ("${feedSaid}")`);
  await page.getByLabel('Feed (mm/min)', { exact: true }).fill('600');

  // The server's check: a stepover wider than the tool is within its range
  // but does not go with the tool diameter.
  await page.getByLabel('Stepover (mm)', { exact: true }).fill('9');
  await page.locator('#form-stepover-error', { hasText: 'bigger than the tool diameter' }).waitFor();
  const serverSaid = await page.locator('#form-stepover-error').innerText();
  t.check(/^the stepover 9 mm is bigger than the tool diameter 8 mm.*\[E_GEN_BAD_VALUE\]$/.test(serverSaid) && (await page.getByRole('button', { name: 'Save as draft' }).isDisabled()), `the server's message shows under the stepover, and nothing can be saved ("${serverSaid}")`);
  await page.getByLabel('Stepover (mm)', { exact: true }).fill('3');

  const said = await previewShown(page);
  await page.waitForFunction(() => Number(document.getElementById('viewer')?.dataset.vertices) > 1);
  const { drawn } = await canvasPixels(page);
  t.check(drawn > 500 && /the check passed/.test(said), `the preview draws the pocket's tool path before anything is saved (${drawn} pixels; "${said}")`);
  const before = (await h.api('boss', 'GET', '/api/programs?q=ELLIPSE')).json.total;
  t.check(before === 0, 'nothing is in the library before the save');
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.getByLabel('Program name').fill('ELLIPSE-1');
  await t.shot(page, 'web-forms.png');

  await page.getByLabel('Reason (optional)').fill('seed 002 pocket from the form');
  await page.getByRole('button', { name: 'Save as draft' }).click();
  await page.locator('#save-status', { hasText: /^Saved: ELLIPSE-1/ }).waitFor();
  await page.getByRole('link', { name: 'Library' }).click();
  await page.getByLabel('Search by name').fill('ELLIPSE');
  const row = page.locator('table[aria-label="Programs"] tbody tr', { hasText: 'ELLIPSE-1' });
  const cells = await row.locator('td').allInnerTexts();
  t.check(cells.length === 4 && cells[2] === 'romi' && cells[3] === 'draft', `the new program is in the library, a romi draft (${cells.join(' | ')})`);
  const saved = (await h.api('boss', 'GET', '/api/programs/ELLIPSE-1')).json.revisions[0];
  t.check(saved.author === 'prog' && saved.check_ok && /elliptical pocket X50 Y40 RX30 RY18/.test(await (await fetch(`${h.base}/api/programs/ELLIPSE-1/revisions/${saved.revision}/text`, { headers: { Authorization: `Bearer ${await h.logIn('boss')}` } })).text()), "the draft is prog's, its check passed, and it is seed 002's pocket");

  // A profile of the plate drawing (examples/plate.dxf), uploaded from the page.
  await page.getByRole('link', { name: 'New program' }).click();
  await page.getByLabel('Cycle', { exact: true }).selectOption('profile_dxf');
  await page.getByLabel('Drawing (DXF)').setInputFiles(join(web, '..', 'examples', 'plate.dxf'));
  await page.getByLabel('Depth (mm)', { exact: true }).fill('6');
  await page.getByLabel('Lead arc radius (0: none) (mm)').fill('4');
  const profile = await previewShown(page);
  t.check(/the check passed/.test(profile) && (await page.locator('#preview-h').innerText()) === 'Preview (rs274ngc)', `a profile of an uploaded drawing is previewed ("${profile}")`);

  // A pocket with islands from a drawing: docs/cam.md's cover, layer POCKET.
  await page.getByLabel('Cycle', { exact: true }).selectOption('pocket_dxf');
  await page.getByLabel('Drawing (DXF)').setInputFiles(join(web, '..', 'examples', 'cover.dxf'));
  await page.getByLabel('Layer (optional)').fill('POCKET');
  await page.getByLabel('Depth (mm)', { exact: true }).fill('4');
  await page.getByLabel('Stepover (mm)', { exact: true }).fill('1.5');
  await page.getByLabel('Tool diameter (mm)', { exact: true }).fill('4');
  const pocket = await previewShown(page);
  t.check(/the check passed/.test(pocket), `a pocket with islands from an uploaded drawing is previewed ("${pocket}")`);

  // The cutting calculator fills the spindle speed (1000 × 200 / (π × 8) = 7958).
  await page.getByLabel('Cutting speed v (m/min)').fill('200');
  await page.getByLabel('Tool diameter D (mm)').fill('8');
  await page.getByRole('button', { name: 'Use in the form' }).click();
  t.check((await page.getByLabel('Spindle speed (rev/min)').inputValue()) === '7958', 'the cutting calculator puts N = 7958 rev/min into the form');
  await axisCalculators(page, t);
}

// Seed 004's §7.5 calculators, computed by the server: example 7.1 as the
// page opens, example 7.3's precision, the register made the limit by a
// short one, and a bad input's message from the server.
async function axisCalculators(page, t) {
  const result = (key) => page.locator(`.calc-results tr[data-result="${key}"] td`).first().innerText();
  await page.locator('.calc-results tr[data-result="pulse_frequency_hz"]').waitFor();
  const fp = await result('pulse_frequency_hz');
  const pulses = await result('whole_pulses');
  await page.getByLabel('Calculator', { exact: true }).selectOption('precision');
  await page.locator('.calc-results tr[data-result="control_resolution_mm"]').waitFor();
  const cr = await result('control_resolution_mm');
  const accuracy = await result('accuracy_mm');
  await page.getByLabel('Register bits B').fill('8');
  await page.locator('.calc-results tr[data-result="limited_by"] td', { hasText: 'register' }).waitFor();
  const cr8 = await result('control_resolution_mm');
  await page.getByLabel('Register bits B').fill('8.5');
  await page.locator('#positioning-status[role="alert"]').waitFor();
  const said = await page.locator('#positioning-status').innerText();
  t.check(fp === '333.333' && pulses === '10000' && cr === '0.025' && accuracy === '0.0275' && cr8 === '3.92157' && said === 'bits: 8.5 is not a whole number', `the axis calculators give seed 004's examples 7.1 and 7.3 (f_p ${fp} Hz, ${pulses} pulses; CR ${cr} mm, accuracy ${accuracy} mm; 8 bits: CR ${cr8} mm, the register's) and the server's message ("${said}")`);

  // Table 7.4: a number as it is punched, the leading zeros as digits.
  await page.getByLabel('Calculator', { exact: true }).selectOption('bcd');
  await page.locator('.calc-results tr[data-result="code"]').waitFor();
  const code = await result('code');
  await page.getByLabel(/Whole number/).fill('0070');
  await page.locator('.calc-results tr[data-result="code"] td', { hasText: '0000 0000 0111 0000' }).waitFor();
  const digits = await page.locator('.calc-results tr[data-result^="digit-"]').allInnerTexts();
  await page.getByLabel(/Whole number/).fill('12a');
  await page.locator('#positioning-status[role="alert"]').waitFor();
  const bad = await page.locator('#positioning-status').innerText();
  t.check(code === '0001 0010 0101 0000' && digits.length === 4 && /Digit 7\s+0111\s+× 10\^1/.test(digits[2]) && /12a/.test(bad), `the BCD of 1250 (${code}), of 0070 digit by digit (${digits.map((d) => d.replace(/\s+/g, ' ')).join('; ')}), and a numeral refused ("${bad}")`);
}
