// A machine's quality records (docs/dnc-server.md, "Quality records"): the
// newest first, a page at a time ("More" asks for the records `before` the
// last shown), each out-of-tolerance value marked NOT OK in words, not
// only in colour; a filter to one characteristic (its measurements over
// time, `?characteristic=`); and, for the roles that may record (operator, approver,
// admin), a form checked as it is typed, with the server's 400 shown as it
// says it.
import { enc, getJson } from './api';
import { field, h } from './dom';
import { qualityForm } from './quality_form';
import { runChart } from './run_chart';

export interface QualityRecord {
  id: number;
  machine: string;
  at_us: number;
  by: string;
  characteristic: string;
  measured: number;
  nominal: number | null;
  min: number | null;
  max: number | null;
  ok: boolean | null;
  unit: string;
  part: string;
  program: string | null;
  job: number | null;
  note: string;
}

const PAGE = 20;

function when(us: number): string {
  return new Date(us / 1000).toISOString().replace('T', ' ').slice(0, 16);
}

function withUnit(v: number, unit: string): string {
  return unit ? `${v} ${unit}` : String(v);
}

export function limitsText(r: QualityRecord): string {
  const u = r.unit;
  const range = r.min !== null && r.max !== null ? `${r.min} to ${withUnit(r.max, u)}` : r.min !== null ? `at least ${withUnit(r.min, u)}` : r.max !== null ? `at most ${withUnit(r.max, u)}` : 'no limits';
  return r.nominal !== null ? `${range} (nominal ${withUnit(r.nominal, u)})` : range;
}

export function verdictText(ok: boolean | null): string {
  return ok === true ? 'OK' : ok === false ? 'NOT OK' : '— (no limits)';
}

function row(r: QualityRecord): HTMLElement {
  const verdict = ok(r.ok);
  const what = [r.part && `part ${r.part}`, r.program && `program ${r.program}`, r.job && `job ${r.job}`, r.note].filter(Boolean).join('; ');
  return h(
    'tr',
    { 'data-id': r.id, class: r.ok === false ? 'not-ok' : '' },
    h('td', { text: when(r.at_us) }),
    h('th', { scope: 'row', text: r.characteristic }),
    h('td', { class: 'measured', text: withUnit(r.measured, r.unit) }),
    h('td', { text: limitsText(r) }),
    h('td', {}, verdict),
    h('td', { text: what || '—' }),
    h('td', { text: r.by }),
  );
}

function ok(v: boolean | null): HTMLElement {
  return h('strong', { class: `verdict ${v === true ? 'ok' : v === false ? 'not-ok' : 'none'}`, text: verdictText(v) });
}

export interface QualityPanel {
  element: HTMLElement;
  add(r: QualityRecord): void; // a record just made (the form's, or an event's)
}

// The records of `machine`, the form below them when `mayRecord`.
export function qualityPanel(machine: string, mayRecord: boolean): QualityPanel {
  const id = `quality-${machine}`;
  const body = h('tbody');
  const shownIds = new Set<number>();
  const heads = ['When (UTC)', 'Characteristic', 'Measured', 'Limits', 'Verdict', 'Part, program, note', 'By'];
  const table = h('table', { id: `${id}-table`, class: 'quality' }, h('caption', { text: `Quality records of ${machine}, newest first` }), h('thead', {}, h('tr', {}, ...heads.map((t) => h('th', { scope: 'col', text: t })))), body);
  // A narrow window scrolls the table, not the page (tabindex: by the keyboard too).
  const scroller = h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': `Quality records of ${machine}` }, table);
  const empty = h('p', { class: 'note', text: 'No quality records yet.', hidden: true }); // shown once read
  const more = h('button', { type: 'button', text: 'More records', hidden: true, 'aria-controls': `${id}-table` });
  const said = h('p', { class: 'status', 'aria-live': 'polite' });
  const names = h('datalist', { id: `${id}-names` });
  const only = h('input', { type: 'search', list: `${id}-names`, autocomplete: 'off', maxlength: 200 });
  const filter = field('Show only the characteristic', only, `${id}-only`);
  const known = new Set<string>();
  const remember = (c: string) => {
    if (known.has(c)) return;
    known.add(c);
    names.append(h('option', { value: c }));
  };
  let before: number | null = null;
  let wanted = ''; // the characteristic shown, '' for all
  const chartHost = h('div', { class: 'chart', hidden: true });
  let records: QualityRecord[] = []; // those shown, newest first
  // One characteristic's records shown: their run chart, with the limits
  // of the newest (a change of limits shows as its points' verdicts).
  const plot = () => {
    chartHost.hidden = !wanted || records.length === 0;
    if (chartHost.hidden) return chartHost.replaceChildren();
    const newest = records[0];
    chartHost.replaceChildren(
      runChart({
        id: `${id}-run`,
        title: `${machine}: ${wanted}, the ${records.length} ${records.length === 1 ? 'measurement' : 'measurements'} shown, against the limits of the newest (${limitsText(newest)})`,
        unit: newest.unit,
        points: [...records].reverse().map((r) => ({ label: when(r.at_us), value: r.measured, ok: r.ok, text: `${when(r.at_us)}: ${withUnit(r.measured, r.unit)}, ${verdictText(r.ok)}${r.part ? `, part ${r.part}` : ''}` })),
        min: newest.min,
        max: newest.max,
        nominal: newest.nominal,
      }),
    );
  };
  const show = () => {
    const n = shownIds.size;
    const of = wanted ? ` of ${wanted}` : '';
    said.textContent = n ? `${n} ${n === 1 ? 'record' : 'records'}${of} shown${more.hidden ? '' : '; more are older'}.` : wanted ? `No records of ${wanted}.` : '';
    scroller.hidden = shownIds.size === 0;
    empty.hidden = shownIds.size !== 0 || wanted !== '';
    plot();
  };
  let asked = 0;
  const load = async () => {
    const n = ++asked;
    more.setAttribute('aria-busy', 'true');
    try {
      const q = (before === null ? '' : `&before=${before}`) + (wanted ? `&characteristic=${enc(wanted)}` : '');
      const page = await getJson<{ records: QualityRecord[]; next_before: number | null }>(`/api/machines/${enc(machine)}/quality?limit=${PAGE}${q}`);
      if (n !== asked) return; // the filter changed meanwhile
      for (const r of page.records) {
        remember(r.characteristic);
        if (shownIds.has(r.id)) continue; // recorded while this page was read
        shownIds.add(r.id);
        records.push(r);
        body.append(row(r));
      }
      before = page.next_before;
      // A short page is the last one.
      more.hidden = page.records.length < PAGE || before === null;
      show();
    } catch (e) {
      said.textContent = `The quality records could not be read: ${(e as Error).message}`;
    } finally {
      more.setAttribute('aria-busy', 'false');
    }
  };
  more.addEventListener('click', () => void load());
  let typing = 0;
  only.addEventListener('input', () => {
    window.clearTimeout(typing);
    typing = window.setTimeout(() => {
      if (only.value.trim() === wanted) return;
      wanted = only.value.trim();
      shownIds.clear();
      records = [];
      body.replaceChildren();
      before = null;
      void load();
    }, 300);
  });
  void load();
  const panel: QualityPanel = {
    element: h('section', { class: 'quality', id, 'aria-labelledby': `${id}-h` }, h('h3', { id: `${id}-h`, text: 'Quality records' }), filter, names, chartHost, scroller, empty, more, said),
    add(r: QualityRecord) {
      remember(r.characteristic);
      if (shownIds.has(r.id) || (wanted && r.characteristic !== wanted)) return;
      shownIds.add(r.id);
      records.unshift(r);
      body.prepend(row(r));
      show();
    },
  };
  if (mayRecord) panel.element.append(qualityForm(machine, (r) => panel.add(r)));
  return panel;
}
