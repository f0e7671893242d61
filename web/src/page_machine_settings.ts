// The admin's machines page (issue 14): every machine in service with its
// link, where it is set (usina-serve.toml, or this page), and those retired;
// a machine added, its settings changed, a machine retired (asking first,
// with a reason). The server checks every value as it checks the file's
// (POST /api/machines, docs/dnc-server.md "Machines added from the page")
// and its message is shown. The file's machines are changed in the file.
import { ApiError, enc, getJson, postJson, type Machine } from './api';
import { confirmAction } from './confirm';
import { h, show, status } from './dom';
import { settingField, SETTINGS, type Settings } from './machine_settings_fields';
import { sessionUser } from './roles';

interface Listed extends Machine {
  source: 'file' | 'api';
  settings: Settings;
}

interface Retired {
  name: string;
  settings: Settings;
  retired_at_us: number;
  retired_by: string;
  retire_reason: string;
}

interface Page {
  said: HTMLElement;
  form: MachineForm;
  refresh: () => Promise<void>;
}

export async function machineSettingsPage(main: HTMLElement): Promise<void> {
  const who = await sessionUser();
  if (who.role !== 'admin') {
    show(main, 'Machine settings', h('p', { class: 'note', text: `You are ${who.role}: the machines' settings are for admins.` }));
    return;
  }
  const said = status('machine-settings-status');
  const body = h('tbody');
  const retiredBody = h('tbody');
  const heads = (names: string[]) => h('thead', {}, h('tr', {}, ...names.map((t) => h('th', { scope: 'col', text: t }))));
  const table = h('table', { class: 'machine-settings', 'aria-label': 'Machines in service' }, heads(['Machine', 'Class', 'Dialect', 'Port', 'Link', 'Mode', 'Set in', 'Change']), body);
  const retired = h('table', { class: 'machine-settings', 'aria-label': 'Retired machines' }, heads(['Machine', 'Port', 'Retired', 'By', 'Reason']), retiredBody);
  const page: Page = { said, form: new MachineForm(() => page), refresh: async () => undefined };
  page.refresh = async () => {
    const list = await getJson<{ machines: Listed[]; retired: Retired[] }>('/api/machines?retired=1');
    body.replaceChildren(...list.machines.map((m) => row(m, page)));
    retiredBody.replaceChildren(...list.retired.map(retiredRow));
    if (!list.retired.length) retiredBody.append(h('tr', {}, h('td', { colspan: 5, text: 'No machine has been retired.' })));
  };
  const scroll = (t: HTMLElement) => h('div', { class: 'table-scroll' }, t);
  show(main, 'Machine settings', h('p', { class: 'note', text: 'Machines set in usina-serve.toml are changed in that file; those added here are changed here. A change or a retirement waits until the machine has no job.' }), scroll(table), page.form.element, said, h('h2', { text: 'Retired machines' }), scroll(retired));
  await page.refresh();
}

function linkText(s: Settings): string {
  const parity = String(s.parity ?? 'even')[0].toUpperCase();
  return `${s.baud} baud ${s.data_bits}${parity}${s.stop_bits}, ${s.flow}, ${s.code}, end of block ${s.eob}`;
}

function row(m: Listed, page: Page): HTMLElement {
  const s = m.settings;
  const change: (HTMLElement | string)[] = [];
  if (m.source === 'api') {
    const edit = h('button', { type: 'button', text: 'Edit', 'aria-label': `Edit ${m.name}` });
    edit.addEventListener('click', () => page.form.edit(m));
    change.push(edit, ' ', retireForm(m, page));
  } else {
    change.push(h('span', { class: 'note', text: 'in the file' }));
  }
  return h(
    'tr',
    { id: `settings-${m.name}` },
    h('th', { scope: 'row', text: m.name }),
    h('td', { text: m.machine_class || 'any' }),
    h('td', { text: m.dialect }),
    h('td', { text: m.port }),
    h('td', { class: 'link', text: linkText(s) }),
    h('td', { text: m.mode }),
    h('td', { class: 'source', text: m.source === 'api' ? 'this page' : 'usina-serve.toml' }),
    h('td', {}, ...change),
  );
}

function retireForm(m: Listed, page: Page): HTMLElement {
  const reason = h('input', { autocomplete: 'off', 'aria-label': `Reason for retiring ${m.name}` });
  const form = h('form', { class: 'inline' }, reason, h('button', { type: 'submit', text: 'Retire', 'aria-label': `Retire ${m.name}` }));
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    const detail = `${m.name} leaves the machines: its port is closed and no job can be sent to it. Its jobs, parts and quality records stay under its name, which no other machine may take.`;
    if (!(await confirmAction(`Retire ${m.name}?`, detail, 'Retire'))) return;
    await said(page, `${m.name}: retired.`, () => postJson(`/api/machines/${enc(m.name)}/retire`, { reason: reason.value }));
  });
  return form;
}

function retiredRow(r: Retired): HTMLElement {
  return h(
    'tr',
    { id: `retired-${r.name}` },
    h('th', { scope: 'row', text: r.name }),
    h('td', { text: String(r.settings.port ?? '') }),
    h('td', { text: new Date(r.retired_at_us / 1000).toISOString().slice(0, 16).replace('T', ' ') + ' UTC' }),
    h('td', { text: r.retired_by }),
    h('td', { text: r.retire_reason }),
  );
}

// Runs a request and says what came of it (the server's message when it
// refused); the tables are read again either way. True when it was done.
// The list is read again after a change, or a refusal of what the server
// holds (409, 404: someone else changed it); not after a 400, which changed
// nothing and would wipe what the admin typed (a reason to retire).
async function said(page: Page, done: string, request: () => Promise<unknown>): Promise<boolean> {
  let ok = false;
  let refresh = true;
  try {
    await request();
    page.said.setAttribute('role', 'status');
    page.said.textContent = done;
    ok = true;
  } catch (e) {
    refresh = !(e instanceof ApiError && e.status === 400);
    page.said.setAttribute('role', 'alert');
    page.said.textContent = (e as ApiError).message;
  }
  if (refresh) await page.refresh();
  return ok;
}

// One form for a new machine and for a machine's changes: the settings of
// the file's [[machine]] table, the usual ones first, the others under
// "More settings". A change sends only what differs from the machine's.
class MachineForm {
  readonly element: HTMLFormElement;
  private controls = new Map<string, HTMLInputElement | HTMLSelectElement>();
  private heading = h('h2', { text: 'Add a machine' });
  private submit = h('button', { type: 'submit', text: 'Add the machine' });
  private cancel = h('button', { type: 'button', text: 'Cancel the change', hidden: true });
  private reason = h('input', { autocomplete: 'off' });
  private editing: Listed | null = null;

  constructor(page: () => Page) {
    const main: HTMLElement[] = [];
    const more: HTMLElement[] = [];
    for (const f of SETTINGS) {
      const { wrapper, control } = settingField(f);
      this.controls.set(f.key, control);
      (f.more ? more : main).push(wrapper);
    }
    this.reason.id = 'machine-reason';
    this.element = h(
      'form',
      { class: 'card machine-form', 'aria-labelledby': 'machine-form-h' },
      this.heading,
      h('div', { class: 'fields' }, ...main),
      h('details', {}, h('summary', { text: 'More settings' }), h('div', { class: 'fields' }, ...more)),
      h('div', { class: 'field' }, h('label', { for: 'machine-reason', text: 'Reason (for the audit log)' }), this.reason),
      h('div', { class: 'buttons' }, this.submit, this.cancel),
    );
    this.heading.id = 'machine-form-h';
    this.cancel.addEventListener('click', () => this.reset());
    this.element.addEventListener('submit', (e) => {
      e.preventDefault();
      void this.send(page());
    });
    this.reset();
  }

  edit(m: Listed): void {
    this.editing = m;
    for (const [key, control] of this.controls) {
      const v = m.settings[key];
      if (control instanceof HTMLInputElement && control.type === 'checkbox') control.checked = v === true;
      else control.value = v === undefined || v === null ? '' : String(v);
    }
    (this.controls.get('name') as HTMLInputElement).readOnly = true;
    this.heading.textContent = `Change ${m.name}`;
    this.submit.textContent = `Save ${m.name}`;
    this.cancel.hidden = false;
    this.controls.get('port')?.focus();
  }

  private reset(): void {
    this.editing = null;
    this.element.reset();
    for (const f of SETTINGS) {
      const control = this.controls.get(f.key);
      if (control instanceof HTMLInputElement && control.type === 'checkbox') control.checked = f.initial === true;
      else if (control) control.value = f.initial === undefined ? '' : String(f.initial);
    }
    (this.controls.get('name') as HTMLInputElement).readOnly = false;
    this.heading.textContent = 'Add a machine';
    this.submit.textContent = 'Add the machine';
    this.cancel.hidden = true;
  }

  // The form's values as the API takes them: numbers as numbers, an empty
  // optional field left out (the server's default).
  private values(): Settings {
    const out: Settings = {};
    for (const f of SETTINGS) {
      const control = this.controls.get(f.key);
      if (!control) continue;
      if (control instanceof HTMLInputElement && control.type === 'checkbox') out[f.key] = control.checked;
      else if (control.value.trim() === '') continue;
      else out[f.key] = f.kind === 'number' || f.numeric ? Number(control.value) : control.value.trim();
    }
    return out;
  }

  private async send(page: Page): Promise<void> {
    const values = this.values();
    const editing = this.editing;
    let ok: boolean;
    if (editing) {
      const changed: Settings = {};
      for (const [k, v] of Object.entries(values)) if (editing.settings[k] !== v) changed[k] = v;
      if (!Object.keys(changed).length) {
        page.said.setAttribute('role', 'status');
        page.said.textContent = `${editing.name}: nothing changed.`;
        return;
      }
      ok = await said(page, `${editing.name}: saved (${Object.keys(changed).join(', ')}); its port was opened again.`, () => postJson(`/api/machines/${enc(editing.name)}`, { ...changed, reason: this.reason.value }));
    } else {
      ok = await said(page, `${String(values.name)}: added.`, () => postJson('/api/machines', { ...values, reason: this.reason.value }));
    }
    if (ok) this.reset();
  }
}
