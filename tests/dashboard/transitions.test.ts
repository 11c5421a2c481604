import assert from 'node:assert/strict';
import { test } from 'node:test';
import { currentStates, latestChain, TransitionHistory } from '../../dashboard/src/transitions';
import type { Machine, Transition } from '../../dashboard/src/types';

function tr(seq: number, t_us: number, machine: string, from: string, to: string, transition: string, cause = 'control_word', value = 0): Transition {
  return { seq, t_us, machine, from, to, transition, cause, value, detail: '', evidence: `${cause} ${value}` };
}

// 0x0001, 0x0003, 0x0007 one by one, then 0x0000 in one write: TR_5, TR_6, TR_7 in the same tick.
const dsv: Transition[] = [
  tr(1, 1000, 'nmt', 'INITIALISING', 'PRE-OPERATIONAL', 'boot-up', 'power'),
  tr(2, 2000, 'dsp408', 'INIT', 'DISABLED', 'TR_2', 'control_word', 1),
  tr(3, 3000, 'dsp408', 'DISABLED', 'HOLD', 'TR_3', 'control_word', 3),
  tr(4, 4000, 'dsp408', 'HOLD', 'DEVICE_MODE_ACTIVE', 'TR_4', 'control_word', 7),
  tr(5, 5000, 'dsp408', 'DEVICE_MODE_ACTIVE', 'HOLD', 'TR_5', 'control_word', 0),
  tr(6, 5000, 'dsp408', 'HOLD', 'DISABLED', 'TR_6', 'control_word', 0),
  tr(7, 5000, 'nmt', 'PRE-OPERATIONAL', 'OPERATIONAL', 'start', 'nmt_command', 1),
  tr(8, 5000, 'dsp408', 'DISABLED', 'INIT', 'TR_7', 'control_word', 0),
];

test('one write of 0x0000 from DEVICE_MODE_ACTIVE: the latest change is TR_5, TR_6, TR_7, each on its own', () => {
  assert.deepEqual(latestChain(dsv, 'dsp408').map((t) => t.transition), ['TR_5', 'TR_6', 'TR_7']);
  assert.deepEqual(latestChain(dsv, 'nmt').map((t) => t.transition), ['start']);
  assert.deepEqual(latestChain(dsv, 'vtvpcd'), []);
});

test('writes in different ticks are different changes', () => {
  assert.deepEqual(latestChain(dsv.slice(0, 4), 'dsp408').map((t) => t.transition), ['TR_4']);
});

test('the same tick but another cause is another change', () => {
  const h = [tr(1, 10, 'dsp408', 'HOLD', 'DEVICE_MODE_ACTIVE', 'TR_4', 'control_word', 7),
    tr(2, 10, 'dsp408', 'DEVICE_MODE_ACTIVE', 'FAULT_REACTION', 'TR_8', 'nmt_command', 2)];
  assert.deepEqual(latestChain(h, 'dsp408').map((t) => t.transition), ['TR_8']);
});

test('the current state is the newest target, else what the server described; bit machines in every set bit', () => {
  const m: Machine = { machine: 'dsp408', title: '', state: 'NOT_READY', states: [], edges: [], note: '' };
  assert.deepEqual([...currentStates(m, dsv)], ['INIT']);
  assert.deepEqual([...currentStates({ ...m, machine: 'vtvpcd', state: 'RUNNING' }, dsv)], ['RUNNING']);
  const alarms: Machine = { ...m, machine: 'cia406.alarms', state: 'position error + magnet lost', bits: [{ bit: 0, name: 'position error' }, { bit: 1, name: 'magnet lost' }] };
  assert.deepEqual([...currentStates(alarms, dsv)].sort(), ['magnet lost', 'position error']);
  assert.deepEqual([...currentStates({ ...alarms, state: 'none' }, dsv)], ['none']);
});

test('the history merges overlapping fetches and stream events by seq, and keeps its bound', () => {
  const h = new TransitionHistory(5);
  h.add([dsv[6], dsv[7]]);             // the stream was first
  h.add(dsv.slice(0, 7));              // then the fetch of everything
  assert.deepEqual(h.all().map((t) => t.seq), [4, 5, 6, 7, 8]);
  assert.equal(h.lastSeq, 8);
  h.add([tr(9, 6000, 'nmt', 'OPERATIONAL', 'STOPPED', 'stop', 'nmt_command', 2)]);
  assert.deepEqual(h.all().map((t) => t.seq), [5, 6, 7, 8, 9]);
  h.clear();
  assert.equal(h.lastSeq, -1);
});
