// The server's tool-path stream (docs/web.md, "The tool-path stream").

export const enum Kind {
  Start = 0,
  Rapid = 1,
  Feed = 2,
  Arc = 3,
  Spline = 4,
  Probe = 5,
}

export interface Toolpath {
  count: number;
  decimated: boolean;
  truncated: boolean;
  stoppedOnError: boolean;
  moves: number;
  min: [number, number, number];
  max: [number, number, number];
  positions: Float32Array; // 3 a vertex
  lines: Uint32Array;
  tools: Uint32Array;
  kinds: Uint8Array;
  times: Float32Array; // s from the program's start when the tool reaches each vertex
  totalSeconds: number; // the program's time on the machine class's profile
}

const MAGIC = 0x50545355; // "USTP"
const HEADER = 56;
const VERTEX = 25; // bytes a vertex: 3 × float32, uint32 line, uint32 tool, float32 time, uint8 kind

export function decodeToolpath(buf: ArrayBuffer): Toolpath {
  const v = new DataView(buf);
  if (buf.byteLength < HEADER || v.getUint32(0, true) !== MAGIC)
    throw new Error('not a usina tool-path stream');
  if (v.getUint32(4, true) !== 2) throw new Error('a tool-path stream of another version');
  const n = v.getUint32(8, true);
  const flags = v.getUint32(12, true);
  if (buf.byteLength !== HEADER + n * VERTEX) throw new Error('the tool-path stream is cut short');
  const f = (o: number) => v.getFloat32(o, true);
  return {
    count: n,
    decimated: (flags & 1) !== 0,
    truncated: (flags & 2) !== 0,
    stoppedOnError: (flags & 4) !== 0,
    moves: Number(v.getBigUint64(16, true)),
    min: [f(24), f(28), f(32)],
    max: [f(36), f(40), f(44)],
    positions: new Float32Array(buf, HEADER, n * 3),
    lines: new Uint32Array(buf, HEADER + n * 12, n),
    tools: new Uint32Array(buf, HEADER + n * 16, n),
    times: new Float32Array(buf, HEADER + n * 20, n),
    kinds: new Uint8Array(buf, HEADER + n * 24, n),
    totalSeconds: v.getFloat64(48, true),
  };
}

// The source line of the move nearest (x, y) seen from above, in the
// stream's millimetres, when one passes within `tolerance`; null when none.
// A move is the segment from the vertex before it to its own.
export function nearestLine(p: Toolpath, x: number, y: number, tolerance: number): number | null {
  let best = tolerance * tolerance;
  let line: number | null = null;
  const q = p.positions;
  for (let i = 1; i < p.count; i++) {
    const [ax, ay, bx, by] = [q[i * 3 - 3], q[i * 3 - 2], q[i * 3], q[i * 3 + 1]];
    const [dx, dy] = [bx - ax, by - ay];
    const len2 = dx * dx + dy * dy;
    const t = len2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / len2)) : 0;
    const [ex, ey] = [ax + t * dx - x, ay + t * dy - y];
    const d2 = ex * ex + ey * ey;
    if (d2 <= best) {
      best = d2;
      line = p.lines[i];
    }
  }
  return line;
}
