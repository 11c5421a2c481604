import assert from 'node:assert/strict';
import { test } from 'node:test';
import { defaultSignals, formatReading } from '../../dashboard/src/signal_choice';

test('the default plots are the plant ports, not the nodes\' copies', () => {
  const all = ['vtvpcd.swivel_angle', 'pump.swivel_angle', 'p_supply.pressure', 'cyl.position', 'cyl.velocity',
    'cyl.pressure_a', 'cyl.pressure_b', 'shaft.speed', 'shaft.angle', 'dsv.solenoid_a_current'];
  assert.deepEqual(defaultSignals(all, ['vtvpcd', 'dsv', 'md2', 'hlt', 'wdga']),
    ['cyl.position', 'pump.swivel_angle', 'p_supply.pressure', 'cyl.pressure_a', 'cyl.pressure_b', 'shaft.speed']);
  assert.deepEqual(defaultSignals(['a.b'], []), []);
});

test('readings: four digits, zero for vanishing values, exponents outside 1e-3..1e6', () => {
  assert.equal(formatReading(3.508e-180), '0');
  assert.equal(formatReading(0.123456), '0.1235');
  assert.equal(formatReading(-690.04), '-690');
  assert.equal(formatReading(12345678), '1.235e+7');
  assert.equal(formatReading(0.00001234), '1.234e-5');
});
