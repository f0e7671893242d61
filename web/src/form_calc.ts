// The cutting calculator of `usina calc cutting` (seed 004, 7.4; src/sim/calc.hpp)
// as a small panel of the "New program" page: the spindle speed from the
// cutting speed and the tool diameter (7.1, N = 1000 v / (π D)), and the feed
// from the teeth and the chip load (7.2, f_r = N n_f f). "Use in the form"
// copies them into the cycle's Spindle speed and Feed fields.
import { field, h, status } from './dom';

function positive(input: HTMLInputElement): number | null {
  const v = Number(input.value);
  return input.value.trim() !== '' && Number.isFinite(v) && v > 0 ? v : null;
}

export function calculatorsPanel(): HTMLElement {
  const speed = h('input', { type: 'number', step: 'any', min: 0, inputmode: 'decimal' });
  const diameter = h('input', { type: 'number', step: 'any', min: 0, inputmode: 'decimal', value: 6 });
  const teeth = h('input', { type: 'number', step: 1, min: 1, inputmode: 'numeric' });
  const chip = h('input', { type: 'number', step: 'any', min: 0, inputmode: 'decimal' });
  const result = status('calc-result');
  const use = h('button', { type: 'button', text: 'Use in the form', disabled: true });
  let rpm = 0;
  let feed: number | null = null;
  const compute = () => {
    const v = positive(speed);
    const d = positive(diameter);
    const n = positive(teeth);
    const f = positive(chip);
    use.disabled = true;
    if (v === null || d === null) {
      result.textContent = 'Give the cutting speed and the tool diameter (above 0).';
      return;
    }
    rpm = (1000 * v) / (Math.PI * d);
    feed = n !== null && f !== null && Number.isInteger(n) ? rpm * n * f : null;
    result.textContent = `Spindle speed N = 1000 v / (π D) = ${rpm.toFixed(0)} rev/min` + (feed !== null ? `; feed f_r = N n_f f = ${feed.toFixed(0)} mm/min` : ' (give whole teeth and a chip load for the feed)');
    use.disabled = false;
  };
  use.addEventListener('click', () => {
    const set = (name: string, value: number) => {
      const input = document.querySelector<HTMLInputElement>(`.form-fields input[name="${name}"]`);
      if (!input) return;
      input.value = String(Math.round(value));
      input.dispatchEvent(new Event('input', { bubbles: true }));
    };
    set('rpm', rpm);
    if (feed !== null) set('feed', feed);
  });
  const form = h(
    'form',
    { class: 'card', 'aria-labelledby': 'calc-h' },
    h('h2', { id: 'calc-h', text: 'Cutting calculator (usina calc cutting)' }),
    field('Cutting speed v (m/min)', speed, 'calc-speed'),
    field('Tool diameter D (mm)', diameter, 'calc-diameter'),
    field('Teeth n_f (optional)', teeth, 'calc-teeth'),
    field('Chip load f (mm per tooth, optional)', chip, 'calc-chip'),
    result,
    use,
  );
  form.addEventListener('input', compute);
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    compute();
  });
  return form;
}
