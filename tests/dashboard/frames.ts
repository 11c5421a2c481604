// Frames for the tests, shaped as the server's live stream sends them.
import type { Frame } from '../../dashboard/src/types';

export function frame(over: Partial<Frame>): Frame {
  return {
    t_us: 0, bus: 'main', id: 0x000, ext: false, rtr: false, dlc: 0, data: '', dir: 'rx',
    service: 'OTHER', node: null, text: '', candump: '', ...over,
  };
}

export const SAMPLE: Frame[] = [
  frame({ t_us: 1000, id: 0x000, dlc: 2, data: '0100', service: 'NMT', text: 'NMT Start remote node → all' }),
  frame({ t_us: 2000, id: 0x080, dlc: 0, service: 'SYNC', text: 'SYNC' }),
  frame({ t_us: 3000, id: 0x602, dlc: 8, data: '2B40600007000000', service: 'SDO_RX', node: 2, text: 'SDO download 6040:00 Device control word = 0x0007' }),
  frame({ t_us: 3500, id: 0x582, dlc: 8, data: '6040600000000000', service: 'SDO_TX', node: 2, text: 'SDO download response 6040:00' }),
  frame({ t_us: 4000, id: 0x185, dlc: 4, data: '10270000', service: 'TPDO1', node: 5, text: 'TPDO1 6004:00 Position value = 10000' }),
  frame({ t_us: 5000, id: 0x085, dlc: 8, data: '0023110000000000', service: 'EMCY', node: 5, text: 'EMCY 2300h' }),
  frame({ t_us: 6000, id: 0x77f, dlc: 1, data: '05', service: 'HEARTBEAT', node: 127, text: 'heartbeat OPERATIONAL' }),
  frame({ t_us: 7000, id: 0x7e5, dlc: 8, data: '0401000000000000', service: 'LSS', text: 'LSS switch state global' }),
  frame({ t_us: 8000, id: 0x12345678, ext: true, dlc: 1, data: 'AA', service: 'OTHER', text: '' }),
];
