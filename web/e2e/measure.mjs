// Figures for docs/web.md: a large program uploaded over the API, its
// tool-path stream timed and sized, then its page opened in chromium: the
// time to the first picture and the page's JavaScript heap.
//   node e2e/measure.mjs --usina build/usina --program big.ngc [--dialect rs274ngc]
import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { arg, Harness, skipUnlessReady } from './harness.mjs';

skipUnlessReady();
const harness = new Harness(resolve(arg('usina', '../build/usina')));
const text = readFileSync(resolve(arg('program', '')), 'utf8');
const ms = (t0) => Math.round(performance.now() - t0);

// The resident memory of chromium's processes started for `profile` (the
// browser and every child: renderer, GPU/SwiftShader), in MB.
function chromiumMegabytes(profile) {
  const procs = readdirSync('/proc').filter((d) => /^\d+$/.test(d)).map((pid) => {
    try {
      const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
      const ppid = stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1];
      const status = readFileSync(`/proc/${pid}/status`, 'utf8');
      const rss = /VmRSS:\s+(\d+)/.exec(status);
      const anon = /RssAnon:\s+(\d+)/.exec(status);
      const cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
      return { pid, ppid, kb: rss ? Number(rss[1]) : 0, anon: anon ? Number(anon[1]) : 0, cmd };
    } catch {
      return null;
    }
  }).filter(Boolean);
  const tree = new Set(procs.filter((p) => p.cmd.includes(profile)).map((p) => p.pid));
  for (let grew = true; grew; ) {
    grew = false;
    for (const p of procs) if (!tree.has(p.pid) && tree.has(p.ppid)) tree.add(p.pid), (grew = true);
  }
  const kb = procs.filter((p) => tree.has(p.pid)).reduce((a, p) => a + p.kb, 0);
  const renderers = procs.filter((p) => tree.has(p.pid) && p.cmd.includes('--type=renderer'));
  const renderer = renderers.reduce((a, p) => a + p.kb, 0);
  // Its own memory: RssAnon leaves out the shared files mapped (chromium's
  // own code and libraries, which every tab shares).
  const own = renderers.reduce((a, p) => a + p.anon, 0);
  // The GPU process (SwiftShader here) holds the page's WebGL buffers.
  const gpu = procs.filter((p) => tree.has(p.pid) && p.cmd.includes('--type=gpu-process')).reduce((a, p) => a + p.anon, 0);
  return { all: (kb / 1024).toFixed(0), renderer: (renderer / 1024).toFixed(0), own: Math.round(own / 1024), gpu: Math.round(gpu / 1024) };
}

try {
  const base = await harness.start();
  const token = await harness.logIn();
  const auth = { Authorization: `Bearer ${token}` };
  let t0 = performance.now();
  const up = await fetch(`${base}/api/programs`, {
    method: 'POST',
    headers: auth,
    body: JSON.stringify({ name: 'BIG', dialect: arg('dialect', 'rs274ngc'), text }),
  });
  const rev = (await up.json()).revision;
  console.log(`upload and check: ${ms(t0)} ms (HTTP ${up.status}), ${text.length} bytes`);
  t0 = performance.now();
  const stream = await fetch(`${base}/api/programs/BIG/revisions/${rev}/toolpath`, { headers: auth });
  const bytes = new Uint8Array(await stream.arrayBuffer());
  const v = new DataView(bytes.buffer);
  console.log(
    `toolpath: ${ms(t0)} ms, ${bytes.length} bytes, ${v.getUint32(8, true)} vertices, ` +
      `${v.getBigUint64(16, true)} moves, flags ${v.getUint32(12, true)}`,
  );
  // The same stream again: from the cache. Then a new run (another budget)
  // with the library asked for while it runs: the loop answers meanwhile.
  const route = `${base}/api/programs/BIG/revisions/${rev}/toolpath`;
  t0 = performance.now();
  const again = await fetch(route, { headers: auth });
  await again.arrayBuffer();
  console.log(`toolpath again: ${ms(t0)} ms (X-Toolpath-Cache: ${again.headers.get('x-toolpath-cache')})`);
  t0 = performance.now();
  const run = fetch(`${route}?max_vertices=100000`, { headers: auth }).then(async (r) => {
    await r.arrayBuffer();
    return `${ms(t0)} ms (${r.headers.get('x-toolpath-cache')})`;
  });
  await new Promise((done) => setTimeout(done, 200)); // the run is under way
  const t1 = performance.now();
  const list = await fetch(`${base}/api/programs`, { headers: auth });
  await list.json();
  const listed = ms(t1);
  console.log(`toolpath of another budget: ${await run}; GET /api/programs meanwhile: ${listed} ms (HTTP ${list.status})`);
  const context = await harness.browser();
  const page = context.pages()[0] ?? (await context.newPage());
  page.setDefaultTimeout(120000);
  await page.goto(`${base}/`);
  await page.evaluate((t) => sessionStorage.setItem('usina.token', t), token);
  await page.goto(`${base}/#/library`);
  await page.locator('#library-table[aria-busy="false"]').waitFor();
  const before = chromiumMegabytes(harness.scratch);
  console.log(`page: before the program (the library shown): the renderer ${before.renderer} MB resident, ${before.own} MB its own (RssAnon); the GPU process ${before.gpu} MB its own`);
  t0 = performance.now();
  await page.goto(`${base}/#/program/BIG/${rev}`);
  await page.waitForFunction(() => Number(document.getElementById('viewer')?.dataset.vertices) > 1);
  console.log(`page: first picture ${ms(t0)} ms after navigation (text, stream, viewer)`);
  const fetched = await page.evaluate(() =>
    performance.getEntriesByType('resource').filter((e) => e.name.includes('/api/programs/')).map((e) => [e.name.split('/').pop(), Math.round(e.startTime), Math.round(e.responseEnd)]),
  );
  console.log(`page: requests (name, start ms, end ms): ${JSON.stringify(fetched)}`);
  await page.locator('#L1').waitFor();
  console.log(`page: the text shown ${ms(t0)} ms after navigation`);
  const cdp = await context.newCDPSession(page);
  await cdp.send('Performance.enable');
  await cdp.send('HeapProfiler.collectGarbage');
  const metrics = (await cdp.send('Performance.getMetrics')).metrics;
  const heap = metrics.find((m) => m.name === 'JSHeapUsedSize').value;
  const mem = chromiumMegabytes(harness.scratch);
  console.log(`page: JavaScript heap ${(heap / 1048576).toFixed(1)} MB (typed arrays aside); chromium resident ${mem.all} MB in all, the page's renderer ${mem.renderer} MB, ${mem.own} MB its own (RssAnon), ${mem.own - before.own} MB more than before the program; the GPU process ${mem.gpu} MB its own, ${mem.gpu - before.gpu} MB more`);
  t0 = performance.now();
  for (const view of ['Top', 'Front', 'Side', 'Iso', 'Top', 'Front', 'Side', 'Iso', 'Top', 'Iso'])
    await page.getByRole('button', { name: `${view} view` }).click();
  console.log(`page: ${((performance.now() - t0) / 10).toFixed(0)} ms a redraw (view buttons, SwiftShader: no GPU)`);
  await context.close();
} finally {
  harness.stop();
}
