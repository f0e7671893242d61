// The machines, live from the server's event stream: each machine's state,
// its job's progress (bytes sent of the total, the block), its part count
// and last cycle time against the estimate of the program last sent; its
// utilisation per day (machine_utilisation.ts); its tool life
// (machine_tools.ts); its quality records (machine_quality.ts); and, for a role that may, the job buttons
// (machine_jobs.ts) and the quality form.
import { enc, getJson, token, type Job, type Machine, type Revision } from './api';
import { h, show, status } from './dom';
import { jobForm, type JobForm } from './machine_jobs';
import { qualityPanel, type QualityPanel, type QualityRecord } from './machine_quality';
import { toolsPanel, type ToolsPanel } from './machine_tools';
import { duration, utilisationPanel, type UtilisationPanel } from './machine_utilisation';
import { mayRecordQuality, mayResetTools, mayRunJobs, sessionUser } from './roles';

let socket: WebSocket | null = null;
let ticker = 0;

export function leaveMachines(): void {
  socket?.close();
  socket = null;
  window.clearInterval(ticker);
}

// The server's clock less this browser's (ms), from the last event's
// `server_us`: a running job's elapsed time is the server's, whatever the
// clock of the PC the page runs on says.
let skewMs = 0;

function serverNowMs(): number {
  return Date.now() + skewMs;
}

// What the page knows of one machine: the last answer of the server and
// the last job heard of (kept after it ends, so a finished send still
// shows its bar at 100 %).
interface Shown {
  machine: Machine;
  job: Job | null;
  status: HTMLElement;
  form: JobForm | null;
  utilisation: UtilisationPanel;
  tools: ToolsPanel;
  quality: QualityPanel;
  estimate: Estimate | null; // of the last job's revision
}

// The check's cycle time of the revision a machine was last sent.
interface Estimate {
  program: string;
  revision: string;
  seconds: number | null;
}

const estimates = new Map<string, Promise<number | null>>();

function checkedCycle(program: string, revision: string): Promise<number | null> {
  const key = `${program}/${revision}`;
  let e = estimates.get(key);
  if (!e) {
    e = getJson<Revision>(`/api/programs/${enc(program)}/revisions/${revision}`).then(
      (r) => r.checks?.cycle_time_s ?? null,
      () => null,
    );
    estimates.set(key, e);
  }
  return e;
}

// "7 min 59.9 s of seed-000 (revision abc…); the last cycle 17 % of it".
function estimateText(s: Shown): string {
  const e = s.estimate;
  if (!e || e.seconds === null) return '—';
  const last = s.machine.last_cycle_seconds;
  const ratio = last && e.seconds > 0 ? `; the last cycle took ${Math.round((100 * last) / e.seconds)} % of it` : '';
  return `${e.seconds.toFixed(1)} s for ${e.program} (${e.revision.slice(0, 12)}), the check's${ratio}`;
}

const ENDED = ['done', 'interrupted', 'failed'];

function percent(j: Job): number {
  return j.bytes_total > 0 ? Math.floor((100 * j.bytes_sent) / j.bytes_total) : 0;
}

// What is left of a running job: a drip feed by the check's cycle time of
// its program (the machine cuts as it reads, so the bytes left stand for
// the time left), a send (or a drip feed without an estimate) by its rate
// so far.
function leftText(j: Job, elapsed: number, cycle: number | null): string {
  if (j.bytes_total <= 0) return '';
  if (j.mode === 'drip' && cycle !== null && cycle > 0) {
    return `, about ${duration((cycle * (j.bytes_total - j.bytes_sent)) / j.bytes_total)} left by the check's cycle time`;
  }
  if (j.bytes_sent <= 0 || elapsed < 1) return '';
  return `, about ${duration((elapsed * (j.bytes_total - j.bytes_sent)) / j.bytes_sent)} left at the rate so far`;
}

// "1 min 12 s elapsed, about 2 min left …" while it runs; "took 9 s" once ended.
function timeText(j: Job, cycle: number | null): string {
  if (j.started_at_us === null || j.started_at_us === undefined) return '';
  if (j.ended_at_us !== null && j.ended_at_us !== undefined) return `; took ${duration((j.ended_at_us - j.started_at_us) / 1e6)}`;
  const elapsed = Math.max(0, (serverNowMs() - j.started_at_us / 1000) / 1000);
  return `; ${duration(elapsed)} elapsed${leftText(j, elapsed, cycle)}`;
}

// The check's cycle time of the job's own revision, when known.
function cycleOf(s: Shown): number | null {
  const e = s.estimate;
  return e && s.job && e.program === s.job.program && e.revision === s.job.revision ? e.seconds : null;
}

function jobLine(name: string, j: Job | null, cycle: number | null): HTMLElement {
  if (!j) return h('p', { class: 'job', text: 'No job yet.' });
  const bar = h('progress', { max: j.bytes_total || 1, value: j.bytes_sent, 'aria-label': `${name}: bytes sent of job ${j.job}` });
  const where = j.block !== null ? `, block ${j.block}` : '';
  return h(
    'p',
    { class: `job ${j.state}`, 'data-job': j.job, 'data-job-state': j.state, 'data-bytes-sent': j.bytes_sent, 'data-bytes-total': j.bytes_total },
    `Job ${j.job}: ${j.program} (${j.mode === 'drip' ? 'drip feed' : 'send'}, ${j.state}${j.alarm ? ', alarm' : ''}) `,
    bar,
    h('span', { class: 'progress-text', text: ` ${j.bytes_sent} / ${j.bytes_total} bytes (${percent(j)} %)${where}` }),
    h('span', { class: 'job-time', text: timeText(j, cycle) }),
    j.reason && ENDED.includes(j.state) && j.state !== 'done' ? h('span', { class: 'reason', text: ` — ${j.reason}` }) : null,
  );
}

function statusOf(s: Shown): HTMLElement[] {
  const m = s.machine;
  const items: [string, string, string][] = [
    ['State', m.state, `state ${m.state}`],
    ['Parts', String(m.part_count ?? 0), 'parts'],
    ['Last cycle', m.last_cycle_seconds ? `${m.last_cycle_seconds.toFixed(1)} s` : '—', 'cycle'],
    ['Estimate', estimateText(s), 'estimate'],
    ['Link', `${m.dialect}, ${m.mode}, ${m.port}${m.link_error ? ` — ${m.link_error}` : ''}`, 'link'],
  ];
  return [
    h('dl', { class: 'summary' }, ...items.flatMap(([k, v, cls]) => [h('dt', { text: k }), h('dd', { class: cls, text: v })])),
    jobLine(m.name, s.job, cycleOf(s)),
    m.last_message ? h('p', { class: 'message', text: `Message from the control: ${m.last_message}` }) : h('span'),
  ];
}

function render(s: Shown): void {
  s.status.replaceChildren(...statusOf(s));
  s.form?.update(s.machine, s.job);
  const j = s.job;
  if (j && (s.estimate?.program !== j.program || s.estimate?.revision !== j.revision)) {
    const wanted: Estimate = { program: j.program, revision: j.revision, seconds: null };
    s.estimate = wanted;
    void checkedCycle(j.program, j.revision).then((seconds) => {
      if (s.estimate !== wanted) return;
      wanted.seconds = seconds;
      s.status.replaceChildren(...statusOf(s));
    });
  }
}

// Who is looking: what the page offers them.
interface Viewer {
  runs: boolean;
  records: boolean;
  resets: boolean;
}

function machineSection(m: Machine, shown: Map<string, Shown>, v: Viewer): HTMLElement {
  const s: Shown = { machine: m, job: m.job, status: h('div', { class: 'machine-status' }), form: null, utilisation: utilisationPanel(m.name), tools: toolsPanel(m.name, v.resets), quality: qualityPanel(m.name, v.records), estimate: null };
  if (v.runs) s.form = jobForm(m, () => shown.get(m.name)?.job ?? null);
  shown.set(m.name, s);
  render(s);
  return h(
    'section',
    { class: 'machine', id: `machine-${m.name}`, 'aria-labelledby': `machine-${m.name}-h`, 'data-state': m.state },
    h('h2', { id: `machine-${m.name}-h`, text: m.name }),
    s.status,
    s.form ? s.form.element : null,
    s.utilisation.element,
    s.tools.element,
    s.quality.element,
  );
}

export async function machinesPage(main: HTMLElement): Promise<void> {
  const [list, who] = await Promise.all([getJson<{ machines: Machine[] }>('/api/machines'), sessionUser()]);
  const v: Viewer = { runs: mayRunJobs(who.role), records: mayRecordQuality(who.role), resets: mayResetTools(who.role) };
  const shown = new Map<string, Shown>();
  const sections = h('div', { id: 'machine-sections' }, ...list.machines.map((m) => machineSection(m, shown, v)));
  const none = h('p', { id: 'no-machines', text: 'No machines are configured (usina-serve.toml, or Machine settings for an admin).', hidden: list.machines.length > 0 });
  const live = status('live-status');
  live.textContent = 'Live updates: connecting…';
  const notes: HTMLElement[] = [];
  if (!v.runs) notes.push(h('p', { class: 'note', text: `You are ${who.role}: you may watch the machines; sending, drip feeding and stopping are for operators, programmers and admins.` }));
  if (!v.records) notes.push(h('p', { class: 'note', id: 'quality-note', text: `You are ${who.role}: you may read the quality records; recording one is for operators, approvers and admins.` }));
  const changes = status('machines-changed');
  show(main, 'Machines', live, ...notes, changes, none, sections);
  // An admin adds or retires a machine while the page is open (page_machine_settings.ts).
  const roster = async (ev: ServerEvent) => {
    const name = ev.machine ?? '';
    if (ev.type === 'machine.retired') {
      shown.delete(name);
      document.getElementById(`machine-${name}`)?.remove();
      changes.textContent = `${name} was retired by ${ev.user ?? 'an admin'}.`;
    } else if (!shown.has(name)) {
      const m = await getJson<Machine>(`/api/machines/${enc(name)}`);
      if (!shown.has(name)) sections.append(machineSection(m, shown, v));
      changes.textContent = `${name} was added by ${ev.user ?? 'an admin'}.`;
    }
    none.hidden = shown.size > 0;
  };
  listen(shown, live, roster);
  // A running job's clock moves between its progress events (a drip feed
  // held by XOFF sends none).
  ticker = window.setInterval(() => {
    for (const s of shown.values()) {
      const span = s.job?.state === 'running' ? s.status.querySelector('.job-time') : null;
      if (span && s.job) span.textContent = timeText(s.job, cycleOf(s));
    }
  }, 1000);
}

async function refresh(shown: Map<string, Shown>, name: string): Promise<void> {
  const s = shown.get(name);
  if (!s) return;
  s.machine = await getJson<Machine>(`/api/machines/${enc(name)}`);
  if (s.machine.job) s.job = s.machine.job;
  document.getElementById(`machine-${name}`)?.setAttribute('data-state', s.machine.state);
  render(s);
}

interface ServerEvent {
  type: string;
  machine?: string;
  name?: string;
  part_count?: number;
  last_cycle_seconds?: number | null;
  user?: string;
  server_us?: number;
}

function listen(shown: Map<string, Shown>, live: HTMLElement, roster: (ev: ServerEvent) => Promise<void>): void {
  leaveMachines();
  const proto = location.protocol === 'https:' ? 'wss' : 'ws';
  const ws = new WebSocket(`${proto}://${location.host}/api/events?token=${enc(token())}`);
  socket = ws;
  ws.addEventListener('open', () => (live.textContent = 'Live updates: connected'));
  ws.addEventListener('close', () => socket === ws && (live.textContent = 'Live updates: disconnected (reload the page)'));
  ws.addEventListener('message', (e) => {
    const ev = JSON.parse(String(e.data)) as ServerEvent;
    if (typeof ev.server_us === 'number') skewMs = ev.server_us / 1000 - Date.now();
    if (ev.type === 'machine.added' || ev.type === 'machine.retired') {
      roster(ev).catch(() => undefined); // a machine retired as soon as added: the next event says so
      return;
    }
    const name = ev.machine ?? (ev.type.startsWith('machine.') ? ev.name : undefined);
    const s = name ? shown.get(name) : undefined;
    if (!s || !name) return;
    if (ev.type.startsWith('job.')) {
      // The job's progress is in the event itself: no request per tick.
      const j = ev as unknown as Job;
      // The running job stays shown until it ends; a job queued behind it
      // is in the queue's list (machine_jobs.ts), and shown when it starts.
      if (!s.job || s.job.state !== 'running' || j.job === s.job.job || j.state === 'running') s.job = j;
      render(s);
      if (ev.type !== 'job.progress') void refresh(shown, name);
      if (ENDED.some((e) => ev.type === `job.${e}`)) {
        s.utilisation.refresh();
        s.tools.refresh();
      }
    } else if (ev.type === 'machine.part') {
      if (ev.part_count !== undefined) s.machine.part_count = ev.part_count;
      if (ev.last_cycle_seconds !== undefined) s.machine.last_cycle_seconds = ev.last_cycle_seconds;
      render(s);
      void refresh(shown, name); // the control's count and message, too
      s.utilisation.refresh();
      s.tools.refresh();
    } else if (ev.type === 'machine.tool_reset') {
      s.tools.refresh(); // from this page or another
    } else if (ev.type === 'machine.quality') {
      s.quality.add(ev as unknown as QualityRecord); // the event is the record
    } else {
      void refresh(shown, name);
    }
  });
}
