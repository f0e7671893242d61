// The fields of a machine's settings (the keys of a [[machine]] table,
// docs/dnc-links.md), with the file's defaults and ranges: the admin's
// machines page builds its form from them. The server checks them again.
import { h } from './dom';

export type Settings = Record<string, string | number | boolean | null | undefined>;

export interface SettingSpec {
  key: string;
  label: string;
  kind: 'text' | 'number' | 'choice' | 'boolean';
  initial?: string | number | boolean; // what a new machine's form starts with
  choices?: string[];
  min?: number;
  max?: number;
  step?: number;
  required?: boolean;
  hint?: string;
  more?: boolean; // under "More settings"
  numeric?: boolean; // a choice of numbers: sent as a number
}

const BAUDS = ['110', '300', '600', '1200', '2400', '4800', '9600', '19200', '38400', '57600', '115200'];

export const SETTINGS: SettingSpec[] = [
  { key: 'name', label: 'Name', kind: 'text', required: true, hint: "letters, digits, - _ . (it is part of the API's routes)" },
  { key: 'port', label: 'Port', kind: 'text', required: true, hint: 'a serial device (/dev/ttyS0), tcp://host:port or tcp-listen://host:port' },
  { key: 'dialect', label: 'Dialect', kind: 'choice', choices: ['rs274ngc', 'fanuc', 'grbl', 'romi'], initial: 'rs274ngc' },
  { key: 'machine_class', label: 'Machine class', kind: 'text', hint: 'empty: programs of any class' },
  { key: 'mode', label: 'Mode', kind: 'choice', choices: ['production', 'tryout'], initial: 'production', hint: 'production takes released revisions; tryout approved ones too' },
  { key: 'baud', numeric: true, label: 'Baud', kind: 'choice', choices: BAUDS, initial: '9600' },
  { key: 'data_bits', numeric: true, label: 'Data bits', kind: 'choice', choices: ['7', '8'], initial: '7' },
  { key: 'parity', label: 'Parity', kind: 'choice', choices: ['none', 'even', 'odd'], initial: 'even' },
  { key: 'stop_bits', numeric: true, label: 'Stop bits', kind: 'choice', choices: ['1', '2'], initial: '2' },
  { key: 'flow', label: 'Flow control', kind: 'choice', choices: ['none', 'xonxoff', 'rtscts', 'dtrdsr'], initial: 'xonxoff' },
  { key: 'code', label: 'Tape code', kind: 'choice', choices: ['ascii', 'iso', 'eia'], initial: 'iso' },
  { key: 'eob', label: 'End of block', kind: 'choice', choices: ['lf', 'crlf', 'cr', 'semicolon', 'hash'], initial: 'lf' },
  { key: 'skid', label: 'Skid (bytes after XOFF)', kind: 'number', min: 1, max: 65536, more: true },
  { key: 'xon', label: 'XON byte', kind: 'number', min: 0, max: 255, more: true },
  { key: 'xoff', label: 'XOFF byte', kind: 'number', min: 0, max: 255, more: true },
  { key: 'leader', label: 'Leader (NULs before)', kind: 'number', min: 0, max: 10000, more: true },
  { key: 'trailer', label: 'Trailer (NULs after)', kind: 'number', min: 0, max: 10000, more: true },
  { key: 'wait_for_xon', label: 'Wait for the first XON', kind: 'boolean', initial: false, more: true },
  { key: 'xon_timeout', label: 'XON timeout (s)', kind: 'number', min: 1, max: 86400, step: 0.1, more: true },
  { key: 'receive_idle', label: 'Receive idle (s)', kind: 'number', min: 0.1, max: 3600, step: 0.1, more: true },
  { key: 'request_program', label: 'Remote request O number', kind: 'number', min: 0, max: 99999999, more: true },
  { key: 'request_lines', label: 'Lines scanned for a request', kind: 'number', min: 1, max: 1000, more: true },
  { key: 'part_count_pattern', label: 'Part count pattern', kind: 'text', more: true, hint: 'a regular expression; empty: the default' },
  { key: 'cycle_time_pattern', label: 'Cycle time pattern', kind: 'text', more: true, hint: 'a regular expression; empty: the default' },
];

// A labelled control for `f`, its hint tied to it (aria-describedby).
export function settingField(f: SettingSpec): { wrapper: HTMLElement; control: HTMLInputElement | HTMLSelectElement } {
  const id = `machine-${f.key.replace(/_/g, '-')}`;
  let control: HTMLInputElement | HTMLSelectElement;
  if (f.kind === 'choice') {
    control = h('select', {}, ...(f.choices ?? []).map((c) => h('option', { value: c, text: c })));
  } else if (f.kind === 'boolean') {
    control = h('input', { type: 'checkbox' });
  } else {
    control = h('input', { type: f.kind === 'number' ? 'number' : 'text', autocomplete: 'off', min: f.min, max: f.max, step: f.step ?? (f.kind === 'number' ? 1 : undefined), required: f.required });
  }
  control.id = id;
  const hint = f.hint ? h('span', { class: 'hint', id: `${id}-hint`, text: f.hint }) : null;
  if (hint) control.setAttribute('aria-describedby', hint.id);
  const wrapper = h('div', { class: f.kind === 'boolean' ? 'field check' : 'field' }, h('label', { for: id, text: f.label }), control, hint);
  return { wrapper, control };
}
