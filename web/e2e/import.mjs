// The library's import of a folder (library_import.ts), as a programmer:
// a folder chosen with its sub-folder, each file's result listed (new, a
// name twice skipped, a binary file skipped, the server's 409 for a program
// of another machine class shown), submitted from the keyboard; several
// files dropped; too many files refused before anything is sent.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { logInAs, listed } from './flows.mjs';

function folder(scratch) {
  const dir = join(scratch, 'import');
  mkdirSync(join(dir, 'sub'), { recursive: true });
  writeFileSync(join(dir, 'imp-a.nc'), 'G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nM2\n');
  writeFileSync(join(dir, 'sub', 'imp-b.ngc'), 'G21 G90\nG0 X5 Y5 Z5\nG1 Z-1 F100\nG1 Y20\nM2\n');
  writeFileSync(join(dir, 'sub', 'imp-a.tap'), 'G0 X1\nM2\n');
  writeFileSync(join(dir, 'seed-000.nc'), 'G0 X1\nM2\n');
  writeFileSync(join(dir, 'imp-bin.nc'), Buffer.from([0x47, 0x30, 0x00, 0x01, 0x0a]));
  return dir;
}

async function results(page) {
  return page.locator('#import-results li').evaluateAll((li) => Object.fromEntries(li.map((x) => [x.dataset.file.replace(/^.*?import\//, ''), `${x.dataset.result}: ${x.textContent}`])));
}

// Files made in the page and dropped on the import's drop zone: [name,
// text] or [name, null, size] (that many bytes of 'M').
async function dropFiles(page, files) {
  const data = await page.evaluateHandle((list) => {
    const dt = new DataTransfer();
    for (const [name, text, size] of list) dt.items.add(new File([text ?? new Uint8Array(size).fill(0x4d)], name, { type: 'text/plain' }));
    return dt;
  }, files);
  await page.locator('form[aria-labelledby="import-h"] .drop').dispatchEvent('drop', { dataTransfer: data });
}

export async function importFlow(page, h, t) {
  await logInAs(page, 'prog');
  await page.getByRole('heading', { name: 'Import a folder' }).waitFor();
  await page.getByLabel('Folder', { exact: true }).setInputFiles(folder(h.scratch));
  await page.locator('#import-status', { hasText: /^5 files chosen/ }).waitFor();
  await page.getByLabel('Machine class of the files (optional)').fill('mill');
  await page.getByLabel('Reason of the import (optional)').fill('the shop folder');
  await page.getByLabel('Reason of the import (optional)').press('Enter'); // the keyboard submits
  await page.locator('#import-status', { hasText: /imported/ }).waitFor({ timeout: 30000 });
  const said = await page.locator('#import-status').innerText();
  const r = await results(page);
  const ok = /^ok: .*imp-a\.nc → imp-a: new revision/.test(r['imp-a.nc'] ?? '') && /^ok: .* → imp-b: new revision/.test(r['sub/imp-b.ngc'] ?? '');
  const twice = /^skipped: .*the same program name, imp-a, as /.test(r['sub/imp-a.tap'] ?? '');
  const binary = /^skipped: .*not a text file/.test(r['imp-bin.nc'] ?? '');
  const refused = /^error: .*refused \(409\)/.test(r['seed-000.nc'] ?? '');
  t.check(ok && twice && binary && refused && /^2 of 5 files imported; 3 not/.test(said), `a folder imported with a result per file ("${said}"; ${JSON.stringify(r)})`);
  const b = await h.api('boss', 'GET', '/api/programs/imp-b');
  t.check(b.status === 200 && b.json.machine_class === 'mill' && b.json.revisions[0].reason === 'the shop folder', 'the imported program is in the library with its class and reason');
  await page.locator('#import-results').evaluate((e) => e.scrollIntoView({ block: 'end' }));
  await t.shot(page, 'web-import.png', false);
  await page.getByLabel('Search by name, comment or O number').fill('imp-');
  t.check(/^2 programs$/.test(await listed(page)), 'the library lists the imported programs');

  await dropFiles(page, [['imp-c.nc', 'G0 X3\nM2\n'], ['imp-d.nc', 'G0 X4\nM2\n'], ['imp-big.nc', null, (16 << 20) + 1]]);
  await page.getByRole('button', { name: 'Import 3 files' }).click();
  await page.locator('#import-status', { hasText: /^2 of 3 files imported; 1 not/ }).waitFor();
  const big = (await results(page))['imp-big.nc'] ?? '';
  t.check((await h.api('boss', 'GET', '/api/programs/imp-d')).status === 200 && /^skipped: .*16777217 bytes, more than the 16777216 of one file here/.test(big) && (await h.api('boss', 'GET', '/api/programs/imp-big')).status === 404, `files dropped are imported, one too large skipped ("${big}")`);

  await dropFiles(page, Array.from({ length: 501 }, (_, i) => [`many-${i}.nc`, 'M2\n']));
  const limit = await page.locator('#import-status[role="alert"]').innerText();
  const disabled = await page.locator('form[aria-labelledby="import-h"] button[type="submit"]').isDisabled();
  t.check(/^501 files: at most 500 at a time/.test(limit) && disabled && (await h.api('boss', 'GET', '/api/programs/many-0')).status === 404, `too many files are refused before anything is sent ("${limit}")`);
  await page.getByLabel('Search by name, comment or O number').fill('');
  await listed(page);
}
