import assert from 'node:assert/strict';
import { test } from 'node:test';
import { applyFilter, matches, serviceGroup, SHOW_ALL } from '../../dashboard/src/trace_filter';
import { frame, SAMPLE } from './frames';

test('service groups fold PDOs and SDO directions', () => {
  assert.equal(serviceGroup('TPDO1'), 'PDO');
  assert.equal(serviceGroup('RPDO4'), 'PDO');
  assert.equal(serviceGroup('SDO_RX'), 'SDO');
  assert.equal(serviceGroup('SDO_TX'), 'SDO');
  assert.equal(serviceGroup('HEARTBEAT'), 'HEARTBEAT');
  assert.equal(serviceGroup('TPDO5'), 'OTHER');
  assert.equal(serviceGroup('something'), 'OTHER');
});

test('no filter shows every frame', () => {
  assert.equal(applyFilter(SAMPLE, SHOW_ALL).length, SAMPLE.length);
});

test('node filter keeps the chosen nodes and the broadcasts', () => {
  const shown = applyFilter(SAMPLE, { nodes: new Set([2]), services: null });
  assert.deepEqual(shown.map((f) => f.id), [0x000, 0x080, 0x602, 0x582, 0x7e5, 0x12345678]);
});

test('service filter keeps only the chosen groups', () => {
  const shown = applyFilter(SAMPLE, { nodes: null, services: new Set(['SDO', 'EMCY'] as const) });
  assert.deepEqual(shown.map((f) => f.service), ['SDO_RX', 'SDO_TX', 'EMCY']);
});

test('both filters apply together', () => {
  const f = { nodes: new Set([5]), services: new Set(['PDO'] as const) };
  assert.deepEqual(applyFilter(SAMPLE, f).map((x) => x.id), [0x185]);
  assert.equal(matches(frame({ service: 'TPDO1', node: 2 }), f), false);
});

test('an empty selection shows nothing of that kind', () => {
  assert.equal(applyFilter(SAMPLE, { nodes: null, services: new Set() }).length, 0);
});
