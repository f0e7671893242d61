// The program page's replay of the cut (issue 14): a time slider from the
// program's start to its end on the machine class's profile (the times the
// server puts on every vertex, as `usina stats` plans them), a Play button
// and a speed. The viewer draws the moves made by that time and the tool
// where it is; the line it cuts is named, and a drag of the slider marks
// that line in the text. At the slider's end the whole path is shown again.
import { field, h, status } from './dom';
import type { Toolpath } from './toolpath';
import type { Viewer } from './viewer';

// Seconds of the program a second of play, the smallest that plays the
// whole program in at most this long is chosen first.
const SPEEDS = [1, 10, 60, 600, 3600];
const PLAY_WHOLE_S = 30;
const STEPS = 2000; // the slider's positions: fine enough for a long program

// `atTime` hears every time the replay shows (the stock follows it).
export function replayPanel(viewer: Viewer, path: Toolpath, viewerHost: HTMLElement, markLine: (line: number) => void, atTime: (seconds: number) => void = () => {}): HTMLElement {
  const total = path.totalSeconds;
  const slider = h('input', { type: 'range', min: 0, max: STEPS, step: 1, value: STEPS, 'aria-valuetext': `${clock(total)}, the end` });
  const speed = h('select', {}, ...SPEEDS.map((s) => h('option', { value: s, text: `×${s}` })));
  speed.value = String(SPEEDS.find((s) => total / s <= PLAY_WHOLE_S) ?? SPEEDS[SPEEDS.length - 1]);
  const play = h('button', { type: 'button', text: 'Play', 'aria-pressed': 'false' });
  const said = status('replay-status');
  said.textContent = `The whole path: ${clock(total)} on the machine.`;
  const usable = path.count > 1 && total > 0;
  slider.toggleAttribute('disabled', !usable);
  play.toggleAttribute('disabled', !usable);
  let now = total;
  let frame: number | undefined;
  let last = 0;

  const to = (seconds: number, mark: boolean) => {
    now = Math.min(Math.max(seconds, 0), total);
    slider.value = String(Math.round((now / total) * STEPS));
    viewerHost.dataset.replayTime = now.toFixed(3);
    atTime(now);
    if (now >= total) {
      viewer.endReplay();
      viewerHost.dataset.replayVertex = String(path.count - 1);
      slider.setAttribute('aria-valuetext', `${clock(total)}, the end`);
      said.textContent = `The whole path: ${clock(total)} on the machine.`;
      return;
    }
    const { vertex } = viewer.replayTo(now);
    const line = path.lines[vertex];
    viewerHost.dataset.replayVertex = String(vertex);
    viewerHost.dataset.replayLine = String(line);
    slider.setAttribute('aria-valuetext', `${clock(now)}, line ${line}`);
    said.textContent = `${clock(now)} of ${clock(total)}: line ${line}`;
    if (mark) markLine(line);
  };
  const stop = () => {
    if (frame !== undefined) cancelAnimationFrame(frame);
    frame = undefined;
    play.textContent = 'Play';
    play.setAttribute('aria-pressed', 'false');
  };
  const tick = (t: number) => {
    const next = now + ((t - last) / 1000) * Number(speed.value);
    last = t;
    to(next, false);
    if (now >= total) {
      stop();
      return;
    }
    frame = requestAnimationFrame(tick);
  };
  play.addEventListener('click', () => {
    if (frame !== undefined) {
      stop();
      to(now, true);
      return;
    }
    if (now >= total) to(0, false);
    play.textContent = 'Pause';
    play.setAttribute('aria-pressed', 'true');
    last = performance.now();
    frame = requestAnimationFrame(tick);
  });
  slider.addEventListener('input', () => {
    stop();
    to((Number(slider.value) / STEPS) * total, true);
  });
  return h(
    'div',
    { class: 'replay-controls', role: 'group', 'aria-label': 'Replay of the cut' },
    field('Replay, time', slider, 'replay-time'),
    play,
    field('Speed', speed, 'replay-speed'),
    said,
  );
}

// 75.25 s: "1:15.3".
export function clock(seconds: number): string {
  const tenths = Math.round(seconds * 10);
  const h_ = Math.floor(tenths / 36000);
  const m = Math.floor((tenths % 36000) / 600);
  const s = ((tenths % 600) / 10).toFixed(1).padStart(4, '0');
  return h_ ? `${h_}:${String(m).padStart(2, '0')}:${s}` : `${m}:${s}`;
}
