// Builds the dashboard with esbuild (no network, no dev server):
//   node build.mjs --outdir DIR          the page: DIR/index.html, DIR/assets/app.js, DIR/assets/app.css,
//                                        the HTML report's code: DIR/report/report.js, DIR/report/report.css,
//                                        and the classroom overview: DIR/classroom/{index.html,classroom.js,classroom.css}
//   node build.mjs --tests-outdir DIR    the unit tests (tests/dashboard/*.test.ts) as ES modules for `node --test`
//   node build.mjs --e2e-outdir DIR      the browser test (tests/dashboard/*.e2e.ts) as CommonJS, playwright-core external
import { build } from 'esbuild';
import { copyFile, mkdir, readdir } from 'node:fs/promises';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const option = (name) => {
  const i = args.indexOf(name);
  return i >= 0 && args[i + 1] ? resolve(args[i + 1]) : null;
};

// The page bundles (the dashboard, the report): one minified script for the browsers in use.
const browserBundle = {
  absWorkingDir: here,
  bundle: true,
  minify: true,
  sourcemap: false,
  format: 'iife',
  target: ['chrome100', 'firefox100', 'safari15'],
  legalComments: 'none',
  logLevel: 'warning',
};

async function buildPage(outdir) {
  await mkdir(join(outdir, 'assets'), { recursive: true });
  await build({ ...browserBundle, entryPoints: { app: 'src/main.ts' }, outdir: join(outdir, 'assets') });
  await copyFile(join(here, 'index.html'), join(outdir, 'index.html'));
  // The report (engine/reporting/html/): vplant writes these two files into the report folder.
  await build({ ...browserBundle, entryPoints: { report: 'src/report/main.ts' }, outdir: join(outdir, 'report') });
  // The trainer's overview of `vplant classroom` (served at /, its files under /classroom/).
  await build({ ...browserBundle, entryPoints: { classroom: 'src/classroom/main.ts' }, outdir: join(outdir, 'classroom') });
  await copyFile(join(here, 'src/classroom/index.html'), join(outdir, 'classroom/index.html'));
}

async function entries(folder, suffix) {
  return (await readdir(join(here, folder))).filter((f) => f.endsWith(suffix)).map((f) => join(folder, f));
}

async function buildTests(outdir) {
  await build({
    absWorkingDir: here,
    entryPoints: await entries('../tests/dashboard', '.test.ts'),
    outdir,
    outExtension: { '.js': '.mjs' },
    entryNames: '[name]',
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node18',
    logLevel: 'warning',
  });
}

async function buildE2e(outdir) {
  await build({
    absWorkingDir: here,
    entryPoints: await entries('../tests/dashboard', '.e2e.ts'),
    outdir,
    outExtension: { '.js': '.cjs' },
    bundle: true,
    platform: 'node',
    format: 'cjs',
    target: 'node18',
    external: ['playwright-core'],
    logLevel: 'warning',
  });
}

const page = option('--outdir'), tests = option('--tests-outdir'), e2e = option('--e2e-outdir');
if (!page && !tests && !e2e) {
  console.error('usage: node build.mjs [--outdir DIR] [--tests-outdir DIR] [--e2e-outdir DIR]');
  process.exit(2);
}
if (page) await buildPage(page);
if (tests) await buildTests(tests);
if (e2e) await buildE2e(e2e);
