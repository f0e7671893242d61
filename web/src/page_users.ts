// The admin's users page (issue 14): every account with its role and
// whether it may log in; a new account; a role changed, an account disabled
// or enabled (asking first), a new password set. The server checks every
// change (GET and POST /api/users, docs/dnc-server.md) and refuses to leave
// the store without an enabled admin; its message is shown.
import { ApiError, enc, getJson, postJson } from './api';
import { confirmAction } from './confirm';
import { field, h, show, status } from './dom';
import { sessionUser, type Role } from './roles';

interface Account {
  name: string;
  role: Role;
  disabled: boolean;
  created_at_us: number;
}

const ROLES: Role[] = ['operator', 'programmer', 'approver', 'admin'];
const MIN_PASSWORD = 8; // the server's kMinPasswordBytes

export async function usersPage(main: HTMLElement): Promise<void> {
  const who = await sessionUser();
  if (who.role !== 'admin') {
    show(main, 'Users', h('p', { class: 'note', text: `You are ${who.role}: the users are for admins.` }));
    return;
  }
  const said = status('users-status');
  const body = h('tbody');
  const table = h('table', { class: 'users', 'aria-label': 'Users' }, h('thead', {}, h('tr', {}, ...['User', 'Role', 'Logs in', 'Since', 'Password'].map((t) => h('th', { scope: 'col', text: t })))), body);
  const refresh = async () => {
    const { users } = await getJson<{ users: Account[] }>('/api/users');
    body.replaceChildren(...users.map((u) => row(u, who.user, said, refresh)));
  };
  show(main, 'Users', newAccountForm(said, refresh), table, said);
  await refresh();
}

// Runs a change and says what came of it; the table is read again either way.
// `undo` puts a refused change's control back before the refusal is said, so
// the row never shows what the server did not take.
async function change(said: HTMLElement, what: string, name: string, body: object, refresh: () => Promise<void>, undo?: () => void): Promise<void> {
  try {
    await postJson(`/api/users/${enc(name)}`, body);
    said.setAttribute('role', 'status');
    said.textContent = `${name}: ${what}.`;
  } catch (e) {
    undo?.();
    said.setAttribute('role', 'alert');
    said.textContent = `${name}: ${(e as ApiError).message}`;
  }
  await refresh();
}

function row(u: Account, me: string, said: HTMLElement, refresh: () => Promise<void>): HTMLElement {
  const role = h('select', { 'aria-label': `Role of ${u.name}` }, ...ROLES.map((r) => h('option', { value: r, text: r })));
  role.value = u.role;
  role.addEventListener('change', () => void change(said, `now ${role.value}`, u.name, { role: role.value }, refresh, () => (role.value = u.role)));
  const toggle = h('button', { type: 'button', text: u.disabled ? 'Enable' : 'Disable', 'aria-label': `${u.disabled ? 'Enable' : 'Disable'} ${u.name}` });
  toggle.addEventListener('click', async () => {
    if (!u.disabled) {
      const self = u.name === me ? ' You are logged in as this user: your own session ends too.' : '';
      if (!(await confirmAction(`Disable ${u.name}?`, `${u.name} is logged out now and cannot log in until enabled again.${self}`, 'Disable'))) return;
    }
    await change(said, u.disabled ? 'enabled' : 'disabled', u.name, { disabled: !u.disabled }, refresh);
  });
  const password = h('input', { type: 'password', autocomplete: 'new-password', minlength: MIN_PASSWORD, required: true });
  password.setAttribute('aria-label', `New password for ${u.name}`);
  const set = h('form', { class: 'inline' }, password, h('button', { type: 'submit', text: 'Set', 'aria-label': `Set the password of ${u.name}` }));
  set.addEventListener('submit', (e) => {
    e.preventDefault();
    void change(said, 'password set (their sessions ended)', u.name, { password: password.value }, refresh);
  });
  const since = new Date(u.created_at_us / 1000).toISOString().slice(0, 10);
  return h(
    'tr',
    { id: `user-${u.name}`, class: u.disabled ? 'disabled' : undefined },
    h('th', { scope: 'row', text: u.name }),
    h('td', {}, role),
    h('td', {}, h('span', { class: 'state', text: u.disabled ? 'no' : 'yes' }), ' ', toggle),
    h('td', { text: since }),
    h('td', {}, set),
  );
}

function newAccountForm(said: HTMLElement, refresh: () => Promise<void>): HTMLElement {
  const name = h('input', { autocomplete: 'off', required: true });
  const role = h('select', {}, ...ROLES.map((r) => h('option', { value: r, text: r })));
  const password = h('input', { type: 'password', autocomplete: 'new-password', minlength: MIN_PASSWORD, required: true });
  const form = h(
    'form',
    { class: 'card new-user', 'aria-label': 'New user' },
    h('h2', { text: 'New user' }),
    field('Name', name, 'new-user-name'),
    field('Role', role, 'new-user-role'),
    field('Password', password, 'new-user-password'),
    h('button', { type: 'submit', text: 'Add the user' }),
  );
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    try {
      await postJson('/api/users', { name: name.value, role: role.value, password: password.value });
      said.setAttribute('role', 'status');
      said.textContent = `${name.value}: added as ${role.value}.`;
      form.reset();
    } catch (err) {
      said.setAttribute('role', 'alert');
      said.textContent = `${name.value}: ${(err as ApiError).message}`;
    }
    await refresh();
  });
  return form;
}
