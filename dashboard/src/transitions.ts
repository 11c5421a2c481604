// A node's transition history as the devices recorded it (GET /api/nodes/{n}/transitions and the
// stream's `transition` events): kept in order of seq, bounded, and read for the diagrams — the
// state a machine is in and the steps of its latest change. Nothing here knows a state machine.
import type { Machine, Transition } from './types';

export class TransitionHistory {
  private entries: Transition[] = [];

  constructor(readonly capacity: number) {}

  /** Adds entries (from a fetch or the stream, in any overlap): each seq once, oldest first. */
  add(batch: readonly Transition[]): void {
    const last = this.lastSeq;
    if (batch.every((t) => t.seq > last)) {
      this.entries.push(...batch);
    } else {
      // a fetch that overlaps what the stream already brought: merge by seq
      const bySeq = new Map(this.entries.map((t) => [t.seq, t]));
      for (const t of batch) bySeq.set(t.seq, t);
      this.entries = [...bySeq.values()].sort((a, b) => a.seq - b.seq);
    }
    if (this.entries.length > this.capacity) this.entries.splice(0, this.entries.length - this.capacity);
  }

  /** The newest seq held (the `after=` of the next fetch), or -1. */
  get lastSeq(): number {
    return this.entries.length ? this.entries[this.entries.length - 1].seq : -1;
  }

  all(): readonly Transition[] {
    return this.entries;
  }

  clear(): void {
    this.entries = [];
  }
}

/** The entries of one machine (the MD2's channels are machines of their own: dsp408.ch1 ...). */
export function ofMachine(history: readonly Transition[], machine: string): Transition[] {
  return history.filter((t) => t.machine === machine);
}

/**
 * The steps of the machine's latest change: the newest entry and the entries just before it that
 * the same cause made in the same tick, each leading into the next (one write of 0x0000 from
 * DEVICE_MODE_ACTIVE: TR_5, TR_6, TR_7). Oldest first; empty when the machine never moved.
 */
export function latestChain(history: readonly Transition[], machine: string): Transition[] {
  const own = ofMachine(history, machine);
  if (own.length === 0) return [];
  const chain = [own[own.length - 1]];
  for (let i = own.length - 2; i >= 0; --i) {
    const t = own[i], next = chain[0];
    if (t.t_us !== next.t_us || t.cause !== next.cause || t.value !== next.value || t.to !== next.from) break;
    chain.unshift(t);
  }
  return chain;
}

/**
 * The states the machine is in: its newest entry's target when the history has one, else what the
 * server described. A bit machine (CiA 406 alarms, ...) is in every state whose bit is set, as the
 * server lists them ("a + b", or "none").
 */
export function currentStates(m: Machine, history: readonly Transition[]): Set<string> {
  if (m.bits) return new Set(m.state.split(' + '));
  const own = ofMachine(history, m.machine);
  return new Set([own.length ? own[own.length - 1].to : m.state]);
}
