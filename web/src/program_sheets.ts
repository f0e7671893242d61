// The revision's setup sheets (docs/dnc-server.md, "Setup sheets"): each
// listed with its format, size, author and date, shown in the page and
// downloaded as a file. The API wants the login's bearer token, which a
// frame's request does not carry: to show a sheet the page asks the server
// for a signed link good for a few minutes (POST .../sheet/link) and opens
// it in a frame. An HTML sheet is someone's upload: its frame is sandboxed
// (no script, an origin of its own), as the server's CSP sandbox makes it
// too. A download is fetched with the token and handed over as an object
// URL, an HTML sheet as a file of no type a browser renders. Who may upload
// a revision attaches a sheet.
import { ApiError, enc, getFile, getJson, postJson } from './api';
import { field, h, status } from './dom';
import { mayUpload, type SessionUser } from './roles';

export interface Sheet {
  format: string; // html | pdf
  sheet: string; // SHA-256 of the bytes
  size: number;
  author: string;
  created_at_us: number;
}

function when(us: number): string {
  return new Date(us / 1000).toISOString().replace('T', ' ').slice(0, 16);
}

export function sizeText(n: number): string {
  return n < 1024 ? `${n} bytes` : n < 1024 * 1024 ? `${(n / 1024).toFixed(1)} KiB` : `${(n / 1024 / 1024).toFixed(1)} MiB`;
}

// Bytes as base64, a chunk at a time (String.fromCharCode takes so many arguments).
export function base64(bytes: Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

// The format a file says it is; the server checks its bytes are that
// format's (a .pdf that is no PDF is its 400, not an HTML sheet).
export function formatOf(f: File): 'pdf' | 'html' {
  return f.type === 'application/pdf' || /\.pdf$/i.test(f.name) ? 'pdf' : 'html';
}

class SheetsPanel {
  readonly said = status('sheets-status');
  readonly list = h('div', { id: 'sheets-list' });
  readonly view = h('div', { id: 'sheet-view' });
  private urls: string[] = [];

  constructor(
    private readonly base: string, // /api/programs/NAME/revisions/REV
    private readonly stem: string, // NAME-REV12
  ) {}

  alert(text: string): void {
    this.said.setAttribute('role', 'alert');
    this.said.textContent = text;
  }

  tell(text: string): void {
    this.said.removeAttribute('role');
    this.said.textContent = text;
  }

  async load(): Promise<void> {
    try {
      const r = await getJson<{ sheets?: Sheet[] }>(this.base);
      this.show(r.sheets ?? []);
    } catch (e) {
      this.alert(`The sheets could not be read: ${(e as Error).message}`);
    }
  }

  private show(sheets: Sheet[]): void {
    while (this.urls.length) URL.revokeObjectURL(this.urls.pop() as string);
    if (!sheets.length) {
      this.list.replaceChildren(h('p', { class: 'note', text: 'This revision has no setup sheet.' }));
      return;
    }
    const heads = ['Format', 'Size', 'Author', 'Attached (UTC)', 'File'];
    const rows = sheets.map((s) => h('tr', { 'data-format': s.format }, h('th', { scope: 'row', text: s.format.toUpperCase() }), h('td', { text: sizeText(s.size) }), h('td', { text: s.author }), h('td', { text: when(s.created_at_us) }), h('td', {}, this.showButton(s), ' ', this.link(s))));
    this.list.replaceChildren(h('table', { 'aria-label': 'Setup sheets' }, h('thead', {}, h('tr', {}, ...heads.map((t) => h('th', { scope: 'col', text: t })))), h('tbody', {}, ...rows)));
  }

  private showButton(s: Sheet): HTMLButtonElement {
    const b = h('button', { type: 'button', id: `show-sheet-${s.format}`, text: `Show the ${s.format.toUpperCase()} sheet` });
    b.addEventListener('click', () => void this.open(s.format));
    return b;
  }

  // The sheet in a frame, through a signed link (it expires in minutes:
  // Show asks for a new one each time).
  private async open(format: string): Promise<void> {
    const label = format.toUpperCase();
    try {
      const link = await postJson<{ url: string; expires_at_us: number }>(`${this.base}/sheet/link`, { format });
      const title = `${label} setup sheet of ${this.stem}`;
      // HTML: no script, an origin of its own. A PDF is drawn by the
      // browser's viewer, which a sandboxed frame does not load.
      const frame = h('iframe', { src: link.url, title, class: `sheet-frame ${format}`, referrerpolicy: 'no-referrer', sandbox: format === 'html' ? '' : undefined });
      const close = h('button', { type: 'button', text: `Close the ${label} sheet` });
      close.addEventListener('click', () => {
        this.view.replaceChildren();
        document.getElementById(`show-sheet-${format}`)?.focus();
      });
      const heading = h('h3', { id: 'sheet-view-h', tabindex: '-1', text: `The ${label} sheet` });
      this.view.replaceChildren(h('div', { class: 'sheet-view-bar' }, heading, close), frame);
      heading.focus();
      this.tell(`Showing the ${label} sheet (its link expires at ${when(link.expires_at_us)} UTC).`);
    } catch (e) {
      this.alert(e instanceof ApiError ? `The ${label} sheet cannot be shown (${e.status}): ${e.message}` : String(e));
    }
  }

  // The link fetches the sheet on its first use, then is the file and is
  // clicked again (Enter or a click alike).
  private link(s: Sheet): HTMLAnchorElement {
    const a = h('a', { href: '#', id: `sheet-${s.format}`, download: `${this.stem}-sheet.${s.format}`, text: `Download the ${s.format.toUpperCase()} sheet` });
    let ready = false;
    a.addEventListener('click', (e) => {
      if (ready) return;
      e.preventDefault();
      a.setAttribute('aria-busy', 'true');
      void getFile(`${this.base}/sheet?format=${s.format}`)
        .then(({ blob }) => {
          // HTML as bytes of no renderable type: a download, never a page of ours.
          const file = s.format === 'pdf' ? new Blob([blob], { type: 'application/pdf' }) : new Blob([blob], { type: 'application/octet-stream' });
          const url = URL.createObjectURL(file);
          this.urls.push(url);
          a.href = url;
          ready = true;
          a.click();
        })
        .catch((err: Error) => this.alert(`The ${s.format.toUpperCase()} sheet could not be read: ${err.message}`))
        .finally(() => a.setAttribute('aria-busy', 'false'));
    });
    return a;
  }

  // The form that attaches a sheet (PDF or HTML) to the revision.
  form(): HTMLElement {
    const file = h('input', { type: 'file', accept: '.pdf,.html,.htm,application/pdf,text/html', required: true });
    const reason = h('input', { autocomplete: 'off' });
    const form = h('form', { class: 'sheet-form', novalidate: true }, field('Setup sheet file (PDF or HTML)', file, 'sheet-file'), field('Reason (optional)', reason, 'sheet-reason'), h('button', { type: 'submit', text: 'Attach the sheet' }));
    form.addEventListener('submit', (e) => {
      e.preventDefault();
      const f = file.files?.[0];
      if (!f) {
        this.alert('Choose a PDF or HTML file first.');
        file.focus();
        return;
      }
      void this.attach(f, reason.value.trim()).then((ok) => ok && form.reset());
    });
    return form;
  }

  private async attach(f: File, reason: string): Promise<boolean> {
    const bytes = new Uint8Array(await f.arrayBuffer());
    const format = formatOf(f);
    this.tell(`Attaching ${f.name} as the ${format.toUpperCase()} sheet…`);
    try {
      const r = await postJson<{ changed: boolean; replaced: string | null }>(`${this.base}/sheet`, { format, text_base64: base64(bytes), ...(reason ? { reason } : {}) });
      this.tell(!r.changed ? `${f.name} is this ${format.toUpperCase()} sheet already.` : r.replaced ? `${f.name} replaced the ${format.toUpperCase()} sheet.` : `${f.name} attached as the ${format.toUpperCase()} sheet.`);
      await this.load();
      return true;
    } catch (e) {
      this.alert(e instanceof ApiError ? `Refused (${e.status}): ${e.message}` : String(e));
      return false;
    }
  }
}

export function sheetsPanel(name: string, rev: string, who: SessionUser): HTMLElement {
  const p = new SheetsPanel(`/api/programs/${enc(name)}/revisions/${rev}`, `${name}-${rev.slice(0, 12)}`);
  void p.load();
  return h(
    'section',
    { 'aria-labelledby': 'sheets-h', class: 'sheets' },
    h('h2', { id: 'sheets-h', text: 'Setup sheets' }),
    p.list,
    p.view,
    mayUpload(who.role) ? p.form() : h('p', { class: 'note', text: `You are ${who.role}: attaching a sheet is for programmers and admins.` }),
    p.said,
  );
}
