// The program's figures: the check's times, bounds and stats checks (the
// revision's check results), and each tool's time and distances (usina
// stats per tool, GET .../tools, computed on the server's pool).
import { type Checks } from './api';
import { h } from './dom';

export interface ToolFigures {
  tool: number;
  total_s: number;
  cutting_s: number;
  rapid_s: number;
  other_s: number;
  cutting_mm: number;
  rapid_mm: number;
  moves: number;
}

export interface Figures {
  machine: string;
  complete: boolean;
  tools: ToolFigures[];
  total?: ToolFigures;
}

function seconds(s: number | undefined): string {
  if (s === undefined) return '—';
  if (s < 60) return `${s.toFixed(1)} s`;
  const m = Math.floor(s / 60);
  return `${m} min ${(s - 60 * m).toFixed(0)} s`;
}

const mm = (x: number) => `${x.toFixed(1)} mm`;

function table(label: string, head: string[], rows: string[][]): HTMLElement {
  return h(
    'table',
    { class: 'stats', 'aria-label': label },
    h('thead', {}, h('tr', {}, ...head.map((t) => h('th', { scope: 'col', text: t })))),
    h('tbody', {}, ...rows.map((r) => h('tr', {}, h('th', { scope: 'row', text: r[0] }), ...r.slice(1).map((c) => h('td', { text: c }))))),
  );
}

function toolTable(f: Figures): HTMLElement {
  const row = (name: string, t: ToolFigures) => [name, seconds(t.total_s), seconds(t.cutting_s), seconds(t.rapid_s), seconds(t.other_s), mm(t.cutting_mm), mm(t.rapid_mm)];
  const rows = f.tools.map((t) => row(t.tool ? `T${t.tool}` : 'no tool', t));
  if (f.total && f.tools.length > 1) rows.push(row('All', f.total));
  return table('Per tool', ['Tool', 'Time', 'Cutting', 'Rapid', 'Other', 'Feed distance', 'Rapid distance'], rows);
}

export function statsPanel(checks: Checks | null, figures: Figures | string): HTMLElement {
  const parts: HTMLElement[] = [h('h2', { id: 'stats-h', text: 'Figures' })];
  if (checks) {
    parts.push(table('Times', ['Time', 'Estimate'], [['Cycle', seconds(checks.cycle_time_s)], ['Cutting', seconds(checks.cutting_s)], ['Rapid', seconds(checks.rapid_s)]]));
    if (checks.bounds) {
      const b = checks.bounds;
      parts.push(table('Bounds', ['Axis', 'Minimum', 'Maximum', 'Size'], ['X', 'Y', 'Z'].map((a, i) => [a, mm(b.min[i]), mm(b.max[i]), mm(b.max[i] - b.min[i])])));
    }
    const codes = Object.entries(checks.checks ?? {});
    if (codes.length) parts.push(table('Checks', ['Check', 'Count'], codes.map(([c, n]) => [c, String(n)])));
  } else {
    parts.push(h('p', { class: 'note', text: 'This revision has no check results.' }));
  }
  if (typeof figures === 'string') parts.push(h('p', { role: 'alert', text: `The figures per tool: ${figures}` }));
  else parts.push(toolTable(figures), h('p', { class: 'note', text: `Per tool on the machine profile ${figures.machine}${figures.complete ? '' : ' (the run stopped early: the figures are of what ran)'}.` }));
  return h('section', { 'aria-labelledby': 'stats-h', class: 'stats-panel', id: 'stats' }, ...parts);
}
