// Seed 004's §7.5 calculators of an NC axis on the "New program" page: the
// open loop (stepper motor), the closed loop (servomotor and encoder) and
// the precision of an axis; and table 7.4's binary-coded decimal (how a
// number is punched on tape, digit by digit). The server computes them (POST /api/calc/NAME,
// `usina calc NAME --format json`), so the page and the command line give
// the same figures and the same messages. Filled with the seed's examples
// 7.1-7.3 (and 1250 for the BCD), answered as you type.
import { ApiError, postJson } from './api';
import { field, h, status } from './dom';

interface Input {
  key: string;
  label: string;
  value: number | string;
  text?: boolean; // sent as typed (a numeral's leading zeros are digits)
}

interface Calculator {
  name: string; // the route's and usina calc's
  title: string;
  inputs: Input[];
}

const PITCH = { key: 'pitch_mm', label: 'Screw pitch p (mm)', value: 6 };
const GEAR = { key: 'gear_ratio', label: 'Gear ratio r_g (motor rev per screw rev)', value: 5 };
const DISTANCE = { key: 'distance_mm', label: 'Distance x (mm)', value: 250 };
const FEED = { key: 'feed_mm_per_min', label: 'Feed f_r (mm/min)', value: 500 };

const CALCULATORS: Calculator[] = [
  { name: 'open-loop', title: 'Open loop: stepper motor (7.5.1)', inputs: [PITCH, GEAR, { key: 'steps_per_rev', label: 'Motor steps per revolution n_s', value: 48 }, DISTANCE, FEED] },
  { name: 'closed-loop', title: 'Closed loop: servomotor and encoder (7.5.2)', inputs: [PITCH, GEAR, { key: 'encoder_slots', label: 'Encoder slots n_s', value: 48 }, DISTANCE, FEED] },
  {
    name: 'precision',
    title: 'Precision of an axis (7.5.3)',
    inputs: [PITCH, GEAR, { key: 'steps_per_rev', label: 'Steps or slots per revolution n_s', value: 48 }, { key: 'travel_mm', label: 'Travel L (mm)', value: 1000 }, { key: 'bits', label: 'Register bits B', value: 16 }, { key: 'sigma_mm', label: 'Mechanical error σ (mm)', value: 0.005 }],
  },
  { name: 'bcd', title: 'Binary-coded decimal of a number (table 7.4)', inputs: [{ key: 'numeral', label: 'Whole number (digits, at most 19)', value: '1250', text: true }] },
];

// Each result in words, with its formula and unit (the seed's symbols).
const RESULTS: Record<string, [string, string]> = {
  step_angle_deg: ['Step angle α = 360 / n_s', '°'],
  slot_angle_deg: ['Slot angle α = 360 / n_s', '°'],
  screw_angle_deg: ['Screw angle A = 360 x / p', '°'],
  motor_angle_deg: ['Motor angle A_m = r_g A', '°'],
  pulses: ['Pulses n_p', 'pulses'],
  whole_pulses: ['Whole pulses (n_p rounded)', 'pulses'],
  distance_reached_mm: ['Distance of the whole pulses', 'mm'],
  screw_rpm: ['Screw speed N = f_r / p', 'rev/min'],
  motor_rpm: ['Motor speed N_m = r_g N', 'rev/min'],
  pulse_frequency_hz: ['Pulse frequency f_p', 'Hz'],
  cr1_mm: ['Resolution of the mechanics CR₁ = p / (n_s r_g)', 'mm'],
  cr2_mm: ['Resolution of the register CR₂ = L / (2^B − 1)', 'mm'],
  control_resolution_mm: ['Control resolution CR = max(CR₁, CR₂)', 'mm'],
  limited_by: ['Limited by', ''],
  accuracy_mm: ['Accuracy CR / 2 + 3σ', 'mm'],
  repeatability_mm: ['Repeatability ± 3σ', 'mm'],
  value: ['Value (the sum of the digits\' place values)', ''],
  code: ['BCD code, four bits a digit', ''],
};

interface BcdDigit {
  digit: number;
  bits: string;
  place_value: number;
}

// A result's rows: one per figure, and one per digit of a BCD code.
function rows(results: Record<string, unknown>): HTMLElement[] {
  return Object.entries(results).flatMap(([k, v]) => {
    if (k === 'digits' && Array.isArray(v)) {
      return (v as BcdDigit[]).map((d, i) => h('tr', { 'data-result': `digit-${i}` }, h('th', { scope: 'row', text: `Digit ${d.digit}` }), h('td', { text: d.bits }), h('td', { text: `× 10^${v.length - 1 - i}` })));
    }
    return [h('tr', { 'data-result': k }, h('th', { scope: 'row', text: RESULTS[k]?.[0] ?? k }), h('td', { text: figure(v) }), h('td', { text: RESULTS[k]?.[1] ?? '' }))];
  });
}

function figure(v: unknown): string {
  return typeof v === 'number' ? String(Number(v.toPrecision(6))) : String(v);
}

export function positioningPanel(): HTMLElement {
  const which = h('select', {}, ...CALCULATORS.map((c) => h('option', { value: c.name, text: c.title })));
  const fields = h('div', { class: 'calc-inputs' });
  const said = status('positioning-status');
  const table = h('table', { class: 'calc-results', 'aria-label': 'Results of the axis calculator' });
  let inputs: { input: Input; control: HTMLInputElement }[] = [];
  let asked = 0;
  let timer = 0;

  const compute = async () => {
    const n = ++asked;
    const c = CALCULATORS.find((x) => x.name === which.value) as Calculator;
    const body: Record<string, number | string> = {};
    for (const { input, control } of inputs) if (control.value.trim() !== '') body[input.key] = input.text ? control.value.trim() : Number(control.value);
    try {
      const r = await postJson<{ results: Record<string, unknown> }>(`/api/calc/${c.name}`, body);
      if (n !== asked) return;
      said.removeAttribute('role');
      said.textContent = `${c.title}: computed by the server (usina calc ${c.name}).`;
      table.replaceChildren(...rows(r.results));
    } catch (e) {
      if (n !== asked) return;
      table.replaceChildren();
      said.setAttribute('role', 'alert');
      said.textContent = e instanceof ApiError ? e.message : String(e);
    }
  };
  const soon = () => {
    window.clearTimeout(timer);
    timer = window.setTimeout(() => void compute(), 200);
  };
  const build = () => {
    const c = CALCULATORS.find((x) => x.name === which.value) as Calculator;
    inputs = c.inputs.map((input) => ({ input, control: input.text ? h('input', { type: 'text', inputmode: 'numeric', value: input.value, name: input.key, autocomplete: 'off' }) : h('input', { type: 'number', step: 'any', inputmode: 'decimal', value: input.value, name: input.key }) }));
    fields.replaceChildren(...inputs.map(({ input, control }) => field(input.label, control, `axis-${input.key}`)));
    void compute();
  };
  which.addEventListener('change', build);
  fields.addEventListener('input', soon);
  const form = h('form', { class: 'card', 'aria-labelledby': 'axis-calc-h' }, h('h2', { id: 'axis-calc-h', text: 'Axis calculators (usina calc)' }), field('Calculator', which, 'axis-calculator'), fields, said, table);
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    void compute();
  });
  build();
  return form;
}
