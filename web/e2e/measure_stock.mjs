// The stock answer's figures (docs/web.md, "The stock answer"): each program
// given is uploaded to a fresh store, then its stock asked for with each
// query given (the server's answer, without the page): the bytes, the
// header's and the frames', the cells, the frames, the cells changed, the
// time of the first request (computed) and of the second (the cache).
// Prints, asserts nothing.
//   node e2e/measure_stock.mjs --usina ../build/usina \
//        --program ../tests/programs/romi/seed-000-example.nc --dialect romi \
//        [--queries '?frames=16|?frames=64']
import { readFileSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { arg, Harness, web } from './harness.mjs';

const harness = new Harness(resolve(arg('usina', join(web, '..', 'build', 'usina'))));
const program = resolve(arg('program', join(web, '..', 'tests', 'programs', 'romi', 'seed-000-example.nc')));
const dialect = arg('dialect', 'romi');
const queries = arg('queries', '?frames=16|?frames=64').split('|');

async function timedGet(token, path) {
  const t0 = performance.now();
  const r = await fetch(`${harness.base}${path}`, { headers: { Authorization: `Bearer ${token}` } });
  const body = Buffer.from(await r.arrayBuffer());
  return { status: r.status, body, ms: performance.now() - t0, from: r.headers.get('x-toolpath-cache') };
}

try {
  await harness.start();
  const token = await harness.logIn('boss');
  const name = basename(program).replace(/[^A-Za-z0-9_-]/g, '-');
  const up = await fetch(`${harness.base}/api/programs`, {
    method: 'POST',
    headers: { Authorization: `Bearer ${token}`, 'Content-Type': 'application/json' },
    body: JSON.stringify({ name, dialect, text: readFileSync(program, 'utf8') }),
  });
  const { revision } = await up.json();
  for (const q of queries) {
    const path = `/api/programs/${name}/revisions/${revision}/stock${q}`;
    const first = await timedGet(token, path);
    const second = await timedGet(token, path);
    if (first.status !== 200) {
      console.log(`${q}: ${first.status} ${first.body.toString()}`);
      continue;
    }
    const length = first.body.readUInt32LE(8);
    const header = JSON.parse(first.body.subarray(12, 12 + length).toString());
    const changed = header.frames.reduce((n, f) => n + f.cells, 0);
    const runs = header.frames.reduce((n, f) => n + f.runs, 0);
    console.log(
      `${name} ${q}: ${first.body.length} bytes (header ${length}, frames ${first.body.length - 12 - length}); ` +
        `box ${header.stock.box.join(' x ')} mm from ${header.stock.origin.join(',')}, ${header.cells.join(' x ')} cells of ${header.cell_mm.map((c) => c.toFixed(4)).join(' x ')} mm; ` +
        `${header.frames.length} frames of ${header.moves} moves; ${changed} cells changed in ${runs} runs; removed ${header.removed_mm3.toFixed(1)} mm3; ` +
        `${first.ms.toFixed(0)} ms (${first.from}), again ${second.ms.toFixed(0)} ms (${second.from})`,
    );
  }
} finally {
  harness.stop();
}
