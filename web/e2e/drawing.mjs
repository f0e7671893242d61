// The program page's 2D drawing (run.mjs runs it on the seed 000 program):
// the part view shows as a picture with its four layers, the SVG is an
// <img> of an object URL (no markup of it in the page), the DXF downloads
// from the keyboard, and the tool-path view has a layer per tool.
import { readFileSync } from 'node:fs';

async function layers(page) {
  await page.locator('#drawing[aria-busy="false"]').waitFor();
  return page.locator('.drawing-layers li').evaluateAll((li) => li.map((x) => x.dataset.layer));
}

// The pixels of the drawing's picture that are not white, read back
// through a canvas (the picture is an object URL of the page's own origin).
function drawnPixels(page) {
  return page.locator('#drawing img').evaluate((img) => {
    const c = document.createElement('canvas');
    c.width = img.clientWidth;
    c.height = img.clientHeight;
    const g = c.getContext('2d');
    g.fillStyle = '#fff';
    g.fillRect(0, 0, c.width, c.height);
    g.drawImage(img, 0, 0, c.width, c.height);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 3 * 235) n++;
    return n;
  });
}

export async function drawingFlow(page, t, rev) {
  await page.getByRole('heading', { name: 'Drawing', exact: true }).waitFor();
  const shown = await layers(page);
  await page.waitForFunction(() => {
    const img = document.querySelector('#drawing img');
    return img && img.complete && img.naturalWidth > 0;
  });
  const img = page.locator('#drawing img');
  const [src, alt, width] = [await img.getAttribute('src'), await img.getAttribute('alt'), await img.evaluate((i) => i.naturalWidth)];
  const inline = await page.locator('#drawing svg, .drawing-panel svg').count();
  const drawn = await drawnPixels(page);
  const svg = await page.evaluate(async (rev) => {
    const r = await fetch(`/api/programs/seed-000/revisions/${rev}/drawing`, { headers: { Authorization: `Bearer ${sessionStorage.getItem('usina.token')}` } });
    return r.text();
  }, rev);
  const four = ['CONTOUR', 'RAPID', 'HOLES', 'POCKETS'].every((l) => shown.includes(l) && svg.includes(`<g id="${l}"`));
  t.check(four && src.startsWith('blob:') && width > 100 && drawn > 1000 && inline === 0 && /^Part drawing of seed-000/.test(alt), `the part drawing shows as a picture with its layers (${shown.join(', ')}; ${width} px wide, ${drawn} pixels drawn; "${alt}")`);
  t.check(/^Drawn: \d+ layers\.$/.test(await page.locator('#drawing-status').innerText()), 'the drawing is whole');
  await page.locator('.drawing-panel').scrollIntoViewIfNeeded();
  await t.shot(page, 'web-drawing.png', false);

  // The DXF from the keyboard: Enter on its link.
  const download = page.waitForEvent('download');
  await page.locator('#drawing-dxf').focus();
  await page.keyboard.press('Enter');
  const dl = await download;
  const dxf = readFileSync(await dl.path(), 'latin1');
  t.check(/\.dxf$/.test(dl.suggestedFilename()) && /SECTION/.test(dxf) && /\nCONTOUR\r?\n/.test(dxf) && /\nHOLES\r?\n/.test(dxf), `the DXF downloads from the keyboard (${dl.suggestedFilename()}, ${dxf.length} bytes)`);

  await zoomDrawing(page, t);

  await page.getByLabel('Drawing view').selectOption('toolpath');
  await page.waitForFunction(() => document.querySelector('.drawing-layers li[data-layer^="TOOLPATH_T"]'));
  const tools = await layers(page);
  t.check(tools.includes('TOOLPATH_T1') && tools.includes('TOOLPATH_T2') && !tools.includes('CONTOUR'), `the tool-path view has a layer per tool (${tools.join(', ')})`);
  await clickDrawing(page, t);
  await page.getByLabel('Drawing view').selectOption('part');
  await page.waitForFunction(() => document.querySelector('.drawing-layers li[data-layer="CONTOUR"]'));
}

// A drawn pixel of the tool-path view and one with nothing drawn within 16
// pixels (the picture read back at its size on the page).
async function drawnAndEmpty(page) {
  return page.evaluate(async () => {
    const img = document.querySelector('#drawing img');
    await img.decode();
    const r = img.getBoundingClientRect();
    const [w, h] = [Math.floor(r.width), Math.floor(r.height)];
    const c = new OffscreenCanvas(w, h);
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0, w, h);
    const d = g.getImageData(0, 0, w, h).data;
    const inked = (x, y) => d[(y * w + x) * 4 + 3] > 40;
    let drawn = null;
    let empty = null;
    for (let y = 20; y < h - 20 && !(drawn && empty); y += 4) {
      for (let x = 20; x < w - 20 && !(drawn && empty); x += 4) {
        if (!drawn && inked(x, y)) drawn = { x, y };
        if (empty) continue;
        let clear = true;
        for (let v = -16; v <= 16 && clear; v++) for (let u = -16; u <= 16 && clear; u++) clear = !inked(x + u, y + v);
        if (clear) empty = { x, y };
      }
    }
    return { drawn, empty };
  });
}

// A click on a move of the drawing picks its line, as the 3D viewer's does;
// a click where nothing is drawn says no move is there.
async function clickDrawing(page, t) {
  await page.waitForFunction(() => document.querySelector('#drawing img')?.complete);
  const { drawn, empty } = await drawnAndEmpty(page);
  const img = page.locator('#drawing img');
  if (!drawn || !empty) return t.check(false, `the drawing has a drawn and an empty place to click (${JSON.stringify({ drawn, empty })})`);
  await img.click({ position: drawn });
  const picked = await page.locator('#picked-line').innerText();
  const line = /^Line (\d+): [1-9]\d* moves? highlighted$/.exec(picked)?.[1];
  const marked = line ? await page.locator(`#L${line}.selected`).count() : 0;
  await img.click({ position: empty });
  const none = await page.locator('#picked-line').innerText();
  t.check(line && marked === 1 && /^No move within [\d.]+ mm of X-?[\d.]+ Y-?[\d.]+$/.test(none), `a click on the drawing picks the move's line and marks it ("${picked}"); a click on nothing says so ("${none}")`);
}

// A drawing that is not whole (an error, or past its entities), and one
// that cannot be made, on their program pages: the note of the first two
// as an alert under a picture, the server's 422 instead of a picture for
// the last.
export async function drawingNotesFlow(page, h, t) {
  const up = async (name, text) => (await h.api('boss', 'POST', '/api/programs', { name, text, dialect: 'rs274ngc' })).json.revision;
  const broken = await up('draw-broken', 'G0 X0 Y0 Z0\nG1 X20 F100\nG999\nG1 Y70\nM2\n');
  const nothing = await up('draw-nothing', 'G999\nG1 X20 F100\nM2\n');
  await page.goto(`${h.base}/#/program/draw-broken/${broken}`);
  await page.getByRole('heading', { name: 'Program draw-broken' }).waitFor();
  await page.locator('#drawing-status[role="alert"]').waitFor();
  const note = await page.locator('#drawing-status').innerText();
  const img = await page.locator('#drawing img').count();
  t.check(img === 1 && /^Not all of it is drawn: the program stops at line 3 \(/.test(note), `a drawing stopped by an error shows what ran, and says why ("${note}")`);
  // Past the drawing's 100,000 entities: random moves, so no two merge.
  let seed = 12345;
  const next = () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 4000; // exact in doubles
  const moves = Array.from({ length: 100050 }, () => `G1 X${next().toFixed(1)} Y${next().toFixed(1)}`);
  const full = await up('draw-full', `G0 X0 Y0 Z0\nF1000\n${moves.join('\n')}\nM2\n`);
  await page.goto(`${h.base}/#/program/draw-full/${full}`);
  await page.getByRole('heading', { name: 'Program draw-full' }).waitFor();
  await page.locator('#drawing-status[role="alert"]').waitFor({ timeout: 60000 });
  const past = await page.locator('#drawing-status').innerText();
  t.check(/^Not all of it is drawn: the drawing holds 100000 entities, .* moves from line \d+ on are not drawn \(the 3D viewer shows every move\)$/.test(past) && !/usina /.test(past), `a drawing past its entities says where the rest is seen, on the page ("${past}")`);
  await page.goto(`${h.base}/#/program/draw-nothing/${nothing}`);
  await page.getByRole('heading', { name: 'Program draw-nothing' }).waitFor();
  await page.locator('#drawing-status[role="alert"]').waitFor();
  const refused = await page.locator('#drawing-status').innerText();
  t.check((await page.locator('#drawing img').count()) === 0 && /^No drawing \(422\): nothing to draw: the program stops at line 1 \(.*before its first move$/.test(refused) && (await page.locator('#drawing-svg').isHidden()), `nothing to draw: the server's reason instead of a picture ("${refused}")`);
}

// The drawing zoomed from the keyboard, the wheel and the buttons, and
// moved with the arrow keys.
async function zoomDrawing(page, t) {
  const width = () => page.locator('#drawing img').evaluate((i) => i.getBoundingClientRect().width);
  const level = () => page.locator('#drawing .drawing-zoom-level').innerText();
  const box = page.locator('#drawing .drawing-zoom-box');
  const whole = await width();
  await box.focus();
  await page.keyboard.press('+');
  await page.keyboard.press('+');
  const zoomed = await width();
  const said = await level();
  const before = await box.evaluate((b) => b.scrollLeft);
  for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
  // The box scrolls smoothly: its position is read once it has moved.
  const moved = await page
    .waitForFunction((b) => document.querySelector('#drawing .drawing-zoom-box').scrollLeft - b, before, { timeout: 5000 })
    .then((r) => r.jsonValue())
    .catch(() => 0);
  t.check(Math.abs(zoomed / whole - 1.5625) < 0.01 && said === 'Zoom 156 %' && moved > 0, `+ twice zooms the drawing to ${said} (${Math.round(whole)} → ${Math.round(zoomed)} px) and the arrow keys move it (${moved} px)`);
  const r = await box.boundingBox();
  await page.mouse.move(r.x + r.width / 2, r.y + r.height / 2);
  await page.mouse.wheel(0, 120);
  await page.locator('#drawing .drawing-zoom-level', { hasText: 'Zoom 125 %' }).waitFor();
  await page.mouse.wheel(0, -120);
  await page.locator('#drawing .drawing-zoom-level', { hasText: 'Zoom 156 %' }).waitFor();
  await page.getByRole('button', { name: 'Zoom out' }).click();
  const out = await level();
  await page.getByRole('button', { name: 'Show the whole drawing' }).click();
  const back = await width();
  await box.focus();
  await page.keyboard.press('-');
  t.check(out === 'Zoom 125 %' && Math.abs(back - whole) < 1 && (await level()) === 'Zoom 100 %', `the wheel zooms out and in about the pointer, Zoom out and Show the whole drawing go back (${Math.round(back)} px), and - stops at the whole`);
}
