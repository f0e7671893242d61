// The admin's users page (issue 14): the nav shows it to admins only; an
// account is added, its role changed and it is disabled (after asking) and
// enabled, each seen by the server; the only admin cannot be demoted and
// the page says why; an operator is told the page is for admins.
import { logInAs } from './flows.mjs';
import { PASSWORD } from './harness.mjs';

async function loginStatus(h, user, password) {
  const r = await fetch(`${h.base}/api/login`, { method: 'POST', body: JSON.stringify({ user, password }) });
  return r.status;
}

const said = (page) => page.locator('#users-status').innerText();

export async function usersFlow(page, h, { check, shot }) {
  await logInAs(page, 'boss');
  await page.getByRole('link', { name: 'Users' }).click();
  await page.getByRole('heading', { name: 'Users', exact: true }).waitFor();
  await page.locator('#user-oper').waitFor();
  check((await page.getByLabel('Role of oper').inputValue()) === 'operator', 'the admin sees every account with its role');

  await page.getByLabel('Name').fill('guest');
  await page.getByLabel('Role', { exact: true }).selectOption('approver');
  await page.getByLabel('Password', { exact: true }).fill(PASSWORD);
  await page.getByRole('button', { name: 'Add the user' }).click();
  await page.locator('#user-guest').waitFor();
  check((await loginStatus(h, 'guest', PASSWORD)) === 200, `a new account logs in ("${await said(page)}")`);

  await page.getByLabel('Role of guest').selectOption('programmer');
  await page.locator('#users-status', { hasText: 'guest: now programmer' }).waitFor();
  const role = (await h.api('boss', 'GET', '/api/users')).json.users.find((u) => u.name === 'guest')?.role;
  check(role === 'programmer', `the role changes on the server (${role})`);

  await page.getByRole('button', { name: 'Disable guest' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Disable' }).click();
  await page.getByRole('button', { name: 'Enable guest' }).waitFor();
  check((await loginStatus(h, 'guest', PASSWORD)) === 401 && (await page.locator('#user-guest .state').innerText()) === 'no', 'a disabled account cannot log in, after the admin confirmed');
  await page.getByRole('button', { name: 'Enable guest' }).click();
  await page.getByRole('button', { name: 'Disable guest' }).waitFor();
  check((await loginStatus(h, 'guest', PASSWORD)) === 200, 'enabled again, it logs in');

  await page.getByLabel('Role of boss').selectOption('operator');
  await page.locator('#users-status[role="alert"]', { hasText: 'only enabled admin' }).waitFor();
  check((await page.getByLabel('Role of boss').inputValue()) === 'admin', `the only admin stays one and the page says why ("${await said(page)}")`);
  await shot(page, 'web-users.png');

  await logInAs(page, 'oper');
  const link = await page.getByRole('link', { name: 'Users' }).isVisible();
  await page.goto(`${h.base}/#/users`);
  await page.getByText('the users are for admins').waitFor();
  check(!link, 'an operator has no Users link and the page says it is for admins');
}
