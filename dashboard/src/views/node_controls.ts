// What a lesson sends to the selected node besides NMT: the DSP 408 control word by SDO, the SYNC
// producer, and the node's PDOs as its mapping parameters (1600h.., 1A00h..) lay them out, with an
// RPDO sender that takes the mapped objects' values (the server packs them as the mapping says).
import { button, el, hex } from '../dom';
import { parseInteger } from '../od_input';
import type { Pdo } from '../types';

/** Control words a trainee uses most, with what they ask of the state machine. */
export const CW_PRESETS = [
  { value: 0x0000, label: '0x0000' },
  { value: 0x0001, label: '0x0001' },
  { value: 0x0003, label: '0x0003' },
  { value: 0x0007, label: '0x0007' },
  { value: 0x000f, label: '0x000F (R, H=1)' },
  { value: 0x0008, label: '0x0008 (R, H=0)' },
] as const;

export interface NodeControlActions {
  writeControlWord(node: string, cw: number): void;
  sendRpdo(node: string, pdo: number, values: Record<string, number>): void;
  reportError(message: string): void;
}

/** The control-word buttons of a DSP 408 node; rendered once per selection so typing survives updates. */
export function renderControlWord(host: HTMLElement, node: string | null, isDsp408: boolean, actions: NodeControlActions): void {
  if (!node || !isDsp408) {
    host.replaceChildren();
    return;
  }
  const cwInput = el('input', { type: 'text', value: '0x0007', size: 7, 'aria-label': 'Control word 6040h', 'data-testid': 'cw-input' });
  const write = () => {
    const n = parseInteger(cwInput.value);
    if (n !== null && n >= 0 && n <= 0xffff) actions.writeControlWord(node, n);
    else actions.reportError(`control word "${cwInput.value}": give 0..65535 or 0x0000..0xFFFF`);
  };
  cwInput.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') write(); });
  host.replaceChildren(el('div', { class: 'cw-controls', role: 'group', 'aria-label': 'Control word (SDO write 6040:00)' },
    el('span', {}, '6040h by SDO:'),
    ...CW_PRESETS.map((p) => button(p.label, { 'data-testid': `cw-preset-0x${hex(p.value, 4)}`, 'aria-label': `Write control word ${p.label}` },
      () => actions.writeControlWord(node, p.value))),
    cwInput, button('Write', { 'data-testid': 'cw-write' }, write)));
}

/** "0x60410010 → 6041:00 Status word, 16 bit". */
export function mappingText(e: { object: string; name: string; bits: number; raw: string }): string {
  return `${e.raw} → ${e.object} ${e.name}, ${e.bits} bit`;
}

function cobId(p: Pdo): string {
  return `${hex(p.cob_id, p.extended ? 8 : 3)}h`;
}

/** The PDO panel: every PDO of the node decoded, and a sender for each valid RPDO. */
export class PdoPanel {
  constructor(private host: HTMLElement, private actions: Pick<NodeControlActions, 'sendRpdo' | 'reportError'>) {}

  show(node: string, pdos: readonly Pdo[]): void {
    const rows: Node[] = [];
    for (const p of pdos) {
      const title = `${p.kind.toUpperCase()}${p.number}  COB-ID ${cobId(p)}${p.valid ? '' : ' (not valid)'}` +
        (p.transmission_type === null ? '' : `, transmission type ${p.transmission_type}`);
      const inputs = new Map<string, HTMLInputElement>();
      const entries = el('ul', { class: 'pdo-entries' }, ...p.entries.map((e) => {
        const li = el('li', { class: 'mono' }, mappingText(e));
        if (p.kind === 'rpdo' && p.valid) {
          const input = el('input', { type: 'text', size: 7, value: '0', 'aria-label': `${e.object} ${e.name}`, 'data-testid': `rpdo-${p.number}-${e.object.replace(':', '-')}` });
          inputs.set(e.object, input);
          li.append(' = ', input);
        }
        return li;
      }));
      const send = p.kind === 'rpdo' && p.valid && p.entries.length > 0
        ? button(`Send RPDO${p.number}`, { 'data-testid': `rpdo-send-${p.number}` }, () => {
            const values: Record<string, number> = {};
            for (const [object, input] of inputs) {
              const v = parseInteger(input.value) ?? Number(input.value.trim());
              if (input.value.trim() === '' || !Number.isFinite(v)) return this.actions.reportError(`RPDO${p.number} ${object}: give a number`);
              values[object] = v;
            }
            this.actions.sendRpdo(node, p.number, values);
          })
        : null;
      rows.push(el('div', { class: `pdo pdo-${p.kind}`, 'data-testid': `pdo-${p.kind}-${p.number}` }, el('div', { class: 'pdo-title' }, title, ' ', send), entries));
    }
    this.host.replaceChildren(...(rows.length ? rows : [el('p', { class: 'none' }, 'no PDO')]));
  }

  unavailable(reason: string): void {
    this.host.replaceChildren(el('p', { class: 'none', 'data-testid': 'pdos-unavailable' }, reason));
  }
}

/** The SYNC producer: period in ms, on and off; the state as the server reports it. */
export class SyncControls {
  private state = el('span', { class: 'sync-state', 'data-testid': 'sync-state' }, '');
  private period = el('input', { type: 'number', min: 1, value: 10, 'aria-label': 'SYNC period in ms', 'data-testid': 'sync-period' });

  constructor(host: HTMLElement, set: (periodMs: number) => void) {
    host.replaceChildren(el('div', { class: 'sync-controls', role: 'group', 'aria-label': 'SYNC producer' },
      el('span', {}, 'SYNC every'), this.period, el('span', {}, 'ms'),
      button('On', { 'data-testid': 'sync-on' }, () => set(Math.max(1, Math.floor(Number(this.period.value) || 1)))),
      button('Off', { 'data-testid': 'sync-off' }, () => set(0)),
      this.state));
  }

  show(periodMs: number | null): void {
    this.state.textContent = periodMs === null ? 'SYNC producer: not available' : periodMs > 0 ? `on, ${periodMs} ms` : 'off';
  }
}
