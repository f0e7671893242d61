// The program page's setup sheets (issue 14): a programmer's PDF attached
// from the page is listed and downloads byte for byte (Attach without a
// file says to choose one); an HTML sheet
// downloads as a file (no tab of the page's origin shows it); a .pdf that
// is no PDF gets the server's 400 in words; an operator sees the sheets
// and no form to attach one.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { logInAs } from './flows.mjs';
import { fitsAtZoom } from './quality.mjs';

const FILE = 'Setup sheet file (PDF or HTML)';

async function openProgram(page, h, rev) {
  await page.goto(`${h.base}/#/program/seed-000/${rev}`);
  await page.getByRole('heading', { name: 'Setup sheets' }).waitFor();
}

async function attach(page, path) {
  await page.getByLabel(FILE).setInputFiles(path);
  await page.getByRole('button', { name: 'Attach the sheet' }).click();
}

async function download(page, id) {
  const got = page.waitForEvent('download');
  await page.locator(id).focus();
  await page.keyboard.press('Enter'); // from the keyboard
  const dl = await got;
  return { name: dl.suggestedFilename(), bytes: readFileSync(await dl.path()) };
}

export async function sheetsFlow(page, h, { check, shot }, rev) {
  // Every byte value, so a base64 or text mix-up shows.
  const pdf = Buffer.concat([Buffer.from('%PDF-1.4\n'), Buffer.from([...Array(256).keys()]), Buffer.from('\n%%EOF\n')]);
  const pdfPath = join(h.scratch, 'plate-sheet.pdf');
  writeFileSync(pdfPath, pdf);
  const html = '<!doctype html><title>Sheet</title><p>Vice, jaw 2</p><script>document.title = "ran"</script>\n';
  const htmlPath = join(h.scratch, 'plate-sheet.html');
  writeFileSync(htmlPath, html);
  const fake = join(h.scratch, 'not-a.pdf');
  writeFileSync(fake, 'no PDF at all\n');

  await logInAs(page, 'boss');
  await openProgram(page, h, rev);
  await page.locator('#sheets-list > *').first().waitFor(); // the list is read after the page shows
  check((await page.getByText('This revision has no setup sheet.').count()) === 1, 'a revision without sheets says so');
  await page.getByRole('button', { name: 'Attach the sheet' }).click();
  await page.locator('#sheets-status[role="alert"]', { hasText: 'Choose a PDF or HTML file first.' }).waitFor();
  check(await page.getByLabel(FILE).evaluate((e) => e === document.activeElement), 'Attach without a file says to choose one and focuses the chooser');
  await attach(page, pdfPath);
  await page.locator('#sheet-pdf').waitFor();
  const row = await page.locator('#sheets-list tr[data-format="pdf"]').innerText();
  check(/^PDF\s+\d+ bytes\s+boss\s+\d{4}-\d\d-\d\d \d\d:\d\d\s+Download the PDF sheet$/.test(row) && row.includes(`${pdf.length} bytes`), `the attached PDF is listed with size, author and date ("${row.replace(/\s+/g, ' ')}")`);
  const got = await download(page, '#sheet-pdf');
  check(got.bytes.equals(pdf) && /^seed-000-[0-9a-f]{12}-sheet\.pdf$/.test(got.name), `the PDF downloads byte for byte (${got.name}, ${got.bytes.length} of ${pdf.length} bytes)`);

  await attach(page, htmlPath);
  await page.locator('#sheet-html').waitFor();
  const before = { url: page.url(), pages: page.context().pages().length };
  const sheet = await download(page, '#sheet-html');
  const stayed = page.url() === before.url && page.context().pages().length === before.pages && (await page.title()) !== 'ran';
  check(sheet.bytes.toString('utf8') === html && /\.html$/.test(sheet.name) && stayed, `the HTML sheet is a download, not a page of ours (${sheet.name}, ${sheet.bytes.length} bytes)`);

  await attach(page, fake);
  await page.locator('#sheets-status[role="alert"]').waitFor();
  const refused = await page.locator('#sheets-status').innerText();
  check(/^Refused \(400\): \S/.test(refused), `a .pdf that is no PDF gets the server's reason ("${refused}")`);
  await page.locator('section.sheets').scrollIntoViewIfNeeded();
  await shot(page, 'web-sheets.png', false);
  const zoomed = await fitsAtZoom(page, 'the program page with two sheets and the form');
  check(zoomed.ok, zoomed.text);

  await logInAs(page, 'oper');
  await openProgram(page, h, rev);
  await page.locator('#sheet-pdf').waitFor();
  const again = await download(page, '#sheet-pdf');
  check(again.bytes.equals(pdf) && (await page.getByLabel(FILE).count()) === 0 && (await page.getByText('attaching a sheet is for programmers and admins').count()) === 1, 'an operator downloads the sheet and has no form to attach one');
}
