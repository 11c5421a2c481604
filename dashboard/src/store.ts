// What the page knows about the running plant, in one place: the scenario, the nodes' live state,
// each node's transition history, the selected node's machines, the clock. The stream and the
// few fetches write it; views subscribe to the topics they draw and never fetch on their own.
import { TransitionHistory } from './transitions';
import type { ClockState, NodeInfo, NodeMachines, Scenario, SignalInfo, Transition } from './types';

export type Topic = 'nodes' | 'selected' | 'transitions' | 'machines' | 'clock';

/** Transitions kept per node on the page (the server keeps its own bounded history). */
const HISTORY_PER_NODE = 500;

export class Store {
  readonly signals: ReadonlyMap<string, SignalInfo>;
  readonly live = new Map<string, NodeInfo>();
  readonly machines = new Map<string, NodeMachines>();
  private histories = new Map<string, TransitionHistory>();
  private listeners = new Map<Topic, Set<() => void>>();
  selected: string | null;
  clock: ClockState;

  constructor(readonly scenario: Scenario, clock: ClockState) {
    this.signals = new Map(scenario.signals.map((s) => [s.name, s]));
    this.selected = scenario.nodes.find((n) => n.profile === 'dsp408')?.name ?? scenario.nodes[0]?.name ?? null;
    this.clock = clock;
  }

  on(topic: Topic, fn: () => void): void {
    if (!this.listeners.has(topic)) this.listeners.set(topic, new Set());
    this.listeners.get(topic)!.add(fn);
  }

  private emit(topic: Topic): void {
    for (const fn of this.listeners.get(topic) ?? []) fn();
  }

  history(node: string): TransitionHistory {
    let h = this.histories.get(node);
    if (!h) this.histories.set(node, h = new TransitionHistory(HISTORY_PER_NODE));
    return h;
  }

  select(name: string): void {
    if (name === this.selected) return;
    this.selected = name;
    this.emit('selected');
  }

  setNodes(nodes: readonly NodeInfo[]): void {
    for (const n of nodes) this.live.set(n.name, n);
    this.emit('nodes');
  }

  addTransitions(node: string, entries: readonly Transition[]): void {
    if (entries.length === 0) return;
    this.history(node).add(entries);
    this.emit('transitions');
  }

  setMachines(m: NodeMachines): void {
    this.machines.set(m.node, m);
    this.emit('machines');
  }

  setClock(c: Partial<ClockState> & { t_us: number; paused: boolean }): void {
    this.clock = { ...this.clock, ...c };
    this.emit('clock');
  }

  /** A restarted scenario: every history starts again (the server's too). */
  forgetHistory(): void {
    for (const h of this.histories.values()) h.clear();
    this.machines.clear();
    this.emit('transitions');
    this.emit('machines');
  }
}
