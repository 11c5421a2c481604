import assert from 'node:assert/strict';
import { test } from 'node:test';
import type { Machine, NodeInfo } from '../../dashboard/src/types';
import { bitNamesOf, deviceSummary, setBits } from '../../dashboard/src/views/node_table';

const machine = (id: string, bits: { bit: number; name: string }[]): Machine =>
  ({ machine: id, title: id, state: 'none', states: [], edges: [], note: '', bits });

// As the WDGA describes its words (GET /api/nodes/wdga/machines).
const wdga = bitNamesOf([
  machine('nmt', []),
  machine('cia406.status', [{ bit: 0, name: 'code sequence' }, { bit: 2, name: 'scaling function' }]),
  machine('cia406.alarms', [{ bit: 0, name: 'position error' }]),
  machine('cia406.warnings', [{ bit: 0, name: 'frequency limit exceeded' }, { bit: 12, name: 'over-temperature' }]),
]);

test('set bits by the names the device serves, none when none, an unnamed bit in hex', () => {
  assert.equal(setBits(0x0004, wdga.status), 'scaling function');
  assert.equal(setBits(0x0005, wdga.status), 'code sequence + scaling function');
  assert.equal(setBits(0x0000, wdga.alarms), 'none');
  assert.equal(setBits(0x1002, wdga.warnings), 'over-temperature + 0002h');
  assert.equal(setBits(0x0001, undefined), '0001h');  // no description (yet): the word in hex
});

test('a CiA 406 node in the node table: each word by its set bits', () => {
  const n = { name: 'wdga', nmt: 'OPERATIONAL', device: { profile: 'cia406', operating_status: 4, alarms: 1, warnings: 0 } } as unknown as NodeInfo;
  assert.equal(deviceSummary(n, wdga), 'status: scaling function\nalarms: position error\nwarnings: none');
  assert.equal(deviceSummary({ ...n, nmt: 'OFF' } as NodeInfo, wdga), 'OFF');
});
