// A program's review: the revision's moves along the state graph (check,
// approve, release, reject) by role, with a reason; the revisions, and the
// normalised and plain diffs of two of them side by side.
import { ApiError, enc, getJson, postJson, type Diff, type Program, type Revision } from './api';
import { field, h, status } from './dom';
import { movesFrom, whyNot, type SessionUser } from './roles';

const LABELS: Record<string, string> = { checked: 'Mark checked', approved: 'Approve', released: 'Release', rejected: 'Reject' };

// The buttons of the moves out of the revision's state; a move the user
// may not make is disabled, with the reason beside it.
export function reviewPanel(p: Program, r: Revision, who: SessionUser, moved: () => void): HTMLElement {
  const moves = movesFrom(r.state);
  const said = status('review-status');
  if (!moves.length) return h('section', { 'aria-labelledby': 'review-h', class: 'review' }, h('h2', { id: 'review-h', text: 'Review' }), h('p', { text: `This revision is ${r.state}: no one moves it further (a fix is a new revision).` }));
  const reason = h('input', { autocomplete: 'off' });
  const buttons = moves.map((to) => {
    const why = whyNot(who, r.author, r.state, to);
    const label = r.state === 'released' && to === 'rejected' ? 'Withdraw' : LABELS[to];
    const b = h('button', { type: 'button', class: to === 'rejected' ? 'reject' : '', 'data-to': to, text: label, disabled: why !== '', 'aria-describedby': why ? `why-${to}` : undefined });
    b.addEventListener('click', () => void move(to));
    return { b, why, to };
  });
  const move = async (to: string) => {
    if (to === 'rejected' && !reason.value.trim()) {
      said.setAttribute('role', 'alert');
      said.textContent = 'Give the reason for rejecting it.';
      reason.focus();
      return;
    }
    try {
      await postJson(`/api/programs/${enc(p.name)}/revisions/${r.revision}/state`, { state: to, reason: reason.value.trim() });
      said.removeAttribute('role');
      said.textContent = `Now ${to}.`;
      moved();
    } catch (e) {
      said.setAttribute('role', 'alert');
      said.textContent = e instanceof ApiError ? `Refused (${e.status}): ${e.message}` : String(e);
    }
  };
  return h(
    'section',
    { 'aria-labelledby': 'review-h', class: 'review' },
    h('h2', { id: 'review-h', text: 'Review' }),
    field('Reason (needed to reject)', reason, 'review-reason'),
    h('div', { class: 'buttons' }, ...buttons.map((x) => x.b)),
    ...buttons.filter((x) => x.why).map((x) => h('p', { class: 'note', id: `why-${x.to}`, text: `${LABELS[x.to]}: ${x.why}.` })),
    said,
  );
}

function when(us: number): string {
  return us ? new Date(us / 1000).toISOString().replace('T', ' ').slice(0, 16) : '—';
}

// The revisions, newest first, and the two diffs of a chosen pair.
export function revisionsPanel(p: Program, shown: Revision): HTMLElement {
  const rows = p.revisions.map((r) =>
    h(
      'tr',
      { class: r.revision === shown.revision ? 'current' : '' },
      h('td', {}, h('a', { href: `#/program/${enc(p.name)}/${r.revision}`, text: r.revision.slice(0, 12), 'aria-current': r.revision === shown.revision ? 'page' : undefined })),
      h('td', { text: r.state }),
      h('td', { text: r.author }),
      h('td', { text: when(r.created_at_us) }),
      h('td', { text: r.reason || '—' }),
    ),
  );
  const table = h('table', { 'aria-label': 'Revisions' }, h('thead', {}, h('tr', {}, ...['Revision', 'State', 'Author', 'Uploaded (UTC)', 'Reason'].map((t) => h('th', { scope: 'col', text: t })))), h('tbody', {}, ...rows));
  const option = (r: Revision) => h('option', { value: r.revision, text: `${r.revision.slice(0, 12)} (${r.state})` });
  const from = h('select', {}, ...p.revisions.map(option));
  const to = h('select', {}, ...p.revisions.map(option));
  const at = p.revisions.findIndex((r) => r.revision === shown.revision);
  to.value = shown.revision;
  from.value = p.revisions[Math.min(at + 1, p.revisions.length - 1)].revision; // the one before
  const out = h('div', { class: 'diffs', id: 'diffs' });
  const form = h('form', { class: 'compare' }, field('From revision', from, 'diff-from'), field('To revision', to, 'diff-to'), h('button', { type: 'submit', text: 'Compare' }));
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    void compare(p.name, from.value, to.value, out);
  });
  const parts: (HTMLElement | null)[] = [h('h2', { id: 'revisions-h', text: 'Revisions' }), table];
  if (p.revisions.length > 1) parts.push(form, out);
  else parts.push(h('p', { class: 'note', text: 'One revision: nothing to compare yet.' }));
  return h('section', { 'aria-labelledby': 'revisions-h', class: 'revisions' }, ...parts);
}

function diffPanel(title: string, d: Diff): HTMLElement {
  const lines = d.diff.split('\n').filter((l, i, a) => l !== '' || i < a.length - 1);
  const pre = h(
    'pre',
    { class: 'diff', tabindex: 0, 'aria-label': `${title} diff` },
    ...lines.map((l) => h('span', { class: l.startsWith('@@') ? 'hunk' : l.startsWith('+') && !l.startsWith('+++') ? 'ins' : l.startsWith('-') && !l.startsWith('---') ? 'del' : '', text: `${l}\n` })),
  );
  const head = d.identical ? 'no difference' : `${d.deleted} removed, ${d.inserted} added`;
  return h('section', { class: 'diff-panel', 'aria-label': title }, h('h3', { text: `${title}: ${head}` }), d.identical ? h('p', { class: 'note', text: 'The two revisions are the same here.' }) : pre);
}

async function compare(name: string, from: string, to: string, out: HTMLElement): Promise<void> {
  out.replaceChildren(h('p', { class: 'status', text: 'Comparing…' }));
  const q = `/api/programs/${enc(name)}/diff?from=${from}&to=${to}`;
  try {
    const [norm, plain] = await Promise.all([getJson<Diff>(`${q}&normalised=1`), getJson<Diff>(q)]);
    out.replaceChildren(diffPanel('Normalised', norm), diffPanel('Plain', plain));
  } catch (e) {
    out.replaceChildren(h('p', { role: 'alert', text: (e as Error).message }));
  }
}
