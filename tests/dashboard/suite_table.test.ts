// The report index's suite table: failures first, filters, sorting (dashboard/src/report/suite_table.ts).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { counts, DEFAULT_VIEW, speed, suiteRows } from '../../dashboard/src/report/suite_table';
import type { CaseSummary } from '../../dashboard/src/report/types';

const c = (name: string, result: CaseSummary['result'], simulated_s?: number, wall_s?: number): CaseSummary =>
  ({ id: name, name, file: `scenarios/${name}.yaml`, result, exit_code: result === 'passed' ? 0 : result === 'failed' ? 1 : 2, simulated_s, wall_s, page: `cases/${name}/index.html` });

const cases = [c('b', 'passed', 6, 0.5), c('a', 'passed', 2, 0.1), c('z', 'failed', 1, 0.2), c('crash', 'error'), c('y', 'failed', 3, 1)];

test('failures first: errors, then failed, then passed, each by name', () => {
  assert.deepEqual(suiteRows(cases, DEFAULT_VIEW).map((r) => r.name), ['crash', 'y', 'z', 'a', 'b']);
});

test('the text filter matches the name or the file, the result filter the result', () => {
  assert.deepEqual(suiteRows(cases, { ...DEFAULT_VIEW, text: 'SCENARIOS/Y' }).map((r) => r.name), ['y']);
  assert.deepEqual(suiteRows(cases, { ...DEFAULT_VIEW, result: 'passed' }).map((r) => r.name), ['a', 'b']);
  assert.deepEqual(suiteRows(cases, { ...DEFAULT_VIEW, text: 'nothing' }), []);
});

test('sorting by speed puts unknown speeds last either way', () => {
  assert.equal(speed(cases[0]), 12);
  assert.ok(Number.isNaN(speed(cases[3])));
  assert.deepEqual(suiteRows(cases, { ...DEFAULT_VIEW, sort: 'speed' }).map((r) => r.name), ['y', 'z', 'b', 'a', 'crash']);
  assert.deepEqual(suiteRows(cases, { ...DEFAULT_VIEW, sort: 'speed', descending: true }).map((r) => r.name), ['a', 'b', 'z', 'y', 'crash']);
});

test('counts per result', () => {
  assert.deepEqual(counts(cases), { passed: 2, failed: 2, error: 1 });
});
