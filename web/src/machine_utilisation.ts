// A machine's utilisation per day (GET /api/machines/{m}/utilisation;
// docs/dnc.md): the last two weeks as a bar chart (chart.ts) and the same
// figures as a table (running time, utilisation, parts, alarm and link-down
// time a day), read again when the machine reports a part or a job ends.
// Days are UTC's; a machine with a shift calendar is shown in its zone's
// days (`days=local`) and charted against its shifts, as its shop plans it
// (the table keeps the whole day's utilisation too).
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
  // With a shift calendar only (absent without one):
  scheduled_seconds?: number;
  running_in_shift_seconds?: number;
  shift_utilisation?: number | null; // null: no shift that day
}

interface Calendar {
  timezone: string;
  shifts: number;
  holidays: number;
  source: 'server' | 'machine';
}

interface Utilisation {
  machine: string;
  from: string;
  to: string;
  days_in: string;
  days: UtilisationDay[];
  calendar: Calendar | null;
}

const DAYS = 14;
const MONTHS = ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'];

export function dayLabel(date: string): string {
  const [, m, d] = date.split('-').map(Number);
  return `${d} ${MONTHS[m - 1] ?? '?'}`;
}

// Rounded to the second first, so 119.7 s is "2 min 0 s", never "1 min 60 s".
export function duration(s: number): string {
  const r = Math.round(s);
  if (r < 60) return `${r} s`;
  if (r < 3600) return `${Math.floor(r / 60)} min ${r % 60} s`;
  return `${Math.floor(r / 3600)} h ${Math.floor((r % 3600) / 60)} min`;
}

export function percent(v: number): string {
  return `${v.toFixed(v < 1 ? 2 : v < 10 ? 1 : 0)} %`;
}

function inShift(d: UtilisationDay): string {
  return d.shift_utilisation === null || d.shift_utilisation === undefined ? 'no shift' : percent(100 * d.shift_utilisation);
}

function shiftCells(u: Utilisation, d: UtilisationDay): HTMLElement[] {
  if (!u.calendar) return [];
  return [h('td', { text: duration(d.scheduled_seconds ?? 0) }), h('td', { text: duration(d.running_in_shift_seconds ?? 0) }), h('td', { class: 'shift', text: inShift(d) })];
}

function table(id: string, u: Utilisation): HTMLElement {
  const heads = ['Day', 'Running', 'Utilisation', 'Parts', 'Alarm', 'Link down', ...(u.calendar ? ['Scheduled', 'Running in shift', 'Shift utilisation'] : [])];
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
          ...shiftCells(u, d),
        ),
      ),
    ),
  );
}

function chart(id: string, u: Utilisation): SVGSVGElement {
  if (u.calendar) return shiftChart(id, u);
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

// Against the shifts: a day without one has no bar and says so.
function shiftChart(id: string, u: Utilisation): SVGSVGElement {
  return barChart({
    id: `${id}-chart`,
    title: `${u.machine}: utilisation in the shifts per day, ${dayLabel(u.from)} to ${dayLabel(u.to)}`,
    xLabel: `Day (${u.days_in})`,
    yLabel: 'Utilisation in shift',
    unit: ' %',
    format: percent,
    bars: u.days.map((d) => ({
      key: d.date,
      label: dayLabel(d.date),
      value: 100 * (d.shift_utilisation ?? 0),
      text:
        d.shift_utilisation === null || d.shift_utilisation === undefined
          ? `${dayLabel(d.date)}: no shift, ${duration(d.running_seconds)} running`
          : `${dayLabel(d.date)}: ${inShift(d)} of ${duration(d.scheduled_seconds ?? 0)} in shifts, ${duration(d.running_in_shift_seconds ?? 0)} running in them, ${d.parts} ${d.parts === 1 ? 'part' : 'parts'}`,
    })),
  });
}

function calendarText(c: Calendar | null): string {
  if (!c) return '';
  const whose = c.source === 'machine' ? "the machine's own" : "the server's";
  return `Shift calendar: ${whose}, ${c.shifts} ${c.shifts === 1 ? 'shift' : 'shifts'} a week in ${c.timezone}${c.holidays ? `, ${c.holidays} ${c.holidays === 1 ? 'holiday' : 'holidays'}` : ''}; days are ${c.timezone}'s.`;
}

// The first day asked for: DAYS days to today (UTC's, or the calendar's
// zone's) by this browser's clock; the server's own today ends the range.
function firstDay(zone: string | null): string {
  const then = new Date(Date.now() - (DAYS - 1) * 86_400_000);
  return zone ? then.toLocaleDateString('en-CA', { timeZone: zone }) : then.toISOString().slice(0, 10);
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
  const basis = h('p', { class: 'note', id: `${id}-calendar` });
  let timer = 0;
  let asked = 0;
  // Known after the first answer: a machine with a calendar is asked in its zone's days.
  let zone: string | null = null;
  const load = async (): Promise<void> => {
    const n = ++asked;
    try {
      const u = await getJson<Utilisation>(`/api/machines/${enc(machine)}/utilisation?from=${firstDay(zone)}${zone ? '&days=local' : ''}`);
      if (n !== asked) return;
      if (u.calendar && zone === null) {
        zone = u.calendar.timezone;
        return load();
      }
      basis.textContent = calendarText(u.calendar);
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
    element: h('section', { class: 'utilisation', id, 'aria-labelledby': `${id}-h` }, h('h3', { id: `${id}-h`, text: 'Utilisation per day' }), basis, picture, figures, said),
    refresh() {
      window.clearTimeout(timer);
      picture.setAttribute('aria-busy', 'true');
      timer = window.setTimeout(() => void load(), 500);
    },
  };
}
