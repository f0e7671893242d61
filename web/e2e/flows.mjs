// The browser test's second part (run.mjs runs it after the first): the
// review by role, the revisions' diffs, a send watched to 100 % while the
// control counts every byte, a part count rising on the control's punch
// and today's utilisation with it (utilisation.mjs), a start from a block.
import { readFileSync } from 'node:fs';
import { Control, text } from './control.mjs';
import { PASSWORD } from './harness.mjs';
import { toolLifeFlow } from './tools.mjs';
import { utilisationFlow } from './utilisation.mjs';

export async function logInAs(page, user) {
  if (await page.getByRole('button', { name: 'Log out' }).isVisible()) {
    await page.getByRole('button', { name: 'Log out' }).click();
  }
  await page.getByRole('heading', { name: 'Log in' }).waitFor();
  await page.getByLabel('User').fill(user);
  await page.getByLabel('Password').fill(PASSWORD);
  await page.getByLabel('Password').press('Enter');
  try {
    await page.getByRole('heading', { name: 'Library' }).waitFor();
  } catch (e) {
    // Say what the page showed instead, so a failure here can be read.
    const shown = await page.locator('#main').innerText().catch(() => '?');
    throw new Error(`${user} logged in but no Library at ${page.url()}: "${shown.slice(0, 300)}" (${e.message.split('\n')[0]})`);
  }
  await page.locator('#who', { hasText: user }).waitFor();
}

async function openProgram(page, base, name, rev) {
  await page.goto(`${base}/#/program/${name}/${rev}`);
  await page.getByRole('heading', { name: `Program ${name}` }).waitFor();
  await page.getByRole('heading', { name: 'Review' }).waitFor();
}

async function stateOf(h, name, rev) {
  const r = await h.api('boss', 'GET', `/api/programs/${name}`);
  return r.json.revisions.find((x) => x.revision === rev)?.state;
}

// The seed as uploaded cannot go to an ISO line: its typographic dash
// (line 15, W_TYPOGRAPHIC_DASH) has no tape code. The fix is a second
// revision, renumbered too (the normalised diff ignores that). It is checked
// by the admin, refused to an operator (disabled, and the server's 403 shown
// when forced), approved by an approver; the diffs of the two revisions.
export async function reviewFlow(page, h, t, seed) {
  const base = h.base;
  const first = (await h.api('boss', 'GET', '/api/programs/seed-000')).json.revisions[0].revision;
  const fixed = readFileSync(seed, 'utf8').replace('N0010 G99#', 'N0011 G99#').replace('Y\u2013250.', 'Y-250.');
  const up = await h.api('boss', 'POST', '/api/programs', { name: 'seed-000', dialect: 'romi', text: fixed, reason: 'a minus sign for the dash of line 15' });
  const second = up.json.revision;
  await openProgram(page, base, 'seed-000', second);
  await page.getByRole('button', { name: 'Mark checked' }).click();
  await page.getByRole('button', { name: 'Approve' }).waitFor();
  t.check((await stateOf(h, 'seed-000', second)) === 'checked', 'the admin marks the fixed revision checked');

  await logInAs(page, 'oper');
  await openProgram(page, base, 'seed-000', second);
  const approve = page.getByRole('button', { name: 'Approve' });
  const why = await page.locator('#why-approved').innerText();
  t.check((await approve.isDisabled()) && /approver, admin; you are operator/.test(why), `an operator's Approve is disabled, with why ("${why}")`);
  await approve.evaluate((b) => (b.disabled = false)); // as a page of a role since changed would
  await approve.click();
  const refused = await page.locator('#review-status[role="alert"]').innerText();
  t.check(/^Refused \(403\)/.test(refused) && (await stateOf(h, 'seed-000', second)) === 'checked', `the server refuses an operator's approval and the page says so ("${refused}")`);

  await logInAs(page, 'appr');
  await openProgram(page, base, 'seed-000', second);
  await page.getByLabel('Reason (needed to reject)').fill('tried on romi-1');
  await page.getByRole('button', { name: 'Approve' }).click();
  await page.getByRole('button', { name: 'Release' }).waitFor();
  t.check((await stateOf(h, 'seed-000', second)) === 'approved', 'an approver approves it with a reason');
  await t.shot(page, 'web-review.png');

  await page.getByLabel('From revision').selectOption(first);
  await page.getByLabel('To revision').selectOption(second);
  await page.getByRole('button', { name: 'Compare' }).click();
  await page.locator('.diff-panel').nth(1).waitFor();
  const norm = await page.locator('.diff-panel').nth(0).innerText();
  const plain = await page.locator('.diff-panel').nth(1).innerText();
  t.check(/^Normalised: 1 removed, 1 added/.test(norm) && /\+G1 Y-250\./.test(norm) && !/G99/.test(norm), `the normalised diff shows the dash fixed, not the renumbering (${JSON.stringify(norm.slice(0, 300))})`);
  t.check(/^Plain: 2 removed, 2 added/.test(plain) && /\+N0011 G99#/.test(plain) && /\+N0120 G1 Y-250\.#/.test(plain), `the plain diff shows both lines (${JSON.stringify(plain.slice(0, 300))})`);
  await page.evaluate(() => document.getElementById('revisions-h').scrollIntoView({ block: 'start' }));
  await t.shot(page, 'web-revisions.png', false);
  return { first, second };
}

async function machineJob(page) {
  const job = page.locator('#machine-romi-1 .job');
  return {
    id: Number(await job.getAttribute('data-job')),
    state: await job.getAttribute('data-job-state'),
    sent: Number(await job.getAttribute('data-bytes-sent')),
    total: Number(await job.getAttribute('data-bytes-total')),
  };
}

// Fills the job form and confirms in the dialog; the job's id from the page.
async function startJob(page, rev, button, at, where) {
  await page.getByLabel('Program', { exact: true }).fill('seed-000');
  await page.getByLabel('Program', { exact: true }).dispatchEvent('change');
  await page.locator('#romi-1-revision option', { hasText: rev.slice(0, 12) }).waitFor({ state: 'attached' });
  await page.getByLabel('Revision').selectOption(rev);
  await page.getByLabel('Start at').selectOption(at);
  if (where) await page.getByLabel('Block or tool').fill(where);
  await page.getByRole('button', { name: button, exact: true }).click();
  const dialog = page.getByRole('dialog');
  await dialog.waitFor();
  return dialog;
}

// The id of the job the page says it queued, once it is a job after `after`.
async function queuedJob(page, after) {
  const said = await page.waitForFunction((n) => {
    const m = /^Job (\d+) queued/.exec(document.getElementById('romi-1-job-status')?.textContent ?? '');
    return m && Number(m[1]) > n ? Number(m[1]) : 0;
  }, after);
  return said.jsonValue();
}

async function waitForEnd(page, id) {
  try {
    await page.waitForFunction((job) => {
      const j = document.querySelector('#machine-romi-1 .job');
      return j && Number(j.dataset.job) === job && j.dataset.jobState === 'done';
    }, id, { timeout: 60000 });
  } catch (e) {
    throw new Error(`job ${id} did not end: ${await page.locator('#machine-romi-1').innerText()}`);
  }
}

// A job queued behind the running drip feed (by the admin, through the API)
// is listed under it, the running job stays shown, and Remove takes the
// queued one out after asking: it ends with nothing sent.
async function removeQueued(page, h, t, rev) {
  const running = await machineJob(page);
  const queued = (await h.api('boss', 'POST', '/api/machines/romi-1/jobs', { program: 'long-drip', revision: rev, mode: 'drip' })).json.job;
  await page.locator(`#romi-1-queue li[data-job="${queued}"]`).waitFor();
  const shown = await machineJob(page);
  await page.getByRole('button', { name: `Remove job ${queued}` }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Remove' }).click();
  await page.locator(`#romi-1-queue li[data-job="${queued}"]`).waitFor({ state: 'detached' });
  const after = (await h.api('boss', 'GET', `/api/jobs/${queued}`)).json;
  t.check(shown.id === running.id && after.state === 'interrupted' && after.bytes_sent === 0 && /before it started/.test(after.reason), `a job queued behind the drip feed is listed and removed from the page (job ${queued}: ${after.state}, "${after.reason}")`);
}

// A drip feed of 25 kB (half a minute at 9600 baud) stopped from the page
// once it is under way: the job ends interrupted, the rest never sent.
async function dripAndStop(page, h, t, control) {
  let text = '';
  for (let n = 1; text.length < 25000; n++) text += `N${n} G01 X${n % 400}. Y${n % 300}. F800#\n`;
  text += 'M02#\n';
  const rev = (await h.api('boss', 'POST', '/api/programs', { name: 'long-drip', dialect: 'romi', text })).json.revision;
  for (const state of ['checked', 'approved']) await h.api('boss', 'POST', `/api/programs/long-drip/revisions/${rev}/state`, { state });
  await page.reload();
  await page.getByText('Live updates: connected').waitFor();
  await page.getByLabel('Program', { exact: true }).fill('long-drip');
  await page.getByLabel('Program', { exact: true }).dispatchEvent('change');
  await page.locator('#romi-1-revision option', { hasText: rev.slice(0, 12) }).waitFor({ state: 'attached' });
  await page.getByRole('button', { name: 'Drip feed', exact: true }).click();
  const dialog = page.getByRole('dialog');
  t.check(/Drip feed long-drip to romi-1\?/.test(await dialog.innerText()), 'Drip feed asks for confirmation');
  await dialog.getByRole('button', { name: 'Drip feed' }).click();
  await page.waitForFunction(() => Number(document.querySelector('#machine-romi-1 .job')?.dataset.bytesSent) > 0);
  // The check's cycle time of long-drip is known: what is left is by it.
  const timed = /^; \d+ s elapsed, about (\d+ min )?\d+ s left by the check's cycle time$/;
  let clock = '';
  try {
    await page.waitForFunction((re) => new RegExp(re).test(document.querySelector('#machine-romi-1 .job-time')?.textContent ?? ''), timed.source, { timeout: 10000 });
    clock = await page.locator('#machine-romi-1 .job-time').innerText();
    await page.waitForFunction((was) => document.querySelector('#machine-romi-1 .job-time')?.textContent !== was, clock, { timeout: 5000 });
  } catch {
    clock = `${clock} → ${await page.locator('#machine-romi-1 .job-time').innerText()}`;
  }
  const later = await page.locator('#machine-romi-1 .job-time').innerText();
  t.check(timed.test(clock) && timed.test(later) && later !== clock, `the running drip feed's clock moves ("${clock.slice(2)}", then "${later.slice(2)}")`);
  await removeQueued(page, h, t, rev);
  await page.getByRole('button', { name: 'Stop the job' }).click();
  await page.getByRole('dialog').getByRole('button', { name: 'Stop the job' }).click();
  await page.waitForFunction(() => document.querySelector('#machine-romi-1 .job')?.dataset.jobState === 'interrupted', null, { timeout: 60000 });
  const j = await machineJob(page);
  t.check(j.sent < j.total, `Stop ends the drip feed: interrupted after ${j.sent} of ${j.total} bytes`);
  await t.shot(page, 'web-machines-stopped.png');
  return control;
}

// A send watched to 100 % (the control counting every byte), a part punched
// back, a start from a block and from a tool change, a dialog cancelled
// from the keyboard, a drip feed stopped.
export async function machineFlow(page, h, t, first) {
  if (!h.controlPath) {
    t.check(true, 'SKIPPED the machine flow: socat is not installed');
    return;
  }
  const control = new Control(h.controlPath);
  try {
    await logInAs(page, 'oper');
    await page.getByRole('link', { name: 'Machines' }).click();
    await page.getByText('Live updates: connected').waitFor();
    // Escape answers no: nothing is sent.
    await startJob(page, first, 'Send', 'start');
    await page.keyboard.press('Escape');
    await page.getByRole('dialog').waitFor({ state: 'detached' });
    const before = (await h.api('boss', 'GET', '/api/machines/romi-1')).json.job;
    t.check(before === null && control.mark() === 0, 'Escape in the confirmation sends nothing');

    const dialog = await startJob(page, first, 'Send', 'start');
    t.check(/Send seed-000 to romi-1\?/.test(await dialog.innerText()), 'Send asks for confirmation');
    await dialog.getByRole('button', { name: 'Send' }).click();
    const id = await queuedJob(page, 0);
    const seen = new Set();
    const watch = setInterval(async () => {
      try {
        const j = await machineJob(page);
        if (j.total) seen.add(Math.floor((100 * j.sent) / j.total));
      } catch {
        /* between renders */
      }
    }, 100);
    await waitForEnd(page, id);
    clearInterval(watch);
    const job = await machineJob(page);
    const bar = page.locator('#machine-romi-1 progress');
    const full = (await bar.getAttribute('value')) === (await bar.getAttribute('max'));
    for (let i = 0; i < 100 && control.mark() < job.total; i++) await page.waitForTimeout(50);
    const got = text(control.received);
    t.check(full && job.sent === job.total && /100 %/.test(await page.locator('#machine-romi-1 .progress-text').innerText()), `the progress bar reaches 100 % (${job.sent} / ${job.total} bytes; seen ${[...seen].sort((a, b) => a - b).join(', ')} %)`);
    t.check(control.mark() === job.total && got.includes('N0230 M02#'), `the control received every byte (${control.mark()} of ${job.total})`);
    const ended = (await h.api('oper', 'GET', `/api/jobs/${id}`)).json;
    const took = await page.locator('#machine-romi-1 .job-time').innerText();
    const want = Math.round((ended.ended_at_us - ended.started_at_us) / 1e6);
    t.check(took === `; took ${want} s` || took === `; took ${Math.floor(want / 60)} min ${want % 60} s`, `the ended send says how long it took ("${took.slice(2)}", the server's ${want} s)`);
    await t.shot(page, 'web-machines.png');

    const parts = Number(await page.locator('#machine-romi-1 dd.parts').innerText());
    control.punch('%\nCYCLE TIME 83.5#\nPART COUNT 1#\n%');
    await page.waitForFunction((n) => Number(document.querySelector('#machine-romi-1 dd.parts')?.textContent) > n, parts);
    const cycle = await page.locator('#machine-romi-1 dd.cycle').innerText();
    t.check(cycle === '83.5 s', `the part count rises when the control reports a part (from ${parts}; last cycle ${cycle})`);
    await utilisationFlow(page, h, t, first);
    await t.shot(page, 'web-utilisation.png', false);
    await toolLifeFlow(page, h, t);
    await t.shot(page, 'web-tools.png', false);

    const mark = control.mark();
    const d2 = await startJob(page, first, 'Send', 'block', 'N0150');
    t.check(/from block N0150/.test(await d2.innerText()), 'the confirmation names the block');
    await d2.getByRole('button', { name: 'Send' }).click();
    const id2 = await queuedJob(page, id);
    await waitForEnd(page, id2);
    const restart = await machineJob(page);
    for (let i = 0; i < 100 && control.mark() - mark < restart.total; i++) await page.waitForTimeout(50);
    const sent = text(control.since(mark));
    t.check(id2 > id && restart.total < job.total && sent.includes('N0150') && !sent.includes('N0120 G1'), `a start from block N0150 sends the restart program (${restart.total} bytes)`);
    const mark2 = control.mark();
    const d3 = await startJob(page, first, 'Send', 'tool', '2');
    t.check(/from the change to tool 2/.test(await d3.innerText()), 'the confirmation names the tool');
    await d3.getByRole('button', { name: 'Send' }).click();
    const id3 = await queuedJob(page, id2);
    await waitForEnd(page, id3);
    const fromTool = await machineJob(page);
    for (let i = 0; i < 100 && control.mark() - mark2 < fromTool.total; i++) await page.waitForTimeout(50);
    const sentT = text(control.since(mark2));
    t.check(fromTool.total < restart.total && sentT.includes('T02 M06') && !sentT.includes('N0150'), `a start from the change to tool 2 sends from there on (${fromTool.total} bytes)`);

    await dripAndStop(page, h, t, control);
    const audit = (await h.api('boss', 'GET', '/api/audit')).json;
    const made = audit.entries.filter((e) => e.action === 'job.create' && e.actor === 'oper').length;
    const stopped = audit.entries.filter((e) => e.action === 'job.interrupted' && /stopped by oper/.test(e.reason)).length;
    t.check(made === 4 && stopped === 2, `the audit log holds the operator's four jobs (${made}), the stop and the removal from the queue (${stopped})`);
  } finally {
    control.close();
  }
}

// The library's count once its table shows the page it last asked for
// (the table is aria-busy from a change of the search or a filter until then).
export async function listed(page) {
  await page.locator('#library-table[aria-busy="false"]').waitFor();
  return page.locator('#library-count').innerText();
}

// "N programs" as a number.
const counted = (text) => Number(text.match(/^(\d+) programs?$/)?.[1] ?? NaN);

// The library's filters and pages: 60 small rs274ngc programs of the class
// `lathe` beside the ROMI ones.
export async function libraryFlow(page, h, t) {
  for (let i = 0; i < 60; i++) {
    const name = `L${String(i).padStart(3, '0')}`;
    const r = await h.api('boss', 'POST', '/api/programs', { name, dialect: 'rs274ngc', machine_class: 'lathe', text: `G0 X${i} Z1\nG1 Z0 F100\nM2\n` });
    if (r.status !== 201) throw new Error(`upload ${name}: ${r.status}`);
  }
  await page.getByRole('link', { name: 'Library' }).click();
  await page.getByRole('heading', { name: 'Library' }).waitFor();
  const rows = () => page.locator('table[aria-label="Programs"] tbody tr').count();
  const total = counted(await listed(page));
  t.check((await rows()) === 50 && (await page.locator('#library-page').innerText()) === `Page 1 of ${Math.ceil(total / 50)}`, `the library shows its first 50 of ${total} programs`);
  await page.getByLabel('Filter by dialect').selectOption('romi');
  const romi = await listed(page);
  t.check(counted(romi) === total - 60 && (await rows()) === total - 60, `the dialect filter leaves the ROMI programs (${romi})`);
  await page.getByLabel('Filter by dialect').selectOption('');
  await listed(page);
  await page.getByLabel('Filter by machine class').selectOption('lathe');
  await listed(page);
  await page.getByRole('button', { name: 'Next page' }).click();
  await listed(page);
  t.check((await page.locator('#library-page').innerText()) === 'Page 2 of 2' && (await rows()) === 10 && (await page.getByRole('button', { name: 'Next page' }).isDisabled()), 'the class filter and the next page: the last 10 lathe programs');
  await page.getByRole('button', { name: 'Previous page' }).click();
  await listed(page);
  t.check((await page.locator('#library-page').innerText()) === 'Page 1 of 2' && (await rows()) === 50, 'the previous page: the first 50 lathe programs');
  await page.getByLabel('Filter by machine class').selectOption('');
  await listed(page);
  // Every lathe program is a draft; the ROMI ones went on along the states.
  await page.getByLabel('Filter by state').selectOption('draft');
  const drafts = await listed(page);
  const draftRows = counted(drafts);
  const listedDrafts = await h.api('boss', 'GET', '/api/programs?state=draft');
  t.check(draftRows >= 60 && draftRows === listedDrafts.json.total, `the state filter leaves the programs whose newest revision is a draft (${drafts}; the server counts ${listedDrafts.json.total})`);
  // L000 released through the API: the list is read when the page opens.
  const l000 = (await h.api('boss', 'GET', '/api/programs/L000')).json.revisions[0].revision;
  for (const state of ['checked', 'approved', 'released']) {
    const moved = await h.api('boss', 'POST', `/api/programs/L000/revisions/${l000}/state`, { state, reason: 'e2e' });
    if (moved.status !== 200) throw new Error(`L000 to ${state}: ${moved.status}`);
  }
  await page.getByRole('link', { name: 'Machines' }).click();
  await page.getByRole('link', { name: 'Library' }).click();
  await page.getByRole('heading', { name: 'Library' }).waitFor();
  await page.getByLabel('Filter by state').selectOption('has a released revision');
  const released = await h.api('boss', 'GET', '/api/programs?released=1');
  const shown = await listed(page);
  t.check(released.json.total >= 1 && (await page.getByRole('link', { name: 'L000' }).count()) === 1 && counted(shown) === released.json.total, `the released filter (${shown}; the server counts ${released.json.total})`);
  await page.getByLabel('Filter by state').selectOption('');
  await listed(page);
  await t.shot(page, 'web-library.png');
}

// At 200 % zoom a 1280 × 860 window is 640 × 430 CSS pixels: every page
// must fit its width (no sideways scrolling), the layout wrapping instead.
export async function zoomFlow(page, h, t, rev) {
  await page.setViewportSize({ width: 640, height: 430 });
  const pages = [['library', 'Library'], ['machines', 'Machines'], [`program/seed-000/${rev}`, 'Program seed-000'], ['new', 'New program']];
  for (const [hash, heading] of pages) {
    await page.goto(`${h.base}/#/${hash}`);
    await page.getByRole('heading', { name: heading, exact: true }).waitFor();
    if (hash.startsWith('program')) await page.locator('#stats').waitFor();
    const [scroll, client] = await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.clientWidth]);
    t.check(scroll <= client, `at 200 % zoom the ${heading} page fits its width (${scroll} of ${client} px)`);
  }
  await page.setViewportSize({ width: 1280, height: 860 });
}
