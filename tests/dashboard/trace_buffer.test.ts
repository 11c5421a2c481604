import assert from 'node:assert/strict';
import { test } from 'node:test';
import { TraceBuffer } from '../../dashboard/src/trace_buffer';
import { frame } from './frames';

const frames = (from: number, n: number) => Array.from({ length: n }, (_, i) => frame({ t_us: from + i }));

test('keeps the newest frames up to its capacity and counts the rest', () => {
  const b = new TraceBuffer(3);
  b.push(frames(0, 5));
  assert.deepEqual(b.shown().map((f) => f.t_us), [2, 3, 4]);
  assert.equal(b.dropped, 2);
});

test('pause freezes what is shown; resume catches up', () => {
  const b = new TraceBuffer(10);
  b.push(frames(0, 2));
  b.pause();
  b.push(frames(2, 2));
  assert.equal(b.paused, true);
  assert.deepEqual(b.shown().map((f) => f.t_us), [0, 1]);
  b.resume();
  assert.deepEqual(b.shown().map((f) => f.t_us), [0, 1, 2, 3]);
});

test('clear empties the view, paused or not', () => {
  const b = new TraceBuffer(10);
  b.push(frames(0, 2));
  b.pause();
  b.clear();
  assert.equal(b.shown().length, 0);
  b.resume();
  b.push(frames(5, 1));
  assert.deepEqual(b.shown().map((f) => f.t_us), [5]);
});
