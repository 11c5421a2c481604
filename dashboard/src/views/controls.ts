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

/** `fixedTarget`: in the lesson view the selected node, whatever the target list says (it is hidden there). */
export function renderNmtControls(host: HTMLElement, nodes: readonly ScenarioNode[], send: (command: string, node: string | 0) => void,
  fixedTarget: () => string | null = () => null): void {
  const target = el('select', { 'aria-label': 'NMT target', 'data-testid': 'nmt-target' },
    el('option', { value: '' }, 'all nodes (0)'), ...nodes.map((n) => el('option', { value: n.name }, `${n.name} (${n.node_id})`)));
  host.replaceChildren(el('div', { class: 'nmt-controls', role: 'group', 'aria-label': 'NMT commands' },
    el('span', {}, 'NMT to '), target,
    ...NMT_COMMANDS.map((c) => button(c.label, { 'data-testid': `nmt-${c.command}` }, () => send(c.command, fixedTarget() ?? (target.value === '' ? 0 : target.value))))));
}

/** Speeds of the virtual clock (× wall clock; 0 = as fast as possible). */
export const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 5, 10, 100, 0] as const;

export interface ClockActions {
  act(action: 'pause' | 'step' | 'run', ms?: number): void;
  resume(speed: number): void;
  restart(): void;
}

/** The clock: time, state, and in virtual time Pause / Resume at a speed / Step / Run N ms, with
 *  keyboard shortcuts (Space pause or resume, S step, R run); Restart in both modes. */
export class ClockControls {
  private time = el('span', { class: 'clock-time', 'data-testid': 'clock-time', role: 'timer', 'aria-live': 'off' });
  private state = el('span', { class: 'clock-state', 'data-testid': 'clock-state' });
  private hint = el('span', { class: 'clock-hint', 'data-testid': 'clock-hint' });
  private readonly mode: string;
  private paused = true;

  constructor(host: HTMLElement, clock: ClockState, actions: ClockActions) {
    this.mode = clock.mode;
    const restart = button('Restart', { 'data-testid': 'restart', title: 'Rebuild the scenario at t = 0: every node boots again' }, () => actions.restart());
    if (clock.mode === 'virtual') {
      const runMs = el('input', { type: 'number', min: 1, value: 100, 'aria-label': 'Milliseconds to run', 'data-testid': 'clock-run-ms' });
      const speed = el('select', { 'aria-label': 'Speed', 'data-testid': 'clock-speed' },
        ...SPEEDS.map((v) => el('option', { value: v, selected: v === (clock.speed ?? 1) }, v === 0 ? 'max' : `${v}×`)));
      const resume = () => actions.resume(Number(speed.value));
      speed.addEventListener('change', () => { if (!this.paused) resume(); });
      const run = () => actions.act('run', Math.max(1, Math.floor(Number(runMs.value) || 1)));
      host.replaceChildren(el('div', { class: 'clock', role: 'group', 'aria-label': 'Virtual clock' },
        this.time, this.state,
        button('Pause', { 'data-testid': 'clock-pause', title: 'Space' }, () => actions.act('pause')),
        button('Resume', { 'data-testid': 'clock-resume', title: 'Space' }, resume), speed,
        button('Step', { 'data-testid': 'clock-step', title: `one tick, ${clock.tick_us} µs (S)` }, () => actions.act('step')),
        button('Run', { 'data-testid': 'clock-run', title: 'R' }, run), runMs, el('span', {}, 'ms'),
        restart, this.hint));
      document.addEventListener('keydown', (ev) => {
        const t = ev.target as HTMLElement | null;
        if (ev.ctrlKey || ev.metaKey || ev.altKey || (t && /^(INPUT|SELECT|TEXTAREA|BUTTON)$/.test(t.tagName))) return;
        if (ev.key === ' ') {
          ev.preventDefault();
          if (this.paused) resume(); else actions.act('pause');
        } else if (ev.key === 's' || ev.key === 'S') {
          actions.act('step');
        } else if (ev.key === 'r' || ev.key === 'R') {
          run();
        }
      });
    } else {
      host.replaceChildren(el('div', { class: 'clock', role: 'group', 'aria-label': 'Real-time clock' }, this.time, this.state, restart));
    }
    this.show(clock.t_us, clock.paused, clock.end_reached ?? false);
  }

  /** `endReached`: the scenario's duration is over; virtual time paused there and Resume goes on. */
  show(t_us: number, paused: boolean, endReached: boolean): void {
    this.paused = paused;
    this.time.textContent = formatTime(t_us);
    this.state.textContent = this.mode === 'realtime' ? 'real time' : paused ? 'paused' : 'running';
    this.hint.textContent = endReached && paused ? '(end of the scenario\'s duration: Resume goes on)' : '';
    this.state.dataset.paused = String(paused);
    this.state.dataset.endReached = String(endReached);
    this.state.dataset.tUs = String(t_us);  // which clock reading the shown state belongs to
  }
}
