// Fault injection (from the scenario's fault catalogue: device, power, bus-off, plant, wire) with the
// list of active faults and their Clear buttons, and the device inputs (set_input).
import { button, el, formatTime } from '../dom';
import { busOffFault, deviceFault, plantFault, powerFault, wireFault } from '../fault_requests';
import type { ActiveFault, Scenario } from '../types';
import { fromDisplay, unitLabel } from '../units';

export interface FaultActions {
  inject(fault: object): void;
  clear(id: number): void;
  /** `value` in SI; `shown` as typed, with its display unit. */
  setInput(node: string, name: string, value: number, shown: string): void;
  reportError(message: string): void;
}

function select(label: string, testid: string, options: readonly string[]): HTMLSelectElement {
  return el('select', { 'aria-label': label, 'data-testid': testid }, ...options.map((o) => el('option', { value: o }, o)));
}

export class FaultsPanel {
  private activeList = el('ul', { class: 'active-faults', 'data-testid': 'active-faults', 'aria-label': 'Active faults' });

  constructor(host: HTMLElement, sc: Scenario, private actions: FaultActions) {
    const parts: Node[] = [];
    parts.push(el('h4', {}, 'Active faults'), this.activeList);

    parts.push(el('h4', {}, 'Device faults'));
    const devTable = el('table', { class: 'fault-catalogue', 'aria-label': 'Device fault catalogue' });
    for (const f of sc.faults.device) {
      devTable.append(el('tr', {},
        el('td', {}, f.node), el('td', { class: 'mono' }, f.name), el('td', {}, f.description),
        el('td', {}, button('Inject', { 'data-testid': `fault-inject-${f.node}-${f.name}`, 'aria-label': `Inject ${f.name} on ${f.node}` },
          () => actions.inject(deviceFault(f.node, f.name))))));
    }
    parts.push(el('div', { class: 'fault-scroll' }, devTable));

    const nodeNames = sc.nodes.map((n) => n.name);
    if (sc.faults.power.length) {
      const node = select('Node to power', 'power-node', nodeNames);
      const action = select('Power action', 'power-action', sc.faults.power);
      parts.push(el('div', { class: 'fault-row' }, el('span', {}, 'Power: '), node, action,
        button('Apply', { 'data-testid': 'power-apply' }, () => actions.inject(powerFault(action.value, node.value)))));
    }
    if (sc.faults.bus_off.length) {
      const node = select('Node to put bus-off', 'busoff-node', sc.faults.bus_off);
      parts.push(el('div', { class: 'fault-row' }, el('span', {}, 'Bus-off: '), node,
        button('Inject', { 'data-testid': 'busoff-inject' }, () => actions.inject(busOffFault(node.value)))));
    }
    if (sc.faults.wire.length && sc.buses.length) {
      const bus = select('Bus', 'wire-bus', sc.buses.map((b) => b.name));
      const match = el('input', { type: 'text', size: 7, value: '0x181', 'aria-label': 'COB-ID to match', 'data-testid': 'wire-match' });
      const action = select('Wire action', 'wire-action', sc.faults.wire);
      parts.push(el('div', { class: 'fault-row' }, el('span', {}, 'Wire: '), bus, match, action,
        button('Inject', { 'data-testid': 'wire-inject' }, () => actions.inject(wireFault(action.value, bus.value, match.value.trim())))));
    }
    if (sc.faults.plant.length) {
      const name = select('Plant parameter', 'plant-name', sc.faults.plant);
      const value = el('input', { type: 'number', step: 'any', size: 8, 'aria-label': 'Plant parameter value', 'data-testid': 'plant-value' });
      parts.push(el('div', { class: 'fault-row' }, el('span', {}, 'Plant: '), name, value,
        button('Apply', { 'data-testid': 'plant-apply' }, () => {
          const v = Number(value.value);
          if (value.value.trim() === '' || !Number.isFinite(v)) actions.reportError('plant fault: give a number');
          else actions.inject(plantFault(name.value, v));
        })));
    }

    if (sc.inputs.length) {
      parts.push(el('h4', {}, 'Device inputs (set_input)'));
      const inputs = el('table', { class: 'inputs', 'aria-label': 'Device inputs' });
      for (const i of sc.inputs) {
        const id = `${i.node}-${i.name}`;
        const value = el('input', { type: 'number', step: 'any', size: 6, value: '1', 'aria-label': `Value for ${i.node}.${i.name}`, 'data-testid': `input-value-${id}` });
        const u = unitLabel(i);
        inputs.append(el('tr', {}, el('td', {}, i.node), el('td', { class: 'mono' }, i.name), el('td', {}, value, u ? ` ${u}` : ''),
          el('td', {}, button('Set', { 'data-testid': `input-set-${id}`, 'aria-label': `Set ${i.node}.${i.name}` }, () => {
            const v = Number(value.value);
            if (value.value.trim() === '' || !Number.isFinite(v)) actions.reportError(`${i.node}.${i.name}: give a number`);
            else actions.setInput(i.node, i.name, fromDisplay(v, i), `${v}${u ? ` ${u}` : ''}`);  // typed in the display unit, sent in SI
          }))));
      }
      parts.push(el('div', { class: 'fault-scroll' }, inputs));
    }
    host.replaceChildren(...parts);
  }

  showActive(faults: readonly ActiveFault[]): void {
    this.activeList.replaceChildren(...(faults.length
      ? faults.map((f) => el('li', { 'data-testid': `active-fault-${f.id}` },
          `#${f.id} ${f.summary} (since ${formatTime(f.since_t_us)}) `,
          button('Clear', { 'data-testid': `fault-clear-${f.id}`, 'aria-label': `Clear fault ${f.id}` }, () => this.actions.clear(f.id))))
      : [el('li', { class: 'none' }, 'none')]));
  }
}
