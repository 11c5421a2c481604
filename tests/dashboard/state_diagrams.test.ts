import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DSP408_DIAGRAM, markedTransition, NMT_DIAGRAM, transitionPath } from '../../dashboard/src/state_diagrams';

const labels = (from: string, to: string) => transitionPath(DSP408_DIAGRAM, from, to).map((e) => e.label);

test('every edge joins two states of its diagram', () => {
  for (const d of [NMT_DIAGRAM, DSP408_DIAGRAM]) {
    const ids = new Set(d.states.map((s) => s.id));
    assert.equal(ids.size, d.states.length, `${d.id}: state ids are unique`);
    for (const e of d.edges) {
      assert.ok(ids.has(e.from) && ids.has(e.to), `${d.id}: ${e.from} -> ${e.to}`);
      const s = d.states.find((x) => x.id === e.from)!;
      assert.ok(s.x > 0 && s.x < d.width && s.y > 0 && s.y < d.height, `${s.id} inside the drawing`);
    }
    const keys = d.edges.map((e) => `${e.from}->${e.to}`);
    assert.equal(new Set(keys).size, keys.length, `${d.id}: one edge per pair of states`);
  }
});

test('the DSP 408 diagram has the eight states of the manual', () => {
  assert.deepEqual(DSP408_DIAGRAM.states.map((s) => s.id).sort(),
    ['DEVICE_MODE_ACTIVE', 'DISABLED', 'FAULT', 'FAULT_HOLD', 'FAULT_REACTION', 'HOLD', 'INIT', 'NOT_READY']);
});

test('a direct transition is one edge', () => {
  assert.deepEqual(labels('HOLD', 'DEVICE_MODE_ACTIVE'), ['TR_4']);
  assert.deepEqual(labels('DEVICE_MODE_ACTIVE', 'HOLD'), ['TR_5']);
  assert.deepEqual(labels('FAULT', 'DISABLED'), ['TR_10']);
});

test('control word 0x0007 from INIT walks TR_2, TR_3, TR_4', () => {
  assert.deepEqual(labels('INIT', 'DEVICE_MODE_ACTIVE'), ['TR_2', 'TR_3', 'TR_4']);
});

test('a fault goes through FAULT_REACTION', () => {
  assert.deepEqual(labels('DEVICE_MODE_ACTIVE', 'FAULT'), ['TR_8', 'TR_12']);
});

test('no path, no edges; same state, no edges', () => {
  assert.deepEqual(labels('INIT', 'NOT_READY'), []);
  assert.deepEqual(labels('HOLD', 'HOLD'), []);
  assert.deepEqual(transitionPath(NMT_DIAGRAM, 'OPERATIONAL', 'UNKNOWN'), []);
});

test('NMT: start from pre-operational, reset from anywhere', () => {
  assert.deepEqual(transitionPath(NMT_DIAGRAM, 'PRE-OPERATIONAL', 'OPERATIONAL').map((e) => e.label), ['start']);
  assert.deepEqual(transitionPath(NMT_DIAGRAM, 'STOPPED', 'INITIALISING').map((e) => e.label), ['reset']);
});

test('the page marks the chain it saw when the server names only its last step', () => {
  const server = { from: 'HOLD', to: 'DEVICE_MODE_ACTIVE' };
  const seen = { from: 'INIT', to: 'DEVICE_MODE_ACTIVE' };
  assert.deepEqual(markedTransition('DEVICE_MODE_ACTIVE', server, seen), seen);
  assert.deepEqual(markedTransition('DEVICE_MODE_ACTIVE', null, seen), seen);
  // What the page saw is stale (the state moved on since): the server's transition counts.
  assert.deepEqual(markedTransition('HOLD', { from: 'DEVICE_MODE_ACTIVE', to: 'HOLD' }, seen), { from: 'DEVICE_MODE_ACTIVE', to: 'HOLD' });
  assert.equal(markedTransition('INIT', null, null), null);
});
