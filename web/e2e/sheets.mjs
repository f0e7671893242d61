// The program page's setup sheets (issue 14): a programmer's PDF attached
// from the page is listed and downloads byte for byte (Attach without a
// file says to choose one); an HTML sheet
// downloads as a file (no tab of the page's origin shows it), and is shown
// in a sandboxed frame through a signed link that opens without a token
// (its script does not run; the link changed is refused), the PDF in a
// frame of its own; a .pdf that
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
  const html = '<!doctype html><title>Sheet</title><p>Vice, jaw 2</p><script>document.title = "ran"; document.body.append("script ran")</script>\n';
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
  check(/^PDF\s+\d+ bytes\s+boss\s+\d{4}-\d\d-\d\d \d\d:\d\d\s+Show the PDF sheet\s+Download the PDF sheet$/.test(row) && row.includes(`${pdf.length} bytes`), `the attached PDF is listed with size, author and date ("${row.replace(/\s+/g, ' ')}")`);
  const got = await download(page, '#sheet-pdf');
  check(got.bytes.equals(pdf) && /^seed-000-[0-9a-f]{12}-sheet\.pdf$/.test(got.name), `the PDF downloads byte for byte (${got.name}, ${got.bytes.length} of ${pdf.length} bytes)`);

  await attach(page, htmlPath);
  await page.locator('#sheet-html').waitFor();
  const before = { url: page.url(), pages: page.context().pages().length };
  const sheet = await download(page, '#sheet-html');
  const stayed = page.url() === before.url && page.context().pages().length === before.pages && (await page.title()) !== 'ran';
  check(sheet.bytes.toString('utf8') === html && /\.html$/.test(sheet.name) && stayed, `the HTML sheet is a download, not a page of ours (${sheet.name}, ${sheet.bytes.length} bytes)`);

  await showFlow(page, h, check, { html, pdf });

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

// The sheets shown in the page: each through a signed link in a frame.
async function showFlow(page, h, check, { html, pdf }) {
  // Chromium says so when the sandbox stops the sheet's script.
  let blocked = 0;
  const blockedScript = (m) => /^Blocked script execution in '.*\/sheet\/view\?.*sandboxed/.test(m.text()) && blocked++;
  page.on('console', blockedScript);
  await page.getByRole('button', { name: 'Show the HTML sheet' }).click();
  const frame = page.locator('#sheet-view iframe');
  await frame.waitFor();
  const [sandbox, src, title] = await Promise.all([frame.getAttribute('sandbox'), frame.getAttribute('src'), frame.getAttribute('title')]);
  const inside = page.frameLocator('#sheet-view iframe');
  await inside.getByText('Vice, jaw 2').waitFor();
  const ran = await inside.getByText('script ran').count();
  const focused = await page.evaluate(() => document.activeElement?.id);
  page.off('console', blockedScript);
  check(sandbox === '' && ran === 0 && blocked > 0 && /^HTML setup sheet of seed-000-/.test(title ?? '') && focused === 'sheet-view-h', `the HTML sheet shows in a sandboxed frame, its script blocked by the browser, the focus on its heading ("${title}")`);
  const open = await fetch(`${h.base}${src}`);
  const body = await open.text();
  const csp = open.headers.get('content-security-policy') ?? '';
  const tampered = await fetch(`${h.base}${src.replace(/sig=([0-9a-f])/, (_, c) => `sig=${c === '0' ? '1' : '0'}`)}`);
  const moved = await fetch(`${h.base}${src.replace('format=html', 'format=pdf')}`);
  check(open.status === 200 && body === html && csp.startsWith('sandbox;') && /expires=\d+&sig=[0-9a-f]{64}$/.test(src) && tampered.status === 403 && moved.status === 403, `its signed link opens without a token (sandboxed), and refuses a changed signature or format (${open.status}, ${tampered.status}, ${moved.status})`);
  await page.getByRole('button', { name: 'Close the HTML sheet' }).press('Enter');
  const back = await page.evaluate(() => document.activeElement?.id);
  check((await frame.count()) === 0 && back === 'show-sheet-html', 'Close from the keyboard takes the frame away and the focus back to Show');

  await page.getByRole('button', { name: 'Show the PDF sheet' }).click();
  await page.locator('#sheet-view iframe.pdf').waitFor();
  const pdfSrc = await page.locator('#sheet-view iframe.pdf').getAttribute('src');
  const got = await fetch(`${h.base}${pdfSrc}`);
  const bytes = Buffer.from(await got.arrayBuffer());
  check(got.status === 200 && got.headers.get('content-type') === 'application/pdf' && bytes.equals(pdf), `the PDF sheet shows in a frame through its own link (${bytes.length} bytes)`);
  // The HTML sheet again, for the picture (this PDF of every byte value is no document to draw).
  await page.getByRole('button', { name: 'Close the PDF sheet' }).click();
  await page.getByRole('button', { name: 'Show the HTML sheet' }).click();
  await page.frameLocator('#sheet-view iframe').getByText('Vice, jaw 2').waitFor();
  await page.locator('section.sheets').scrollIntoViewIfNeeded();
}
