// The program's figures: the check's times, bounds and stats checks (the
// revision's check results), and the distance each tool travels, feeding
// and rapid, summed over the tool path the viewer draws.
import { type Checks } from './api';
import { h } from './dom';
import { Kind, type Toolpath } from './toolpath';

export interface ToolDistance {
  tool: number;
  feed: number; // mm: feeds, arcs, splines, probes
  rapid: number; // mm
}

// Per tool, in the order of the tools' numbers.
export function distances(path: Toolpath): ToolDistance[] {
  const by = new Map<number, ToolDistance>();
  const p = path.positions;
  for (let i = 1; i < path.count; i++) {
    const d = Math.hypot(p[3 * i] - p[3 * i - 3], p[3 * i + 1] - p[3 * i - 2], p[3 * i + 2] - p[3 * i - 1]);
    const t = path.tools[i];
    const row = by.get(t) ?? { tool: t, feed: 0, rapid: 0 };
    if (path.kinds[i] === Kind.Rapid) row.rapid += d;
    else row.feed += d;
    by.set(t, row);
  }
  return [...by.values()].sort((a, b) => a.tool - b.tool);
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

export function statsPanel(checks: Checks | null, path: Toolpath): HTMLElement {
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
  const rows = distances(path).map((d) => [d.tool ? `T${d.tool}` : 'no tool', mm(d.feed), mm(d.rapid)]);
  parts.push(table('Distances per tool', ['Tool', 'Feed', 'Rapid'], rows));
  if (path.decimated) parts.push(h('p', { class: 'note', text: `The distances are summed over the ${path.count} points drawn for ${path.moves} moves (decimated): a little short of the program's.` }));
  return h('section', { 'aria-labelledby': 'stats-h', class: 'stats-panel', id: 'stats' }, ...parts);
}
