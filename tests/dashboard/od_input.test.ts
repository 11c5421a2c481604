import assert from 'node:assert/strict';
import { test } from 'node:test';
import { formatIndex, formatValue, parseInteger, sdoWriteBody } from '../../dashboard/src/od_input';

test('integers in decimal or hex', () => {
  assert.equal(parseInteger('15'), 15);
  assert.equal(parseInteger(' 0x0F '), 15);
  assert.equal(parseInteger('-3'), -3);
  assert.equal(parseInteger('1.5'), null);
  assert.equal(parseInteger('abc'), null);
});

test('integer types check their range before anything is sent', () => {
  assert.deepEqual(sdoWriteBody(0x6040, 0, 'UNSIGNED16', '0x0007'), { index: 0x6040, sub: 0, value: 7 });
  assert.ok('error' in sdoWriteBody(0x6040, 0, 'UNSIGNED16', '65536'));
  assert.ok('error' in sdoWriteBody(0x6300, 0, 'INTEGER16', '-32769'));
  assert.deepEqual(sdoWriteBody(0x6300, 0, 'INTEGER16', '-32768'), { index: 0x6300, sub: 0, value: -32768 });
  assert.ok('error' in sdoWriteBody(0x6040, 0, 'UNSIGNED16', 'seven'));
});

test('reals, strings and raw bytes', () => {
  assert.deepEqual(sdoWriteBody(0x2000, 1, 'REAL32', '2.5'), { index: 0x2000, sub: 1, value: 2.5 });
  assert.ok('error' in sdoWriteBody(0x2000, 1, 'REAL32', ''));
  assert.deepEqual(sdoWriteBody(0x1008, 0, 'VISIBLE_STRING', 'AB'), { index: 0x1008, sub: 0, data: '4142' });
  assert.deepEqual(sdoWriteBody(0x1f50, 1, 'DOMAIN', '0a 0b'), { index: 0x1f50, sub: 1, data: '0A0B' });
  assert.ok('error' in sdoWriteBody(0x1f50, 1, 'DOMAIN', 'abc'));
});

test('index, sub-index and values as a CANopen engineer reads them', () => {
  assert.equal(formatIndex(0x6040, 0), '6040:00');
  assert.equal(formatIndex(0x1a0, 0x1f), '01A0:1F');
  assert.equal(formatValue(15, 'UNSIGNED16'), '15 (0xF)');
  assert.equal(formatValue(-2, 'INTEGER16'), '-2');
  assert.equal(formatValue('vplant', 'VISIBLE_STRING'), 'vplant');
  assert.equal(formatValue(null, 'UNSIGNED8'), '');
});
