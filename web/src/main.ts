// The page's router: #/login, #/library, #/program/NAME[/REV], #/machines, #/new, #/users,
// #/machine-settings.
import { ApiError, getJson, postJson, setToken, token } from './api';
import { h, show } from './dom';
import { loginPage } from './page_login';
import { libraryPage } from './page_library';
import { programPage } from './page_program';
import { machinesPage, leaveMachines } from './page_machines';
import { formsPage } from './page_forms';
import { usersPage } from './page_users';
import { machineSettingsPage } from './page_machine_settings';

const main = document.getElementById('main') as HTMLElement;

async function route(): Promise<void> {
  leaveMachines();
  const parts = location.hash.replace(/^#\/?/, '').split('/').map(decodeURIComponent);
  const nav = document.getElementById('nav') as HTMLElement;
  nav.hidden = !token();
  if (!token() && parts[0] !== 'login') {
    location.hash = '#/login';
    return;
  }
  try {
    if (parts[0] === 'login') await loginPage(main);
    else if (parts[0] === 'program' && parts[1]) await programPage(main, parts[1], parts[2]);
    else if (parts[0] === 'machines') await machinesPage(main);
    else if (parts[0] === 'new') await formsPage(main);
    else if (parts[0] === 'users') await usersPage(main);
    else if (parts[0] === 'machine-settings') await machineSettingsPage(main);
    else await libraryPage(main);
  } catch (e) {
    if (e instanceof ApiError && e.status === 401) {
      if (!token()) location.hash = '#/login'; // else a newer session already routed on
      return;
    }
    show(main, 'Something went wrong', h('p', { role: 'alert', text: String((e as Error).message ?? e) }));
  }
}

async function whoAmI(): Promise<void> {
  const who = document.getElementById('who') as HTMLElement;
  const adminLinks = ['nav-users', 'nav-machine-settings'].map((id) => document.getElementById(id) as HTMLElement);
  if (!token()) return;
  try {
    const s = await getJson<{ user: string; role: string }>('/api/session');
    who.textContent = `${s.user} (${s.role})`;
    for (const a of adminLinks) a.hidden = s.role !== 'admin'; // the server refuses the others anyway
  } catch {
    who.textContent = '';
    for (const a of adminLinks) a.hidden = true;
  }
}

document.getElementById('logout')?.addEventListener('click', async () => {
  try {
    await postJson('/api/logout', {});
  } catch {
    /* the session may have ended already */
  }
  setToken('');
  location.hash = '#/login';
});

window.addEventListener('hashchange', () => void route());
window.addEventListener('usina:login', () => void whoAmI());
void whoAmI();
void route();
