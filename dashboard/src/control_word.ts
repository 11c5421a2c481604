// DSP 408 control word 6040h and status word 6041h, as a trainee reads them.

export const CW_BITS = [
  { bit: 0, name: 'D', meaning: 'Disable' },
  { bit: 1, name: 'H', meaning: 'Hold enable' },
  { bit: 2, name: 'M', meaning: 'Device mode active' },
  { bit: 3, name: 'R', meaning: 'Reset fault (0→1 edge)' },
] as const;

/** "0x0007 (D H M)": the word in hex and the device-command bits that are set. */
export function describeControlWord(cw: number): string {
  const set = CW_BITS.filter((b) => (cw >> b.bit) & 1).map((b) => b.name);
  const hex = '0x' + cw.toString(16).toUpperCase().padStart(4, '0');
  return set.length ? `${hex} (${set.join(' ')})` : `${hex} (none)`;
}

/** Status word bits 3..0 (R M H D) → the DSP 408 device state, or null for a code no state has. */
export function stateFromStatusWord(sw: number): string | null {
  switch (sw & 0xf) {
    case 0x0: return 'NOT_READY';
    case 0x8: return 'INIT';
    case 0x9: return 'DISABLED';
    case 0xb: return 'HOLD';
    case 0xf: return 'DEVICE_MODE_ACTIVE';
    case 0x7: return 'FAULT_REACTION';
    case 0x3: return 'FAULT_HOLD';
    case 0x1: return 'FAULT';
    default: return null;
  }
}

/** Control words a trainee uses most, with what they ask of the state machine. */
export const CW_PRESETS = [
  { value: 0x0000, label: '0x0000 → INIT' },
  { value: 0x0001, label: '0x0001 → DISABLED' },
  { value: 0x0003, label: '0x0003 → HOLD' },
  { value: 0x0007, label: '0x0007 → ACTIVE' },
  { value: 0x000f, label: '0x000F reset fault (H=1)' },
  { value: 0x0008, label: '0x0008 reset fault (H=0)' },
] as const;
