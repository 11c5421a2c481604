import assert from 'node:assert/strict';
import { test } from 'node:test';
import { candumpLine, candumpLog } from '../../dashboard/src/candump_export';
import { frame } from './frames';

test('a standard frame in candump -L format', () => {
  assert.equal(candumpLine(frame({ t_us: 12000, id: 0x602, dlc: 8, data: '2b4060000f000000' })), '(0.012000) main 602#2B4060000F000000');
});

test('seconds and microseconds are split and padded', () => {
  assert.equal(candumpLine(frame({ t_us: 3_000_007, id: 0x80, data: '' })), '(3.000007) main 080#');
});

test('extended IDs get eight digits, RTR frames an R', () => {
  assert.equal(candumpLine(frame({ t_us: 0, id: 0x1abcdef, ext: true, data: '01' })), '(0.000000) main 01ABCDEF#01');
  assert.equal(candumpLine(frame({ t_us: 0, id: 0x705, rtr: true, dlc: 1 })), '(0.000000) main 705#R');
});

test('the log prefers the server line and ends with a newline', () => {
  const log = candumpLog([
    frame({ t_us: 1, id: 0x701, data: '00', candump: '(0.000001) main 701#00' }),
    frame({ t_us: 2, id: 0x702, data: '7F' }),
  ]);
  assert.equal(log, '(0.000001) main 701#00\n(0.000002) main 702#7F\n');
});

test('nothing shown, empty log', () => {
  assert.equal(candumpLog([]), '');
});
