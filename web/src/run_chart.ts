// A run chart in SVG (no chart library): one characteristic's measurements
// in the order they were made, joined by a line, with its limits and its
// nominal as horizontal lines, as an inspector plots them by hand. A value
// outside the limits is a square, not a circle (not only a colour). One
// image to assistive technology: its title, and a description counting the
// values and those outside; the table beside it has the figures.

const SVG = 'http://www.w3.org/2000/svg';
const W = 640;
const H = 220;
const LEFT = 72;
const RIGHT = 132; // room for the limits' labels
const TOP = 12;
const BOTTOM = 40;

export interface RunPoint {
  label: string; // under the axis for the first and last ("2026-12-04 03:41")
  value: number;
  ok: boolean | null; // null: no limits
  text: string; // the point's tooltip
}

export interface RunChart {
  id: string;
  title: string;
  unit: string;
  points: RunPoint[]; // oldest first
  min: number | null;
  max: number | null;
  nominal: number | null;
}

function el<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number>, text?: string): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

// The y range: the values and the limits, with a margin, never empty.
function range(c: RunChart): [number, number] {
  const all = [...c.points.map((p) => p.value), ...[c.min, c.max, c.nominal].filter((v): v is number => v !== null)];
  let lo = Math.min(...all);
  let hi = Math.max(...all);
  const pad = hi > lo ? (hi - lo) * 0.1 : Math.max(Math.abs(hi) * 0.01, 1e-3);
  return [lo - pad, hi + pad];
}

function description(c: RunChart): string {
  const out = c.points.filter((p) => p.ok === false).length;
  const first = c.points[0];
  const last = c.points[c.points.length - 1];
  return `${c.points.length} measurements from ${first.label} to ${last.label}; ${out} outside the limits; the last ${last.value}${c.unit ? ` ${c.unit}` : ''}.`;
}

export function runChart(c: RunChart): SVGSVGElement {
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-labelledby': `${c.id}-title ${c.id}-desc`, id: c.id, class: 'run-chart' });
  svg.append(el('title', { id: `${c.id}-title` }, c.title), el('desc', { id: `${c.id}-desc` }, c.points.length ? description(c) : 'No measurements.'));
  if (!c.points.length) return svg;
  const [lo, hi] = range(c);
  const plotW = W - LEFT - RIGHT;
  const plotH = H - TOP - BOTTOM;
  const y = (v: number) => TOP + plotH - ((v - lo) / (hi - lo)) * plotH;
  const x = (i: number) => LEFT + (c.points.length === 1 ? plotW / 2 : (i * plotW) / (c.points.length - 1));
  const unit = c.unit ? ` ${c.unit}` : '';
  svg.append(el('line', { x1: LEFT, x2: LEFT, y1: TOP, y2: TOP + plotH, class: 'axis' }));
  svg.append(el('line', { x1: LEFT, x2: W - RIGHT, y1: TOP + plotH, y2: TOP + plotH, class: 'axis' }));
  for (const v of [lo, (lo + hi) / 2, hi]) svg.append(el('text', { x: LEFT - 6, y: y(v) + 4, 'text-anchor': 'end', class: 'tick' }, String(Number(v.toPrecision(5)))));
  const limits: [string, number | null][] = [
    ['max', c.max],
    ['nominal', c.nominal],
    ['min', c.min],
  ];
  // Limits of one value (a nominal at the min) share one label.
  const labels: { at: number; names: string[]; value: number }[] = [];
  for (const [name, v] of limits) {
    if (v === null) continue;
    svg.append(el('line', { x1: LEFT, x2: W - RIGHT, y1: y(v).toFixed(2), y2: y(v).toFixed(2), class: `limit ${name}` }));
    const same = labels.find((l) => l.value === v);
    if (same) {
      same.names.push(name);
      continue;
    }
    // Different values too close to read apart: the label moves down a line.
    const near = labels.find((l) => Math.abs(l.at - y(v)) < 12);
    labels.push({ at: near ? near.at + 12 : y(v), names: [name], value: v });
  }
  for (const l of labels) svg.append(el('text', { x: W - RIGHT + 4, y: l.at + 4, class: 'tick' }, `${l.names.join(' = ')} ${l.value}${unit}`));
  svg.append(el('polyline', { points: c.points.map((p, i) => `${x(i).toFixed(2)},${y(p.value).toFixed(2)}`).join(' '), class: 'run' }));
  c.points.forEach((p, i) => {
    const cx = x(i);
    const cy = y(p.value);
    const mark = p.ok === false ? el('rect', { x: (cx - 4).toFixed(2), y: (cy - 4).toFixed(2), width: 8, height: 8, class: 'point not-ok' }) : el('circle', { cx: cx.toFixed(2), cy: cy.toFixed(2), r: 3.5, class: 'point' });
    mark.setAttribute('data-value', String(p.value));
    mark.append(el('title', {}, p.text));
    svg.append(mark);
  });
  const first = c.points[0];
  const last = c.points[c.points.length - 1];
  svg.append(el('text', { x: LEFT, y: TOP + plotH + 16, 'text-anchor': 'start', class: 'tick' }, first.label));
  if (c.points.length > 1) svg.append(el('text', { x: W - RIGHT, y: TOP + plotH + 16, 'text-anchor': 'end', class: 'tick' }, last.label));
  svg.append(el('text', { x: LEFT + plotW / 2, y: H - 6, 'text-anchor': 'middle', class: 'axis-label' }, 'Measurements in the order they were made'));
  return svg;
}
