// The form that records a quality measurement on a machine (POST
// /api/machines/{m}/quality): each field checked as it is typed (numbers,
// min not above max), the problems said beside their fields, and the
// server's own 400 shown as it says it.
import { ApiError, enc, postJson } from './api';
import { field, h, status } from './dom';
import type { QualityRecord } from './machine_quality';

// A number as typed: '' is none; a decimal comma is read as a point.
export function parseNumber(text: string): number | null | undefined {
  const t = text.trim().replace(/^([-+]?\d*),(\d+)$/, '$1.$2');
  if (t === '') return null;
  if (!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(t)) return undefined; // not a number
  const v = Number(t);
  return Number.isFinite(v) ? v : undefined;
}

export interface QualityInput {
  characteristic: string;
  measured: string;
  nominal: string;
  min: string;
  max: string;
}

// What is wrong with the form's values, by field; empty when nothing is.
export function problems(v: QualityInput): Record<string, string> {
  const out: Record<string, string> = {};
  if (!v.characteristic.trim()) out.characteristic = 'Say what was measured.';
  for (const k of ['measured', 'nominal', 'min', 'max'] as const) if (parseNumber(v[k]) === undefined) out[k] = 'Not a number (like 20.021).';
  if (!out.measured && parseNumber(v.measured) === null) out.measured = 'Give the measured value.';
  const [lo, hi] = [parseNumber(v.min), parseNumber(v.max)];
  if (typeof lo === 'number' && typeof hi === 'number' && lo > hi) out.max = 'The max is below the min.';
  return out;
}

const FIELDS: [key: string, label: string][] = [
  ['characteristic', 'Characteristic'],
  ['measured', 'Measured'],
  ['nominal', 'Nominal'],
  ['min', 'Min'],
  ['max', 'Max'],
  ['unit', 'Unit'],
  ['part', 'Part'],
  ['note', 'Note'],
];
const NUMBERS = ['measured', 'nominal', 'min', 'max'];

export function qualityForm(machine: string, recorded: (r: QualityRecord) => void): HTMLElement {
  const id = `q-${machine}`;
  const inputs = new Map<string, HTMLInputElement>();
  const hints = new Map<string, HTMLElement>();
  const said = status(`${id}-status`);
  const fields = FIELDS.map(([key, label]) => {
    const input = h('input', { autocomplete: 'off', inputmode: NUMBERS.includes(key) ? 'decimal' : undefined, required: key === 'characteristic' || key === 'measured', 'aria-describedby': `${id}-${key}-hint` });
    const hint = h('p', { class: 'field-error', id: `${id}-${key}-hint`, 'aria-live': 'polite' });
    inputs.set(key, input);
    hints.set(key, hint);
    const f = field(label, input, `${id}-${key}`);
    f.append(hint);
    return f;
  });
  const value = (k: string) => inputs.get(k)?.value ?? '';
  const button = h('button', { type: 'submit', text: 'Record' });
  // Marks each field's problem; the count of them.
  const check = (touched: Set<string>): number => {
    const p = problems({ characteristic: value('characteristic'), measured: value('measured'), nominal: value('nominal'), min: value('min'), max: value('max') });
    for (const [k, input] of inputs) {
      const why = touched.has(k) ? (p[k] ?? '') : '';
      (hints.get(k) as HTMLElement).textContent = why;
      if (why) input.setAttribute('aria-invalid', 'true');
      else input.removeAttribute('aria-invalid');
    }
    return Object.keys(p).length;
  };
  const touched = new Set<string>();
  const form = h('form', { class: 'quality-form', 'aria-label': `Record a quality measurement on ${machine}`, novalidate: true }, h('h4', { text: 'Record a measurement' }), h('div', { class: 'fields' }, ...fields), button, said);
  form.addEventListener('input', (e) => {
    const k = [...inputs].find(([, i]) => i === e.target)?.[0];
    if (k) touched.add(k);
    if (k === 'min') touched.add('max'); // min <= max is said at max
    check(touched);
  });
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    const all = new Set(inputs.keys());
    if (check(all)) {
      said.setAttribute('role', 'alert');
      said.textContent = 'Not recorded: see the fields marked.';
      form.querySelector<HTMLInputElement>('[aria-invalid="true"]')?.focus();
      return;
    }
    void send();
  });
  const send = async () => {
    const body: Record<string, string | number> = {};
    for (const k of inputs.keys()) {
      const v = value(k).trim();
      if (v === '') continue;
      body[k] = NUMBERS.includes(k) ? (parseNumber(v) as number) : v;
    }
    button.disabled = true;
    try {
      const r = await postJson<QualityRecord>(`/api/machines/${enc(machine)}/quality`, body);
      said.removeAttribute('role');
      said.textContent = `Recorded: ${r.characteristic} ${r.measured}${r.unit ? ` ${r.unit}` : ''}, ${r.ok === true ? 'OK' : r.ok === false ? 'NOT OK' : 'no limits'}.`;
      recorded(r);
      for (const k of ['measured', 'part', 'note']) (inputs.get(k) as HTMLInputElement).value = ''; // the next part, same limits
      touched.clear();
      check(touched);
      inputs.get('measured')?.focus();
    } catch (err) {
      said.setAttribute('role', 'alert');
      said.textContent = err instanceof ApiError ? `Refused (${err.status}): ${err.message}` : String(err);
    } finally {
      button.disabled = false;
    }
  };
  return form;
}
