// Browser end-to-end test of the dashboard in real headless Chromium (Debian's /usr/bin/chromium,
// driven by playwright-core; no browser is ever downloaded). It starts
//   vplant run scenarios/reference-plant.yaml --no-script --ui PORT
// (virtual time), and, as a trainee would, from the page: sees five nodes, starts them by NMT,
// drives the DSV to DEVICE_MODE_ACTIVE by writing its control word, sees the state highlight and
// the decoded SDO in the trace, sees the cylinder plot rise, injects "magnet lost" on the HLT 1100
// and reads the decoded EMCY, clears the fault, steps the virtual clock, and exports the trace.
// Screenshots go to --screenshots DIR (and with --docs-images DIR also there, for docs/dashboard.md).
//   node dashboard.e2e.cjs --vplant BIN --scenario FILE --screenshots DIR [--docs-images DIR]
import assert from 'node:assert/strict';
import { ChildProcess, spawn } from 'node:child_process';
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
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
const docsImages = option('--docs-images');
if (!vplant || !scenario || !screenshots) {
  console.error('usage: dashboard.e2e.cjs --vplant BIN --scenario FILE --screenshots DIR [--docs-images DIR]');
  process.exit(2);
}

const CHROMIUM = '/usr/bin/chromium';
const WAIT_MS = 20_000;
// Below ctest's TIMEOUT: a hung run still kills the server it started instead of leaving it behind.
const WATCHDOG_MS = 280_000;

let server: ChildProcess | undefined;
let serverLog = '';
let context: BrowserContext | undefined;
let page: Page;
let profileDir = '';
const pageErrors: string[] = [];

function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const s = createServer();
    s.once('error', reject);
    s.listen(0, '127.0.0.1', () => {
      const port = (s.address() as { port: number }).port;
      s.close(() => resolve(port));
    });
  });
}

/** Starts vplant and resolves with the URL it prints when it is ready. */
function startServer(port: number): Promise<string> {
  return new Promise((resolve, reject) => {
    const child = spawn(vplant!, ['run', scenario!, '--no-script', '--ui', String(port)], { stdio: ['ignore', 'pipe', 'pipe'] });
    server = child;
    const timer = setTimeout(() => reject(new Error(`vplant did not print its URL within 30 s:\n${serverLog}`)), 30_000);
    const onData = (d: Buffer) => {
      serverLog += d.toString();
      const m = serverLog.match(/http:\/\/(127\.0\.0\.1|localhost):(\d+)\/?/);
      if (m && Number(m[2]) === port) {
        clearTimeout(timer);
        resolve(`http://127.0.0.1:${port}/`);
      }
    };
    child.stdout!.on('data', onData);
    child.stderr!.on('data', onData);
    child.once('exit', (code, signal) => {
      clearTimeout(timer);
      reject(new Error(`vplant exited (${code ?? signal}) before it served the page:\n${serverLog}`));
    });
  });
}

/** A screenshot of the viewport with the section `anchor` at the top (or the top of the page). */
async function shot(name: string, anchor?: string): Promise<void> {
  await page.evaluate((id) => (id ? document.getElementById(id)?.scrollIntoView() : window.scrollTo(0, 0)), anchor);
  await page.waitForTimeout(300);  // a plot redraw (5 per second) after the scroll
  const file = join(screenshots!, `${name}.png`);
  await page.screenshot({ path: file, fullPage: false });
  if (docsImages) copyFileSync(file, join(docsImages, `dashboard-${name}.png`));
}

const byTestId = (id: string) => page.getByTestId(id);

// The reference plant lasts 6 s; with --ui the virtual clock pauses there (end_reached) and Resume
// goes on. Like a trainer, the test resumes it whenever that happens, except in the clock test.
let autoResume = true;
let resuming: Promise<unknown> = Promise.resolve();
const resumer = setInterval(() => {
  if (!autoResume || !page) return;
  resuming = page.evaluate(async () => {
    const c = await (await fetch('/api/clock')).json();
    if (c.paused && c.end_reached) {
      await fetch('/api/clock', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"action":"resume"}' });
    }
  }).catch(() => undefined);
}, 250);

function killServer(): void {
  if (server && server.exitCode === null && server.signalCode === null) server.kill('SIGKILL');
}
process.on('exit', killServer);
for (const sig of ['SIGINT', 'SIGTERM'] as const) process.on(sig, () => { killServer(); process.exit(1); });
setTimeout(() => {
  console.error(`dashboard e2e: no end after ${WATCHDOG_MS / 1000} s; server log:\n${serverLog}`);
  killServer();
  process.exit(1);
}, WATCHDOG_MS).unref();

before(async () => {
  mkdirSync(screenshots!, { recursive: true });
  if (docsImages) mkdirSync(docsImages, { recursive: true });
  const port = await freePort();
  const url = await startServer(port);
  profileDir = mkdtempSync(join(tmpdir(), 'vplant-chromium-'));
  // A fresh profile each run (playwright passes it as --user-data-dir).
  context = await chromium.launchPersistentContext(profileDir, {
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run'],
    viewport: { width: 1400, height: 1000 },
    acceptDownloads: true,
  });
  context.setDefaultTimeout(WAIT_MS);
  page = context.pages()[0] ?? await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  await page.goto(url);
});

after(async () => {
  clearInterval(resumer);
  // What the page showed last, for a failed run: its screenshot and its status line.
  if (page) {
    await page.screenshot({ path: join(screenshots!, 'final.png'), fullPage: true }).catch(() => undefined);
    console.log(`page status line: ${await byTestId('messages').textContent().catch(() => '?')}`);
  }
  await context?.close();
  if (server && server.exitCode === null) {
    server.kill('SIGTERM');
    await new Promise<void>((resolve) => {
      const t = setTimeout(() => { server!.kill('SIGKILL'); resolve(); }, 5000);
      server!.once('exit', () => { clearTimeout(t); resolve(); });
    });
  }
  if (profileDir) rmSync(profileDir, { recursive: true, force: true });
});

test('the page shows the five nodes of the reference plant', async () => {
  await page.waitForSelector('[data-testid=node-table] tbody tr');
  assert.equal(await page.locator('[data-testid=node-table] tbody tr').count(), 5);
  for (const name of ['vtvpcd', 'dsv', 'md2', 'hlt', 'wdga']) await byTestId(`node-row-${name}`).waitFor();
  await page.waitForFunction(() => document.querySelector('[data-testid=connection]')?.textContent === 'live');
  // With --ui, virtual time may start paused (the trainer starts it): start it from the page.
  await page.waitForFunction(() => ['paused', 'running'].includes(document.querySelector('[data-testid=clock-state]')?.textContent ?? ''));
  if ((await byTestId('clock-state').textContent()) === 'paused') await byTestId('clock-resume').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'running');
  await page.waitForFunction(() => document.querySelector('[data-testid=nmt-dsv]')?.textContent === 'PRE-OPERATIONAL');
  assert.deepEqual(pageErrors, []);
  await shot('overview-preop');
});

test('NMT start from the page brings every node to OPERATIONAL', async () => {
  await byTestId('nmt-target').selectOption('');
  await byTestId('nmt-start').click();
  for (const name of ['vtvpcd', 'dsv', 'md2', 'hlt', 'wdga']) {
    await page.waitForFunction((n) => document.querySelector(`[data-testid=nmt-${n}]`)?.textContent === 'OPERATIONAL', name);
  }
  await byTestId('node-row-dsv').click();
  await page.waitForSelector('[data-testid=diagram-nmt] [data-state=OPERATIONAL][data-current=true]');
  await page.waitForSelector('[data-testid=transition-list] tbody tr[data-machine=nmt][data-transition="NMT 01h"]');
  // The trace decodes the NMT command the page sent.
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr[data-service=NMT] td.decoded')]
    .some((td) => /start/i.test(td.textContent ?? '')));
});

test('control word 0x0007 by SDO drives the DSV to DEVICE_MODE_ACTIVE', async () => {
  await byTestId('node-row-dsv').click();
  await byTestId('cw-preset-0x0007').click();
  await page.waitForFunction(() => /DEVICE_MODE_ACTIVE/.test(document.querySelector('[data-testid=device-dsv]')?.textContent ?? ''));
  // The SDO download and its response, decoded with the object's name.
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr td.decoded')]
    .some((td) => /6040:00/.test(td.textContent ?? '') && /control ?word/i.test(td.textContent ?? '')));
  await shot('dsv-active', 'detail-section');
});

/** Pairs of a diagram's labels that cover each other or a state box (SVG user units, as drawn). */
async function labelCollisions(p: Page, testid: string): Promise<string[]> {
  return p.$$eval(`[data-testid=${testid}]`, (roots) => {
    const out: string[] = [];
    for (const root of roots) {
      const box = (e: Element) => (e as SVGGraphicsElement).getBBox();
      const hit = (a: DOMRect, b: DOMRect) => Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x) > 0.5 &&
        Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y) > 0.5;
      const labels = [...root.querySelectorAll('.edge-label')].map((e) => ({ name: e.textContent ?? '', b: box(e) }));
      const states = [...root.querySelectorAll('.state rect')].map((e) => ({ name: e.parentElement?.getAttribute('data-state') ?? '', b: box(e) }));
      labels.forEach((l, i) => {
        for (const o of labels.slice(i + 1)) if (hit(l.b, o.b)) out.push(`${l.name} / ${o.name}`);
        for (const s of states) if (hit(l.b, s.b)) out.push(`${l.name} / state ${s.name}`);
      });
    }
    return out;
  });
}

test('exercise 2 step 2: one write of 0x0000 from DEVICE_MODE_ACTIVE highlights TR_5, TR_6, TR_7, each on its own', async () => {
  await byTestId('node-row-dsv').click();
  await page.waitForSelector('[data-testid=diagram-dsp408] [data-state=DEVICE_MODE_ACTIVE][data-current=true]');
  await byTestId('cw-preset-0x0000').click();
  await page.waitForSelector('[data-testid=diagram-dsp408] [data-state=INIT][data-current=true]');
  const marked = () => page.$$eval('[data-testid=diagram-dsp408] .edge.last', (es) =>
    es.map((e) => ({ step: Number(e.getAttribute('data-step')), tr: e.getAttribute('data-transition') })).sort((a, b) => a.step - b.step).map((e) => e.tr));
  await page.waitForFunction(() => document.querySelectorAll('[data-testid=diagram-dsp408] .edge.last').length === 3);
  assert.deepEqual(await marked(), ['TR_5', 'TR_6', 'TR_7']);
  assert.equal(await page.locator('[data-testid=diagram-dsp408] .state.current').count(), 1);
  // The transition list: three rows of the same write, newest first, the control word as cause.
  const rows = await page.locator('[data-testid=transition-list] tbody tr[data-machine=dsp408]').evaluateAll((trs) =>
    trs.slice(0, 3).map((tr) => ({ tr: tr.getAttribute('data-transition'), cause: tr.querySelector('td.cause')?.textContent ?? '' })));
  assert.deepEqual(rows.map((r) => r.tr), ['TR_7', 'TR_6', 'TR_5']);
  for (const r of rows) assert.match(r.cause, /0x0000/);
  assert.match((await byTestId('last-change-dsp408').textContent()) ?? '', /TR_5, TR_6, TR_7/);
  // Every label legible: none covers another or a state (the numbered steps included).
  assert.deepEqual(await labelCollisions(page, 'diagram-dsp408'), []);
  assert.deepEqual(await labelCollisions(page, 'diagram-nmt'), []);
  await shot('dsv-tr567', 'detail-section');
  // And back: 0x0007 from INIT walks TR_2, TR_3, TR_4.
  await byTestId('cw-preset-0x0007').click();
  await page.waitForSelector('[data-testid=diagram-dsp408] [data-state=DEVICE_MODE_ACTIVE][data-current=true]');
  await page.waitForFunction(() => document.querySelectorAll('[data-testid=diagram-dsp408] .edge.last').length === 3);
  assert.deepEqual(await marked(), ['TR_2', 'TR_3', 'TR_4']);
});

test('an SDO write the node refuses shows the abort code and its text', async () => {
  // 6300h:01 (vpoc set point) is an INTEGER16 limited to -16384..16384: 20000 fits the type, so it
  // goes on the bus, and the DSV answers with an abort.
  await byTestId('node-row-dsv').click();
  await byTestId('od-filter').fill('6300');
  await byTestId('od-input-6300-01').fill('20000');
  await byTestId('od-write-6300-01').click();
  await page.waitForFunction(() => /refused by the node: abort 0x0609003[0-2] \S/.test(document.querySelector('[data-testid=od-result]')?.textContent ?? ''));
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr td.decoded')]
    .some((td) => /abort/i.test(td.textContent ?? '') && /0609003[0-2]/.test(td.textContent ?? '')));
  await byTestId('od-filter').fill('');
});

test('the cylinder plot rises when the pump delivers and the DSV opens; plots and node table read in bar and mm', async () => {
  const position = () => page.evaluate(() => {
    const el = document.querySelector('[data-testid="plot-value-cyl.position"]');
    const m = (el?.textContent ?? '').match(/= (-?[\d.e+-]+)/);
    return m ? Number(m[1]) : NaN;
  });
  await page.waitForFunction(() => /= /.test(document.querySelector('[data-testid="plot-value-cyl.position"]')?.textContent ?? ''));
  const start = await position();
  // Pump swivel angle command 50 % (VT-VPCD 2C72h), through the object-dictionary browser.
  await byTestId('node-row-vtvpcd').click();
  await byTestId('od-filter').fill('2c72');
  await byTestId('od-input-2C72-00').fill('16384');
  await byTestId('od-write-2C72-00').click();
  await page.waitForFunction(() => /done/.test(document.querySelector('[data-testid=od-result]')?.textContent ?? ''));
  // DSV spool set point 50 % (6300h:01), likewise.
  await byTestId('node-row-dsv').click();
  await byTestId('od-filter').fill('6300');
  await byTestId('od-input-6300-01').fill('8192');
  await byTestId('od-write-6300-01').click();
  await page.waitForFunction(() => /6300:01.*done/.test(document.querySelector('[data-testid=od-result]')?.textContent ?? ''));
  await page.waitForFunction((s) => {
    const m = (document.querySelector('[data-testid="plot-value-cyl.position"]')?.textContent ?? '').match(/= (-?[\d.e+-]+)/);
    return m !== null && Number(m[1]) > s + 50;  // mm
  }, start, { timeout: 30_000 });
  await byTestId('od-filter').fill('');
  // Display units: the plots and the node table in bar and mm, never raw SI or e-notation.
  assert.match((await byTestId('plot-value-cyl.position').textContent()) ?? '', /^= -?\d+(\.\d+)? mm$/);
  assert.match((await byTestId('plot-value-p_supply.pressure').textContent()) ?? '', /^= -?\d+(\.\d+)? bar$/);
  await page.waitForFunction(() => /position -?\d+(\.\d+)? mm/.test(document.querySelector('[data-testid=values-hlt]')?.textContent ?? ''));
  await page.waitForFunction(() => /pressure_a -?\d+(\.\d+)? bar/.test(document.querySelector('[data-testid=values-vtvpcd]')?.textContent ?? ''));
  await shot('cylinder-rising', 'plots-section');
});

test('"magnet lost" on the HLT 1100: the decoded EMCY, then the fault cleared', async () => {
  await byTestId('node-row-hlt').click();
  await byTestId('fault-inject-hlt-magnet_lost').click();
  await page.waitForSelector('[data-testid=active-faults] [data-testid^=active-fault-]');
  await page.waitForFunction(() => (document.querySelector('[data-testid=emcy-hlt]')?.textContent ?? '') !== '');
  // The last EMCY in the product's words (the HLT 1100 manual's FF00h), the code said once.
  assert.match((await byTestId('emcy-hlt').textContent()) ?? '', /^FF00h position error: no magnet detected; register: /);
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr[data-service=EMCY] td.decoded')]
    .some((td) => /EMCY/.test(td.textContent ?? '')));
  const emcyText = await page.locator('[data-testid=trace-table] tbody tr[data-service=EMCY] td.decoded').first().textContent();
  assert.match(emcyText ?? '', /EMCY/);
  await page.waitForSelector('[data-testid=emcy-list] li');
  // The node table names the alarm bit (the name served by the device, not a hex word), and the
  // transition list names the fault with its EMCY code as the cause.
  await page.waitForFunction(() => /alarms: position error/.test(document.querySelector('[data-testid=device-hlt]')?.textContent ?? ''));
  assert.match((await byTestId('device-hlt').textContent()) ?? '', /status: .*warnings: none/s);
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=transition-list] tbody tr[data-machine="cia406.alarms"] td.cause')]
    .some((td) => /device fault position error \(EMCY [0-9A-F]{4}h\)/.test(td.textContent ?? '')));
  await shot('hlt-magnet-lost');
  await byTestId('trace-service-EMCY').waitFor();
  await shot('trace-emcy', 'trace-section');
  await page.locator('[data-testid^=fault-clear-]').first().click();
  await page.waitForFunction(() => document.querySelectorAll('[data-testid=active-faults] [data-testid^=active-fault-]').length === 0);
});

test('a heartbeat consumer (exercise 3): the link dropped, EMCY 8130h decoded, the link back, EMCY 0000h', async () => {
  const odWrite = async (node: string, filter: string, id: string, value: string) => {
    await byTestId(`node-row-${node}`).click();
    await byTestId('od-filter').fill(filter);
    await byTestId(`od-input-${id}`).fill(value);
    await byTestId(`od-write-${id}`).click();
    await page.waitForFunction((i) => new RegExp(`${i.replace('-', ':')}.*done`).test(document.querySelector('[data-testid=od-result]')?.textContent ?? ''), id);
  };
  await odWrite('dsv', '1017', '1017-00', '100');              // the DSV's heartbeat every 100 ms
  await odWrite('wdga', '1016', '1016-01', '0x000201F4');      // the WDGA watches node 2, 500 ms
  await byTestId('od-filter').fill('');
  await page.waitForTimeout(300);  // monitoring starts with the DSV's next heartbeat
  // Break the link: drop 702h on the wire.
  await byTestId('wire-match').fill('0x702');
  await byTestId('wire-action').selectOption('drop');
  await byTestId('wire-inject').click();
  await page.waitForSelector('[data-testid=active-faults] [data-testid^=active-fault-]');
  await page.waitForFunction(() => /^8130h/.test(document.querySelector('[data-testid=emcy-wdga]')?.textContent ?? ''));
  await page.waitForFunction(() => (parseInt((document.querySelector('[data-testid=errreg-wdga]')?.textContent ?? '0x0').slice(2), 16) & 0x10) !== 0);
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr[data-service=EMCY] td.decoded')]
    .some((td) => /8130/.test(td.textContent ?? '')));
  // The WDGA's own reaction (1029h:01 = 0): OPERATIONAL → PRE-OPERATIONAL, the missed heartbeat as cause.
  await byTestId('node-row-wdga').click();
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=transition-list] tbody tr[data-machine=nmt]')]
    .some((tr) => /OPERATIONAL → PRE-OPERATIONAL/.test(tr.textContent ?? '') && /heartbeat/i.test(tr.querySelector('td.cause')?.textContent ?? '')));
  await shot('heartbeat-consumer-fault', 'trace-section');
  // Recover: the next heartbeat reaches the WDGA, which sends the error reset.
  await page.locator('[data-testid^=fault-clear-]').first().click();
  await page.waitForFunction(() => document.querySelectorAll('[data-testid=active-faults] [data-testid^=active-fault-]').length === 0);
  await page.waitForFunction(() => /^0000h/.test(document.querySelector('[data-testid=emcy-wdga]')?.textContent ?? ''));
  await page.waitForFunction(() => document.querySelector('[data-testid=errreg-wdga]')?.textContent === '0x00');
  await odWrite('wdga', '1016', '1016-01', '0');  // stop watching (the DSV's heartbeat goes on)
  await byTestId('od-filter').fill('');
});

test('the trace filters by node and service and exports what it shows as a candump log', async () => {
  // Only the HLT 1100 (node 5): every row shown is node 5 or a broadcast.
  for (const id of [63, 2, 3, 127]) await byTestId(`trace-node-${id}`).uncheck();
  await byTestId('trace-pause').click();
  await page.waitForTimeout(400);
  const nodes = await page.locator('[data-testid=trace-table] tbody tr td:nth-child(6)').allTextContents();
  assert.ok(nodes.length > 0);
  assert.ok(nodes.every((n) => n === '' || n === '5'), `nodes shown: ${[...new Set(nodes)].join(',')}`);
  const [download] = await Promise.all([page.waitForEvent('download'), byTestId('trace-export').click()]);
  const log = readFileSync((await download.path())!, 'utf8').trimEnd().split('\n');
  assert.ok(log.length > 0);
  for (const line of log) assert.match(line, /^\(\d+\.\d{6}\) main [0-9A-F]{3}#([0-9A-F]*|R)$/);
  for (const line of log) {
    const id = parseInt(line.split(' ')[2].split('#')[0], 16);
    const broadcast = [0x000, 0x080, 0x100, 0x7e4, 0x7e5].includes(id);
    assert.ok(broadcast || (id & 0x7f) === 5, `a frame of another node in the export: ${line}`);
  }
  await byTestId('trace-pause').click();
  for (const id of [63, 2, 3, 127]) await byTestId(`trace-node-${id}`).check();
});

test('virtual time under the trainer: pause, one tick, run 100 ms, resume', async () => {
  autoResume = false;
  await resuming;  // a resume already on its way must not undo the pause below
  const now = () => page.evaluate(async () => (await (await fetch('/api/clock')).json()) as { t_us: number; paused: boolean; tick_us: number });
  await byTestId('clock-pause').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'paused');
  const t0 = await now();
  assert.equal(t0.paused, true);
  await page.waitForTimeout(300);
  assert.equal((await now()).t_us, t0.t_us, 'paused time stands still');
  await byTestId('clock-step').click();
  await page.waitForFunction((t) => fetch('/api/clock').then((r) => r.json()).then((c) => c.t_us === t), t0.t_us + t0.tick_us);
  await byTestId('clock-run-ms').fill('100');
  await byTestId('clock-run').click();
  await page.waitForFunction((t) => fetch('/api/clock').then((r) => r.json()).then((c) => c.t_us === t && c.paused), t0.t_us + t0.tick_us + 100_000);
  await byTestId('clock-resume').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'running');
  // The same from the keyboard: Space pauses, S steps one tick, R runs N ms, Space resumes.
  await page.locator('body').click({ position: { x: 5, y: 5 } });
  await page.keyboard.press(' ');
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'paused');
  const t1 = await now();
  await page.keyboard.press('s');
  await page.waitForFunction((t) => fetch('/api/clock').then((r) => r.json()).then((c) => c.t_us === t), t1.t_us + t1.tick_us);
  await page.keyboard.press('r');
  await page.waitForFunction((t) => fetch('/api/clock').then((r) => r.json()).then((c) => c.t_us === t && c.paused), t1.t_us + t1.tick_us + 100_000);
  // Space toggles what the page shows: wait until it shows the pause at the end of the run (the
  // page showed "paused" before the run too, and a late "running" from the run's middle would turn
  // Space into a second pause).
  await page.waitForFunction((t) => {
    const s = document.querySelector<HTMLElement>('[data-testid=clock-state]');
    return s?.textContent === 'paused' && s.dataset.tUs === String(t);
  }, t1.t_us + t1.tick_us + 100_000);
  await page.keyboard.press(' ');
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'running');
  // L: the lesson view and back.
  await page.keyboard.press('l');
  await page.waitForFunction(() => document.body.classList.contains('lesson') && location.hash === '#lesson');
  await page.keyboard.press('L');
  await page.waitForFunction(() => !document.body.classList.contains('lesson') && location.hash === '');
  assert.deepEqual(pageErrors, []);
});

test('the SYNC producer and an RPDO by mapped values move the cylinder', async () => {
  if ((await byTestId('clock-state').textContent()) === 'paused') await byTestId('clock-resume').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'running');
  // SYNC every 10 ms: the HLT 1100's synchronous TPDO2 (285h) answers it.
  await byTestId('sync-period').fill('10');
  await byTestId('sync-on').click();
  await page.waitForFunction(() => /on, 10 ms/.test(document.querySelector('[data-testid=sync-state]')?.textContent ?? ''));
  await page.waitForFunction(() => document.querySelectorAll('[data-testid=trace-table] tbody tr[data-service=SYNC]').length > 0);
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr td:nth-child(4)')].some((td) => td.textContent === '285'));
  // The DSV's RPDO1 as its mapping (1600h) lays it out: 6040:00 control word, 6300:01 set point.
  await byTestId('node-row-dsv').click();
  await byTestId('pdo-rpdo-1').waitFor();
  assert.match((await byTestId('pdo-rpdo-1').textContent()) ?? '', /0x60400010 → 6040:00 .*16 bit/);
  const reading = () => Number((document.querySelector('[data-testid="plot-value-cyl.position"]')?.textContent ?? '').match(/= (-?[\d.]+) mm/)?.[1]);
  const start = await page.evaluate(reading);
  assert.ok(Number.isFinite(start));
  await byTestId('rpdo-1-6040-00').fill('7');
  await byTestId('rpdo-1-6300-01').fill('-8192');  // 50 % the other way: the cylinder retracts
  await byTestId('rpdo-send-1').click();
  await page.waitForFunction(() => /RPDO1 sent to dsv/.test(document.querySelector('[data-testid=messages]')?.textContent ?? ''));
  // The DSV answers its RPDO1 at once with its TPDO1 (182h, the status word).
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid=trace-table] tbody tr[data-service=TPDO1] td:nth-child(4)')].some((td) => td.textContent === '182'));
  await page.waitForFunction((s) => {
    const m = (document.querySelector('[data-testid="plot-value-cyl.position"]')?.textContent ?? '').match(/= (-?[\d.]+) mm/);
    return m !== null && Number(m[1]) < s - 50;
  }, start, { timeout: 30_000 });
  await shot('sync-rpdo', 'pdo-section');
  await byTestId('sync-off').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=sync-state]')?.textContent === 'off');
});

test('an SDO to a STOPPED node says timeout, not refused', async () => {
  if ((await byTestId('clock-state').textContent()) === 'paused') await byTestId('clock-resume').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=clock-state]')?.textContent === 'running');
  await byTestId('node-row-dsv').click();
  await byTestId('nmt-target').selectOption('dsv');
  await byTestId('nmt-stop').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=nmt-dsv]')?.textContent === 'STOPPED');
  // NMT Stop in DEVICE_MODE_ACTIVE: TR_8, TR_12 to FAULT, caused by the NMT command, not by a control word.
  await page.waitForSelector('[data-testid=diagram-dsp408] [data-state=FAULT][data-current=true]');
  await page.waitForFunction(() => /TR_8, TR_12/.test(document.querySelector('[data-testid=last-change-dsp408]')?.textContent ?? ''));
  assert.doesNotMatch((await byTestId('last-change-dsp408').textContent()) ?? '', /control word/);
  await shot('dsv-nmt-stop', 'detail-section');
  await byTestId('od-filter').fill('1000');
  await byTestId('od-read-1000-00').click();
  await page.waitForFunction(() => /timeout/.test(document.querySelector('[data-testid=od-result]')?.textContent ?? ''));
  assert.doesNotMatch((await byTestId('od-result').textContent()) ?? '', /refused/);
  await byTestId('od-filter').fill('');
  await byTestId('nmt-start').click();
  await page.waitForFunction(() => document.querySelector('[data-testid=nmt-dsv]')?.textContent === 'OPERATIONAL');
  await byTestId('nmt-target').selectOption('');
});

test('an NMT command to a node that is not on the bus is a finding on the master, streamed', async () => {
  // The frame goes out as the master's (POST /api/frames); the verdict's finding reaches the page on the stream.
  await page.evaluate(() => fetch('/api/frames', {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"bus":"main","id":"0x000","data":"0109"}',
  }));
  await page.waitForSelector('[data-testid=findings] li[data-rule=nmt-unknown-node]', { state: 'attached' });
  await page.waitForFunction(() => /nmt-unknown-node \(\w+\): 1/.test(document.querySelector('[data-testid=findings-summary]')?.textContent ?? ''));
  assert.equal(await page.locator('[data-testid=findings] li[data-rule=nmt-unknown-node]').count(), 1, 'shown once');
});

test('Restart brings every node back to its boot-up', async () => {
  autoResume = false;
  await byTestId('restart').click();
  await page.waitForFunction(() => /restarted/.test(document.querySelector('[data-testid=messages]')?.textContent ?? ''));
  if ((await byTestId('clock-state').textContent()) === 'paused') await byTestId('clock-resume').click();
  for (const name of ['vtvpcd', 'dsv', 'md2', 'hlt', 'wdga']) {
    await page.waitForFunction((n) => document.querySelector(`[data-testid=nmt-${n}]`)?.textContent === 'PRE-OPERATIONAL', name);
  }
  const t = await page.evaluate(async () => (await (await fetch('/api/clock')).json()).t_us as number);
  assert.ok(t < 5_000_000, `the clock started again: ${t}`);
  // Every node's boot-up (700h + ID, data 00) is in the trace again.
  await page.waitForFunction(() => {
    const ids = [...document.querySelectorAll('[data-testid=trace-table] tbody tr[data-service=HEARTBEAT]')]
      .filter((tr) => tr.querySelector('td:nth-child(7)')?.textContent === '00')
      .map((tr) => tr.querySelector('td:nth-child(4)')?.textContent);
    return ['77F', '702', '703', '705', '73F'].every((id) => ids.includes(id));
  });
  // The DSV's transition list starts again: its power-on at 0 s, nothing of the old run (which
  // drove it to DEVICE_MODE_ACTIVE).
  await byTestId('node-row-dsv').click();
  await page.waitForFunction(() => {
    const rows = [...document.querySelectorAll('[data-testid=transition-list] tbody tr')].map((tr) => tr.textContent ?? '');
    return rows.some((r) => r.startsWith('0.000 s') && r.includes('OFF → INITIALISING')) && !rows.some((r) => r.includes('DEVICE_MODE_ACTIVE'));
  });
  // The old run's findings are gone with it.
  assert.equal(await page.locator('[data-testid=findings] li[data-rule=nmt-unknown-node]').count(), 0);
  await page.screenshot({ path: join(screenshots!, 'restart.png') });
});

/** The panels shown (main's sections not hidden) as boxes in CSS pixels, and the page's extent. */
async function panelBoxes(p: Page) {
  return p.evaluate(() => ({
    boxes: [...document.querySelectorAll('main > section')].filter((s) => getComputedStyle(s).display !== 'none').map((s) => {
      const r = s.getBoundingClientRect();
      return { id: s.id, x: r.x, y: r.y + window.scrollY, w: r.width, h: r.height };
    }),
    header: document.querySelector('header')!.getBoundingClientRect().bottom,
    innerWidth: window.innerWidth, innerHeight: window.innerHeight,
    scrollWidth: document.documentElement.scrollWidth, scrollHeight: document.documentElement.scrollHeight,
  }));
}

type Box = { id: string; x: number; y: number; w: number; h: number };
function overlaps(a: Box, b: Box): boolean {
  const dx = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
  const dy = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
  return dx > 1 && dy > 1;
}

test('no panel overlaps another at 1366×768 and 1920×1080, 100 % and 150 %; the lesson view fits one screen', async () => {
  const url = page.url().replace(/#.*$/, '');
  await byTestId('node-row-dsv').click();
  const browser: Browser = await chromium.launch({ executablePath: CHROMIUM, args: ['--headless', '--no-sandbox', '--disable-gpu'] });
  try {
    for (const [w, h] of [[1366, 768], [1920, 1080]]) {
      for (const zoom of [1, 1.5]) {
        for (const lesson of [false, true]) {
          // 150 % zoom: the CSS viewport shrinks by the factor, each CSS pixel is 1.5 device pixels.
          const ctx = await browser.newContext({ viewport: { width: Math.round(w / zoom), height: Math.round(h / zoom) }, deviceScaleFactor: zoom });
          const p = await ctx.newPage();
          const errors: string[] = [];
          p.on('pageerror', (e) => errors.push(e.message));
          await p.goto(url + (lesson ? '#lesson' : ''));
          await p.getByTestId('node-row-dsv').waitFor({ state: 'attached' });
          await p.waitForFunction(() => document.querySelector('[data-testid=connection]')?.textContent === 'live');
          await p.waitForTimeout(800);  // plots drawn, the trace rendered
          const name = `layout-${w}x${h}-${zoom * 100}${lesson ? '-lesson' : ''}`;
          await p.screenshot({ path: join(screenshots!, `${name}.png`) });
          if (docsImages && name === 'layout-1366x768-150-lesson') copyFileSync(join(screenshots!, `${name}.png`), join(docsImages, 'dashboard-lesson.png'));
          const L = await panelBoxes(p);
          for (let i = 0; i < L.boxes.length; ++i) {
            for (let j = i + 1; j < L.boxes.length; ++j) {
              assert.ok(!overlaps(L.boxes[i], L.boxes[j]), `${name}: ${L.boxes[i].id} overlaps ${L.boxes[j].id}: ${JSON.stringify([L.boxes[i], L.boxes[j]])}`);
            }
          }
          assert.ok(L.scrollWidth <= L.innerWidth + 1, `${name}: the page is wider than the window (${L.scrollWidth} > ${L.innerWidth})`);
          // No empty band between the header and the first panel.
          const top = Math.min(...L.boxes.map((b) => b.y));
          assert.ok(top - L.header <= 12, `${name}: ${top - L.header} px between the header and the first panel`);
          // The CiA 406 encoders' words by their bits' names.
          await p.waitForFunction(() => /status: [a-z].*alarms: none/s.test(document.querySelector('[data-testid=device-wdga]')?.textContent ?? ''));
          if (lesson) {
            // the exercise panel is there when the server has exercises (GET /api/exercises)
            const exercises = await p.evaluate(async () => ((await (await fetch('api/exercises')).json()) as string[]).length > 0);
            assert.deepEqual(L.boxes.map((b) => b.id).sort(),
              ['controls-section', 'detail-section', ...(exercises ? ['exercise-section'] : []), 'trace-section', 'transitions-section']);
            // the selected node's device diagram whole on the screen, beside the NMT diagram
            const diagram = await p.evaluate(() => {
              const r = document.querySelector('[data-machine=dsp408] svg')!.getBoundingClientRect();
              return { y: r.y, bottom: r.bottom, h: r.height };
            });
            const detail = L.boxes.find((b) => b.id === 'detail-section')!;
            assert.ok(diagram.h >= 120 && diagram.y >= detail.y && diagram.bottom <= detail.y + detail.h + 1,
              `${name}: the DSP 408 diagram is not whole in its panel: ${JSON.stringify([diagram, detail])}`);
            assert.ok(L.scrollHeight <= L.innerHeight + 1, `${name}: the lesson view scrolls (${L.scrollHeight} > ${L.innerHeight})`);
            // the large drawing's labels: none covers another or a state
            assert.deepEqual(await labelCollisions(p, 'diagram-dsp408'), [], `${name}: labels overlap`);
            // The diagram is the largest thing on the screen, its state names legible from a
            // projector (the font as rendered, after the drawing is scaled to its panel).
            const drawn = await p.evaluate(() => {
              const svgEl = document.querySelector('[data-machine=dsp408] svg')!;
              const r = svgEl.getBoundingClientRect();
              const text = svgEl.querySelector('.state text') as SVGGraphicsElement;
              return { area: r.width * r.height, namePx: text.getScreenCTM()!.a * parseFloat(getComputedStyle(text).fontSize) };
            });
            for (const b of L.boxes.filter((b) => b.id !== 'detail-section')) {
              assert.ok(drawn.area > b.w * b.h, `${name}: ${b.id} (${b.w}×${b.h}) is larger than the diagram (${drawn.area} px²)`);
            }
            assert.ok(drawn.namePx >= 10, `${name}: the diagram's state names in ${drawn.namePx.toFixed(1)} px`);
            // NMT has its own tab and is drawn as large.
            await p.getByTestId('machine-tab-nmt').click();
            const nmtPx = await p.evaluate(() => {
              const text = document.querySelector('[data-machine=nmt] svg .state text') as SVGGraphicsElement;
              return text.getScreenCTM()!.a * parseFloat(getComputedStyle(text).fontSize);
            });
            assert.ok(nmtPx >= 10, `${name}: the NMT diagram's state names in ${nmtPx.toFixed(1)} px`);
            await p.getByTestId('machine-tab-dsp408').click();
            // Every column of the transition list readable: no cell runs past its panel or the window.
            const cut = await p.evaluate(() => {
              const panel = document.getElementById('transitions-section')!.getBoundingClientRect();
              return [...document.querySelectorAll('[data-testid=transition-list] th, [data-testid=transition-list] td')]
                .map((c) => ({ text: (c.textContent ?? '').slice(0, 30), right: c.getBoundingClientRect().right }))
                .filter((c) => c.right > Math.min(panel.right, window.innerWidth) + 1);
            });
            assert.deepEqual(cut, [], `${name}: transition list cells cut off at the right`);
            for (const b of L.boxes) {
              assert.ok(b.y >= L.header - 1 && b.y + b.h <= L.innerHeight + 1 && b.h >= (b.id === 'exercise-section' ? 20 : 60), `${name}: ${b.id} is not on the screen: ${JSON.stringify(b)}`);
            }
            // large type for a projector
            const px = await p.evaluate(() => parseFloat(getComputedStyle(document.querySelector('[data-testid=transition-list]')!).fontSize));
            assert.ok(px >= 15, `${name}: transition list in ${px} px`);
          }
          assert.deepEqual(errors, []);
          await ctx.close();
        }
      }
    }
  } finally {
    await browser.close();
  }
});
