// The admin's machine settings page (issue 14): romi-1, the file's, is
// listed and cannot be changed from the page; a machine is added from the
// keyboard (a tape code its frame cannot carry is the server's 400 in
// words first), its settings changed, and retired after the confirmation
// (without a reason the server's 400 is shown); each step is on the server
// and in the audit log; the machines page follows a machine added and
// retired while it is open; an operator has no link and is told the page is for
// admins.
import { logInAs } from './flows.mjs';
import { fitsAtZoom } from './quality.mjs';

const said = (page) => page.locator('#machine-settings-status').innerText();

async function alertSays(page, text) {
  await page.locator('#machine-settings-status[role="alert"]', { hasText: text }).waitFor();
  return said(page);
}

async function machines(h) {
  return (await h.api('boss', 'GET', '/api/machines?retired=1')).json;
}

async function audited(h, name) {
  const log = (await h.api('boss', 'GET', '/api/audit?limit=100000')).json.entries; // after the big library's
  return log.filter((e) => e.subject === name).map((e) => `${e.action}:${e.reason}`);
}

export async function machineSettingsFlow(page, h, { check, shot }) {
  await logInAs(page, 'boss');
  await page.getByRole('link', { name: 'Machine settings' }).click();
  await page.getByRole('heading', { name: 'Machine settings', exact: true }).waitFor();
  await page.locator('#settings-romi-1').waitFor();
  const file = await page.locator('#settings-romi-1').innerText();
  check(/usina-serve\.toml/.test(file) && (await page.getByRole('button', { name: 'Edit romi-1' }).count()) === 0, `romi-1 is listed as the file's, with no Edit or Retire ("${file.replace(/\s+/g, ' ')}")`);

  // A new machine, typed and submitted with Enter; EIA on 7 data bits first.
  await page.getByLabel('Name', { exact: true }).fill('mill-9');
  await page.getByLabel('Port', { exact: true }).fill('tcp://127.0.0.1:9');
  await page.getByLabel('Machine class').fill('mill');
  await page.getByLabel('Baud').selectOption('4800');
  await page.getByLabel('Tape code').selectOption('eia');
  await page.getByLabel('Reason (for the audit log)').fill('the new mill');
  await page.getByLabel('Reason (for the audit log)').press('Enter');
  const eia = await alertSays(page, 'code = "eia" needs data_bits = 8');
  check((await machines(h)).machines.every((m) => m.name !== 'mill-9'), `a frame EIA cannot use is refused with the server's message and nothing added ("${eia}")`);
  await page.getByLabel('Tape code').selectOption('ascii');
  await page.getByLabel('Reason (for the audit log)').press('Enter');
  await page.locator('#settings-mill-9').waitFor();
  const added = (await machines(h)).machines.find((m) => m.name === 'mill-9');
  check(added?.source === 'api' && added.settings.baud === 4800 && added.settings.code === 'ascii' && added.machine_class === 'mill', `the machine is added on the server (${JSON.stringify(added?.settings ?? null).slice(0, 90)}…)`);

  // Its settings changed: the form is filled from the server's.
  await page.getByRole('button', { name: 'Edit mill-9' }).click();
  await page.getByRole('heading', { name: 'Change mill-9' }).waitFor();
  const filled = await page.getByLabel('Baud').inputValue();
  const nameLocked = await page.getByLabel('Name', { exact: true }).evaluate((e) => e.readOnly);
  await page.getByLabel('Baud').selectOption('19200');
  await page.getByLabel('Mode', { exact: true }).selectOption('tryout');
  await page.getByLabel('Reason (for the audit log)').fill('faster cable');
  await page.getByRole('button', { name: 'Save mill-9' }).click();
  await page.locator('#machine-settings-status', { hasText: 'mill-9: saved' }).waitFor();
  const changed = (await machines(h)).machines.find((m) => m.name === 'mill-9');
  check(filled === '4800' && nameLocked && changed?.settings.baud === 19200 && changed.mode === 'tryout', `the change is on the server: 4800 → ${changed?.settings.baud} baud, ${changed?.mode} ("${await said(page)}")`);
  await page.locator('#settings-mill-9').scrollIntoViewIfNeeded();
  await shot(page, 'web-machine-settings.png');

  // Retired: without a reason the server says so; then after the confirmation.
  await page.getByRole('button', { name: 'Retire mill-9' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Retire' }).click();
  const noReason = await alertSays(page, 'give the reason');
  await page.getByLabel('Reason for retiring mill-9').fill('sold');
  await page.getByRole('button', { name: 'Retire mill-9' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Cancel' }).focus();
  await page.keyboard.press('Escape');
  const stillThere = (await machines(h)).machines.some((m) => m.name === 'mill-9');
  await page.getByRole('button', { name: 'Retire mill-9' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Retire' }).click();
  await page.locator('#retired-mill-9').waitFor().catch(async (e) => {
    throw new Error(`mill-9 not listed as retired; the page said "${await said(page)}" (${e.message.split('\n')[0]})`);
  });
  const after = await machines(h);
  const gone = (await h.api('boss', 'GET', '/api/machines/mill-9')).status;
  check(stillThere && gone === 404 && after.retired.some((m) => m.name === 'mill-9' && m.retire_reason === 'sold') && (await page.locator('#settings-mill-9').count()) === 0, `retired after the confirmation (Escape kept it; without a reason: "${noReason}")`);
  const log = await audited(h, 'mill-9');
  check(JSON.stringify(log) === JSON.stringify(['machine.add:the new mill', 'machine.change:faster cable', 'machine.retire:sold']), `each change is in the audit log (${log.join(', ')})`);
  const zoomed = await fitsAtZoom(page, 'the machine settings page');
  check(zoomed.ok, zoomed.text);

  // The machines page follows machines added and retired while it is open.
  await page.getByRole('link', { name: 'Machines', exact: true }).click();
  await page.getByText('Live updates: connected').waitFor();
  await h.api('boss', 'POST', '/api/machines', { name: 'lathe-9', port: 'tcp://127.0.0.1:10', reason: 'live' });
  await page.locator('#machine-lathe-9').waitFor();
  const addedSaid = await page.locator('#machines-changed').innerText();
  await h.api('boss', 'POST', '/api/machines/lathe-9/retire', { reason: 'gone' });
  await page.locator('#machine-lathe-9').waitFor({ state: 'detached' });
  const retiredSaid = await page.locator('#machines-changed').innerText();
  check(addedSaid === 'lathe-9 was added by boss.' && retiredSaid === 'lathe-9 was retired by boss.', `the machines page shows a machine added and takes away one retired, live ("${addedSaid}", "${retiredSaid}")`);

  // An answer to the last session's request, arriving after the next login,
  // does not log the new session out (a 401 ends only the session it was for).
  let release;
  const gate = new Promise((r) => (release = r));
  let held = 0;
  await page.route('**/api/machines', async (route) => (held++ === 0 ? gate.then(() => route.continue()) : route.continue()));
  await page.getByRole('link', { name: 'Library', exact: true }).click();
  await page.getByRole('heading', { name: 'Library' }).waitFor();
  await page.getByRole('link', { name: 'Machines', exact: true }).click();
  while (held === 0) await page.waitForTimeout(50);
  await logInAs(page, 'oper');
  const late = page.waitForResponse((r) => r.url().endsWith('/api/machines'));
  release();
  const lateStatus = (await late).status();
  await page.unroute('**/api/machines');
  await page.waitForTimeout(200); // the page's handling of the late 401
  const still = await page.evaluate(() => sessionStorage.getItem('usina.token') !== null);
  await page.evaluate(() => (location.hash = '#/library'));
  await page.getByRole('heading', { name: 'Library' }).waitFor({ timeout: 5000 }).catch(() => undefined);
  const onLibrary = await page.getByRole('heading', { name: 'Library' }).isVisible();
  check(lateStatus === 401 && still && onLibrary, `a late 401 for the last session leaves the next one logged in (status ${lateStatus}, token kept ${still}, library shown ${onLibrary})`);

  const link = await page.getByRole('link', { name: 'Machine settings' }).isVisible();
  await page.goto(`${h.base}/#/machine-settings`);
  await page.getByText("the machines' settings are for admins").waitFor();
  check(!link, 'an operator has no Machine settings link and the page says it is for admins');
}
