// Zoom and pan of the drawing's picture (program_drawing.ts): the picture
// is drawn wider than its box, which scrolls. Buttons zoom in, out and back
// to the whole; the wheel over the picture zooms about the pointer; with the
// picture focused, + and - zoom, 0 shows the whole and the arrow keys pan
// (the box's own scrolling). The level is said in a live status line.
import { h } from './dom';

const STEP = 1.25;
const MAX = 32; // 32 × a 4096-pixel picture is about a pixel a screen pixel

export class DrawingZoom {
  readonly box = h('div', { class: 'drawing-zoom-box', tabindex: '0', role: 'group', 'aria-label': 'Drawing: + and - zoom, 0 shows it whole, the arrow keys move it' });
  readonly said = h('span', { class: 'drawing-zoom-level', 'aria-live': 'polite', text: 'Zoom 100 %' });
  readonly controls: HTMLElement;
  private level = 1;
  private base = 0; // the picture's width when whole, in CSS pixels

  constructor() {
    const button = (text: string, label: string, act: () => void) => {
      const b = h('button', { type: 'button', text, 'aria-label': label });
      b.addEventListener('click', act);
      return b;
    };
    this.controls = h(
      'div',
      { class: 'drawing-zoom', role: 'group', 'aria-label': 'Zoom of the drawing' },
      button('+', 'Zoom in', () => this.zoom(this.level * STEP)),
      button('−', 'Zoom out', () => this.zoom(this.level / STEP)),
      button('Whole', 'Show the whole drawing', () => this.zoom(1)),
      this.said,
    );
    this.box.addEventListener('keydown', (e) => this.key(e));
    this.box.addEventListener('wheel', (e) => this.wheel(e), { passive: false });
  }

  // A new picture: shown whole.
  show(img: HTMLImageElement): void {
    this.box.replaceChildren(img);
    this.zoom(1);
  }

  get percent(): number {
    return Math.round(this.level * 100);
  }

  // To `level`, keeping the point at (x, y) of the box (its centre by
  // default) where it is.
  zoom(level: number, x = this.box.clientWidth / 2, y = this.box.clientHeight / 2): void {
    const next = Math.min(MAX, Math.max(1, level));
    const ratio = next / this.level;
    const left = (this.box.scrollLeft + x) * ratio - x;
    const top = (this.box.scrollTop + y) * ratio - y;
    const img = this.box.querySelector('img');
    if (img && this.level === 1) this.base = img.getBoundingClientRect().width || this.box.clientWidth;
    this.level = next;
    this.box.classList.toggle('zoomed', next > 1);
    if (img) img.style.width = next > 1 ? `${Math.round(this.base * next)}px` : '';
    this.box.scrollLeft = left;
    this.box.scrollTop = top;
    this.said.textContent = `Zoom ${this.percent} %`;
  }

  private key(e: KeyboardEvent): void {
    if (e.key === '+' || e.key === '=') this.zoom(this.level * STEP);
    else if (e.key === '-' || e.key === '_') this.zoom(this.level / STEP);
    else if (e.key === '0') this.zoom(1);
    else return; // the arrow keys scroll the box
    e.preventDefault();
  }

  private wheel(e: WheelEvent): void {
    if (e.deltaY === 0) return;
    e.preventDefault();
    const r = this.box.getBoundingClientRect();
    this.zoom(e.deltaY < 0 ? this.level * STEP : this.level / STEP, e.clientX - r.left, e.clientY - r.top);
  }
}
