// The library: every program, a search by name, and the upload of a file.
import { enc, getJson, postJson, type ProgramSummary } from './api';
import { field, h, show, status } from './dom';
import { mayUpload, sessionUser } from './roles';

const DIALECTS = ['rs274ngc', 'fanuc', 'grbl', 'romi'];
const STATES = ['draft', 'checked', 'approved', 'released', 'rejected', 'check-failed'];
const HAS_RELEASED = 'has a released revision';

// Rows a page of the table shows: 10,000 programs arrive in one request
// (about 0.7 MB of JSON), but only a page of them becomes rows.
const PAGE = 50;

function choices(label: string, values: string[]): HTMLSelectElement {
  return h('select', {}, h('option', { value: '', text: label }), ...values.map((v) => h('option', { value: v, text: v || '(none)' })));
}

export async function libraryPage(main: HTMLElement): Promise<void> {
  const [list, who] = await Promise.all([getJson<{ programs: ProgramSummary[] }>('/api/programs'), sessionUser()]);
  show(
    main,
    'Library',
    programsSection(list.programs),
    mayUpload(who.role) ? uploadForm() : h('p', { class: 'note', text: `You are ${who.role}: uploading programs is for programmers and admins.` }),
  );
}

function programRow(p: ProgramSummary): HTMLElement {
  const state = p.newest_state ?? '';
  const released = p.released_revision && state !== 'released' ? ' (one released)' : '';
  return h(
    'tr',
    {},
    h('td', {}, h('a', { href: `#/program/${enc(p.name)}`, text: p.name })),
    h('td', { text: p.machine_class || '—' }),
    h('td', { text: p.dialect }),
    h('td', { text: state + released }),
  );
}

// The state filter: the newest revision's state, or a released revision anywhere.
function stateMatches(p: ProgramSummary, wanted: string): boolean {
  if (!wanted) return true;
  if (wanted === HAS_RELEASED) return !!p.released_revision;
  return p.newest_state === wanted;
}

// The search, the filters, a page of the table and the pager.
function programsSection(all: ProgramSummary[]): HTMLElement {
  const search = h('input', { type: 'search', placeholder: 'O1234', autocomplete: 'off' });
  const classes = choices('every class', [...new Set(all.map((p) => p.machine_class))].sort());
  const dialects = choices('every dialect', [...new Set(all.map((p) => p.dialect))].sort());
  const states = choices('every state', [...STATES, HAS_RELEASED]);
  const body = h('tbody');
  const count = status('library-count');
  const prev = h('button', { type: 'button', text: 'Previous page' });
  const next = h('button', { type: 'button', text: 'Next page' });
  const where = h('span', { id: 'library-page', 'aria-live': 'polite' });
  let page = 0;
  const render = () => {
    const q = search.value.trim().toLowerCase();
    const rows = all.filter((p) => p.name.toLowerCase().includes(q) && (!classes.value || p.machine_class === classes.value) && (!dialects.value || p.dialect === dialects.value) && stateMatches(p, states.value));
    const pages = Math.max(1, Math.ceil(rows.length / PAGE));
    page = Math.min(page, pages - 1);
    body.replaceChildren(...rows.slice(page * PAGE, (page + 1) * PAGE).map(programRow));
    count.textContent = `${rows.length} of ${all.length} programs`;
    where.textContent = `Page ${page + 1} of ${pages}`;
    prev.disabled = page === 0;
    next.disabled = page >= pages - 1;
  };
  const go = (to: (at: number) => number) => () => {
    page = to(page);
    render();
  };
  search.addEventListener('input', go(() => 0)); // a new filter starts at its first page
  classes.addEventListener('change', go(() => 0));
  dialects.addEventListener('change', go(() => 0));
  states.addEventListener('change', go(() => 0));
  prev.addEventListener('click', go((at) => at - 1));
  next.addEventListener('click', go((at) => at + 1));
  render();
  const table = h('table', { 'aria-label': 'Programs' }, h('thead', {}, h('tr', {}, ...['Name', 'Machine class', 'Dialect', 'State'].map((t) => h('th', { scope: 'col', text: t })))), body);
  return h(
    'section',
    { 'aria-labelledby': 'search-h' },
    h('h2', { id: 'search-h', text: 'Programs' }),
    h('div', { class: 'filters' }, field('Search by name', search, 'library-search'), field('Filter by machine class', classes, 'library-class'), field('Filter by dialect', dialects, 'library-dialect'), field('Filter by state', states, 'library-state')),
    count,
    table,
    h('div', { class: 'pager', role: 'group', 'aria-label': 'Pages' }, prev, where, next),
  );
}

function uploadForm(): HTMLElement {
  const file = h('input', { type: 'file', accept: '.nc,.ngc,.tap,.txt,.cnc,.gcode,*/*', required: true });
  const name = h('input', { required: true, autocomplete: 'off', pattern: '[A-Za-z0-9][A-Za-z0-9_.\\-]*' });
  const machineClass = h('input', { autocomplete: 'off' });
  const dialect = h('select', {}, ...DIALECTS.map((d) => h('option', { value: d, text: d })));
  const reason = h('input', { autocomplete: 'off' });
  const message = status('upload-status');
  const drop = h('p', { class: 'drop', text: 'or drop a file here' });
  let text: string | null = null;
  const take = async (f: File) => {
    text = await f.text();
    if (!name.value) name.value = f.name.replace(/\.[^.]*$/, '').replace(/[^A-Za-z0-9_.-]/g, '_');
    message.textContent = `${f.name}: ${f.size} bytes read`;
  };
  file.addEventListener('change', () => file.files?.[0] && void take(file.files[0]));
  drop.addEventListener('dragover', (e) => e.preventDefault());
  drop.addEventListener('drop', (e) => {
    e.preventDefault();
    const f = e.dataTransfer?.files[0];
    if (f) void take(f);
  });
  const form = h(
    'form',
    { class: 'card', 'aria-labelledby': 'upload-h' },
    h('h2', { id: 'upload-h', text: 'Upload a program' }),
    field('Program file', file, 'upload-file'),
    drop,
    field('Name', name, 'upload-name'),
    field('Machine class (optional)', machineClass, 'upload-class'),
    field('Dialect', dialect, 'upload-dialect'),
    field('Reason (optional)', reason, 'upload-reason'),
    h('button', { type: 'submit', text: 'Upload' }),
    message,
  );
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    if (text === null) {
      message.textContent = 'Choose a file first.';
      return;
    }
    message.textContent = 'Uploading…';
    try {
      const body: Record<string, string> = { name: name.value, text, dialect: dialect.value };
      if (machineClass.value) body.machine_class = machineClass.value;
      if (reason.value) body.reason = reason.value;
      const r = await postJson<{ name: string; revision: string }>('/api/programs', body);
      location.hash = `#/program/${enc(r.name)}/${r.revision}`;
    } catch (err) {
      message.setAttribute('role', 'alert');
      message.textContent = (err as Error).message;
    }
  });
  return form;
}
