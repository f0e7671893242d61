// The library's import of a folder or of several files: each file uploaded
// in turn through the upload of one (POST /api/programs), named after the
// file, with a result per file (new, unchanged, or the server's refusal)
// and limits on the count and the sizes said before anything is sent.
import { ApiError, postJson } from './api';
import { field, h, status } from './dom';

// At most this many files and bytes an import: more is a job for
// POST /api/import or `usina serve`'s folder import (docs/dnc.md).
export const MAX_FILES = 500;
export const MAX_FILE_BYTES = 16 << 20;
export const MAX_TOTAL_BYTES = 128 << 20;
const NAME_BYTES = 64;

// A file chosen, and where it was: in the folder chosen or dropped, or
// its name alone.
interface Picked {
  file: File;
  path: string;
}

interface Planned {
  file: File;
  path: string; // in the folder, or the file's name
  name: string; // the program's
  skip: string; // why it is not uploaded; '' to upload
}

// The program name of a file: its name without the extension, every other
// character than letters, digits and `_ - . +` made `_` (store_names.hpp).
export function programName(fileName: string): string {
  const stem = fileName.replace(/\.[^.]*$/, '') || fileName;
  return stem.replace(/[^A-Za-z0-9_.+-]/g, '_').slice(0, NAME_BYTES);
}

function plan(files: Picked[]): Planned[] {
  const seen = new Map<string, string>();
  return files.map(({ file, path }) => {
    const name = programName(file.name);
    let skip = '';
    if (file.name.startsWith('.')) skip = 'a hidden file';
    else if (/^[.-]/.test(name)) skip = `no program name can start with "${name[0]}"`;
    else if (file.size > MAX_FILE_BYTES) skip = `${file.size} bytes, more than the ${MAX_FILE_BYTES} of one file here`;
    else if (seen.has(name)) skip = `the same program name, ${name}, as ${seen.get(name)}`;
    if (!skip) seen.set(name, path);
    return { file, path, name, skip };
  });
}

// Why a whole selection is refused, '' when it may go; `more`: a folder
// dropped had more files than were walked.
function refusal(files: Picked[], more: boolean): string {
  const total = files.reduce((n, f) => n + f.file.size, 0);
  if (more) return `More than ${MAX_FILES} files: at most ${MAX_FILES} at a time. Choose a smaller folder.`;
  if (files.length > MAX_FILES) return `${files.length} files: at most ${MAX_FILES} at a time. Choose a smaller folder.`;
  if (total > MAX_TOTAL_BYTES) return `${total} bytes: at most ${MAX_TOTAL_BYTES} at a time. Choose fewer files.`;
  return '';
}

interface Options {
  dialect: string;
  machineClass: string;
  reason: string;
}

// One file's upload; its line of the result.
async function upload(p: Planned, o: Options): Promise<{ ok: boolean; text: string }> {
  const text = await p.file.text();
  if (text.includes('\0')) return { ok: false, text: 'skipped: not a text file (it holds a NUL byte)' };
  const body: Record<string, string> = { name: p.name, text };
  if (o.dialect) body.dialect = o.dialect;
  if (o.machineClass) body.machine_class = o.machineClass;
  if (o.reason) body.reason = o.reason;
  try {
    const r = await postJson<{ revision: string; created: boolean; check_ok?: boolean }>('/api/programs', body);
    return { ok: true, text: `${r.created ? 'new revision' : 'unchanged (the same bytes are there)'} ${r.revision.slice(0, 12)}` };
  } catch (e) {
    return { ok: false, text: e instanceof ApiError ? `refused (${e.status}): ${e.message}` : `failed: ${(e as Error).message}` };
  }
}

function resultLine(p: Planned, result: string, kind: 'ok' | 'error' | 'skipped'): HTMLElement {
  return h('li', { class: kind, 'data-result': kind, 'data-file': p.path }, h('strong', { text: p.path }), ` → ${p.name}: ${result}`);
}

function plural(n: number): string {
  return `${n} ${n === 1 ? 'file' : 'files'}`;
}

// The files of a list chosen in a file input: the folder chooser gives
// each its path in the folder.
export function pickedOf(list: FileList | null): Picked[] {
  return [...(list ?? [])].map((file) => ({ file, path: file.webkitRelativePath || file.name }));
}

// The entries of a folder, by name: readEntries gives them in batches (a
// hundred in Chromium) until it gives none.
function entriesOf(dir: FileSystemDirectoryEntry): Promise<FileSystemEntry[]> {
  const reader = dir.createReader();
  const all: FileSystemEntry[] = [];
  return new Promise((resolve, reject) => {
    const next = (): void =>
      reader.readEntries((batch) => {
        if (!batch.length) resolve(all.sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0)));
        else {
          all.push(...batch);
          next();
        }
      }, reject);
    next();
  });
}

// Every file under `e`, depth first, in the order of the names; stops once
// more than `limit` are found (the selection is refused then anyway).
async function walk(e: FileSystemEntry, out: Picked[], limit: number): Promise<void> {
  if (out.length > limit) return;
  if (e.isFile) {
    const file = await new Promise<File>((ok, fail) => (e as FileSystemFileEntry).file(ok, fail));
    out.push({ file, path: e.fullPath.replace(/^\//, '') });
  } else if (e.isDirectory) {
    for (const child of await entriesOf(e as FileSystemDirectoryEntry)) await walk(child, out, limit);
  }
}

// What a drop holds: its files, and every file under a folder dropped (the
// browser hands a folder as one entry of the drop, with no file of its own).
// The entries are taken before anything is awaited: after the drop event
// its DataTransfer is empty.
export async function droppedFiles(dt: DataTransfer): Promise<{ picked: Picked[]; more: boolean }> {
  const roots = [...dt.items].filter((i) => i.kind === 'file').map((i) => i.webkitGetAsEntry() ?? i.getAsFile());
  const picked: Picked[] = [];
  for (const r of roots) {
    if (r instanceof File) {
      picked.push({ file: r, path: r.name }); // counted whole: "501 files"
    } else if (r) {
      await walk(r, picked, MAX_FILES);
      if (picked.length > MAX_FILES) return { picked, more: true }; // a folder walked in part
    }
  }
  return { picked, more: false };
}

// The form's controls and the files chosen last.
class FolderImport {
  readonly folder = h('input', { type: 'file', multiple: true, webkitdirectory: true });
  readonly files = h('input', { type: 'file', multiple: true });
  readonly drop = h('p', { class: 'drop', text: 'or drop a folder or several files here' });
  readonly dialect: HTMLSelectElement;
  readonly machineClass = h('input', { autocomplete: 'off' });
  readonly reason = h('input', { autocomplete: 'off' });
  readonly go = h('button', { type: 'submit', text: 'Import', disabled: true });
  readonly said = status('import-status');
  readonly results = h('ol', { id: 'import-results', class: 'import-results', 'aria-label': 'Imported files' });
  private chosen: Picked[] = [];

  constructor(dialects: string[]) {
    this.dialect = h('select', {}, h('option', { value: '', text: 'guessed from each file' }), ...dialects.map((d) => h('option', { value: d, text: d })));
  }

  say(text: string, alert: boolean): void {
    this.said.setAttribute('role', alert ? 'alert' : 'status');
    this.said.textContent = text;
  }

  // A new selection: refused whole past the limits, else ready to import.
  choose(list: Picked[], more = false): void {
    this.chosen = list;
    this.results.replaceChildren();
    const why = refusal(list, more);
    this.say(why || `${plural(list.length)} chosen (${list.reduce((n, f) => n + f.file.size, 0)} bytes).`, !!why);
    this.go.disabled = !!why || list.length === 0;
    this.go.textContent = list.length && !why ? `Import ${plural(list.length)}` : 'Import';
  }

  // Each file in turn, its result listed as it comes.
  async run(): Promise<void> {
    if (this.go.disabled) return;
    this.go.disabled = true;
    const planned = plan(this.chosen);
    const o = { dialect: this.dialect.value, machineClass: this.machineClass.value, reason: this.reason.value };
    let ok = 0;
    this.results.replaceChildren();
    for (const [i, p] of planned.entries()) {
      this.said.textContent = `Importing ${i + 1} of ${planned.length}: ${p.path}…`;
      if (p.skip) {
        this.results.append(resultLine(p, `skipped: ${p.skip}`, 'skipped'));
        continue;
      }
      const r = await upload(p, o);
      if (r.ok) ok++;
      this.results.append(resultLine(p, r.text, r.ok ? 'ok' : r.text.startsWith('skipped') ? 'skipped' : 'error'));
    }
    const missed = planned.length - ok;
    this.say(`${ok} of ${plural(planned.length)} imported${missed ? `; ${missed} not (listed below)` : ''}.`, missed > 0);
    this.go.disabled = false;
  }
}

export function importForm(dialects: string[], imported: () => void): HTMLElement {
  const f = new FolderImport(dialects);
  f.folder.addEventListener('change', () => f.choose(pickedOf(f.folder.files)));
  f.files.addEventListener('change', () => f.choose(pickedOf(f.files.files)));
  f.drop.addEventListener('dragover', (e) => e.preventDefault());
  f.drop.addEventListener('drop', (e) => {
    e.preventDefault();
    if (!e.dataTransfer) return;
    f.say('Reading what was dropped…', false);
    droppedFiles(e.dataTransfer).then(
      ({ picked, more }) => f.choose(picked, more),
      (err: Error) => f.say(`What was dropped cannot be read: ${err.message}`, true),
    );
  });
  const form = h(
    'form',
    { class: 'card', 'aria-labelledby': 'import-h' },
    h('h2', { id: 'import-h', text: 'Import a folder' }),
    h('p', { class: 'note', text: `Each file becomes a program named after it (or a new revision of the program of that name). At most ${MAX_FILES} files and ${MAX_TOTAL_BYTES >> 20} MiB at a time, ${MAX_FILE_BYTES >> 20} MiB a file.` }),
    field('Folder', f.folder, 'import-folder'),
    field('Files', f.files, 'import-files'),
    f.drop,
    field('Dialect of the files', f.dialect, 'import-dialect'),
    field('Machine class of the files (optional)', f.machineClass, 'import-class'),
    field('Reason of the import (optional)', f.reason, 'import-reason'),
    f.go,
    f.said,
    f.results,
  );
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    void f.run().then(imported);
  });
  return form;
}
