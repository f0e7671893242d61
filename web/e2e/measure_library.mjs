// The library's figures (docs/web.md, "The library"): a fresh store of
// 10,000 programs imported through the API, then the time of
// GET /api/programs for the first page, a search and a tool, each asked
// five times (the server's answer, without the page), and the page's first
// page after navigation in Debian's chromium. Prints, asserts nothing.
//   node e2e/measure_library.mjs --usina ../build/usina
import { join, resolve } from 'node:path';
import { bigLibraryImport } from './library.mjs';
import { arg, Harness, PASSWORD, skipUnlessReady, web } from './harness.mjs';

skipUnlessReady();
const harness = new Harness(resolve(arg('usina', join(web, '..', 'build', 'usina'))));

async function timed(token, path) {
  const times = [];
  let total = 0;
  for (let i = 0; i < 5; i++) {
    const t0 = performance.now();
    const r = await fetch(`${harness.base}${path}`, { headers: { Authorization: `Bearer ${token}` } });
    const j = await r.json();
    times.push(performance.now() - t0);
    total = j.total;
  }
  times.sort((a, b) => a - b);
  console.log(`${path}: ${total} programs; ${times.map((t) => t.toFixed(0)).join(', ')} ms`);
}

try {
  await harness.start();
  const seeding = performance.now();
  await bigLibraryImport(harness);
  console.log(`10000 programs imported in ${((performance.now() - seeding) / 1000).toFixed(1)} s`);
  const token = await harness.logIn('boss');
  for (const path of ['/api/programs?limit=50', '/api/programs?limit=50&offset=9950', '/api/programs?limit=50&text=zebra', '/api/programs?limit=50&text=O98765', '/api/programs?limit=50&tool=777', '/api/programs?limit=50&text=part']) await timed(token, path);
  const context = await harness.browser();
  const page = context.pages()[0] ?? (await context.newPage());
  await page.goto(`${harness.base}/`);
  await page.getByLabel('User').fill('boss');
  await page.getByLabel('Password').fill(PASSWORD);
  await page.getByLabel('Password').press('Enter');
  await page.getByRole('heading', { name: 'Library' }).waitFor();
  for (let i = 0; i < 3; i++) {
    await page.getByRole('link', { name: 'Machines' }).click();
    await page.getByRole('heading', { name: 'Machines' }).waitFor();
    const t0 = performance.now();
    await page.getByRole('link', { name: 'Library' }).click();
    await page.locator('table[aria-label="Programs"] tbody tr').nth(49).waitFor();
    const t1 = performance.now();
    await page.reload();
    await page.locator('table[aria-label="Programs"] tbody tr').nth(49).waitFor();
    console.log(`the page's first page: ${(t1 - t0).toFixed(0)} ms from the Library link, ${(performance.now() - t1).toFixed(0)} ms for a fresh load`);
  }
  await context.close();
} finally {
  harness.stop();
}
