// NMT commands (to one node or all; the words of every front door: devices/canopen/nmt_command.h) and, in virtual time, the clock: pause, resume, one tick, run N ms.
import { button, el, formatTime } from '../dom';
import type { ClockState, ScenarioNode } from '../types';

export const NMT_COMMANDS = [
  { command: 'start', label: 'Start' },
  { command: 'stop', label: 'Stop' },
  { command: 'pre_operational', label: 'Pre-operational' },
  { command: 'reset_node', label: 'Reset node' },
  { command: 'reset_communication', label: 'Reset communication' },
] as const;

export function renderNmtControls(host: HTMLElement, nodes: readonly ScenarioNode[], send: (command: string, node: string | 0) => void): void {
  const target = el('select', { 'aria-label': 'NMT target', 'data-testid': 'nmt-target' },
    el('option', { value: '' }, 'all nodes (0)'), ...nodes.map((n) => el('option', { value: n.name }, `${n.name} (${n.node_id})`)));
  host.replaceChildren(el('div', { class: 'nmt-controls', role: 'group', 'aria-label': 'NMT commands' },
    el('span', {}, 'NMT to '), target,
    ...NMT_COMMANDS.map((c) => button(c.label, { 'data-testid': `nmt-${c.command}` }, () => send(c.command, target.value === '' ? 0 : target.value)))));
}

export class ClockControls {
  private time = el('span', { class: 'clock-time', 'data-testid': 'clock-time', role: 'timer', 'aria-live': 'off' });
  private state = el('span', { class: 'clock-state', 'data-testid': 'clock-state' });
  private hint = el('span', { class: 'clock-hint', 'data-testid': 'clock-hint' });
  private buttons: HTMLButtonElement[] = [];
  private readonly mode: string;

  constructor(host: HTMLElement, clock: ClockState, act: (action: string, ms?: number) => void) {
    this.mode = clock.mode;
    const runMs = el('input', { type: 'number', min: 1, value: 100, size: 5, 'aria-label': 'Milliseconds to run', 'data-testid': 'clock-run-ms' });
    if (clock.mode === 'virtual') {
      this.buttons = [
        button('Pause', { 'data-testid': 'clock-pause' }, () => act('pause')),
        button('Resume', { 'data-testid': 'clock-resume' }, () => act('resume')),
        button('Step 1 tick', { 'data-testid': 'clock-step', title: `${clock.tick_us} µs` }, () => act('step')),
        button('Run', { 'data-testid': 'clock-run' }, () => act('run', Math.max(1, Math.floor(Number(runMs.value) || 1)))),
      ];
      host.replaceChildren(el('div', { class: 'clock', role: 'group', 'aria-label': 'Virtual clock' },
        this.time, this.state, this.hint, ...this.buttons.slice(0, 3), this.buttons[3], runMs, el('span', {}, ' ms')));
    } else {
      host.replaceChildren(el('div', { class: 'clock', role: 'group', 'aria-label': 'Real-time clock' }, this.time, this.state));
    }
    this.show(clock.t_us, clock.paused, clock.end_reached ?? false);
  }

  /** `endReached`: the scenario's duration is over; virtual time paused there and Resume goes on. */
  show(t_us: number, paused: boolean, endReached: boolean): void {
    this.time.textContent = formatTime(t_us);
    this.state.textContent = this.mode === 'realtime' ? 'real time' : paused ? 'paused' : 'running';
    this.hint.textContent = endReached && paused ? '(end of the scenario\'s duration: Resume goes on)' : '';
    this.state.dataset.paused = String(paused);
    this.state.dataset.endReached = String(endReached);
  }
}
