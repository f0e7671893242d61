// The server's stock answer (docs/web.md, "The stock"): a JSON header, then
// each frame as the cells that changed since the frame before; and the
// stock as a shaded three.js mesh built from the height map (a vertex per
// cell, up to a display budget; side walls and a bottom), updated in place
// as the replay moves from frame to frame.
import * as THREE from 'three';
import { toolColour } from './viewer';

export interface StockFrame {
  moves: number;
  line: number;
  removed_mm3: number;
  time_s: number; // when the planner (usina stats' on the generic mill) has run its moves
  runs: number;
  cells: number;
  offset: number;
}

export interface StockHeader {
  stock: { box: [number, number, number]; origin: [number, number, number]; from_program: boolean };
  cells: [number, number];
  cell_mm: [number, number];
  top_mm: number;
  bottom_mm: number;
  depth_unit_mm: number;
  moves: number;
  time_s: number;
  peak_removal: { mm3_per_min: number; at_s: number; bin_s: number } | null;
  complete: boolean;
  removed_mm3: number;
  tools: { tool: number; shape: string; diameter_mm: number; removed_mm3: number }[];
  checks: { code: string; line: number; message: string }[];
  checks_total: number;
  frames: StockFrame[];
}

const MAGIC = 0x4b535355; // "USSK"
const RAPID_MARK = 255;

export function decodeStockHeader(buf: ArrayBuffer): { header: StockHeader; data: ArrayBuffer } {
  const v = new DataView(buf);
  if (buf.byteLength < 12 || v.getUint32(0, true) !== MAGIC) throw new Error('not a usina stock answer');
  if (v.getUint32(4, true) !== 1) throw new Error('a stock answer of another version');
  const length = v.getUint32(8, true);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, 12, length))) as StockHeader;
  return { header, data: buf.slice(12 + length) };
}

// The height map at any frame: the uncut stock with the frames' changes laid
// on in order (going back starts again from the uncut stock).
export class StockReplay {
  readonly header: StockHeader;
  readonly depth: Uint16Array;
  readonly mark: Uint8Array;
  private data: ArrayBuffer;
  private at = 0; // frames laid on

  constructor(buf: ArrayBuffer) {
    const d = decodeStockHeader(buf);
    this.header = d.header;
    this.data = d.data;
    const cells = d.header.cells[0] * d.header.cells[1];
    this.depth = new Uint16Array(cells);
    this.mark = new Uint8Array(cells);
  }

  get frames(): number {
    return this.header.frames.length;
  }

  // `n` frames laid on (0: the uncut stock, frames: the final one).
  seek(n: number): void {
    if (n < this.at) {
      this.depth.fill(0);
      this.mark.fill(0);
      this.at = 0;
    }
    for (; this.at < n; this.at++) this.apply(this.header.frames[this.at]);
  }

  private apply(f: StockFrame): void {
    const runs = new Uint32Array(this.data, f.offset, f.runs * 2);
    const depths = new Uint16Array(this.data, f.offset + f.runs * 8, f.cells);
    const marks = new Uint8Array(this.data, f.offset + f.runs * 8 + f.cells * 2, f.cells);
    let k = 0;
    for (let r = 0; r < f.runs; r++) {
      const first = runs[2 * r];
      const count = runs[2 * r + 1];
      this.depth.set(depths.subarray(k, k + count), first);
      this.mark.set(marks.subarray(k, k + count), first);
      k += count;
    }
  }
}

export type StockColour = 'depth' | 'tool';

// A vertex per cell up to this many (a 512 × 512 grid): beyond, a vertex
// stands for a block of cells and takes the deepest of them, so no cut
// narrower than the block is lost.
const DISPLAY_CELLS = 262144;
const UNCUT = new THREE.Color(0x9aa5b1);
const RAPID = new THREE.Color(0xe53935);

// The stock's mesh: the top surface on a grid (gx × gy vertices), a wall
// along each side down to the bottom, and the bottom face.
export class StockMesh {
  readonly object = new THREE.Group();
  private replay: StockReplay;
  private step: number;
  private gx: number;
  private gy: number;
  private surface: THREE.BufferGeometry;
  private walls: THREE.BufferGeometry;
  private wallTop: Uint32Array; // the surface vertex each wall's top vertex follows
  colour: StockColour = 'depth';

  constructor(replay: StockReplay) {
    this.replay = replay;
    const [nx, ny] = replay.header.cells;
    this.step = Math.max(1, Math.ceil(Math.sqrt((nx * ny) / DISPLAY_CELLS)));
    this.gx = Math.ceil(nx / this.step);
    this.gy = Math.ceil(ny / this.step);
    this.surface = this.buildSurface();
    const { geometry, top } = this.buildWalls();
    this.walls = geometry;
    this.wallTop = top;
    const material = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide });
    this.object.add(new THREE.Mesh(this.surface, material), new THREE.Mesh(this.walls, material));
    this.object.add(new THREE.AmbientLight(0xffffff, 1.2));
    const sun = new THREE.DirectionalLight(0xffffff, 2.2);
    sun.position.set(0.4, -0.7, 1);
    this.object.add(sun);
    this.update();
  }

  // The vertex (i, j)'s X and Y: the centre of its block of cells.
  private xy(i: number, j: number): [number, number] {
    const h = this.replay.header;
    const [nx, ny] = h.cells;
    const ci = Math.min(nx - 1, i * this.step + (this.step - 1) / 2);
    const cj = Math.min(ny - 1, j * this.step + (this.step - 1) / 2);
    return [h.stock.origin[0] + (ci + 0.5) * h.cell_mm[0], h.stock.origin[1] + (cj + 0.5) * h.cell_mm[1]];
  }

  private buildSurface(): THREE.BufferGeometry {
    const { gx, gy } = this;
    const xyz = new Float32Array(gx * gy * 3);
    for (let j = 0; j < gy; j++)
      for (let i = 0; i < gx; i++) xyz.set([...this.xy(i, j), 0], (j * gx + i) * 3);
    const index = new Uint32Array(Math.max(0, (gx - 1) * (gy - 1) * 6));
    let k = 0;
    for (let j = 0; j + 1 < gy; j++)
      for (let i = 0; i + 1 < gx; i++) {
        const a = j * gx + i;
        index.set([a, a + 1, a + gx + 1, a, a + gx + 1, a + gx], k);
        k += 6;
      }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
    g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(gx * gy * 3), 3));
    g.setIndex(new THREE.BufferAttribute(index, 1));
    return g;
  }

  // The border's vertices in order round the stock, each with one at the
  // bottom below it: a strip of quads; and the bottom face.
  private buildWalls(): { geometry: THREE.BufferGeometry; top: Uint32Array } {
    const { gx, gy } = this;
    const ring: number[] = [];
    for (let i = 0; i < gx; i++) ring.push(i);
    for (let j = 1; j < gy; j++) ring.push(j * gx + gx - 1);
    for (let i = gx - 2; i >= 0; i--) ring.push((gy - 1) * gx + i);
    for (let j = gy - 2; j >= 0; j--) ring.push(j * gx);
    const n = ring.length;
    const h = this.replay.header;
    const xyz = new Float32Array(n * 2 * 3 + 4 * 3);
    const surface = this.surface.getAttribute('position') as THREE.BufferAttribute;
    for (let k = 0; k < n; k++) {
      xyz.set([surface.getX(ring[k]), surface.getY(ring[k]), 0], 2 * k * 3);
      xyz.set([surface.getX(ring[k]), surface.getY(ring[k]), h.bottom_mm], (2 * k + 1) * 3);
    }
    const [x0, y0] = this.xy(0, 0);
    const [x1, y1] = this.xy(gx - 1, gy - 1);
    xyz.set([x0, y0, h.bottom_mm, x1, y0, h.bottom_mm, x1, y1, h.bottom_mm, x0, y1, h.bottom_mm], n * 6);
    const index: number[] = [];
    for (let k = 0; k < n; k++) {
      const a = 2 * k;
      const b = 2 * ((k + 1) % n);
      index.push(a, a + 1, b + 1, a, b + 1, b);
    }
    const base = 2 * n;
    index.push(base, base + 2, base + 1, base, base + 3, base + 2);
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
    g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(xyz.length), 3));
    g.setIndex(index);
    return { geometry: g, top: Uint32Array.from(ring) };
  }

  // The heights and colours of the replay's map as it stands now.
  update(): void {
    const { gx, gy, step } = this;
    const h = this.replay.header;
    const [nx, ny] = h.cells;
    const { depth, mark } = this.replay;
    const pos = this.surface.getAttribute('position') as THREE.BufferAttribute;
    const col = this.surface.getAttribute('color') as THREE.BufferAttribute;
    const c = new THREE.Color();
    for (let j = 0; j < gy; j++)
      for (let i = 0; i < gx; i++) {
        let deepest = 0;
        let at = j * step * nx + i * step;
        for (let b = j * step; b < Math.min(ny, (j + 1) * step); b++)
          for (let a = i * step; a < Math.min(nx, (i + 1) * step); a++) {
            const k = b * nx + a;
            if (depth[k] > deepest) {
              deepest = depth[k];
              at = k;
            }
          }
        const v = j * gx + i;
        pos.setZ(v, h.top_mm - deepest * h.depth_unit_mm);
        this.paint(c, deepest, mark[at]);
        col.setXYZ(v, c.r, c.g, c.b);
      }
    pos.needsUpdate = col.needsUpdate = true;
    this.surface.computeVertexNormals();
    this.updateWalls(pos, col);
  }

  private paint(c: THREE.Color, depth: number, m: number): void {
    if (depth === 0) c.copy(UNCUT);
    else if (this.colour === 'tool') {
      if (m === RAPID_MARK) c.copy(RAPID);
      else c.setHex(toolColour(this.replay.header.tools[m - 1]?.tool ?? 0));
    } else c.setHSL(0.58 - 0.58 * Math.min(1, depth / 65535), 0.75, 0.55); // blue shallow, red through
  }

  private updateWalls(pos: THREE.BufferAttribute, col: THREE.BufferAttribute): void {
    const wp = this.walls.getAttribute('position') as THREE.BufferAttribute;
    const wc = this.walls.getAttribute('color') as THREE.BufferAttribute;
    for (let k = 0; k < this.wallTop.length; k++) {
      const v = this.wallTop[k];
      wp.setZ(2 * k, pos.getZ(v));
      for (const w of [2 * k, 2 * k + 1]) wc.setXYZ(w, col.getX(v) * 0.8, col.getY(v) * 0.8, col.getZ(v) * 0.8);
    }
    for (let k = 2 * this.wallTop.length; k < wc.count; k++) wc.setXYZ(k, UNCUT.r * 0.6, UNCUT.g * 0.6, UNCUT.b * 0.6);
    wp.needsUpdate = wc.needsUpdate = true;
    this.walls.computeVertexNormals();
  }
}
