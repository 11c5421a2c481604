// Browser test of the HTML report in real headless Chromium (Debian's /usr/bin/chromium driven by
// playwright-core). It writes a report of two cases with vplant,
//   vplant run scenarios/reference-plant.yaml --report DIR --report-no-index      (passes)
//   vplant run tests/data/scenarios/report/hlt-magnet-lost-failing.yaml --report DIR   (fails; writes the index)
// opens DIR/index.html from file:// as a downloaded CI artefact is opened, and checks: the suite
// table lists the failure first, filters and sorts; the failing case's page shows the failed
// assertion on its timeline with its file:line:col, the fault, plots drawn by uPlot, the decoded
// trace with the dashboard's filters; and no request ever leaves the folder. Screenshots at
// 1366×768 and 1920×1080 go to --screenshots DIR.
//   node report.e2e.cjs --vplant BIN --source ROOT --screenshots DIR
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { after, before, test } from 'node:test';
import { BrowserContext, chromium, Page } from 'playwright-core';

function option(name: string): string | undefined {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : undefined;
}
const vplant = option('--vplant');
const source = option('--source');
const screenshots = option('--screenshots');
if (!vplant || !source || !screenshots) {
  console.error('usage: report.e2e.cjs --vplant BIN --source ROOT --screenshots DIR');
  process.exit(2);
}

const CHROMIUM = '/usr/bin/chromium';
const SIZES = [{ width: 1366, height: 768 }, { width: 1920, height: 1080 }];
let work = '';
let report = '';
let profileDir = '';
let context: BrowserContext | undefined;
let page: Page;
const requests: string[] = [];
const pageErrors: string[] = [];

function run(args: string[], expected: number): void {
  // The scenarios' own outputs (trace, CSV under out/) go to the temporary folder too.
  const r = spawnSync(vplant!, ['run', ...args, '--quiet'], { cwd: work, encoding: 'utf8', timeout: 120_000 });
  assert.equal(r.status, expected, `vplant run ${args.join(' ')} exited ${r.status}:\n${r.stdout}${r.stderr}`);
}

async function shot(name: string, anchor?: string): Promise<void> {
  for (const size of SIZES) {
    await page.setViewportSize(size);
    await page.evaluate((id) => (id ? document.getElementById(id)?.scrollIntoView() : window.scrollTo(0, 0)), anchor);
    await page.waitForTimeout(200);  // uPlot redraws after a resize
    await page.screenshot({ path: join(screenshots!, `report-${name}-${size.width}x${size.height}.png`) });
  }
}

before(async () => {
  mkdirSync(screenshots!, { recursive: true });
  work = mkdtempSync(join(tmpdir(), 'vplant-report-e2e-'));
  report = join(work, 'report');
  run([join(source!, 'scenarios/reference-plant.yaml'), '--report', report, '--report-no-index'], 0);
  run([join(source!, 'tests/data/scenarios/report/hlt-magnet-lost-failing.yaml'), '--report', report], 1);
  profileDir = mkdtempSync(join(tmpdir(), 'vplant-chromium-'));
  context = await chromium.launchPersistentContext(profileDir, {
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run'],
    viewport: SIZES[0],
  });
  context.setDefaultTimeout(20_000);
  context.on('request', (r) => requests.push(r.url()));
  page = context.pages()[0] ?? await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
});

after(async () => {
  if (page) await page.screenshot({ path: join(screenshots!, 'report-final.png'), fullPage: true }).catch(() => undefined);
  await context?.close();
  if (profileDir) rmSync(profileDir, { recursive: true, force: true });
  if (work) rmSync(work, { recursive: true, force: true });
});

test('the index lists both cases, the failure first, with filter and sort', async () => {
  await page.goto(pathToFileURL(join(report, 'index.html')).href);
  const rows = page.locator('[data-testid=suite-table] tbody tr');
  await rows.first().waitFor();
  assert.equal(await rows.count(), 2);
  assert.match(await rows.nth(0).innerText(), /hlt-magnet-lost-failing\s+failed\s+4 \/ 5/);
  assert.match(await rows.nth(0).innerText(), /hlt-magnet-lost-failing\.yaml:\d+:\d+: the position follows the rod again/);
  assert.match(await rows.nth(1).innerText(), /reference-plant\s+passed\s+16 \/ 16\s+6\.000/);
  assert.match(await page.getByTestId('suite-totals').innerText(), /2 cases: 1 passed, 1 failed, 0 errors/);
  await shot('index');

  await page.getByTestId('suite-filter').fill('reference');
  assert.equal(await rows.count(), 1);
  await page.getByTestId('suite-filter').fill('');
  await page.getByTestId('suite-result').selectOption('failed');
  assert.equal(await rows.count(), 1);
  assert.match(await rows.nth(0).innerText(), /hlt-magnet-lost-failing/);
  await page.getByTestId('suite-result').selectOption('all');
  await page.locator('th', { hasText: 'Case' }).click();  // by name, ascending
  assert.match(await rows.nth(0).innerText(), /^hlt-magnet-lost-failing/);
  await page.locator('th', { hasText: 'Case' }).click();  // descending
  assert.match(await rows.nth(0).innerText(), /^reference-plant/);
});

test('the failing case shows the failed assertion on its timeline, the fault, plots and the decoded trace', async () => {
  await page.locator('a', { hasText: 'hlt-magnet-lost-failing' }).click();
  await page.getByTestId('case-name').waitFor();
  assert.equal(await page.getByTestId('case-result').innerText(), 'failed');
  // The failed assertion: a mark on the timeline (its hover text) and the list with file:line:col.
  const failedMarks = page.locator('[data-testid=timeline-failed]');
  assert.equal(await failedMarks.count(), 1);
  assert.match(await failedMarks.first().locator('title').textContent() ?? '',
    /FAILED the position follows the rod again: expected .*> 0\.5.*hlt-magnet-lost-failing\.yaml:\d+:\d+/);
  assert.equal(await page.locator('[data-testid=timeline-passed]').count(), 4);
  assert.equal(await page.locator('[data-testid=timeline-fault]').count(), 1);
  assert.match(await page.getByTestId('failures').innerText(),
    /hlt-magnet-lost-failing\.yaml:\d+:\d+: FAILED at \d+\.\d{3} s: the position follows the rod again: expected/);
  assert.match(await page.getByTestId('faults').innerText(), /magnet_lost/);
  await shot('case-failed');

  // Without `plots:`, one plot per wired signal, and the bus load: drawn (non-blank canvases).
  const plots = page.locator('.report-plot');
  assert.ok(await plots.count() >= 2);
  const inked = await page.evaluate(() => [...document.querySelectorAll('.report-plot canvas')].map((c) => {
    const canvas = c as HTMLCanvasElement;
    const px = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
    let coloured = 0;
    for (let i = 0; i < px.length; i += 4) if (px[i + 3] > 0 && (px[i] !== px[i + 1] || px[i + 1] !== px[i + 2])) coloured++;
    return coloured;
  }));
  assert.ok(inked.length >= 2 && inked.every((n) => n > 100), `plot canvases without coloured lines: ${inked}`);
  await shot('case-plots', 'plots');

  // The decoded trace with the dashboard's service filter: EMCY only.
  const traceRows = page.locator('[data-testid=trace-table] tbody tr');
  assert.ok(await traceRows.count() > 100);
  for (const box of await page.locator('[data-testid^=trace-service-]').all()) {
    if ((await box.getAttribute('data-testid')) !== 'trace-service-EMCY') await box.uncheck();
  }
  const services = await traceRows.evaluateAll((trs) => trs.map((tr) => tr.getAttribute('data-service')));
  assert.ok(services.length >= 2, `EMCY rows: ${services.length}`);
  assert.ok(services.every((s) => s === 'EMCY'), services.join(','));
  assert.match(await traceRows.first().innerText(), /EMCY/);
  await shot('case-trace', 'trace');
});

test('the reference plant page draws the scenario plots and the bus load', async () => {
  await page.goto(pathToFileURL(join(report, 'cases/reference-plant/index.html')).href);
  await page.getByTestId('case-name').waitFor();
  assert.equal(await page.getByTestId('case-result').innerText(), 'passed');
  assert.equal(await page.locator('.report-plot').count(), 4);  // three from plots: + bus load
  assert.match(await page.locator('.report-plot figcaption').first().innerText(), /Reference plant - cylinder/);
  assert.match(await page.getByTestId('bus-main').innerText(), /5\d{3} frames, mean load 1\d\.\d\d %/);
  await shot('case-passed');
  await shot('case-passed-plots', 'plots');
});

test('no request left the report folder and the pages raised no error', () => {
  const inside = pathToFileURL(report).href + '/';
  assert.ok(requests.length >= 5, `requests: ${requests.join('\n')}`);
  const outside = requests.filter((u) => !u.startsWith(inside) && u !== 'data:,');
  assert.deepEqual(outside, []);
  assert.deepEqual(pageErrors, []);
});
