import assert from 'node:assert/strict';
import { test } from 'node:test';
import { decimalsFor, formatReading, formatSignal, fromDisplay, restingRange, signalInfo, tickLabels, toDisplay, unitLabel } from '../../dashboard/src/units';
import type { SignalInfo } from '../../dashboard/src/types';

const pressure: SignalInfo = { name: 'p_supply.pressure', unit: 'Pa', display_unit: 'bar', display_scale: 1e-5, display_offset: 0 };
const position: SignalInfo = { name: 'cyl.position', unit: 'm', display_unit: 'mm', display_scale: 1000, display_offset: 0 };

test('a signal in its display unit: 2.549e7 Pa reads 254.9 bar, 0.1234 m reads 123.4 mm', () => {
  assert.equal(formatSignal(2.549e7, pressure), '254.9 bar');
  assert.equal(formatSignal(0.1234, position), '123.4 mm');
  assert.equal(toDisplay(1, { ...position, display_scale: 1, display_offset: -273.15 }), 1 - 273.15);
  assert.ok(Math.abs(fromDisplay(254.9, pressure) - 2.549e7) < 1e-3);
  assert.equal(fromDisplay(toDisplay(0.25, position), position), 0.25);
});

test('a name the scenario does not list reads as it comes; "1" is no unit', () => {
  assert.deepEqual(signalInfo('cyl.position'), { name: 'cyl.position', unit: '', display_unit: '', display_scale: 1, display_offset: 0 });
  assert.equal(formatSignal(0.5, signalInfo('x')), '0.5');
  assert.equal(unitLabel({ ...pressure, display_unit: '', unit: '1' }), '');
});

test('readings: four digits, zero for vanishing values, never e-notation', () => {
  assert.equal(formatReading(3.508e-180), '0');
  assert.equal(formatReading(0.123456), '0.1235');
  assert.equal(formatReading(-690.04), '-690');
  assert.equal(formatReading(25490000), '25490000');
  assert.equal(formatReading(0.00001234), '0.00001234');
  assert.equal(formatReading(1.234e-7), '0.0000001234');
});

test('decimals from a tick step', () => {
  assert.equal(decimalsFor(5), 0);
  assert.equal(decimalsFor(0.25), 2);
  assert.equal(decimalsFor(0.1), 1);
  assert.equal(decimalsFor(0.001), 3);
});

test('axis ticks: one format per axis, no e-notation, no two ticks alike', () => {
  assert.deepEqual(tickLabels([0, 0.5, 1, 1.5]), ['0.0', '0.5', '1.0', '1.5']);
  assert.deepEqual(tickLabels([25000000, 25500000, 26000000]), ['25000000', '25500000', '26000000']);
  assert.deepEqual(tickLabels([254.99, 254.995, 255]), ['254.990', '254.995', '255.000']);
  // float noise in the ticks does not make labels alike or longer than needed
  assert.deepEqual(tickLabels([0.1, 0.2, 0.30000000000000004]), ['0.1', '0.2', '0.3']);
  const labels = tickLabels([-0.0001, 0, 0.0001]);
  assert.equal(new Set(labels).size, 3);
  assert.ok(labels.every((l) => !/e/i.test(l)));
  assert.deepEqual(tickLabels([]), []);
});

test('a signal at rest spans its display_span about its level; one that moves, the plot\'s own range', () => {
  const bar: SignalInfo = { ...pressure, display_span: 1 };
  const r = restingRange(-0.00702, -0.00335, bar)!;
  assert.ok(Math.abs(r[0] - -0.505185) < 1e-9 && Math.abs(r[1] - 0.494815) < 1e-9, String(r));
  assert.equal(restingRange(0, 210, bar), null);
  assert.equal(restingRange(null, null, bar), null, 'no data yet');
  assert.equal(restingRange(-0.007, -0.003, pressure), null, 'a server without spans: the plot chooses');
  assert.equal(restingRange(1, 1, { ...bar, display_span: 0 }), null);
});
