// The program's 2D drawing (usina draw's, made by the server: GET
// .../drawing, docs/web.md "The drawing"): the part view or the tool path
// as an SVG picture, with its layers named, and the SVG and DXF files to
// download. The SVG is shown as an <img> of an object URL, never put into
// the page as markup, so nothing in it can run.
import { ApiError, getFile } from './api';
import { field, h, status } from './dom';

type DrawingView = 'part' | 'toolpath';

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

export function drawingPanel(base: string, name: string, rev: string): HTMLElement {
  const view = h('select', {}, h('option', { value: 'part', text: 'Part: contour, holes, pockets' }), h('option', { value: 'toolpath', text: 'Tool path: every move by tool' }));
  const said = status('drawing-status');
  const picture = h('div', { class: 'drawing-picture', id: 'drawing' });
  const layers = h('div');
  const stem = `${name}-${rev.slice(0, 12)}`;
  const svgLink = h('a', { id: 'drawing-svg', download: `${stem}.svg`, text: 'Download SVG', hidden: true });
  const dxfLink = h('a', { id: 'drawing-dxf', href: '#', download: `${stem}.dxf`, text: 'Download DXF' });
  const urls: string[] = [];
  const objectUrl = (blob: Blob) => {
    const u = URL.createObjectURL(blob);
    urls.push(u);
    return u;
  };
  let asked = 0;
  let dxfView = '';
  const load = async () => {
    const n = ++asked;
    const v = view.value as DrawingView;
    said.textContent = 'Drawing…';
    said.removeAttribute('role');
    picture.setAttribute('aria-busy', 'true');
    try {
      const { blob, headers } = await getFile(`${base}/drawing?view=${v}&format=svg`);
      if (n !== asked) return;
      while (urls.length) URL.revokeObjectURL(urls.pop() as string);
      const src = objectUrl(blob);
      const found = layersOf(await blob.text());
      const img = h('img', { src, alt: `${v === 'part' ? 'Part drawing' : 'Tool path drawing'} of ${name} seen from above (layers ${found.map((l) => l.name).join(', ') || 'none'})` });
      picture.replaceChildren(img);
      layers.replaceChildren(legend(found));
      svgLink.href = src;
      svgLink.download = `${stem}-${v}.svg`;
      svgLink.hidden = false;
      dxfLink.href = '#';
      dxfLink.download = `${stem}-${v}.dxf`;
      dxfView = '';
      const note = noteOf(headers);
      const whole = headers.get('X-Drawing-Complete') !== 'false';
      said.textContent = whole ? `Drawn: ${found.length} layers.` : `Not all of it is drawn: ${note}`;
      if (!whole) said.setAttribute('role', 'alert');
    } catch (e) {
      if (n !== asked) return;
      picture.replaceChildren();
      layers.replaceChildren();
      svgLink.hidden = true;
      said.setAttribute('role', 'alert');
      said.textContent = e instanceof ApiError ? `No drawing (${e.status}): ${e.message}` : `No drawing: ${(e as Error).message}`;
    } finally {
      if (n === asked) picture.setAttribute('aria-busy', 'false');
    }
  };
  // The DXF is asked for on the first click of its link (a second run on the
  // server), then the link is the file.
  dxfLink.addEventListener('click', async (e) => {
    if (dxfView === view.value) return;
    e.preventDefault();
    const v = view.value;
    dxfLink.setAttribute('aria-busy', 'true');
    try {
      const { blob } = await getFile(`${base}/drawing?view=${v}&format=dxf`);
      dxfLink.href = objectUrl(blob);
      dxfView = v;
      dxfLink.click();
    } catch (err) {
      said.setAttribute('role', 'alert');
      said.textContent = `No DXF: ${(err as Error).message}`;
    } finally {
      dxfLink.setAttribute('aria-busy', 'false');
    }
  });
  view.addEventListener('change', () => void load());
  void load();
  return h(
    'section',
    { 'aria-labelledby': 'drawing-h', class: 'drawing-panel' },
    h('h2', { id: 'drawing-h', text: 'Drawing' }),
    h('div', { class: 'drawing-controls' }, field('Drawing view', view, 'drawing-view'), svgLink, dxfLink),
    said,
    picture,
    layers,
  );
}
