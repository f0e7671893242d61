// The library: a page of programs at a time, filtered, searched and counted
// by the server (GET /api/programs, docs/dnc-server.md "The library's
// list"), the upload of a file and the import of a folder (library_import.ts).
import { ApiError, enc, getJson, postJson, type LibraryList, type ProgramSummary } from './api';
import { field, h, show, status } from './dom';
import { importForm } from './library_import';
import { mayUpload, sessionUser } from './roles';

const DIALECTS = ['rs274ngc', 'fanuc', 'grbl', 'romi'];
const STATES = ['draft', 'checked', 'approved', 'released', 'rejected', 'check-failed'];
const HAS_RELEASED = 'has a released revision';

// Rows a page of the table shows, and so a request asks for: 10,000
// programs never come to the page at once.
const PAGE = 50;
// The search asks the server this long after the last key.
const TYPING_MS = 250;

function choices(label: string, values: string[]): HTMLSelectElement {
  return h('select', {}, h('option', { value: '', text: label }), ...values.map((v) => h('option', { value: v, text: v || '(none)' })));
}

export async function libraryPage(main: HTMLElement): Promise<void> {
  const [first, who] = await Promise.all([getJson<LibraryList>(`/api/programs?limit=${PAGE}`), sessionUser()]);
  const programs = programsSection(first);
  show(
    main,
    'Library',
    programs.element,
    ...(mayUpload(who.role)
      ? [h('div', { class: 'cards' }, uploadForm(), importForm(DIALECTS, programs.reload))]
      : [h('p', { class: 'note', text: `You are ${who.role}: uploading programs is for programmers and admins.` })]),
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

// The tool field's number ("5", "T5", "t05"), '' for none, null when it is no tool.
function toolNumber(typed: string): string | null {
  const t = typed.trim();
  if (!t) return '';
  const m = /^[Tt]?\s*(\d{1,8})$/.exec(t);
  return m ? String(Number(m[1])) : null;
}

// The filters and the search as the server's query, for the page at `offset`.
interface Filters {
  search: HTMLInputElement;
  tool: HTMLInputElement;
  classes: HTMLSelectElement;
  dialects: HTMLSelectElement;
  states: HTMLSelectElement;
}

function query(f: Filters, offset: number): string {
  const p = new URLSearchParams({ limit: String(PAGE), offset: String(offset) });
  if (f.search.value.trim()) p.set('text', f.search.value.trim());
  const tool = toolNumber(f.tool.value);
  if (tool) p.set('tool', tool);
  if (f.classes.value) p.set('machine_class', f.classes.value);
  if (f.dialects.value) p.set('dialect', f.dialects.value);
  if (f.states.value === HAS_RELEASED) p.set('released', '1');
  else if (f.states.value) p.set('state', f.states.value);
  return `/api/programs?${p}`;
}

// The class filter's choices: the library's classes, the chosen one kept.
function setClasses(select: HTMLSelectElement, classes: string[]): void {
  const chosen = select.value;
  const all = [...new Set([...classes, ...(chosen ? [chosen] : [])])].sort();
  const have = [...select.options].slice(1).map((o) => o.value);
  if (have.join('\n') === all.join('\n')) return;
  select.replaceChildren(h('option', { value: '', text: 'every class' }), ...all.map((v) => h('option', { value: v, text: v || '(none)' })));
  select.value = chosen;
}

// The search, the filters, a page of the table and the pager. Each change
// asks the server for one page; an answer to an older request is dropped
// (and its request cancelled), so the table always shows the newest ask.
// The table is aria-busy from a change until its page is shown.
function programsSection(first: LibraryList): { element: HTMLElement; reload: () => void } {
  const f: Filters = {
    search: h('input', { type: 'search', placeholder: 'O1234, a comment, a name', autocomplete: 'off', maxlength: 200 }),
    tool: h('input', { id: 'library-tool', type: 'text', inputmode: 'numeric', placeholder: 'T5', autocomplete: 'off', size: 8, 'aria-describedby': 'library-tool-error' }),
    classes: choices('every class', []),
    dialects: choices('every dialect', DIALECTS),
    states: choices('every state', [...STATES, HAS_RELEASED]),
  };
  const toolError = h('p', { id: 'library-tool-error', class: 'field-error', 'aria-live': 'polite', hidden: true });
  const body = h('tbody');
  const count = status('library-count');
  const prev = h('button', { type: 'button', text: 'Previous page' });
  const next = h('button', { type: 'button', text: 'Next page' });
  const where = h('span', { id: 'library-page', 'aria-live': 'polite' });
  const table = h('table', { id: 'library-table', 'aria-label': 'Programs', 'aria-busy': 'false' }, h('thead', {}, h('tr', {}, ...['Name', 'Machine class', 'Dialect', 'State'].map((t) => h('th', { scope: 'col', text: t })))), body);
  let offset = 0;
  let asked = 0; // the newest request: older answers are dropped
  let inFlight: AbortController | null = null;
  let timer = 0;
  const shown = (list: LibraryList) => {
    body.replaceChildren(...list.programs.map(programRow));
    const pages = Math.max(1, Math.ceil(list.total / PAGE));
    count.textContent = `${list.total} ${list.total === 1 ? 'program' : 'programs'}`;
    where.textContent = `Page ${Math.floor(offset / PAGE) + 1} of ${pages}`;
    prev.disabled = offset === 0;
    next.disabled = offset + PAGE >= list.total;
    setClasses(f.classes, list.machine_classes ?? []);
    table.setAttribute('aria-busy', 'false');
  };
  const load = async (): Promise<void> => {
    window.clearTimeout(timer);
    inFlight?.abort();
    const mine = new AbortController();
    inFlight = mine;
    const n = ++asked;
    table.setAttribute('aria-busy', 'true');
    try {
      const list = await getJson<LibraryList>(query(f, offset), mine.signal);
      if (n !== asked) return;
      if (list.programs.length === 0 && offset > 0 && list.total > 0) {
        offset = Math.floor((list.total - 1) / PAGE) * PAGE; // the library shrank under the page
        return load();
      }
      shown(list);
    } catch (e) {
      if (n !== asked || (e as Error).name === 'AbortError') return;
      if (e instanceof ApiError && e.status === 401) location.hash = '#/login';
      count.textContent = `The library could not be read: ${(e as Error).message}`;
      table.setAttribute('aria-busy', 'false');
    }
  };
  // A key in the search or the tool: the first page, asked after a pause.
  const typed = () => {
    offset = 0;
    const tool = toolNumber(f.tool.value);
    toolError.textContent = tool === null ? 'A tool is a whole number of up to 8 digits (5 or T5).' : '';
    toolError.hidden = tool !== null; // shown only with its message: the fields stay in line
    if (tool === null) f.tool.setAttribute('aria-invalid', 'true');
    else f.tool.removeAttribute('aria-invalid');
    window.clearTimeout(timer);
    if (tool === null) return;
    table.setAttribute('aria-busy', 'true');
    timer = window.setTimeout(() => void load(), TYPING_MS);
  };
  const now = (to: (at: number) => number) => () => {
    offset = Math.max(0, to(offset));
    void load();
  };
  f.search.addEventListener('input', typed);
  f.tool.addEventListener('input', typed);
  for (const select of [f.classes, f.dialects, f.states]) select.addEventListener('change', now(() => 0)); // a new filter starts at its first page
  prev.addEventListener('click', now((at) => at - PAGE));
  next.addEventListener('click', now((at) => at + PAGE));
  shown(first);
  const element = h(
    'section',
    { 'aria-labelledby': 'search-h' },
    h('h2', { id: 'search-h', text: 'Programs' }),
    h(
      'div',
      { class: 'filters' },
      field('Search by name, comment or O number', f.search, 'library-search'),
      h('div', { class: 'field' }, h('label', { for: 'library-tool', text: 'Uses tool' }), f.tool, toolError),
      field('Filter by machine class', f.classes, 'library-class'),
      field('Filter by dialect', f.dialects, 'library-dialect'),
      field('Filter by state', f.states, 'library-state'),
    ),
    count,
    table,
    h('div', { class: 'pager', role: 'group', 'aria-label': 'Pages' }, prev, where, next),
  );
  return { element, reload: () => void load() };
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
