// A multi-channel DSP 408 device (the MD2): one device state machine per channel. The API lists
// every channel under device.channels (channel 1's state is also the device's own fields); a
// single-channel valve (the DSV) has no list.
import { hex } from './dom';
import type { Dsp408Channel, Dsp408State } from './types';

/** The channels to show one by one: the list when the device has more than one, else none. */
export function channelsOf(d: Dsp408State): Dsp408Channel[] {
  return d.channels && d.channels.length > 1 ? d.channels : [];
}

/** The node table's device cell: the state and status word, per channel when there are several. */
export function dsp408Summary(d: Dsp408State): string {
  const channels = channelsOf(d);
  if (!channels.length) return `${d.state} (sw 0x${hex(d.status_word, 4)})`;
  return channels.map((c) => `ch${c.channel} ${c.state} (sw 0x${hex(c.status_word, 4)})`).join('; ');
}

/** One line per channel for the node's detail: state, control word, status word, last transition. */
export function channelLine(c: Dsp408Channel): string {
  const lt = c.last_transition;
  return `Channel ${c.channel}: ${c.state}; control word 0x${hex(c.control_word, 4)}; status word 0x${hex(c.status_word, 4)}` +
    (lt ? `; last transition ${lt.from} → ${lt.to} (cw 0x${hex(lt.control_word, 4)})` : '');
}
