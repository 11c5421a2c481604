import assert from 'node:assert/strict';
import { test } from 'node:test';
import { describeControlWord, stateFromStatusWord } from '../../dashboard/src/control_word';

test('control word bits by name', () => {
  assert.equal(describeControlWord(0x0007), '0x0007 (D H M)');
  assert.equal(describeControlWord(0x000f), '0x000F (D H M R)');
  assert.equal(describeControlWord(0x0000), '0x0000 (none)');
  assert.equal(describeControlWord(0x2001), '0x2001 (D)');
});

test('status word bits 3..0 name the state (CiA 408 codes)', () => {
  assert.equal(stateFromStatusWord(0x0008), 'INIT');
  assert.equal(stateFromStatusWord(0x0009), 'DISABLED');
  assert.equal(stateFromStatusWord(0x000b), 'HOLD');
  assert.equal(stateFromStatusWord(0x100f), 'DEVICE_MODE_ACTIVE');
  assert.equal(stateFromStatusWord(0x0001), 'FAULT');
  assert.equal(stateFromStatusWord(0x0003), 'FAULT_HOLD');
  assert.equal(stateFromStatusWord(0x0007), 'FAULT_REACTION');
  assert.equal(stateFromStatusWord(0x0018), 'INIT');
  assert.equal(stateFromStatusWord(0x0002), null);
});
