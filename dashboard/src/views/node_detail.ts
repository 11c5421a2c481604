// The selected node's state machines as its C++ profile describes them (GET .../machines): each
// drawn from the description, the current state and the steps of the latest change from the
// transition history, the change's cause in words beneath, the profile's note (how a latched
// VT-VPCD fault is acknowledged, ...). The MD2's channels are chosen one at a time. Then the EMCY history.
import { el, formatTime, hex, spacedHex } from '../dom';
import { currentStates, latestChain } from '../transitions';
import type { Machine, NodeInfo, NodeMachines, Transition } from '../types';
import { renderMachine } from './machine_diagram';

const CHANNEL = /^(.*)\.ch(\d+)$/;

export class NodeDetail {
  private channel = new Map<string, string>();  // node → the MD2 channel machine shown
  private lessonMachine = new Map<string, string>();  // node → the machine the lesson view shows
  private lesson = false;

  constructor(private host: HTMLElement, private onRedraw: () => void) {}

  /** The lesson view (a projector) shows one machine at a time, large, with a tab per machine. */
  setLesson(on: boolean): void {
    this.lesson = on;
    this.onRedraw();
  }

  render(node: NodeInfo | undefined, machines: NodeMachines | undefined, history: readonly Transition[], unavailable: string | null): void {
    if (!node) {
      this.host.replaceChildren(el('p', {}, 'Select a node in the table.'));
      return;
    }
    const powered = machines ? machines.powered && node.nmt !== 'OFF' : node.nmt !== 'OFF';
    const parts: Node[] = [el('h3', {}, `${node.name} (node ${node.node_id})`,
      powered ? '' : el('span', { class: 'badge off', 'data-testid': 'node-off' }, 'OFF: no power'))];
    if (!machines) {
      parts.push(el('p', { class: 'none', 'data-testid': 'machines-unavailable' }, unavailable ?? 'loading the state machines…'));
    } else {
      const boxes = el('div', { class: 'machines' });
      let shown = this.shownMachines(node.name, machines.machines, boxes);
      if (this.lesson) shown = this.lessonTabs(node.name, shown, boxes);
      for (const m of shown) boxes.append(this.machineBox(m, history));
      parts.push(boxes);
    }
    const emcy = node.emcy.slice().reverse();
    parts.push(el('h4', {}, 'EMCY history (newest first)'),
      emcy.length
        ? el('ol', { class: 'emcy-list', 'data-testid': 'emcy-list' },
            ...emcy.map((e) => el('li', { class: e.code === 0 ? 'emcy-reset' : '' },
              `${formatTime(e.t_us)}  ${hex(e.code, 4)}h  reg ${hex(e.register, 2)}h  ${spacedHex(e.data)}  ${e.text}`)))
        : el('p', { 'data-testid': 'emcy-list' }, 'none'));
    this.host.replaceChildren(...parts);
  }

  /** Every machine, except that of several channels (dsp408.ch1 ... ch8) only the chosen one,
   *  with a selector put in front. */
  private shownMachines(node: string, all: readonly Machine[], boxes: HTMLElement): Machine[] {
    const channels = all.filter((m) => CHANNEL.test(m.machine));
    if (channels.length < 2) return [...all];
    const chosen = channels.find((m) => m.machine === this.channel.get(node)) ?? channels[0];
    const select = el('select', { 'aria-label': 'Channel', 'data-testid': 'channel-select' },
      ...channels.map((m) => el('option', { value: m.machine, selected: m === chosen }, `channel ${m.machine.match(CHANNEL)![2]}`)));
    select.addEventListener('change', () => { this.channel.set(node, select.value); this.onRedraw(); });
    boxes.append(el('label', { class: 'channel-choice' }, 'Device state machine of ', select));
    return all.filter((m) => !channels.includes(m) || m === chosen);
  }

  /** One tab per machine; the chosen one (first the device's own, else NMT) is the one drawn. */
  private lessonTabs(node: string, all: readonly Machine[], boxes: HTMLElement): Machine[] {
    if (all.length === 0) return [];
    const chosen = all.find((m) => m.machine === this.lessonMachine.get(node)) ?? all.find((m) => m.machine !== 'nmt') ?? all[0];
    boxes.append(el('div', { class: 'machine-tabs', role: 'group', 'aria-label': 'State machine shown', 'data-testid': 'machine-tabs' },
      ...all.map((m) => {
        const b = el('button', { type: 'button', 'aria-pressed': String(m === chosen), 'data-testid': `machine-tab-${m.machine}` },
          m.machine === 'nmt' ? 'NMT' : (m.title || m.machine).replace(/\s*\(.*\)$/, ''));
        b.addEventListener('click', () => { this.lessonMachine.set(node, m.machine); this.onRedraw(); });
        return b;
      })));
    return [chosen];
  }

  private machineBox(m: Machine, history: readonly Transition[]): HTMLElement {
    const current = currentStates(m, history);
    const shown = [...current].join(' + ');
    const chain = latestChain(history, m.machine);
    const last = chain.length
      ? `${chain.map((t) => t.transition).join(', ')} (${chain[0].from} → ${chain[chain.length - 1].to}) at ${formatTime(chain[0].t_us)}: ${chain[chain.length - 1].evidence || chain[0].cause}`
      : `no transition recorded; state ${shown}`;
    return el('figure', { class: `diagram-box machine-${m.machine.split('.')[0]}`, 'data-machine': m.machine },
      el('figcaption', { class: 'machine-title' }, el('strong', {}, m.title || m.machine), ` — ${shown}`),
      renderMachine(m, current, chain, this.lesson),
      el('figcaption', { 'data-testid': `last-change-${m.machine}`, class: 'last-change' }, last),
      m.note ? el('p', { class: 'machine-note', 'data-testid': `note-${m.machine}` }, m.note) : null);
  }
}
