// "New program": a cycle's form (conversational programming, issue 14).
// Pick a cycle, fill its fields (units and usina gen's defaults); each field
// is checked as it is typed, then the server makes the program and answers
// with its text, its check and its tool path (debounced), shown in the 3D
// viewer before anything is saved; "Save as draft" stores it for a machine.
import { enc, getJson, postJson, ApiError, type CheckDiagnostic, type Checks, type Machine } from './api';
import { field, h, show, status } from './dom';
import { calculatorsPanel } from './form_calc';
import { positioningPanel } from './positioning_calc';
import { checkField, cyclesOf, type CycleDef, type FieldDef, type FormSpecs } from './form_cycles';
import { mayUpload, sessionUser } from './roles';
import { decodeToolpath } from './toolpath';
import { Viewer } from './viewer';

const DIALECTS = ['rs274ngc', 'fanuc', 'grbl', 'romi'];
const DEBOUNCE_MS = 400;
const SHOWN_LINES = 400; // of the program's text; all of it is saved

interface Preview {
  text: string;
  bytes: number;
  dialect: string;
  diagnostics: CheckDiagnostic[];
  checks: Checks;
  check_ok: boolean;
  toolpath: string; // base64 of the viewer's stream
}

interface FieldError {
  field: string;
  message: string;
  code: string;
}

interface Inputs {
  cycle: CycleDef;
  controls: Map<string, HTMLInputElement | HTMLSelectElement>;
  errors: Map<string, HTMLElement>;
  files: Map<string, string>; // a file field's text, once read
  fileRead: () => void;
}

// A field's value as the page checks and sends it.
function rawValue(inputs: Inputs, f: FieldDef): string {
  if (f.file) return inputs.files.get(f.name) ?? '';
  return inputs.controls.get(f.name)?.value ?? '';
}

function fromBase64(s: string): ArrayBuffer {
  const bin = atob(s);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  return bytes.buffer;
}

function fieldControl(f: FieldDef, inputs: Inputs): HTMLInputElement | HTMLSelectElement {
  if (f.choices) return h('select', {}, ...f.choices.map((c) => h('option', { value: c, text: c })));
  if (f.file) {
    const file = h('input', { type: 'file', accept: '.dxf,*/*', required: true });
    file.addEventListener('change', () => {
      const chosen = file.files?.[0];
      if (!chosen) return;
      void chosen.text().then((text) => {
        inputs.files.set(f.name, text);
        inputs.fileRead();
      });
    });
    return file;
  }
  if (f.text) return h('input', { type: 'text', autocomplete: 'off', value: f.textValue, maxlength: f.max });
  const step = f.whole ? '1' : 'any';
  return h('input', { type: 'number', inputmode: 'decimal', step, min: f.min, max: f.max, value: f.value, required: f.value === undefined });
}

// One field: its label with the unit, the control, and its message slot
// (named by aria-describedby, so a screen reader reads the error with it).
function fieldRow(f: FieldDef, inputs: Inputs): HTMLElement {
  const id = `form-${f.name}`;
  const control = fieldControl(f, inputs);
  const error = h('p', { id: `${id}-error`, class: 'field-error', 'aria-live': 'polite' });
  control.setAttribute('aria-describedby', error.id);
  control.name = f.name;
  inputs.controls.set(f.name, control);
  inputs.errors.set(f.name, error);
  const label = f.unit ? `${f.label} (${f.unit})` : f.label;
  const row = field(label, control, id);
  row.append(error);
  return row;
}

function setError(inputs: Inputs, name: string, message: string): void {
  const control = inputs.controls.get(name);
  const slot = inputs.errors.get(name);
  if (!control || !slot) return;
  slot.textContent = message;
  if (message) control.setAttribute('aria-invalid', 'true');
  else control.removeAttribute('aria-invalid');
}

// The page's own checks; true when every field may be sent.
function checkAll(inputs: Inputs): boolean {
  let ok = true;
  for (const f of inputs.cycle.fields) {
    const message = checkField(f, rawValue(inputs, f));
    setError(inputs, f.name, message);
    if (message) ok = false;
  }
  return ok;
}

// The fields as the server reads them: an empty field is left out (its default).
function body(inputs: Inputs, dialect: string, machineClass: string): Record<string, unknown> {
  const out: Record<string, unknown> = { dialect };
  if (machineClass) out.machine_class = machineClass;
  for (const f of inputs.cycle.fields) {
    const raw = rawValue(inputs, f);
    if (raw.trim() === '') continue;
    out[f.name] = f.text ? raw : Number(raw);
  }
  return out;
}

export async function formsPage(main: HTMLElement): Promise<void> {
  const [who, { machines: list }] = await Promise.all([sessionUser(), getJson<{ machines: Machine[] }>('/api/machines')]);
  if (!mayUpload(who.role)) {
    show(main, 'New program', h('p', { class: 'note', text: `You are ${who.role}: new programs are for programmers and admins.` }), calculatorsPanel(), positioningPanel());
    return;
  }
  // The fields' ranges and defaults are the server's (GET /api/forms).
  const page = new FormsPage(list, cyclesOf(await getJson<FormSpecs>('/api/forms')));
  show(main, 'New program', page.element, calculatorsPanel(), positioningPanel());
  page.start();
}

class FormsPage {
  readonly element: HTMLElement;
  private cycleSelect: HTMLSelectElement;
  private machineSelect: HTMLSelectElement;
  private dialectSelect = h('select', {}, ...DIALECTS.map((d) => h('option', { value: d, text: d })));
  private fieldsHost = h('fieldset', { class: 'form-fields' });
  private formStatus = status('form-status');
  private previewHeading = h('h2', { id: 'preview-h', text: 'Preview' });
  private previewNote = h('p', { class: 'note' });
  private viewerHost = h('div', { class: 'viewer', id: 'viewer', hidden: true });
  private previewBody = h('div');
  private previewHost = h('section', { 'aria-labelledby': 'preview-h', class: 'preview' }, this.previewHeading, this.previewNote, this.viewerHost, this.previewBody);
  private saveForm: HTMLFormElement;
  private saveStatus = status('save-status');
  private nameInput = h('input', { required: true, autocomplete: 'off', pattern: '[A-Za-z0-9][A-Za-z0-9_.\\-]*' });
  private reasonInput = h('input', { autocomplete: 'off' });
  private inputs!: Inputs;
  private timer = 0;
  private asked = 0; // the latest preview asked for: older answers are dropped
  private preview: Preview | null = null;
  private viewer: Viewer | null = null;

  constructor(
    private machines: Machine[],
    private cycles: CycleDef[],
  ) {
    this.cycleSelect = h('select', {}, ...cycles.map((c) => h('option', { value: c.name, text: c.title })));
    this.machineSelect = h('select', {}, h('option', { value: '', text: '(no machine: choose the control below)' }), ...machines.map((m) => h('option', { value: m.name, text: `${m.name} (${m.machine_class || 'no class'}, ${m.dialect})` })));
    this.saveForm = this.makeSaveForm();
    const cycleForm = h(
      'form',
      { class: 'card wide', 'aria-labelledby': 'cycle-h' },
      h('h2', { id: 'cycle-h', text: 'The cycle' }),
      field('Cycle', this.cycleSelect, 'form-cycle'),
      field('Machine', this.machineSelect, 'form-machine'),
      field('Control (dialect)', this.dialectSelect, 'form-dialect'),
      this.fieldsHost,
      this.formStatus,
    );
    cycleForm.addEventListener('submit', (e) => {
      e.preventDefault();
      this.changed(0);
    });
    cycleForm.addEventListener('input', () => this.changed(DEBOUNCE_MS));
    this.cycleSelect.addEventListener('change', () => this.build());
    this.machineSelect.addEventListener('change', () => this.machineChosen());
    this.element = h('div', { class: 'forms' }, h('div', { class: 'split' }, cycleForm, this.previewHost), this.saveForm);
  }

  start(): void {
    this.build();
  }

  // The chosen cycle's fields, with their defaults.
  private build(): void {
    const cycle = this.cycles.find((c) => c.name === this.cycleSelect.value) ?? this.cycles[0];
    this.inputs = { cycle, controls: new Map(), errors: new Map(), files: new Map(), fileRead: () => this.changed(0) };
    this.fieldsHost.replaceChildren(h('legend', { text: `${cycle.title}: fields` }), ...cycle.fields.map((f) => fieldRow(f, this.inputs)));
    this.preview = null;
    this.viewerHost.hidden = true;
    this.previewNote.textContent = 'Fill the fields: the tool path shows here before anything is saved.';
    this.previewBody.replaceChildren();
    this.changed(0);
  }

  private machineChosen(): void {
    const m = this.machines.find((x) => x.name === this.machineSelect.value);
    if (m && DIALECTS.includes(m.dialect)) this.dialectSelect.value = m.dialect;
    this.dialectSelect.disabled = !!m;
    this.changed(0);
  }

  private machineClass(): string {
    return this.machines.find((x) => x.name === this.machineSelect.value)?.machine_class ?? '';
  }

  // Checks the fields now; asks the server for a preview when they pass
  // and the user has stopped typing for `wait` ms.
  private changed(wait: number): void {
    window.clearTimeout(this.timer);
    this.preview = null;
    this.updateSave();
    if (!checkAll(this.inputs)) {
      this.formStatus.textContent = 'Some fields need a value or a change (see under each).';
      return;
    }
    this.formStatus.textContent = 'Making the preview…';
    this.timer = window.setTimeout(() => void this.ask(), wait);
  }

  private async ask(): Promise<void> {
    const mine = ++this.asked;
    const cycle = this.inputs.cycle;
    try {
      const p = await postJson<Preview>(`/api/forms/${enc(cycle.name)}/preview`, body(this.inputs, this.dialectSelect.value, this.machineClass()));
      if (mine !== this.asked) return;
      this.show(p);
    } catch (e) {
      if (mine !== this.asked) return;
      this.refused(e as ApiError);
    }
  }

  // The server's 400 names each bad field: its message goes next to it.
  private refused(e: ApiError): void {
    const errors = ((e.body as { errors?: FieldError[] } | undefined)?.errors ?? []) as FieldError[];
    const general: string[] = [];
    for (const x of errors) {
      if (this.inputs.controls.has(x.field)) setError(this.inputs, x.field, `${x.message} [${x.code}]`);
      else general.push(`${x.field ? `${x.field}: ` : ''}${x.message} [${x.code}]`);
    }
    if (!errors.length) general.push(`${e.status ?? ''} ${e.message}`.trim());
    this.formStatus.setAttribute('role', 'alert');
    this.formStatus.textContent = general.length ? general.join('; ') : 'The server refused some fields (see under each).';
  }

  private show(p: Preview): void {
    this.formStatus.setAttribute('role', 'status');
    this.preview = p;
    const lines = p.text.split('\n');
    const path = decodeToolpath(fromBase64(p.toolpath));
    const diags = p.diagnostics.map((d) => h('li', { class: d.severity, text: `${d.line ? `line ${d.line}: ` : ''}${d.code} ${d.message}` }));
    const minutes = (p.checks?.cycle_time_s ?? 0) / 60;
    this.formStatus.textContent = `Preview: ${lines.length} lines, ${p.bytes} bytes, ${path.moves} moves, cycle time ${minutes.toFixed(1)} min; ${p.check_ok ? 'the check passed' : 'the check found errors'}.`;
    const shown = lines.slice(0, SHOWN_LINES).join('\n') + (lines.length > SHOWN_LINES ? `\n… ${lines.length - SHOWN_LINES} more lines (all are saved)` : '');
    this.previewHeading.textContent = `Preview (${p.dialect})`;
    this.previewNote.textContent = 'Nothing is saved yet.';
    this.previewBody.replaceChildren(
      diags.length ? h('ul', { class: 'diag-list', 'aria-label': 'The check of the preview' }, ...diags) : h('p', { class: 'ok', text: 'The check found nothing to say.' }),
      h('details', {}, h('summary', { text: 'The program text' }), h('pre', { class: 'diff program-text', tabindex: 0, 'aria-label': 'The program text', text: shown })),
    );
    // One viewer for every preview: a browser has few WebGL contexts to give.
    this.viewerHost.hidden = false;
    this.viewer ??= new Viewer(this.viewerHost);
    this.viewer.load(path);
    this.viewer.setView('top');
    this.viewerHost.dataset.vertices = String(path.count);
    this.updateSave();
  }

  private updateSave(): void {
    const button = this.saveForm.querySelector('button[type="submit"]') as HTMLButtonElement | null;
    if (button) button.disabled = this.preview === null;
  }

  private makeSaveForm(): HTMLFormElement {
    const form = h(
      'form',
      { class: 'card', 'aria-labelledby': 'save-h' },
      h('h2', { id: 'save-h', text: 'Save as draft' }),
      h('p', { class: 'note', text: 'A new draft revision in the library, for the machine chosen above (its class and control).' }),
      field('Program name', this.nameInput, 'save-name'),
      field('Reason (optional)', this.reasonInput, 'save-reason'),
      h('button', { type: 'submit', text: 'Save as draft', disabled: true }),
      this.saveStatus,
    );
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      void this.save();
    });
    return form;
  }

  private async save(): Promise<void> {
    const p = this.preview;
    if (!p) return;
    this.saveStatus.setAttribute('role', 'status');
    this.saveStatus.textContent = 'Saving…';
    try {
      const up: Record<string, string> = { name: this.nameInput.value, dialect: p.dialect, text: p.text, reason: this.reasonInput.value || `${this.inputs.cycle.title} form` };
      if (this.machineClass()) up.machine_class = this.machineClass();
      const r = await postJson<{ name: string; revision: string; state: string }>('/api/programs', up);
      this.saveStatus.replaceChildren(`Saved: ${r.name}, revision ${r.revision.slice(0, 12)} (${r.state}). `, h('a', { href: `#/program/${enc(r.name)}/${r.revision}`, text: `Open ${r.name}` }));
    } catch (err) {
      this.saveStatus.setAttribute('role', 'alert');
      this.saveStatus.textContent = `Not saved: ${(err as Error).message}`;
    }
  }
}
