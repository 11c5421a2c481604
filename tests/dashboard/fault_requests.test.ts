// The faults panel's request bodies: the scenario's fault actions as JSON (POST /api/faults).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { busOffFault, deviceFault, plantFault, powerFault, wireFault } from '../../dashboard/src/fault_requests';

test('device, power, bus-off and plant faults are written as in a scenario', () => {
  assert.deepEqual(deviceFault('hlt', 'magnet_lost'), { device_fault: { node: 'hlt', fault: 'magnet_lost' } });
  assert.deepEqual(powerFault('power_off', 'dsv'), { power_off: 'dsv' });
  assert.deepEqual(powerFault('reset', 'md2'), { reset: 'md2' });
  assert.deepEqual(busOffFault('wdga'), { bus_off: 'wdga' });
  assert.deepEqual(plantFault('cyl.viscous_friction', 3000), { plant: { parameter: 'cyl.viscous_friction', value: 3000 } });
});

test('wire faults carry the bus, the identifier and the amount their action needs', () => {
  assert.deepEqual(wireFault('drop', 'main', '0x285'), { drop: { bus: 'main', id: '0x285' } });
  assert.deepEqual(wireFault('delay', 'main', '0x181'), { delay: { bus: 'main', id: '0x181', by: '10ms' } });
  assert.deepEqual(wireFault('corrupt', 'can1', '0x702'), { corrupt: { bus: 'can1', id: '0x702', byte: 0, xor: 255 } });
});
