// A small accessible bar chart in SVG, drawn from numbers only (no chart
// library): a bar per item, a labelled y axis from 0 to a round maximum
// with its ticks, the items' labels under the x axis. The picture is one
// image to assistive technology (role="img", its title and a description
// saying the highest and the last value); the figures themselves go in a
// table beside it (the caller's).

const SVG = 'http://www.w3.org/2000/svg';

export interface Bar {
  key: string; // data-key of the bar (a date)
  label: string; // under the axis ("3 Dec")
  value: number; // in the chart's unit
  text: string; // the bar's tooltip ("3 Dec: 0.10 %, 1 min 24 s running")
}

export interface BarChart {
  id: string;
  title: string;
  xLabel: string;
  yLabel: string;
  unit: string; // after a tick's number (" %")
  format: (v: number) => string; // a value with its unit, for the description and tooltips
  bars: Bar[];
}

function el<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number>, text?: string): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

// The smallest of 1, 2, 2.5, 5 × 10^n at or above `v` (1 for nothing): with
// its ticks (ticksOf), every tick is a round number.
export function roundMaximum(v: number): number {
  if (!(v > 0) || !Number.isFinite(v)) return 1;
  const p = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 2, 2.5, 5, 10]) if (m * p >= v * (1 - 1e-12)) return m * p;
  return 10 * p;
}

const W = 640;
const H = 240;
const LEFT = 64;
const RIGHT = 8;
const TOP = 10;
const BOTTOM = 52;

// Intervals of the y axis: 0.5 × 10^n each for a maximum of 2 × 10^n, else
// a fifth of it (0.2, 0.5, 1 × 10^n).
export function ticksOf(max: number): number {
  const mantissa = max / 10 ** Math.floor(Math.log10(max));
  return Math.abs(mantissa - 2) < 1e-9 ? 4 : 5;
}

// A tick's number with the decimals its interval needs.
function tickText(v: number, step: number, unit: string): string {
  return `${v.toFixed(Math.max(0, Math.ceil(-Math.log10(step) - 1e-9)))}${unit}`;
}

function summary(c: BarChart): string {
  if (!c.bars.length) return 'No days.';
  const top = c.bars.reduce((a, b) => (b.value > a.value ? b : a));
  const last = c.bars[c.bars.length - 1];
  return `${c.bars.length} bars from ${c.bars[0].label} to ${last.label}; the highest ${c.format(top.value)} on ${top.label}; the last ${c.format(last.value)}.`;
}

function yAxis(svg: SVGSVGElement, c: BarChart, max: number, plotH: number): void {
  const n = ticksOf(max);
  for (let i = 0; i <= n; i++) {
    const y = TOP + plotH - (plotH * i) / n;
    svg.append(el('line', { x1: LEFT, x2: W - RIGHT, y1: y, y2: y, class: i ? 'grid' : 'axis' }));
    svg.append(el('text', { x: LEFT - 6, y: y + 4, 'text-anchor': 'end', class: 'tick' }, tickText((max * i) / n, max / n, c.unit)));
  }
  svg.append(el('text', { x: 12, y: TOP + plotH / 2, transform: `rotate(-90 12 ${TOP + plotH / 2})`, 'text-anchor': 'middle', class: 'axis-label' }, c.yLabel));
}

export function barChart(c: BarChart): SVGSVGElement {
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-labelledby': `${c.id}-title ${c.id}-desc`, id: c.id, class: 'bar-chart' });
  svg.append(el('title', { id: `${c.id}-title` }, c.title), el('desc', { id: `${c.id}-desc` }, summary(c)));
  const plotW = W - LEFT - RIGHT;
  const plotH = H - TOP - BOTTOM;
  const max = roundMaximum(Math.max(0, ...c.bars.map((b) => b.value)));
  yAxis(svg, c, max, plotH);
  const step = plotW / Math.max(1, c.bars.length);
  // Labels of every bar when they fit ("30 Nov" takes some 44 units), else of every n-th.
  const every = Math.max(1, Math.ceil(46 / step));
  c.bars.forEach((b, i) => {
    const hgt = (plotH * Math.max(0, b.value)) / max;
    const x = LEFT + i * step + step * 0.15;
    const rect = el('rect', { x: x.toFixed(2), y: (TOP + plotH - hgt).toFixed(2), width: (step * 0.7).toFixed(2), height: hgt.toFixed(2), class: 'bar', 'data-key': b.key, 'data-value': b.value });
    rect.append(el('title', {}, b.text));
    svg.append(rect);
    if (i % every === 0 || i === c.bars.length - 1)
      svg.append(el('text', { x: (LEFT + (i + 0.5) * step).toFixed(2), y: TOP + plotH + 16, 'text-anchor': 'middle', class: 'tick' }, b.label));
  });
  svg.append(el('text', { x: LEFT + plotW / 2, y: H - 8, 'text-anchor': 'middle', class: 'axis-label' }, c.xLabel));
  return svg;
}
