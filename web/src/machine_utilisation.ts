// A machine's utilisation per day (GET /api/machines/{m}/utilisation, UTC
// days; docs/dnc.md): the last two weeks as a bar chart (chart.ts) and the
// same figures as a table (running time, utilisation, parts, alarm and
// link-down time a day), read again when the machine reports a part or a
// job ends.
import { enc, getJson } from './api';
import { barChart } from './chart';
import { h } from './dom';

export interface UtilisationDay {
  date: string; // YYYY-MM-DD
  running_seconds: number;
  utilisation: number; // running_seconds / day_seconds
  parts: number;
  alarm_seconds: number;
  link_down_seconds: number;
}

interface Utilisation {
  machine: string;
  from: string;
  to: string;
  days_in: string;
  days: UtilisationDay[];
}

const DAYS = 14;
const MONTHS = ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'];

export function dayLabel(date: string): string {
  const [, m, d] = date.split('-').map(Number);
  return `${d} ${MONTHS[m - 1] ?? '?'}`;
}

export function duration(s: number): string {
  if (s < 60) return `${Math.round(s)} s`;
  if (s < 3600) return `${Math.floor(s / 60)} min ${Math.round(s % 60)} s`;
  return `${Math.floor(s / 3600)} h ${Math.round((s % 3600) / 60)} min`;
}

export function percent(v: number): string {
  return `${v.toFixed(v < 1 ? 2 : v < 10 ? 1 : 0)} %`;
}

function table(id: string, u: Utilisation): HTMLElement {
  const heads = ['Day', 'Running', 'Utilisation', 'Parts', 'Alarm', 'Link down'];
  return h(
    'table',
    { id: `${id}-table`, class: 'figures' },
    h('caption', { text: `Utilisation per day (${u.days_in} days), ${dayLabel(u.from)} to ${dayLabel(u.to)}` }),
    h('thead', {}, h('tr', {}, ...heads.map((t) => h('th', { scope: 'col', text: t })))),
    h(
      'tbody',
      {},
      ...u.days.map((d) =>
        h(
          'tr',
          { 'data-date': d.date },
          h('th', { scope: 'row', text: dayLabel(d.date) }),
          h('td', { text: duration(d.running_seconds) }),
          h('td', { text: percent(100 * d.utilisation) }),
          h('td', { text: String(d.parts) }),
          h('td', { text: duration(d.alarm_seconds) }),
          h('td', { text: duration(d.link_down_seconds) }),
        ),
      ),
    ),
  );
}

function chart(id: string, u: Utilisation): SVGSVGElement {
  return barChart({
    id: `${id}-chart`,
    title: `${u.machine}: utilisation per day, ${dayLabel(u.from)} to ${dayLabel(u.to)}`,
    xLabel: `Day (${u.days_in})`,
    yLabel: 'Utilisation',
    unit: ' %',
    format: percent,
    bars: u.days.map((d) => ({
      key: d.date,
      label: dayLabel(d.date),
      value: 100 * d.utilisation,
      text: `${dayLabel(d.date)}: ${percent(100 * d.utilisation)}, ${duration(d.running_seconds)} running, ${d.parts} ${d.parts === 1 ? 'part' : 'parts'}`,
    })),
  });
}

// The first day asked for: DAYS days to today (UTC) by this browser's clock;
// the server's own today ends the range.
function firstDay(): string {
  return new Date(Date.now() - (DAYS - 1) * 86_400_000).toISOString().slice(0, 10);
}

export interface UtilisationPanel {
  element: HTMLElement;
  refresh(): void; // soon, once for several calls
}

export function utilisationPanel(machine: string): UtilisationPanel {
  const id = `util-${machine}`;
  const picture = h('div', { class: 'chart', 'aria-busy': 'true' });
  const figures = h('details', {}, h('summary', { text: 'The figures as a table' }));
  const said = h('p', { class: 'status', 'aria-live': 'polite' });
  let timer = 0;
  let asked = 0;
  const load = async () => {
    const n = ++asked;
    try {
      const u = await getJson<Utilisation>(`/api/machines/${enc(machine)}/utilisation?from=${firstDay()}`);
      if (n !== asked) return;
      picture.replaceChildren(chart(id, u));
      figures.replaceChildren(figures.firstChild as Node, table(id, u));
      said.textContent = '';
    } catch (e) {
      if (n === asked) said.textContent = `The utilisation could not be read: ${(e as Error).message}`;
    } finally {
      if (n === asked) picture.setAttribute('aria-busy', 'false');
    }
  };
  void load();
  return {
    element: h('section', { class: 'utilisation', id, 'aria-labelledby': `${id}-h` }, h('h3', { id: `${id}-h`, text: 'Utilisation per day' }), picture, figures, said),
    refresh() {
      window.clearTimeout(timer);
      picture.setAttribute('aria-busy', 'true');
      timer = window.setTimeout(() => void load(), 500);
    },
  };
}
