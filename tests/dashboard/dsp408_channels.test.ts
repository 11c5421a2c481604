import assert from 'node:assert/strict';
import { test } from 'node:test';
import { channelLine, channelsOf, dsp408Summary } from '../../dashboard/src/dsp408_channels';
import type { Dsp408State } from '../../dashboard/src/types';

const dsv: Dsp408State = { profile: 'dsp408', state: 'DEVICE_MODE_ACTIVE', control_word: 7, status_word: 0x0f, last_transition: null };
const md2: Dsp408State = {
  profile: 'dsp408', state: 'DEVICE_MODE_ACTIVE', control_word: 7, status_word: 0x0f, last_transition: null,
  channels: [
    { channel: 1, state: 'DEVICE_MODE_ACTIVE', control_word: 7, status_word: 0x0f,
      last_transition: { from: 'DEVICE_ACTIVE', to: 'DEVICE_MODE_ACTIVE', control_word: 7, t_us: 1000 } },
    { channel: 2, state: 'DEVICE_INIT', control_word: 0, status_word: 0x01, last_transition: null },
  ],
};

test('a single-channel valve shows its one state', () => {
  assert.deepEqual(channelsOf(dsv), []);
  assert.equal(dsp408Summary(dsv), 'DEVICE_MODE_ACTIVE (sw 0x000F)');
});

test('a two-channel MD2 shows both channels with their status words', () => {
  assert.equal(channelsOf(md2).length, 2);
  assert.equal(dsp408Summary(md2), 'ch1 DEVICE_MODE_ACTIVE (sw 0x000F); ch2 DEVICE_INIT (sw 0x0001)');
  assert.equal(channelLine(md2.channels![0]),
    'Channel 1: DEVICE_MODE_ACTIVE; control word 0x0007; status word 0x000F; last transition DEVICE_ACTIVE → DEVICE_MODE_ACTIVE (cw 0x0007)');
  assert.equal(channelLine(md2.channels![1]), 'Channel 2: DEVICE_INIT; control word 0x0000; status word 0x0001');
});

test('a channel list of one is the device itself', () => {
  assert.deepEqual(channelsOf({ ...md2, channels: md2.channels!.slice(0, 1) }), []);
});
