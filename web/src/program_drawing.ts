// The program's 2D drawing (usina draw's, made by the server: GET
// .../drawing, docs/web.md "The drawing"): the part view or the tool path
// as an SVG picture, with its layers named, and the SVG and DXF files to
// download. The SVG is shown as an <img> of an object URL, never put into
// the page as markup, so nothing in it can run. It zooms and pans
// (drawing_zoom.ts).
import { ApiError, getFile } from './api';
import { field, h, status } from './dom';
import { DrawingZoom } from './drawing_zoom';

type DrawingView = 'part' | 'toolpath';

// Where a click on the drawing is, in the program's millimetres (y up), and
// how far a pixel reaches there: the page names the move's line.
export type DrawingClick = (x: number, y: number, pixel: number) => void;

interface ViewBox {
  x: number;
  y: number;
  w: number;
  h: number;
}

// The SVG's viewBox ("minx -maxy width height": y is written negated).
function viewBoxOf(svg: string): ViewBox | null {
  const m = /<svg [^>]*viewBox="([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)"/.exec(svg);
  if (!m) return null;
  const [x, y, w, h] = m.slice(1).map(Number);
  return [x, y, w, h].every(Number.isFinite) && w > 0 && h > 0 ? { x, y, w, h } : null;
}

interface Layer {
  name: string;
  colour: string;
  dashed: boolean;
}

// The layers of the server's SVG (its <g id="NAME" ... stroke="#rrggbb">),
// read as text for the legend; only names and colours of the expected form.
function layersOf(svg: string): Layer[] {
  const out: Layer[] = [];
  for (const m of svg.matchAll(/<g id="([A-Z0-9_]{1,40})"[^>]*?stroke="(#[0-9a-fA-F]{6})"([^>]*)>/g))
    out.push({ name: m[1], colour: m[2], dashed: m[3].includes('stroke-dasharray') });
  return out;
}

function legend(layers: Layer[]): HTMLElement {
  return h(
    'ul',
    { class: 'legend drawing-layers', 'aria-label': 'Layers of the drawing' },
    ...layers.map((l) => {
      const sw = h('span', { class: `swatch${l.dashed ? ' dashed' : ''}`, 'aria-hidden': 'true' });
      if (l.dashed) sw.style.borderTopColor = l.colour;
      else sw.style.background = l.colour;
      return h('li', { 'data-layer': l.name }, sw, l.dashed ? `${l.name} (dashed)` : l.name);
    }),
  );
}

// The note of a drawing that is not whole (its header is %-encoded).
function noteOf(headers: Headers): string {
  const note = headers.get('X-Drawing-Note');
  if (!note) return '';
  try {
    return decodeURIComponent(note);
  } catch {
    return note;
  }
}

// The panel's parts and its one drawing in flight at a time.
class DrawingPanel {
  readonly view = h('select', {}, h('option', { value: 'part', text: 'Part: contour, holes, pockets' }), h('option', { value: 'toolpath', text: 'Tool path: every move by tool' }));
  readonly said = status('drawing-status');
  readonly picture = h('div', { class: 'drawing-picture', id: 'drawing' });
  readonly zoom = new DrawingZoom();
  readonly layers = h('div');
  readonly svgLink = h('a', { id: 'drawing-svg', text: 'Download SVG', hidden: true });
  readonly dxfLink = h('a', { id: 'drawing-dxf', href: '#', text: 'Download DXF' });
  private urls: string[] = []; // the object URLs of the view shown
  private asked = 0; // the newest request: older answers are dropped
  private dxfView = ''; // the view whose DXF the link holds

  constructor(
    private readonly base: string,
    private readonly name: string,
    private readonly stem: string, // NAME-REV12
    private readonly onClick?: DrawingClick,
  ) {}

  private objectUrl(blob: Blob): string {
    const u = URL.createObjectURL(blob);
    this.urls.push(u);
    return u;
  }

  private alert(text: string): void {
    this.said.setAttribute('role', 'alert');
    this.said.textContent = text;
  }

  async load(): Promise<void> {
    const n = ++this.asked;
    const v = this.view.value as DrawingView;
    this.said.textContent = 'Drawing…';
    this.said.removeAttribute('role');
    this.picture.setAttribute('aria-busy', 'true');
    try {
      const { blob, headers } = await getFile(`${this.base}/drawing?view=${v}&format=svg`);
      const svg = await blob.text();
      if (n === this.asked) this.show(v, blob, layersOf(svg), headers, viewBoxOf(svg));
    } catch (e) {
      if (n !== this.asked) return;
      this.picture.replaceChildren();
      this.layers.replaceChildren();
      this.svgLink.hidden = true;
      this.alert(e instanceof ApiError ? `No drawing (${e.status}): ${e.message}` : `No drawing: ${(e as Error).message}`);
    } finally {
      if (n === this.asked) this.picture.setAttribute('aria-busy', 'false');
    }
  }

  private show(v: DrawingView, blob: Blob, found: Layer[], headers: Headers, box: ViewBox | null): void {
    while (this.urls.length) URL.revokeObjectURL(this.urls.pop() as string);
    const src = this.objectUrl(blob);
    const what = v === 'part' ? 'Part drawing' : 'Tool path drawing';
    const img = h('img', { src, alt: `${what} of ${this.name} seen from above (layers ${found.map((l) => l.name).join(', ') || 'none'}); a click names the line of the move there` });
    const onClick = this.onClick;
    if (box && onClick) {
      img.addEventListener('click', (e) => {
        const r = img.getBoundingClientRect();
        if (r.width <= 0 || r.height <= 0) return;
        const x = box.x + ((e.clientX - r.left) / r.width) * box.w;
        const y = -(box.y + ((e.clientY - r.top) / r.height) * box.h);
        onClick(x, y, box.w / r.width);
      });
    }
    this.zoom.show(img);
    this.picture.replaceChildren(this.zoom.controls, this.zoom.box);
    this.layers.replaceChildren(legend(found));
    this.svgLink.href = src;
    this.svgLink.download = `${this.stem}-${v}.svg`;
    this.svgLink.hidden = false;
    this.dxfLink.href = '#';
    this.dxfLink.download = `${this.stem}-${v}.dxf`;
    this.dxfView = '';
    if (headers.get('X-Drawing-Complete') === 'false') this.alert(`Not all of it is drawn: ${noteOf(headers)}`);
    else this.said.textContent = `Drawn: ${found.length} layers.`;
  }

  // The DXF is asked for on the first click of its link (a second run on the
  // server), then the link is the file and is clicked again.
  async dxf(e: Event): Promise<void> {
    const v = this.view.value;
    if (this.dxfView === v) return;
    e.preventDefault();
    this.dxfLink.setAttribute('aria-busy', 'true');
    try {
      const { blob } = await getFile(`${this.base}/drawing?view=${v}&format=dxf`);
      this.dxfLink.href = this.objectUrl(blob);
      this.dxfView = v;
      this.dxfLink.click();
    } catch (err) {
      this.alert(`No DXF: ${(err as Error).message}`);
    } finally {
      this.dxfLink.setAttribute('aria-busy', 'false');
    }
  }
}

export function drawingPanel(base: string, name: string, rev: string, onClick?: DrawingClick): HTMLElement {
  const p = new DrawingPanel(base, name, `${name}-${rev.slice(0, 12)}`, onClick);
  p.dxfLink.addEventListener('click', (e) => void p.dxf(e));
  p.view.addEventListener('change', () => void p.load());
  void p.load();
  return h(
    'section',
    { 'aria-labelledby': 'drawing-h', class: 'drawing-panel' },
    h('h2', { id: 'drawing-h', text: 'Drawing' }),
    h('div', { class: 'drawing-controls' }, field('Drawing view', p.view, 'drawing-view'), p.svgLink, p.dxfLink),
    p.said,
    p.picture,
    p.layers,
  );
}
