// The library at a plant's size (run.mjs runs it last): 10,000 programs
// imported through the API (POST /api/import, 500 a request), the library
// opened and the time to its first page printed (not asserted), then a
// search by a comment's word, by a tool and by an O number, each finding
// the one program that has it.
import { listed } from './flows.mjs';

export const BIG_LIBRARY = 10000;
const BATCH = 500;

// Program n of the big library: its own O number and comment, one of 20
// tools. Three of them hold what the searches look for, which no other
// program's name, comment, O number or tool holds.
function bigProgram(n) {
  const name = `BIG${String(n).padStart(5, '0')}`;
  let number = `O${n}`;
  let comment = `PART ${n} OF THE BIG LIBRARY`;
  let tool = 1 + (n % 20);
  if (n === 4321) comment = 'FIXTURE WITH A ZEBRA CLAMP';
  if (n === 7777) tool = 777;
  if (n === 9001) number = 'O98765';
  const text = `%\n${number} (${comment})\nG21 G90\nT${tool} M6\nG0 X${n % 100} Y1 Z5\nG1 Z-1 F100\nM2\n%\n`;
  return { name: `${name}.nc`, text };
}

// Imports the programs through the API as the admin, one token for all.
export async function bigLibraryImport(h) {
  const token = await h.logIn('boss');
  for (let from = 1; from <= BIG_LIBRARY; from += BATCH) {
    const files = [];
    for (let n = from; n < from + BATCH && n <= BIG_LIBRARY; n++) files.push(bigProgram(n));
    const r = await fetch(`${h.base}/api/import`, {
      method: 'POST',
      headers: { Authorization: `Bearer ${token}`, 'Content-Type': 'application/json' },
      body: JSON.stringify({ files, machine_class: 'big', dialect: 'rs274ngc', reason: 'e2e: a big library' }),
    });
    const j = await r.json();
    if (r.status !== 200 || j.imported !== files.length) throw new Error(`import from ${from}: ${r.status} ${JSON.stringify(j).slice(0, 300)}`);
  }
}

// The search box or the tool field filled, the one program it finds.
async function found(page, label, value) {
  await page.getByLabel(label).fill(value);
  const count = await listed(page);
  const names = await page.locator('table[aria-label="Programs"] tbody tr td:first-child').allInnerTexts();
  await page.getByLabel(label).fill('');
  await listed(page);
  return { count, names };
}

export async function bigLibraryFlow(page, h, t) {
  const before = (await h.api('boss', 'GET', '/api/programs?limit=1')).json.total;
  const seeding = Date.now();
  await bigLibraryImport(h);
  console.log(`     (${BIG_LIBRARY} programs imported through POST /api/import in ${((Date.now() - seeding) / 1000).toFixed(1)} s)`);
  const total = before + BIG_LIBRARY;

  // From another page of the app to the library's first page.
  await page.getByRole('link', { name: 'Machines' }).click();
  await page.getByRole('heading', { name: 'Machines' }).waitFor();
  const clicked = Date.now();
  await page.getByRole('link', { name: 'Library' }).click();
  await page.locator('table[aria-label="Programs"] tbody tr').nth(49).waitFor();
  const inApp = Date.now() - clicked;
  // The whole page loaded afresh (its script too) up to the first page.
  const loading = Date.now();
  await page.reload();
  await page.locator('table[aria-label="Programs"] tbody tr').nth(49).waitFor();
  const fresh = Date.now() - loading;
  const count = await listed(page);
  console.log(`     (the first page of ${total} programs: ${inApp} ms from the Library link, ${fresh} ms for a fresh load of the page)`);
  t.check(count === `${total} programs` && (await page.locator('#library-page').innerText()) === `Page 1 of ${Math.ceil(total / 50)}`, `a library of ${total} programs opens at its first page (${count})`);

  const comment = await found(page, 'Search by name', 'zebra');
  t.check(comment.count === '1 program' && comment.names.join() === 'BIG04321', `the search by a comment's word finds its program (${comment.count}: ${comment.names.join()})`);
  const number = await found(page, 'Search by name', 'O98765');
  t.check(number.count === '1 program' && number.names.join() === 'BIG09001', `the search by an O number finds its program (${number.count}: ${number.names.join()})`);
  const tool = await found(page, 'Uses tool', 'T777');
  t.check(tool.count === '1 program' && tool.names.join() === 'BIG07777', `the tool filter finds the program that calls T777 (${tool.count}: ${tool.names.join()})`);
  await page.getByLabel('Uses tool').fill('T7x');
  const refused = await page.locator('#library-tool-error').innerText();
  t.check(/whole number/.test(refused) && (await page.getByLabel('Uses tool').getAttribute('aria-invalid')) === 'true', `a tool that is no number is refused on the page ("${refused}")`);
  await page.getByLabel('Uses tool').fill('');
  await listed(page);
}
