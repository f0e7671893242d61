// A machine's job buttons: send or drip feed a revision, from its start, a
// block (a line number or an N word) or a tool change; stop the running
// job; take a queued job out of the queue. Each asks for confirmation
// first, and each is one call of the API, which writes the audit log
// (docs/web.md, "The machines' jobs").
import { ApiError, enc, getJson, postJson, type Job, type LibraryList, type Machine, type Program } from './api';
import { confirmAction } from './confirm';
import { field, h, status } from './dom';

export interface JobForm {
  element: HTMLElement;
  update(m: Machine, job: Job | null): void;
}

const RUNNING = ['queued', 'running'];

// The revisions this machine takes: released ones, and approved ones on a
// machine in try-out.
function sendable(state: string, mode: string): boolean {
  return state === 'released' || (mode === 'tryout' && state === 'approved');
}

// The program (typed or picked) and the revisions of it the machine takes.
class ProgramPicker {
  readonly list: HTMLDataListElement;
  readonly program: HTMLInputElement;
  readonly revision = h('select', { required: true }, h('option', { value: '', text: 'choose a program first' }));

  constructor(
    id: (x: string) => string,
    public mode: string,
  ) {
    this.list = h('datalist', { id: id('programs') });
    this.program = h('input', { list: id('programs'), autocomplete: 'off', required: true });
    this.program.addEventListener('change', () => void this.fill());
    this.program.addEventListener('input', () => this.suggest());
    this.suggest();
  }

  private asked = 0; // the newest suggestion asked for: older answers are dropped
  private timer = 0;

  // The names the datalist offers: the first 20 holding what is typed, asked
  // of the server 250 ms after the last key (a library of 10,000 programs is
  // never read whole for a list of names).
  suggest(): void {
    window.clearTimeout(this.timer);
    this.timer = window.setTimeout(() => {
      const n = ++this.asked;
      const q = new URLSearchParams({ limit: '20', q: this.name() });
      void getJson<LibraryList>(`/api/programs?${q}`)
        .then((l) => n === this.asked && this.list.replaceChildren(...l.programs.map((p) => h('option', { value: p.name }))))
        .catch(() => undefined); // no suggestions; the field still takes a typed name
    }, 250);
  }

  name(): string {
    return this.program.value.trim();
  }

  async fill(): Promise<void> {
    if (!this.name()) return;
    try {
      const p = await getJson<Program>(`/api/programs/${enc(this.name())}`);
      const ok = p.revisions.filter((r) => sendable(r.state, this.mode));
      this.revision.replaceChildren(...ok.map((r) => h('option', { value: r.revision, text: `${r.revision.slice(0, 12)} — ${r.state}${r.reason ? `: ${r.reason}` : ''}` })));
      if (!ok.length) this.revision.append(h('option', { value: '', text: `no revision ${this.mode === 'tryout' ? 'approved or released' : 'released'}` }));
    } catch (e) {
      this.revision.replaceChildren(h('option', { value: '', text: (e as Error).message }));
    }
  }
}

// Where the job starts: the program's start, a block, or a tool change.
class StartPicker {
  readonly at = h('select', {}, h('option', { value: 'start', text: 'the start' }), h('option', { value: 'block', text: 'a block (line or N word)' }), h('option', { value: 'tool', text: 'a tool change' }));
  readonly where = h('input', { autocomplete: 'off', inputmode: 'numeric', placeholder: '120 or N120', disabled: true });

  constructor() {
    this.at.addEventListener('change', () => {
      this.where.disabled = this.at.value === 'start';
      this.where.required = !this.where.disabled;
      this.where.placeholder = this.at.value === 'tool' ? '5' : '120 or N120';
    });
  }

  // The order's start_block or start_tool.
  fields(): Record<string, string | number> {
    const v = this.where.value.trim();
    if (this.at.value === 'block') return /^\d+$/.test(v) ? { start_block: Number(v) } : { start_block: v };
    if (this.at.value === 'tool') return { start_tool: Number(v) };
    return {};
  }

  describe(): string {
    const v = this.where.value.trim();
    if (this.at.value === 'block') return `from block ${v}`;
    if (this.at.value === 'tool') return `from the change to tool ${v}`;
    return 'from its start';
  }
}

// A status line that turns into an alert for a refusal.
function reporter(line: HTMLElement) {
  return {
    ok(text: string) {
      line.removeAttribute('role');
      line.textContent = text;
    },
    fail(err: unknown) {
      line.setAttribute('role', 'alert');
      line.textContent = err instanceof ApiError ? `${err.status}: ${err.message}` : (err as Error).message ?? String(err);
    },
  };
}

export function jobForm(m: Machine, currentJob: () => Job | null): JobForm {
  const id = (x: string) => `${m.name}-${x}`;
  const pick = new ProgramPicker(id, m.mode);
  const from = new StartPicker();
  const stop = h('button', { type: 'button', class: 'stop', text: 'Stop the job', disabled: true });
  const said = status(id('job-status'));
  const report = reporter(said);
  const queue = h('ul', { class: 'queue', id: id('queue'), 'aria-label': `Queued for ${m.name}` });
  const start = async (how: string) => {
    if (!pick.revision.value) return report.fail(new Error('Choose a program and a revision the machine may take.'));
    const verb = how === 'drip' ? 'Drip feed' : 'Send';
    if (!(await confirmAction(`${verb} ${pick.name()} to ${m.name}?`, `Revision ${pick.revision.value.slice(0, 12)}, ${from.describe()}. The machine's control must be ready to read.`, verb))) return;
    try {
      const j = await postJson<Job>(`/api/machines/${enc(m.name)}/jobs`, { program: pick.name(), revision: pick.revision.value, mode: how, ...from.fields() });
      report.ok(`Job ${j.job} queued: ${j.program} to ${m.name} (${j.bytes_total} bytes).`);
    } catch (err) {
      report.fail(err);
    }
  };
  stop.addEventListener('click', () => void stopJob(m, currentJob(), report));
  const form = h(
    'form',
    { class: 'job-form', 'aria-label': `Jobs for ${m.name}` },
    pick.list,
    field('Program', pick.program, id('program')),
    field('Revision', pick.revision, id('revision')),
    field('Start at', from.at, id('start-at')),
    field('Block or tool', from.where, id('start-where')),
    h('div', { class: 'buttons' }, h('button', { type: 'submit', value: 'send', text: 'Send' }), h('button', { type: 'submit', value: 'drip', text: 'Drip feed' }), stop),
    queue,
    said,
  );
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    void start(((e as SubmitEvent).submitter as HTMLButtonElement | null)?.value ?? 'send');
  });
  return {
    element: form,
    update(machine: Machine, job: Job | null) {
      if (machine.mode !== pick.mode) {
        pick.mode = machine.mode;
        void pick.fill();
      }
      stop.disabled = !job || !RUNNING.includes(job.state);
      const waiting = (machine.queue ?? []).filter((n) => n !== job?.job);
      queue.replaceChildren(...waiting.map((n) => queuedItem(m, n, report)));
    },
  };
}

// A job waiting for the machine, and the button that takes it out of the queue.
function queuedItem(m: Machine, n: number, report: ReturnType<typeof reporter>): HTMLElement {
  const remove = h('button', { type: 'button', text: `Remove job ${n}` });
  remove.addEventListener('click', async () => {
    if (!(await confirmAction(`Remove job ${n} from ${m.name}'s queue?`, 'It has not started: nothing of it is sent.', 'Remove'))) return;
    try {
      await postJson(`/api/jobs/${n}/stop`, {});
      report.ok(`Job ${n}: removed from the queue.`);
    } catch (err) {
      report.fail(err);
    }
  });
  return h('li', { 'data-job': n }, `Job ${n}, queued `, remove);
}

async function stopJob(m: Machine, j: Job | null, report: ReturnType<typeof reporter>): Promise<void> {
  if (!j || !RUNNING.includes(j.state)) return;
  if (!(await confirmAction(`Stop job ${j.job} on ${m.name}?`, `${j.program}: ${j.bytes_sent} of ${j.bytes_total} bytes sent. The rest is not sent.`, 'Stop the job'))) return;
  try {
    await postJson(`/api/jobs/${j.job}/stop`, {});
    report.ok(`Job ${j.job}: stop asked.`);
  } catch (err) {
    report.fail(err);
  }
}
