// A program: its text with line numbers and the check's diagnostics inline,
// the 3D viewer of its tool path (a click on a move shows its line; a
// line's moves can be highlighted; the cut replays in time), its 2D
// drawing and its setup sheets.
import { enc, getBytes, getJson, getText, type CheckDiagnostic, type Program, type Revision } from './api';
import { field, h, show, status } from './dom';
import { drawingPanel } from './program_drawing';
import { replayPanel } from './program_replay';
import { sheetsPanel } from './program_sheets';
import { reviewPanel, revisionsPanel } from './program_review';
import { statsPanel, type Figures } from './program_stats';
import { stockPanel } from './program_stock';
import { sessionUser } from './roles';
import { decodeToolpath, Kind, nearestLine } from './toolpath';
import { toolColour, Viewer, type View } from './viewer';

// Lines shown in the text panel; a longer program shows its start (the
// viewer still has every move).
const MAX_LINES = 20000;

export async function programPage(main: HTMLElement, name: string, rev?: string): Promise<void> {
  const [program, who] = await Promise.all([getJson<Program>(`/api/programs/${enc(name)}`), sessionUser()]);
  const revision = program.revisions.find((r) => r.revision === rev) ?? program.revisions[0];
  if (!revision) throw new Error(`${name} has no revisions`);
  const base = `/api/programs/${enc(name)}/revisions/${revision.revision}`;
  // The stream is asked for first: the picture is what the shop looks at
  // first. The server computes it on its pool (or has it cached), so the
  // text is read meanwhile and fills in after.
  const stream = getBytes(`${base}/toolpath`);
  const text = getText(`${base}/text`);
  const picked = status('picked-line');
  const code = codePanel(revision.checks?.diagnostics ?? []);
  const viewerHost = h('div', { class: 'viewer', id: 'viewer' }, h('p', { class: 'status', text: 'Loading the tool path…' }));
  const statsHost = h('p', { class: 'status', text: 'The figures follow the tool path…' });
  const split = h('div', { class: 'split' }, h('section', { 'aria-labelledby': 'code-h', class: 'code-panel' }, h('h2', { id: 'code-h', text: 'Text' }), diagnosticList(revision, (line) => code.onSelect(line)), code.element), h('section', { 'aria-labelledby': 'view-h' }, h('h2', { id: 'view-h', text: 'Tool path' }), viewerHost, picked));
  const again = () => void programPage(main, name, revision.revision).catch((e) => console.error(e));
  show(
    main,
    `Program ${program.name}`,
    summary(program, revision),
    reviewPanel(program, revision, who, again),
    split,
    statsHost,
    sheetsPanel(program.name, revision.revision, who),
    revisionsPanel(program, revision),
  );
  const path = decodeToolpath(await stream);
  viewerHost.replaceChildren();
  const viewer = new Viewer(viewerHost);
  viewer.load(path);
  // The drawing after the 3D picture, which the shop looks at first. A click
  // on it picks the move within 6 pixels there, as a click in the viewer does.
  const drawingClick = (x: number, y: number, pixel: number) => {
    const line = nearestLine(path, x, y, 6 * pixel);
    if (line !== null) select(line);
    else picked.textContent = `No move within ${(6 * pixel).toPrecision(2)} mm of X${x.toFixed(2)} Y${y.toFixed(2)}`;
  };
  split.append(drawingPanel(base, program.name, revision.revision, drawingClick));
  void getJson<Figures>(`${base}/tools`).then(
    (f) => statsHost.replaceWith(statsPanel(revision.checks, f)),
    (e: Error) => statsHost.replaceWith(statsPanel(revision.checks, e.message)),
  );
  const select = (line: number) => {
    const moves = viewer.highlightLine(line);
    code.mark(line);
    picked.textContent = `Line ${line}: ${moves} ${moves === 1 ? 'move' : 'moves'} highlighted`;
  };
  const feedTools: number[] = [];
  for (let i = 1; i < path.count; i++) if (path.kinds[i] !== Kind.Rapid) feedTools.push(path.tools[i]);
  const stock = stockPanel(viewer, base, viewerHost);
  viewerHost.before(viewControls(viewer, feedTools, select, picked), stock.element);
  viewerHost.after(replayPanel(viewer, path, viewerHost, (line) => code.mark(line, false), (s) => stock.atTime(s)));
  viewer.onPick = select;
  code.onSelect = select;
  viewerHost.dataset.vertices = String(path.count);
  viewerHost.dataset.moves = String(path.moves);
  if (path.decimated) picked.textContent = `${path.moves} moves, shown as ${path.count} points`;
  code.fill(await text);
}

function summary(p: Program, r: Revision): HTMLElement {
  const c = r.checks;
  const items: [string, string][] = [
    ['Revision', r.revision.slice(0, 12)],
    ['State', r.state],
    ['Dialect', p.dialect],
    ['Author', r.author],
    ['Check', c ? `${c.errors} errors, ${c.warnings} warnings` : 'not checked'],
    ['Cycle time', c ? `${c.cycle_time_s.toFixed(1)} s` : '—'],
  ];
  return h('dl', { class: 'summary' }, ...items.flatMap(([k, v]) => [h('dt', { text: k }), h('dd', { text: v })]));
}

// The diagnostics above the text, each a link to its line (and its moves).
function diagnosticList(r: Revision, select: (line: number) => void): HTMLElement {
  const d = r.checks?.diagnostics ?? [];
  if (!d.length) return h('p', { class: 'ok', text: 'The check found nothing to report.' });
  const list = h(
    'ul',
    { class: 'diag-list', 'aria-label': 'Diagnostics' },
    ...d.map((x) => h('li', { class: x.severity }, h('a', { href: `#L${x.line}`, 'data-line': x.line, text: `line ${x.line}: ${x.code}` }), ` ${x.message}`)),
  );
  list.addEventListener('click', (e) => {
    const a = (e.target as HTMLElement).closest('a[data-line]') as HTMLElement | null;
    if (!a) return;
    e.preventDefault(); // the page's routes are in the hash: stay on this one
    select(Number(a.dataset.line));
  });
  return list;
}

// The first `max` lines of `text` and its count of lines, without making a
// string of every line of a long program.
function firstLines(text: string, max: number): { lines: string[]; total: number } {
  const lines: string[] = [];
  let total = 0;
  let at = 0;
  while (at < text.length) {
    let end = at;
    while (end < text.length && text[end] !== '\n' && text[end] !== '\r') end++;
    if (lines.length < max) lines.push(text.slice(at, end));
    total++;
    at = end + (text.startsWith('\r\n', end) ? 2 : 1);
  }
  return { lines, total };
}

interface CodePanel {
  element: HTMLElement;
  fill(text: string): void;
  // Marks the line; scrolls the page to it too unless `page` is false (the
  // text panel alone scrolls: a replay's slider stays under the pointer).
  mark(line: number, page?: boolean): void;
  onSelect: (line: number) => void;
}

function codePanel(diags: CheckDiagnostic[]): CodePanel {
  const byLine = new Map<number, CheckDiagnostic[]>();
  for (const d of diags) byLine.set(d.line, [...(byLine.get(d.line) ?? []), d]);
  const list = h('ol', { class: 'code', 'aria-label': 'Program text' });
  const note = h('p', { class: 'status', text: 'Loading the text…' });
  const panel: CodePanel = {
    element: h('div', { class: 'code-scroll' }, list, note),
    fill(text: string) {
      const { lines, total } = firstLines(text, MAX_LINES);
      const shown = lines.length;
      const items = document.createDocumentFragment();
      for (let i = 0; i < shown; i++) {
        const n = i + 1;
        const li = h('li', { id: `L${n}`, 'data-line': n }, h('span', { class: 'ln', 'aria-hidden': 'true', text: String(n) }), h('code', { text: lines[i] }));
        for (const d of byLine.get(n) ?? []) {
          li.classList.add(`has-${d.severity}`);
          li.append(h('div', { class: `diag ${d.severity}`, role: 'note' }, h('strong', { text: d.code }), ` ${d.message}`));
        }
        items.append(li);
      }
      list.replaceChildren(items);
      note.textContent = shown < total ? `The first ${shown} of ${total} lines are shown.` : '';
    },
    mark(line: number, page = true) {
      list.querySelector('.selected')?.classList.remove('selected');
      const li = document.getElementById(`L${line}`);
      if (!li) return;
      li.classList.add('selected');
      if (page) {
        li.scrollIntoView({ block: 'center' });
        return;
      }
      const box = panel.element;
      box.scrollTop += li.getBoundingClientRect().top - box.getBoundingClientRect().top - box.clientHeight / 2;
    },
    onSelect: () => {},
  };
  // A click on a line of the text, or on a diagnostic's link above it.
  const pickFrom = (e: Event) => {
    const t = (e.target as HTMLElement).closest('[data-line]') as HTMLElement | null;
    if (!t) return;
    e.preventDefault();
    panel.onSelect(Number(t.dataset.line));
  };
  list.addEventListener('click', pickFrom);
  return panel;
}

function viewControls(viewer: Viewer, feedTools: number[], select: (line: number) => void, picked: HTMLElement): HTMLElement {
  const views: [View, string][] = [
    ['top', 'Top'],
    ['front', 'Front'],
    ['side', 'Side'],
    ['iso', 'Iso'],
  ];
  const line = h('input', { type: 'number', min: 1, inputmode: 'numeric' });
  const go = h('form', { class: 'goto' }, field('Highlight the moves of line', line, 'goto-line'), h('button', { type: 'submit', text: 'Highlight' }));
  go.addEventListener('submit', (e) => {
    e.preventDefault();
    const n = Number(line.value);
    if (Number.isInteger(n) && n > 0) select(n);
    else picked.textContent = 'Give a line number.';
  });
  const used = [...new Set(feedTools)].sort((a, b) => a - b);
  const legend = h(
    'ul',
    { class: 'legend', 'aria-label': 'Legend' },
    h('li', {}, h('span', { class: 'swatch rapid', 'aria-hidden': 'true' }), 'rapid (dashed)'),
    ...used.map((t) => {
      const sw = h('span', { class: 'swatch', 'aria-hidden': 'true' });
      sw.style.background = `#${toolColour(t).toString(16).padStart(6, '0')}`;
      return h('li', {}, sw, t ? `feed, tool T${t}` : 'feed, no tool');
    }),
  );
  return h(
    'div',
    { class: 'view-controls' },
    h('div', { role: 'group', 'aria-label': 'Standard views' }, ...views.map(([v, label]) => {
      const b = h('button', { type: 'button', text: label, 'aria-label': `${label} view` });
      b.addEventListener('click', () => viewer.setView(v));
      return b;
    })),
    go,
    legend,
  );
}
