// Browser test of `vplant classroom` (docs/classroom.md) in Debian's headless Chromium (driven by
// playwright-core): two seats and the trainer. The trainee opens seat 1's link (the token becomes
// a cookie) and starts the plant by NMT from the page; the trainer's overview, opened from its own
// link, shows seat 1's nodes OPERATIONAL and seat 2's PRE-OPERATIONAL, and after giving every seat
// the `nmt` exercise, seat 1's first step done and none of seat 2's; the trainer's read-only
// view of seat 2 is refused a command; seat 2's page is closed to seat 1's cookie. Screenshots of
// the overview and a seat at 1366×768 and 1920×1080 go to --screenshots DIR (classroom-*.png).
//   node classroom.e2e.cjs --vplant BIN --scenario FILE --screenshots DIR
import assert from 'node:assert/strict';
import { ChildProcess, spawn } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { Browser, BrowserContext, chromium, Page } from 'playwright-core';

function option(name: string): string | undefined {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : undefined;
}
const vplant = option('--vplant');
const scenario = option('--scenario');
const screenshots = option('--screenshots');
if (!vplant || !scenario || !screenshots) {
  console.error('usage: classroom.e2e.cjs --vplant BIN --scenario FILE --screenshots DIR');
  process.exit(2);
}

const CHROMIUM = '/usr/bin/chromium';
const WAIT_MS = 20_000;
const WATCHDOG_MS = 150_000;
const SIZES = [
  { width: 1366, height: 768 },
  { width: 1920, height: 1080 },
];

let server: ChildProcess | undefined;
let serverLog = '';
let browser: Browser | undefined;
let trainer: BrowserContext, trainee: BrowserContext;
let overview: Page, seat1: Page;
const links: string[] = [];  // [0] the trainer's, [k] seat k's
const pageErrors: string[] = [];

/** Starts the classroom and resolves once it printed every link. */
function startServer(): Promise<void> {
  return new Promise((resolve, reject) => {
    const child = spawn(vplant!, ['classroom', scenario!, '--seats', '2', '--ui', '127.0.0.1:0'], { stdio: ['ignore', 'pipe', 'pipe'] });
    server = child;
    const timer = setTimeout(() => reject(new Error(`vplant classroom printed no links within 30 s:\n${serverLog}`)), 30_000);
    const onData = (d: Buffer) => {
      serverLog += d.toString();
      for (const m of serverLog.matchAll(/(trainer|seat (\d+)): (http:\/\/\S+)/g)) links[m[2] ? Number(m[2]) : 0] = m[3];
      if (links[0] && links[1] && links[2]) {
        clearTimeout(timer);
        resolve();
      }
    };
    child.stdout!.on('data', onData);
    child.stderr!.on('data', onData);
    child.once('exit', (code, signal) => {
      clearTimeout(timer);
      reject(new Error(`vplant classroom exited (${code ?? signal}) before it served:\n${serverLog}`));
    });
  });
}

function killServer(): void {
  if (server && server.exitCode === null && server.signalCode === null) server.kill('SIGKILL');
}
process.on('exit', killServer);
for (const sig of ['SIGINT', 'SIGTERM'] as const) process.on(sig, () => { killServer(); process.exit(1); });
setTimeout(() => {
  console.error(`classroom e2e: no end after ${WATCHDOG_MS / 1000} s; server log:\n${serverLog}`);
  killServer();
  process.exit(1);
}, WATCHDOG_MS).unref();

/** A request from the page, as its own scripts would make it (relative URL, the page's cookies). */
function fetchStatus(page: Page, method: string, path: string, body?: object): Promise<number> {
  return page.evaluate(
    async ([m, p, b]) => (await fetch(p as string, { method: m as string, headers: { 'Content-Type': 'application/json' }, body: b as string | undefined })).status,
    [method, path, body ? JSON.stringify(body) : undefined],
  );
}

async function shots(page: Page, name: string): Promise<void> {
  for (const size of SIZES) {
    await page.setViewportSize(size);
    await page.waitForTimeout(300);
    await page.screenshot({ path: join(screenshots!, `classroom-${name}-${size.width}x${size.height}.png`) });
  }
}

before(async () => {
  mkdirSync(screenshots!, { recursive: true });
  await startServer();
  browser = await chromium.launch({
    executablePath: CHROMIUM,
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
  // Two browsers' worth of cookies: the trainer's and a trainee's.
  trainer = await browser.newContext({ viewport: SIZES[0] });
  trainee = await browser.newContext({ viewport: SIZES[0] });
  for (const c of [trainer, trainee]) c.setDefaultTimeout(WAIT_MS);
  overview = await trainer.newPage();
  seat1 = await trainee.newPage();
  for (const p of [overview, seat1]) p.on('pageerror', (e) => pageErrors.push(e.message));
});

after(async () => {
  if (overview) await overview.screenshot({ path: join(screenshots!, 'classroom-final.png'), fullPage: true }).catch(() => undefined);
  await browser?.close();
  if (server && server.exitCode === null) {
    server.kill('SIGINT');
    await new Promise<void>((resolve) => {
      const t = setTimeout(() => { server!.kill('SIGKILL'); resolve(); }, 5000);
      server!.once('exit', () => { clearTimeout(t); resolve(); });
    });
  }
});

test('a seat link opens the seat page, its token kept as a cookie the scripts cannot read', async () => {
  await seat1.goto(links[1]);
  assert.equal(new URL(seat1.url()).pathname, '/seats/1/');
  assert.equal(new URL(seat1.url()).search, '');
  await seat1.getByTestId('scenario-name').filter({ hasText: 'reference' }).waitFor();
  assert.equal(await seat1.evaluate(() => document.cookie), '');
  const cookies = await trainee.cookies();
  assert.equal(cookies.length, 1);
  assert.equal(cookies[0].httpOnly, true);
  assert.equal(cookies[0].sameSite, 'Strict');
  assert.equal(cookies[0].path, '/seats/1/');
});

test('the seat cookie opens only its seat', async () => {
  assert.equal(await fetchStatus(seat1, 'GET', '/seats/2/api/nodes'), 401);
  assert.equal(await fetchStatus(seat1, 'GET', '/api/seats'), 401);
  assert.equal(await fetchStatus(seat1, 'GET', 'api/nodes'), 200);
});

test('the trainee starts seat 1; the overview shows it, seat 2 stays PRE-OPERATIONAL', async () => {
  // Every node of seat 1 has booted before the start (one still initialising ignores it).
  await seat1.waitForFunction(async () => {
    const nodes = (await (await fetch('api/nodes')).json()) as { nmt: string }[];
    return nodes.length > 0 && nodes.every((n) => n.nmt === 'PRE-OPERATIONAL');
  });
  assert.equal(await fetchStatus(seat1, 'POST', 'api/nmt', { command: 'start', node: 0 }), 200);
  await overview.goto(links[0]);
  assert.equal(new URL(overview.url()).pathname, '/');
  const s1 = overview.getByTestId('seat-1'), s2 = overview.getByTestId('seat-2');
  await s1.getByTestId('node-dsv').filter({ hasText: 'OPERATIONAL' }).filter({ hasNotText: 'PRE-' }).waitFor();
  await s1.getByTestId('node-vtvpcd').filter({ hasText: 'OPERATIONAL' }).filter({ hasNotText: 'PRE-' }).waitFor();
  for (const node of ['vtvpcd', 'dsv', 'md2', 'hlt', 'wdga'])
    assert.match((await s2.getByTestId(`node-${node}`).textContent()) ?? '', /PRE-OPERATIONAL/);
});

test('the trainer gives every seat the nmt exercise; the overview shows each seat its own progress', async () => {
  await overview.getByTestId('exercise-choice').selectOption('nmt');
  await overview.getByTestId('give-exercise').click();
  await overview.getByTestId('messages').filter({ hasText: 'Every seat has the exercise "nmt"' }).waitFor();
  // Seat 1's DSV is OPERATIONAL already: its first step ("Start the DSV") is done; seat 2 has none.
  const s1 = overview.getByTestId('seat-1'), s2 = overview.getByTestId('seat-2');
  await s1.getByTestId('progress').filter({ hasText: '1/5 steps done' }).waitFor();
  await s2.getByTestId('progress').filter({ hasText: '0/5 steps done' }).waitFor();
  // The trainee's page (under /seats/1/) shows the exercise with its first step done.
  await seat1.getByTestId('exercise-step-1').and(seat1.locator('[data-status="done"]')).waitFor();
  await shots(overview, 'overview');
  await shots(seat1, 'seat1');
});

test('the trainee completes dsp408 by clicking in the lesson view; the overview shows the progress', async () => {
  await seat1.getByTestId('node-row-dsv').click();
  await seat1.getByTestId('view-toggle').click();
  await seat1.getByTestId('exercise-choice').selectOption('dsp408');
  const done = (n: number) => seat1.getByTestId(`exercise-step-${n}`).and(seat1.locator('[data-status="done"]')).waitFor();
  // Each step by the page's own buttons: control words by SDO, then NMT to the selected node.
  const steps: [number, string[]][] = [
    [1, ['cw-preset-0x0001']], [2, ['cw-preset-0x0003']], [3, ['cw-preset-0x0007']],
    [4, ['cw-preset-0x0000']], [5, ['cw-preset-0x0007']], [6, ['nmt-start', 'nmt-stop']],
  ];
  for (const [n, buttons] of steps) {
    for (const b of buttons) await seat1.getByTestId(b).click();
    await done(n);
  }
  await seat1.getByTestId('transition-list').locator('tr[data-transition="TR_8"]').first().waitFor();
  // The DSV's DSP 408 diagram stays whole beside the open exercise.
  const whole = await seat1.evaluate(() => {
    const d = document.querySelector('[data-machine=dsp408] svg')!.getBoundingClientRect();
    const p = document.getElementById('detail-section')!.getBoundingClientRect();
    return d.height >= 100 && d.top >= p.top && d.bottom <= p.bottom + 1;
  });
  assert.ok(whole, 'the DSP 408 diagram is cut off in the lesson view');
  await shots(seat1, 'seat1-dsp408-done');
  // The trainer sees seat 1 through; seat 2 (still on nmt) has none of it.
  const s1 = overview.getByTestId('seat-1');
  await s1.getByTestId('progress').filter({ hasText: '6/6 steps done' }).waitFor();
  await shots(overview, 'overview-dsp408');
});

test("the trainer's view of a seat is read-only", async () => {
  const [view] = await Promise.all([trainer.waitForEvent('page'), overview.getByTestId('seat-2').getByTestId('view').click()]);
  view.on('pageerror', (e) => pageErrors.push(e.message));
  await view.waitForURL(/\/seats\/2\/$/);
  await view.getByTestId('scenario-name').filter({ hasText: 'reference' }).waitFor();
  assert.equal(await fetchStatus(view, 'GET', 'api/nodes'), 200);
  assert.equal(await fetchStatus(view, 'POST', 'api/nmt', { command: 'start', node: 0 }), 403);
  await view.close();
});

test('the trainer restarts a seat from the overview (or is told why not)', async () => {
  await overview.getByTestId('seat-2').getByTestId('restart').click();
  await overview.getByTestId('messages').filter({ hasText: /Seat 2/ }).waitFor();
});

test('no page error', () => {
  assert.deepEqual(pageErrors, []);
});
