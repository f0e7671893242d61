// A machine's job buttons: send or drip feed a revision, from its start, a
// block (a line number or an N word) or a tool change; stop the running
// job. Each asks for confirmation first, and each is one call of the API,
// which writes the audit log (docs/dnc-server.md).
import { ApiError, enc, getJson, postJson, type Job, type Machine, type Program, type ProgramSummary } from './api';
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

function startFields(at: string, value: string): Record<string, string | number> {
  if (at === 'block') return /^\d+$/.test(value) ? { start_block: Number(value) } : { start_block: value };
  if (at === 'tool') return { start_tool: Number(value) };
  return {};
}

export function jobForm(m: Machine, currentJob: () => Job | null): JobForm {
  const id = (x: string) => `${m.name}-${x}`;
  const programs = h('datalist', { id: id('programs') });
  const program = h('input', { list: id('programs'), autocomplete: 'off', required: true });
  const revision = h('select', { required: true }, h('option', { value: '', text: 'choose a program first' }));
  const at = h('select', {}, h('option', { value: 'start', text: 'the start' }), h('option', { value: 'block', text: 'a block (line or N word)' }), h('option', { value: 'tool', text: 'a tool change' }));
  const where = h('input', { autocomplete: 'off', inputmode: 'numeric', placeholder: '120 or N120', disabled: true });
  const send = h('button', { type: 'submit', value: 'send', text: 'Send' });
  const drip = h('button', { type: 'submit', value: 'drip', text: 'Drip feed' });
  const stop = h('button', { type: 'button', class: 'stop', text: 'Stop the job', disabled: true });
  const said = status(id('job-status'));
  let mode = m.mode;
  at.addEventListener('change', () => {
    where.disabled = at.value === 'start';
    where.required = !where.disabled;
    where.placeholder = at.value === 'tool' ? '5' : '120 or N120';
  });
  const fillRevisions = async () => {
    const name = program.value.trim();
    if (!name) return;
    try {
      const p = await getJson<Program>(`/api/programs/${enc(name)}`);
      const ok = p.revisions.filter((r) => sendable(r.state, mode));
      revision.replaceChildren(...ok.map((r) => h('option', { value: r.revision, text: `${r.revision.slice(0, 12)} — ${r.state}${r.reason ? `: ${r.reason}` : ''}` })));
      if (!ok.length) revision.append(h('option', { value: '', text: `no revision ${mode === 'tryout' ? 'approved or released' : 'released'}` }));
    } catch (e) {
      revision.replaceChildren(h('option', { value: '', text: (e as Error).message }));
    }
  };
  program.addEventListener('change', () => void fillRevisions());
  void getJson<{ programs: ProgramSummary[] }>('/api/programs').then((l) => programs.replaceChildren(...l.programs.map((p) => h('option', { value: p.name }))));
  const form = h(
    'form',
    { class: 'job-form', 'aria-label': `Jobs for ${m.name}` },
    programs,
    field('Program', program, id('program')),
    field('Revision', revision, id('revision')),
    field('Start at', at, id('start-at')),
    field('Block or tool', where, id('start-where')),
    h('div', { class: 'buttons' }, send, drip, stop),
    said,
  );
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    const how = ((e as SubmitEvent).submitter as HTMLButtonElement | null)?.value ?? 'send';
    void start(how);
  });
  const fail = (err: unknown) => {
    said.setAttribute('role', 'alert');
    said.textContent = err instanceof ApiError ? `${err.status}: ${err.message}` : String(err);
  };
  const start = async (how: string) => {
    if (!revision.value) return fail(new Error('Choose a program and a revision the machine may take.'));
    const from = at.value === 'start' ? 'from its start' : at.value === 'block' ? `from block ${where.value}` : `from the change to tool ${where.value}`;
    const verb = how === 'drip' ? 'Drip feed' : 'Send';
    const ok = await confirmAction(`${verb} ${program.value} to ${m.name}?`, `Revision ${revision.value.slice(0, 12)}, ${from}. The machine's control must be ready to read.`, verb);
    if (!ok) return;
    try {
      const j = await postJson<Job>(`/api/machines/${enc(m.name)}/jobs`, { program: program.value.trim(), revision: revision.value, mode: how, ...startFields(at.value, where.value.trim()) });
      said.removeAttribute('role');
      said.textContent = `Job ${j.job} queued: ${j.program} to ${m.name} (${j.bytes_total} bytes).`;
    } catch (err) {
      fail(err);
    }
  };
  stop.addEventListener('click', async () => {
    const j = currentJob();
    if (!j || !RUNNING.includes(j.state)) return;
    if (!(await confirmAction(`Stop job ${j.job} on ${m.name}?`, `${j.program}: ${j.bytes_sent} of ${j.bytes_total} bytes sent. The rest is not sent.`, 'Stop the job'))) return;
    try {
      await postJson(`/api/jobs/${j.job}/stop`, {});
      said.removeAttribute('role');
      said.textContent = `Job ${j.job}: stop asked.`;
    } catch (err) {
      fail(err);
    }
  });
  return {
    element: form,
    update(machine: Machine, job: Job | null) {
      if (machine.mode !== mode) {
        mode = machine.mode;
        void fillRevisions();
      }
      stop.disabled = !job || !RUNNING.includes(job.state);
    },
  };
}
