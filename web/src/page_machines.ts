// The machines, their state live from the server's event stream.
import { enc, getJson, token, type Machine } from './api';
import { h, show, status } from './dom';

let socket: WebSocket | null = null;

export function leaveMachines(): void {
  socket?.close();
  socket = null;
}

function row(m: Machine): HTMLElement {
  const job = m.job;
  const progress = job
    ? h('progress', { max: job.bytes_total || 1, value: job.bytes_sent, 'aria-label': `${m.name}: bytes sent` })
    : null;
  return h(
    'tr',
    { id: `machine-${m.name}`, 'data-state': m.state },
    h('th', { scope: 'row', text: m.name }),
    h('td', { class: `state ${m.state}`, text: m.state }),
    h('td', {}, job ? `${job.program} (${job.state}) ` : '—', progress, job ? ` ${job.bytes_sent} / ${job.bytes_total} bytes, block ${job.block ?? '—'}` : ''),
    h('td', { text: String(m.part_count ?? 0) }),
    h('td', { text: m.last_cycle_seconds ? `${m.last_cycle_seconds.toFixed(1)} s` : '—' }),
    h('td', { text: `${m.dialect}, ${m.mode}, ${m.port}${m.link_error ? ` — ${m.link_error}` : ''}` }),
  );
}

export async function machinesPage(main: HTMLElement): Promise<void> {
  const list = await getJson<{ machines: Machine[] }>('/api/machines');
  const body = h('tbody', {}, ...list.machines.map(row));
  const live = status('live-status');
  live.textContent = 'Live updates: connecting…';
  const table = h(
    'table',
    { 'aria-label': 'Machines' },
    h('thead', {}, h('tr', {}, ...['Machine', 'State', 'Job', 'Parts', 'Last cycle', 'Link'].map((t) => h('th', { scope: 'col', text: t })))),
    body,
  );
  show(main, 'Machines', live, list.machines.length ? table : h('p', { text: 'No machines are configured (usina-serve.toml).' }));
  const refresh = async (name: string) => {
    const m = await getJson<Machine>(`/api/machines/${enc(name)}`);
    const old = document.getElementById(`machine-${m.name}`);
    if (old) old.replaceWith(row(m));
  };
  leaveMachines();
  const proto = location.protocol === 'https:' ? 'wss' : 'ws';
  const ws = new WebSocket(`${proto}://${location.host}/api/events?token=${enc(token())}`);
  socket = ws;
  ws.addEventListener('open', () => (live.textContent = 'Live updates: connected'));
  ws.addEventListener('close', () => socket === ws && (live.textContent = 'Live updates: disconnected (reload the page)'));
  ws.addEventListener('message', (e) => {
    const ev = JSON.parse(String(e.data)) as { type: string; machine?: string; name?: string };
    const name = ev.machine ?? (ev.type.startsWith('machine.') ? ev.name : undefined);
    if (name) void refresh(name);
  });
}
