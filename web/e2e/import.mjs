// The library's import of a folder (library_import.ts), as a programmer:
// a folder chosen with its sub-folder, each file's result listed (new, a
// name twice skipped, a binary file skipped, the server's 409 for a program
// of another machine class shown), submitted from the keyboard; several
// files dropped; a folder dropped walked into, sub-folders too; too many
// files refused before anything is sent.
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

// A folder dropped on the import's drop zone: the browser hands it as one
// item whose webkitGetAsEntry() is a directory entry. A test cannot make a
// real one (DataTransfer takes files only), so the entries are made in the
// page with Chromium's interface: readEntries in batches of 2, then none.
// `tree`: {name: text, folder: {...}}.
async function dropFolder(page, name, tree) {
  await page.evaluate(
    ([top, spec]) => {
      const entry = (path, key, value) => {
        if (typeof value === 'string')
          return { isFile: true, isDirectory: false, name: key, fullPath: `${path}/${key}`, file: (ok) => ok(new File([value], key, { type: 'text/plain' })) };
        const children = Object.entries(value).map(([k, v]) => entry(`${path}/${key}`, k, v));
        return {
          isFile: false,
          isDirectory: true,
          name: key,
          fullPath: `${path}/${key}`,
          createReader: () => {
            let at = 0;
            return { readEntries: (ok) => setTimeout(() => ok(children.slice(at, (at += 2))), 1) };
          },
        };
      };
      const root = entry('', top, spec);
      const ev = new Event('drop', { bubbles: true, cancelable: true });
      Object.defineProperty(ev, 'dataTransfer', { value: { items: [{ kind: 'file', webkitGetAsEntry: () => root, getAsFile: () => null }], files: [] } });
      document.querySelector('form[aria-labelledby="import-h"] .drop').dispatchEvent(ev);
    },
    [name, tree],
  );
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

  await dropFolder(page, 'dropped', { 'imp-e.nc': 'G0 X5\nM2\n', deep: { 'imp-f.nc': 'G0 X6\nM2\n', deeper: { 'imp-g.nc': 'G0 X7\nM2\n' }, '.hidden.nc': 'M2\n' }, 'imp-h.nc': 'G0 X8\nM2\n' });
  await page.getByRole('button', { name: 'Import 5 files' }).click();
  await page.locator('#import-status', { hasText: /^4 of 5 files imported; 1 not/ }).waitFor();
  const walked = await page.locator('#import-results li').evaluateAll((li) => li.map((x) => `${x.dataset.file} ${x.dataset.result}`));
  const found = await Promise.all(['imp-e', 'imp-f', 'imp-g', 'imp-h'].map(async (n) => (await h.api('boss', 'GET', `/api/programs/${n}`)).status));
  t.check(found.every((s) => s === 200) && walked.join() === 'dropped/deep/.hidden.nc skipped,dropped/deep/deeper/imp-g.nc ok,dropped/deep/imp-f.nc ok,dropped/imp-e.nc ok,dropped/imp-h.nc ok', `a folder dropped is walked into, its sub-folders too (${walked.join(', ')})`);
  await dropFolder(page, 'huge', Object.fromEntries(Array.from({ length: 600 }, (_, i) => [`huge-${i}.nc`, 'M2\n'])));
  await page.locator('#import-status[role="alert"]', { hasText: 'More than 500 files' }).waitFor();
  t.check(await page.locator('form[aria-labelledby="import-h"] button[type="submit"]').isDisabled(), `a folder dropped with more than 500 files is refused before anything is sent ("${await page.locator('#import-status').innerText()}")`);

  await dropFiles(page, Array.from({ length: 501 }, (_, i) => [`many-${i}.nc`, 'M2\n']));
  await page.locator('#import-status[role="alert"]', { hasText: /^501 files/ }).waitFor(); // a drop is read before it is chosen
  const limit = await page.locator('#import-status[role="alert"]').innerText();
  const disabled = await page.locator('form[aria-labelledby="import-h"] button[type="submit"]').isDisabled();
  t.check(/^501 files: at most 500 at a time/.test(limit) && disabled && (await h.api('boss', 'GET', '/api/programs/many-0')).status === 404, `too many files are refused before anything is sent ("${limit}")`);
  await page.getByLabel('Search by name, comment or O number').fill('');
  await listed(page);
}
