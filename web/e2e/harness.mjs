// What the browser test and the measurements share: a scratch folder, the
// page built into it, a fresh store, a real `usina serve`, Debian's chromium.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const web = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const CHROMIUM = '/usr/bin/chromium';
export const PASSWORD = 'correct horse 1';
export const SKIP = 77;
// The machine's shift calendar (above): its zone, and a holiday in the
// chart's two weeks.
export const ZONE = 'America/Sao_Paulo';
export const HOLIDAY = new Date(Date.now() - 3 * 86_400_000).toLocaleDateString('en-CA', { timeZone: ZONE });

export function arg(name, fallback) {
  const at = process.argv.indexOf(`--${name}`);
  return at > 0 ? process.argv[at + 1] : fallback;
}

// Exits 77 with the reason when the browser test cannot run here.
export function skipUnlessReady() {
  const why = !existsSync(CHROMIUM)
    ? `${CHROMIUM} is not installed (scripts/setup.sh installs Debian's chromium)`
    : !existsSync(join(web, 'node_modules', '@playwright', 'test'))
      ? 'web/node_modules is missing (scripts/setup.sh runs `npm ci` in web/)'
      : '';
  if (!why) return;
  console.log(`SKIPPED: ${why}`);
  process.exit(SKIP);
}

export class Harness {
  constructor(usina) {
    this.usina = usina;
    this.scratch = mkdtempSync(join(tmpdir(), 'usina-web-'));
    this.children = [];
  }

  // Builds the page, makes the store and the configuration, starts the
  // server; the page's address.
  async start() {
    const page = join(this.scratch, 'page');
    const built = spawnSync(process.execPath, [join(web, 'build.mjs'), '--outdir', page], { stdio: 'inherit' });
    if (built.status !== 0) throw new Error('the page does not build');
    const data = join(this.scratch, 'data');
    writeFileSync(join(this.scratch, 'pw'), `${PASSWORD}\n`);
    const init = spawnSync(this.usina, ['serve', '--init', '--data', data, '--admin', 'boss', '--password-file', join(this.scratch, 'pw')], { stdio: 'inherit' });
    if (init.status !== 0) throw new Error('usina serve --init failed');
    const config = join(this.scratch, 'usina-serve.toml');
    writeFileSync(
      config,
      `[web]\nroot = "page"\n\n[server]\nmax_upload = 134217728\n\n[[machine]]\nname = "romi-1"\ndialect = "romi"\nport = "${this.machinePort()}"\n` +
        `baud = 9600\ndata_bits = 7\nparity = "even"\nstop_bits = 2\nflow = "xonxoff"\ncode = "iso"\neob = "hash"\nmode = "tryout"\n` +
        // Shifts the whole day every day in a zone not UTC's, and a holiday
        // three days ago: the utilisation is charted in the zone's days
        // against the shifts, and a day without a shift says so (utilisation.mjs).
        `\n[machine.calendar]\ntimezone = "${ZONE}"\nshifts = [{days = "mon-sun", start = "00:00", end = "12:00"}, {days = "mon-sun", start = "12:00", end = "24:00"}]\nholidays = ["${HOLIDAY}"]\n` +
        // A life for two tools: T1 is worn out by the first part (tools.mjs).
        `\n[machine.tool_life]\nT1 = {parts = 1}\nT2 = {cutting_minutes = 600}\n`,
    );
    const port = await this.serve(['serve', '--data', data, '--config', config, '--listen', '127.0.0.1:0']);
    this.base = `http://127.0.0.1:${port}`;
    return this.base;
  }

  // The server's port, from its "listening on http://127.0.0.1:PORT" line.
  serve(args) {
    return new Promise((done, fail) => {
      const p = spawn(this.usina, args, { stdio: ['ignore', 'inherit', 'pipe'] });
      this.children.push(p);
      let said = '';
      p.stderr.on('data', (b) => {
        said += b.toString();
        process.stderr.write(b);
        const m = said.match(/listening on http:\/\/127\.0\.0\.1:(\d+)/);
        if (m) done(Number(m[1]));
      });
      p.on('exit', (code) => fail(new Error(`usina serve exited with ${code}: ${said}`)));
    });
  }

  // A simulated machine's serial line: a socat pty pair (when socat is there).
  machinePort() {
    if (spawnSync('sh', ['-c', 'command -v socat']).status !== 0) return '/nonexistent/usina-e2e-tty';
    const cnc = join(this.scratch, 'cnc');
    this.controlPath = join(this.scratch, 'ctl'); // the control's end (e2e/control.mjs)
    const p = spawn('socat', [`pty,raw,echo=0,link=${join(this.scratch, 'ctl')}`, `pty,raw,echo=0,link=${cnc}`], { stdio: 'ignore' });
    this.children.push(p);
    for (let i = 0; i < 250 && !existsSync(cnc); i++) spawnSync('sleep', ['0.02']);
    return cnc;
  }

  // Debian's chromium, headless, in a fresh profile.
  async browser() {
    const { chromium } = await import('@playwright/test'); // its browser API (its runner: docs/web.md)
    return chromium.launchPersistentContext(join(this.scratch, 'profile'), {
      executablePath: CHROMIUM,
      headless: true,
      viewport: { width: 1280, height: 860 },
      args: [
        '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        // WebGL without a GPU: SwiftShader, which Chromium no longer falls back to by itself.
        '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
      ],
    });
  }

  // A token for the API (the measurements upload without the page).
  async logIn(user = 'boss') {
    const r = await fetch(`${this.base}/api/login`, { method: 'POST', body: JSON.stringify({ user, password: PASSWORD }) });
    return (await r.json()).token;
  }

  // A user of `role` (as the admin, by the API).
  async addUser(name, role) {
    const r = await fetch(`${this.base}/api/users`, {
      method: 'POST',
      headers: { Authorization: `Bearer ${await this.logIn()}`, 'Content-Type': 'application/json' },
      body: JSON.stringify({ name, role, password: PASSWORD }),
    });
    if (r.status !== 201 && r.status !== 200) throw new Error(`cannot add ${name}: ${r.status} ${await r.text()}`);
  }

  // An API call as `user` (what the page would do), its status and JSON.
  async api(user, method, path, body) {
    const r = await fetch(`${this.base}${path}`, {
      method,
      headers: { Authorization: `Bearer ${await this.logIn(user)}`, 'Content-Type': 'application/json' },
      body: body === undefined ? undefined : JSON.stringify(body),
    });
    return { status: r.status, json: await r.json().catch(() => null) };
  }

  stop() {
    for (const c of this.children) if (c.exitCode === null) c.kill('SIGTERM');
    rmSync(this.scratch, { recursive: true, force: true });
  }
}

// The viewer's canvas read back: the pixels that are not its background,
// and where a pixel of tool 1's colour is (a feed to click).
export async function canvasPixels(page) {
  return page.evaluate(() => {
    const c = document.querySelector('#viewer canvas');
    const t = document.createElement('canvas');
    t.width = c.width;
    t.height = c.height;
    const g = t.getContext('2d');
    g.drawImage(c, 0, 0);
    const d = g.getImageData(0, 0, t.width, t.height).data;
    const bg = [0x1d, 0x23, 0x2a];
    let drawn = 0;
    let feed = null; // a pixel of tool 1's colour (#ffb74d): a feed to click
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) drawn++;
      if (!feed && Math.abs(d[i] - 0xff) < 30 && Math.abs(d[i + 1] - 0xb7) < 40 && Math.abs(d[i + 2] - 0x4d) < 50) {
        const px = (i / 4) % t.width;
        const py = Math.floor(i / 4 / t.width);
        feed = { x: (px * c.clientWidth) / t.width, y: (py * c.clientHeight) / t.height };
      }
    }
    return { drawn, feed, total: d.length / 4 };
  });
}
