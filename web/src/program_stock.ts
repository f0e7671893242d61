// The program page's stock (issue 17): a "Stock" toggle asks the server to
// simulate the revision on its stock (the program's own box), shows it as a
// shaded mesh with or instead of the tool path, coloured by depth or by the
// tool that cut last, and replays the removal frame by frame with a slider
// and a play button (every control a labelled form control: the keyboard
// drives them all). The replay of the cut in time moves it too.
import { getBytes } from './api';
import { field, h, status } from './dom';
import { StockMesh, StockReplay, type StockColour } from './stock';
import type { Viewer } from './viewer';

// A replay lasts about this long a frame on average; each frame is shown
// for its share of the program's time (at least MIN_STEP_MS).
const PLAY_STEP_MS = 400;
const MIN_STEP_MS = 60;

export interface StockPanel {
  element: HTMLElement;
  // The replay of the cut moved to `seconds`: the stock shown, when it is,
  // as the frames made by then leave it (program_replay.ts).
  atTime(seconds: number): void;
}

export function stockPanel(viewer: Viewer, base: string, viewerHost: HTMLElement): StockPanel {
  const show = h('input', { type: 'checkbox' });
  const path = h('input', { type: 'checkbox', checked: true });
  const colour = h('select', {}, h('option', { value: 'depth', text: 'depth' }), h('option', { value: 'tool', text: 'the tool that cut last' }));
  const slider = h('input', { type: 'range', min: 0, max: 0, step: 1, value: 0, disabled: true });
  const play = h('button', { type: 'button', text: 'Play', 'aria-pressed': 'false', disabled: true });
  const said = status('stock-status');
  const controls = h('div', { class: 'stock-replay', hidden: true }, field('Colour the stock by', colour, 'stock-colour'), field('Removal, frame', slider, 'stock-frame'), play);
  const panel = h(
    'div',
    { class: 'stock-controls', role: 'group', 'aria-label': 'Stock' },
    h('div', { class: 'field check' }, show, h('label', { for: 'stock-show', text: 'Stock' })),
    h('div', { class: 'field check' }, path, h('label', { for: 'stock-path', text: 'Tool path' })),
    controls,
    said,
  );
  show.id = 'stock-show';
  path.id = 'stock-path';
  let replay: StockReplay | null = null;
  let mesh: StockMesh | null = null;
  let timer: number | undefined;

  const frameTo = (n: number) => {
    if (!replay || !mesh) return;
    replay.seek(n);
    mesh.update();
    viewer.render();
    slider.value = String(n);
    viewerHost.dataset.stockFrame = String(n);
    said.textContent = describe(replay, n);
  };
  const stop = () => {
    window.clearTimeout(timer);
    timer = undefined;
    play.textContent = 'Play';
    play.setAttribute('aria-pressed', 'false');
  };
  const load = async () => {
    said.textContent = 'Simulating the stock…';
    replay = new StockReplay(await getBytes(`${base}/stock`));
    mesh = new StockMesh(replay);
    slider.max = String(replay.frames);
    slider.disabled = play.disabled = false;
    controls.hidden = false;
    viewerHost.dataset.stockFrames = String(replay.frames);
  };
  show.addEventListener('change', () => {
    void (async () => {
      if (!show.checked) {
        stop();
        viewer.setStock(null);
        controls.hidden = true;
        said.textContent = '';
        return;
      }
      if (!replay) await load();
      controls.hidden = false;
      viewer.setStock(mesh!.object);
      frameTo(replay!.frames);
    })().catch((e: Error) => {
      show.checked = false;
      said.textContent = `The stock could not be simulated: ${e.message}`;
    });
  });
  path.addEventListener('change', () => viewer.showPath(path.checked));
  colour.addEventListener('change', () => {
    if (!mesh) return;
    mesh.colour = colour.value as StockColour;
    frameTo(Number(slider.value));
  });
  slider.addEventListener('input', () => frameTo(Number(slider.value)));
  play.addEventListener('click', () => {
    if (timer !== undefined || !replay) return stop();
    if (Number(slider.value) >= replay.frames) frameTo(0);
    play.textContent = 'Pause';
    play.setAttribute('aria-pressed', 'true');
    const step = () => {
      const next = Number(slider.value) + 1;
      if (!replay || next > replay.frames) return stop();
      timer = window.setTimeout(() => {
        frameTo(next);
        step();
      }, stepMs(replay, next));
    };
    step();
  });
  const atTime = (seconds: number) => {
    if (!replay || !show.checked) return;
    stop();
    frameTo(framesBy(replay, seconds));
  };
  return { element: panel, atTime };
}

// How many frames are done by `seconds` of the program (each frame's time
// is when its last move ends).
export function framesBy(r: StockReplay, seconds: number): number {
  const f = r.header.frames;
  let lo = 0;
  let hi = Math.min(f.length, r.frames);
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (f[mid].time_s <= seconds) lo = mid + 1;
    else hi = mid;
  }
  return seconds >= r.header.time_s ? r.frames : lo;
}

// How long frame n stays before the next: its share of the program's time.
function stepMs(r: StockReplay, n: number): number {
  const h = r.header;
  const total = h.time_s;
  if (!(total > 0) || n < 1) return PLAY_STEP_MS;
  const before = n >= 2 ? h.frames[n - 2].time_s : 0;
  const share = (h.frames[n - 1].time_s - before) / total;
  return Math.max(MIN_STEP_MS, Math.round(share * PLAY_STEP_MS * r.frames));
}

// 754.5 s → "12:34.5".
function clock(s: number): string {
  const m = Math.floor(s / 60);
  return `${m}:${(s - m * 60).toFixed(1).padStart(4, '0')}`;
}

function describe(r: StockReplay, n: number): string {
  const h = r.header;
  if (n === 0) return `Frame 0 of ${r.frames}: the stock uncut (${h.stock.box.join(' × ')} mm).`;
  const f = h.frames[n - 1];
  return `Frame ${n} of ${r.frames}: ${f.moves} of ${h.moves} moves, line ${f.line}, at ${clock(f.time_s)} of ${clock(h.time_s)}, ${f.removed_mm3.toFixed(1)} mm³ removed.`;
}
