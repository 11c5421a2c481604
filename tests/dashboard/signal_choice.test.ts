import assert from 'node:assert/strict';
import { test } from 'node:test';
import { defaultSignals } from '../../dashboard/src/signal_choice';

test('the default plots are the plant ports, not the nodes\' copies', () => {
  const all = ['vtvpcd.swivel_angle', 'pump.swivel_angle', 'p_supply.pressure', 'cyl.position', 'cyl.velocity',
    'cyl.pressure_a', 'cyl.pressure_b', 'shaft.speed', 'shaft.angle', 'dsv.solenoid_a_current'];
  assert.deepEqual(defaultSignals(all, ['vtvpcd', 'dsv', 'md2', 'hlt', 'wdga']),
    ['cyl.position', 'pump.swivel_angle', 'p_supply.pressure', 'cyl.pressure_a', 'cyl.pressure_b', 'shaft.speed']);
  assert.deepEqual(defaultSignals(['a.b'], []), []);
});
