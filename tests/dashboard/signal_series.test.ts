import assert from 'node:assert/strict';
import { test } from 'node:test';
import { SignalSeries } from '../../dashboard/src/signal_series';

test('columns in uPlot layout, time in seconds', () => {
  const s = new SignalSeries(['a', 'b'], 1_000_000);
  s.append({ t_us: [0, 50_000], values: { a: [1, 2], b: [3, 4] } });
  assert.deepEqual(s.plotData(), [[0, 0.05], [1, 2], [3, 4]]);
  assert.equal(s.latest('a'), 2);
  assert.equal(s.latest('x'), undefined);
});

test('a signal missing from a batch becomes a gap', () => {
  const s = new SignalSeries(['a', 'b'], 1_000_000);
  s.append({ t_us: [0], values: { a: [1] } });
  assert.ok(Number.isNaN(s.plotData()[2][0]));
});

test('the window keeps the newest samples only', () => {
  const s = new SignalSeries(['a'], 100);
  s.append({ t_us: [0, 50, 100, 150, 200], values: { a: [0, 1, 2, 3, 4] } });
  assert.deepEqual(s.plotData()[1], [2, 3, 4]);
});

test('time going backwards starts afresh', () => {
  const s = new SignalSeries(['a'], 1000);
  s.append({ t_us: [500, 600], values: { a: [1, 2] } });
  s.append({ t_us: [0], values: { a: [9] } });
  assert.deepEqual(s.plotData(), [[0], [9]]);
});
