// The library: every program, a search by name, and the upload of a file.
import { enc, getJson, postJson, type ProgramSummary } from './api';
import { field, h, show, status } from './dom';

const DIALECTS = ['rs274ngc', 'fanuc', 'grbl', 'romi'];

export async function libraryPage(main: HTMLElement): Promise<void> {
  const list = await getJson<{ programs: ProgramSummary[] }>('/api/programs');
  const search = h('input', { type: 'search', placeholder: 'O1234', autocomplete: 'off' });
  const body = h('tbody');
  const count = status('library-count');
  const render = () => {
    const q = search.value.trim().toLowerCase();
    const rows = list.programs.filter((p) => p.name.toLowerCase().includes(q));
    body.replaceChildren(
      ...rows.map((p) =>
        h(
          'tr',
          {},
          h('td', {}, h('a', { href: `#/program/${enc(p.name)}`, text: p.name })),
          h('td', { text: p.machine_class || '—' }),
          h('td', { text: p.dialect }),
        ),
      ),
    );
    count.textContent = `${rows.length} of ${list.programs.length} programs`;
  };
  search.addEventListener('input', render);
  render();
  const table = h(
    'table',
    { 'aria-label': 'Programs' },
    h('thead', {}, h('tr', {}, h('th', { scope: 'col', text: 'Name' }), h('th', { scope: 'col', text: 'Machine class' }), h('th', { scope: 'col', text: 'Dialect' }))),
    body,
  );
  show(
    main,
    'Library',
    h('section', { 'aria-labelledby': 'search-h' }, h('h2', { id: 'search-h', text: 'Programs' }), field('Search by name', search, 'library-search'), count, table),
    uploadForm(),
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
