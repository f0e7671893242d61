import { postJson, setToken } from './api';
import { field, h, show, status } from './dom';

export async function loginPage(main: HTMLElement): Promise<void> {
  const user = h('input', { name: 'user', autocomplete: 'username', required: true });
  const password = h('input', { name: 'password', type: 'password', autocomplete: 'current-password', required: true });
  const message = status('login-status');
  const form = h(
    'form',
    { class: 'card', 'aria-label': 'Log in' },
    field('User', user, 'login-user'),
    field('Password', password, 'login-password'),
    h('button', { type: 'submit', text: 'Log in' }),
    message,
  );
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    message.textContent = 'Logging in…';
    try {
      const r = await postJson<{ token: string }>('/api/login', { user: user.value, password: password.value });
      setToken(r.token);
      window.dispatchEvent(new Event('usina:login'));
      location.hash = '#/library';
    } catch (err) {
      message.setAttribute('role', 'alert');
      message.textContent = (err as Error).message;
    }
  });
  show(main, 'Log in', form);
  user.focus();
}
