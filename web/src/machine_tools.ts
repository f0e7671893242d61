// A machine's tool-life counts (GET /api/machines/{m}/tools; docs/dnc.md
// "Utilisation and tool life"): per tool number the parts made and the
// cutting time since its last reset (or since the first record), who reset
// it and why; for the roles that may (operator, programmer, admin), a Reset
// button per tool that asks for confirmation and a reason, which the audit
// log keeps. Read again when a part is made, a job ends or a tool is reset
// (from this page or another: the `machine.tool_reset` event). A tool with
// a life (`tool_life` of usina-serve.toml) shows the share of it used, and
// says in words when it is worn out or near its end.
import { ApiError, enc, getJson, postJson } from './api';
import { confirmWithReason } from './confirm';
import { h } from './dom';
import { duration } from './machine_utilisation';

interface ToolUse {
  tool: number;
  parts: number;
  cutting_seconds: number;
  seconds: number; // in the spindle: cutting, rapids and the rest
  since_us: number;
  counted_from: 'reset' | 'range';
  reset_at_us: number | null;
  reset_by: string | null;
  reset_reason: string | null;
  life_parts: number | null;
  life_cutting_minutes: number | null;
  life_used: number | null; // 1: worn
  worn: boolean;
}

// At this share of its life a tool is "near its end".
const NEAR_END = 0.9;

function lifeText(t: ToolUse): string {
  const parts = t.life_parts !== null ? `${t.life_parts} ${t.life_parts === 1 ? 'part' : 'parts'}` : '';
  const minutes = t.life_cutting_minutes !== null ? `${t.life_cutting_minutes} min cutting` : '';
  return [parts, minutes].filter(Boolean).join(' or ') || '—';
}

function usedText(t: ToolUse): string {
  if (t.life_used === null) return '—';
  const share = `${Math.round(100 * t.life_used)} %`;
  return t.worn ? `${share}: WORN OUT` : t.life_used >= NEAR_END ? `${share}: near its end` : share;
}

interface ToolLife {
  machine: string;
  parts: number;
  parts_without_program: number;
  parts_without_tool_list: number;
  tools: ToolUse[];
}

function when(us: number): string {
  return new Date(us / 1000).toISOString().replace('T', ' ').slice(0, 16);
}

function resetText(t: ToolUse): string {
  if (t.reset_at_us === null) return 'never';
  return `${when(t.reset_at_us)} by ${t.reset_by ?? '?'}${t.reset_reason ? `: ${t.reset_reason}` : ''}`;
}

// Parts the counts cannot give a tool: made before a job told which
// program ran, or by a revision checked before tool lists were kept.
function uncounted(life: ToolLife): string {
  const n = life.parts_without_program + life.parts_without_tool_list;
  if (n === 0) return '';
  return `${n} of ${life.parts} ${life.parts === 1 ? 'part is' : 'parts are'} in no tool's count (the control reported ${n === 1 ? 'it' : 'them'} with no program, or its revision has no tool list).`;
}

export interface ToolsPanel {
  element: HTMLElement;
  refresh(): void; // soon, once for several calls
}

export function toolsPanel(machine: string, mayReset: boolean): ToolsPanel {
  const id = `tools-${machine}`;
  const body = h('tbody');
  const heads = ['Tool', 'Parts', 'Cutting', 'In the spindle', 'Life', 'Used', 'Counted since (UTC)', 'Last reset', ...(mayReset ? ['Reset'] : [])];
  const table = h('table', { id: `${id}-table`, class: 'figures' }, h('caption', { text: `Tool life on ${machine}: each tool since its last reset` }), h('thead', {}, h('tr', {}, ...heads.map((t) => h('th', { scope: 'col', text: t })))), body);
  const scroller = h('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': `Tool life on ${machine}`, hidden: true }, table);
  const empty = h('p', { class: 'note', text: 'No tool has cut a counted part yet.', hidden: true });
  const note = h('p', { class: 'note' });
  const said = h('p', { class: 'status', role: 'status', 'aria-live': 'polite' });
  let timer = 0;
  let asked = 0;

  const reset = async (t: ToolUse) => {
    const reason = await confirmWithReason(
      `Reset T${t.tool} on ${machine}?`,
      `Its count (${t.parts} ${t.parts === 1 ? 'part' : 'parts'}, ${duration(t.cutting_seconds)} cutting) starts again from now. The audit log keeps who did it and why.`,
      `Reset T${t.tool}`,
      'Reason (a new insert, a regrind…)',
    );
    if (reason === null) return;
    try {
      const r = await postJson<{ tool: number; reset_by: string }>(`/api/machines/${enc(machine)}/tools/${t.tool}/reset`, { reason });
      said.textContent = `T${r.tool} reset by ${r.reset_by}.`;
      void load();
    } catch (e) {
      const why = e instanceof ApiError && e.status === 403 ? 'your role may not reset a tool' : (e as Error).message;
      said.textContent = `T${t.tool} was not reset: ${why}`;
    }
  };

  const row = (t: ToolUse) =>
    h(
      'tr',
      { 'data-tool': t.tool, class: t.worn ? 'worn' : t.life_used !== null && t.life_used >= NEAR_END ? 'near-end' : '' },
      h('th', { scope: 'row', text: t.tool === 0 ? 'T0 (no tool)' : `T${t.tool}` }),
      h('td', { class: 'parts', text: String(t.parts) }),
      h('td', { text: duration(t.cutting_seconds) }),
      h('td', { text: duration(t.seconds) }),
      h('td', { text: lifeText(t) }),
      h('td', { class: 'used', text: usedText(t) }),
      h('td', { text: t.counted_from === 'reset' ? when(t.since_us) : 'the first record' }),
      h('td', { class: 'reset', text: resetText(t) }),
      mayReset ? h('td', {}, button(t)) : null,
    );
  const button = (t: ToolUse) => {
    const b = h('button', { type: 'button', text: 'Reset', 'aria-label': `Reset the life of T${t.tool}` });
    b.addEventListener('click', () => void reset(t));
    return b;
  };

  const load = async () => {
    const n = ++asked;
    try {
      const life = await getJson<ToolLife>(`/api/machines/${enc(machine)}/tools`);
      if (n !== asked) return;
      body.replaceChildren(...life.tools.map(row));
      scroller.hidden = life.tools.length === 0;
      empty.hidden = life.tools.length !== 0;
      note.textContent = uncounted(life);
    } catch (e) {
      if (n === asked) said.textContent = `The tool life could not be read: ${(e as Error).message}`;
    }
  };
  void load();
  return {
    element: h('section', { class: 'tools', id, 'aria-labelledby': `${id}-h` }, h('h3', { id: `${id}-h`, text: 'Tool life' }), scroller, empty, note, said),
    refresh() {
      window.clearTimeout(timer);
      timer = window.setTimeout(() => void load(), 500);
    },
  };
}
