// Screenshots compared with a golden picture, with a tolerance (issue 14:
// "its 3D view (screenshot compared with a tolerance)"). The goldens are in
// web/e2e/golden/, each looked at by hand once (web/e2e/golden/README.md
// says what each must show). USINA_UPDATE_GOLDEN=1 writes them anew.
//
// The tolerance: WebGL here is SwiftShader, on whatever CPU runs the test,
// and a line may land one pixel over. So a pixel differs only when no pixel
// of the other picture within one pixel of it has its colour (within 48 in
// every channel), looked at both ways; and at most 0.5 % of the pixels may
// differ. A picture of another size differs entirely.
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const GOLDEN = join(dirname(fileURLToPath(import.meta.url)), 'golden');
export const MOST_DIFFERING = 0.005;

// Compares two PNG pictures (Buffers) in the page; the share of pixels that
// differ, and the sizes.
export async function differing(page, a, b) {
  return page.evaluate(
    async ([a64, b64]) => {
      const pixels = async (b64) => {
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
        const c = new OffscreenCanvas(bitmap.width, bitmap.height);
        const g = c.getContext('2d');
        g.drawImage(bitmap, 0, 0);
        return { w: c.width, h: c.height, d: g.getImageData(0, 0, c.width, c.height).data };
      };
      const [p, q] = [await pixels(a64), await pixels(b64)];
      if (p.w !== q.w || p.h !== q.h) return { share: 1, size: `${p.w}×${p.h} against ${q.w}×${q.h}` };
      const near = (x, y, i) => {
        for (let dy = -1; dy <= 1; dy++) {
          for (let dx = -1; dx <= 1; dx++) {
            const [u, v] = [x + dx, y + dy];
            if (u < 0 || v < 0 || u >= p.w || v >= p.h) continue;
            const j = (v * p.w + u) * 4;
            if (Math.abs(i.from[i.at] - i.to[j]) <= 48 && Math.abs(i.from[i.at + 1] - i.to[j + 1]) <= 48 && Math.abs(i.from[i.at + 2] - i.to[j + 2]) <= 48) return true;
          }
        }
        return false;
      };
      let off = 0;
      for (let y = 0; y < p.h; y++) {
        for (let x = 0; x < p.w; x++) {
          const at = (y * p.w + x) * 4;
          if (!near(x, y, { from: p.d, to: q.d, at }) || !near(x, y, { from: q.d, to: p.d, at })) off++;
        }
      }
      return { share: off / (p.w * p.h), size: `${p.w}×${p.h}` };
    },
    [a.toString('base64'), b.toString('base64')],
  );
}

// The golden picture NAME against `shot`: { ok, share, text } for check().
// `control`: a picture that must not match (it never writes the golden).
export async function matchesGolden(page, shot, name, { control = false } = {}) {
  const path = join(GOLDEN, name);
  if (process.env.USINA_UPDATE_GOLDEN === '1' && !control) {
    mkdirSync(GOLDEN, { recursive: true });
    writeFileSync(path, shot);
    return { ok: false, text: `${name} written anew: look at it, say what it shows in golden/README.md, run again without USINA_UPDATE_GOLDEN` };
  }
  if (!existsSync(path)) return { ok: false, text: `no golden ${name} (USINA_UPDATE_GOLDEN=1 writes it)` };
  const d = await differing(page, shot, readFileSync(path));
  return { ok: d.share <= MOST_DIFFERING, share: d.share, text: `${(d.share * 100).toFixed(3)} % of ${d.size} pixels differ from golden/${name} (at most ${MOST_DIFFERING * 100} %)` };
}
