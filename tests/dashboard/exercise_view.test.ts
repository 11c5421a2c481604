import assert from 'node:assert/strict';
import { test } from 'node:test';
import { doneTime, exerciseModel, type ExerciseState } from '../../dashboard/src/views/exercise_view';

const state: ExerciseState = {
  name: 'nmt',
  title: 'NMT: the network management state machine',
  introduction: 'Drive the DSV.',
  steps: [
    { title: 'Start the DSV', text: 'Press Start.', hint: 'The target list.', done: true, t_us: 612000 },
    { title: 'Stop the DSV', text: 'Press Stop.', hint: '', done: false, t_us: null },
    { title: 'Back to PRE-OPERATIONAL', text: 'Press Pre-operational.', hint: '', done: false, t_us: null },
  ],
};

test('done steps carry their mark and virtual time, the first open one is current, later ones open', () => {
  const m = exerciseModel(state);
  assert.ok(m);
  assert.equal(m.heading, 'NMT: the network management state machine');
  assert.equal(m.progress, '1 of 3 steps done');
  assert.deepEqual(m.rows.map((r) => [r.number, r.status, r.mark, r.time]), [
    [1, 'done', '✓', 'done at 0.612 s'],
    [2, 'current', '▶', ''],
    [3, 'open', '', ''],
  ]);
  assert.equal(m.rows[0].hint, 'The target list.');
});

test('every step done: no current step, the progress says so', () => {
  const all = { ...state, steps: state.steps.map((s, i) => ({ ...s, done: true, t_us: 1000000 * (i + 1) })) };
  const m = exerciseModel(all);
  assert.ok(m);
  assert.equal(m.progress, 'all 3 steps done');
  assert.deepEqual(m.rows.map((r) => r.status), ['done', 'done', 'done']);
  assert.equal(m.rows[2].time, 'done at 3.000 s');
});

test('no exercise selected: nothing to show', () => {
  assert.equal(exerciseModel({ name: null, title: '', introduction: '', steps: [] }), null);
  assert.equal(doneTime(1234567), 'done at 1.235 s');
});
