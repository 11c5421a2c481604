// The state machines the dashboard draws: states placed on a plane and the transitions between
// them, as data. NMT per CiA 301 (for every node); the device control state machine of CiA DSP 408
// (MD2, DSV) with the transition names the manuals use (TR_0..TR_12, TR_567).

export interface DiagramState { id: string; label: string; x: number; y: number; fault?: boolean }
export interface DiagramEdge { from: string; to: string; label: string; condition: string }
export interface Diagram { id: string; title: string; width: number; height: number; states: DiagramState[]; edges: DiagramEdge[] }

export const NMT_DIAGRAM: Diagram = {
  id: 'nmt',
  title: 'NMT (CiA 301)',
  width: 420,
  height: 300,
  states: [
    { id: 'OFF', label: 'OFF', x: 70, y: 40 },
    { id: 'INITIALISING', label: 'INITIALISING', x: 230, y: 40 },
    { id: 'PRE-OPERATIONAL', label: 'PRE-OPERATIONAL', x: 230, y: 140 },
    { id: 'OPERATIONAL', label: 'OPERATIONAL', x: 100, y: 250 },
    { id: 'STOPPED', label: 'STOPPED', x: 340, y: 250 },
  ],
  edges: [
    { from: 'OFF', to: 'INITIALISING', label: 'power on', condition: 'supply switched on' },
    { from: 'INITIALISING', to: 'PRE-OPERATIONAL', label: 'boot-up', condition: 'initialisation done: boot-up message 700h+ID #00' },
    { from: 'PRE-OPERATIONAL', to: 'OPERATIONAL', label: 'start', condition: 'NMT 01h Start remote node' },
    { from: 'STOPPED', to: 'OPERATIONAL', label: 'start', condition: 'NMT 01h Start remote node' },
    { from: 'OPERATIONAL', to: 'PRE-OPERATIONAL', label: 'pre-op', condition: 'NMT 80h Enter pre-operational' },
    { from: 'STOPPED', to: 'PRE-OPERATIONAL', label: 'pre-op', condition: 'NMT 80h Enter pre-operational' },
    { from: 'PRE-OPERATIONAL', to: 'STOPPED', label: 'stop', condition: 'NMT 02h Stop remote node' },
    { from: 'OPERATIONAL', to: 'STOPPED', label: 'stop', condition: 'NMT 02h Stop remote node' },
    { from: 'PRE-OPERATIONAL', to: 'INITIALISING', label: 'reset', condition: 'NMT 81h Reset node / 82h Reset communication' },
    { from: 'OPERATIONAL', to: 'INITIALISING', label: 'reset', condition: 'NMT 81h Reset node / 82h Reset communication' },
    { from: 'STOPPED', to: 'INITIALISING', label: 'reset', condition: 'NMT 81h Reset node / 82h Reset communication' },
  ],
};

export const DSP408_DIAGRAM: Diagram = {
  id: 'dsp408',
  title: 'Device control (CiA DSP 408)',
  width: 460,
  height: 380,
  states: [
    { id: 'NOT_READY', label: 'NOT_READY', x: 150, y: 30 },
    { id: 'INIT', label: 'INIT', x: 150, y: 110 },
    { id: 'DISABLED', label: 'DISABLED', x: 150, y: 190 },
    { id: 'HOLD', label: 'HOLD', x: 150, y: 270 },
    { id: 'DEVICE_MODE_ACTIVE', label: 'DEVICE_MODE_ACTIVE', x: 150, y: 350 },
    { id: 'FAULT_REACTION', label: 'FAULT_REACTION', x: 370, y: 60, fault: true },
    { id: 'FAULT_HOLD', label: 'FAULT_HOLD', x: 370, y: 200, fault: true },
    { id: 'FAULT', label: 'FAULT', x: 370, y: 330, fault: true },
  ],
  edges: [
    { from: 'NOT_READY', to: 'INIT', label: 'TR_1', condition: 'initialisation successful' },
    { from: 'INIT', to: 'DISABLED', label: 'TR_2', condition: 'control word xxxx xxx1 (D = 1); blocked while the enable input is 0' },
    { from: 'DISABLED', to: 'HOLD', label: 'TR_3', condition: 'control word xxxx xx11 (D = H = 1)' },
    { from: 'HOLD', to: 'DEVICE_MODE_ACTIVE', label: 'TR_4', condition: 'control word xxxx x111 (D = H = M = 1)' },
    { from: 'DEVICE_MODE_ACTIVE', to: 'HOLD', label: 'TR_5', condition: 'control word xxxx x0xx (M = 0)' },
    { from: 'HOLD', to: 'DISABLED', label: 'TR_6', condition: 'control word xxxx x00x (M = H = 0)' },
    { from: 'DISABLED', to: 'INIT', label: 'TR_7', condition: 'control word xxxx x000 (D = H = M = 0); also TR_567' },
    { from: 'HOLD', to: 'INIT', label: 'TR_567', condition: 'NMT Reset node or the enable input 1→0' },
    { from: 'DEVICE_MODE_ACTIVE', to: 'INIT', label: 'TR_567', condition: 'NMT Reset node or the enable input 1→0' },
    { from: 'INIT', to: 'FAULT_REACTION', label: 'TR_8', condition: 'a device error' },
    { from: 'DISABLED', to: 'FAULT_REACTION', label: 'TR_8', condition: 'a device error, NMT Stop or Reset communication' },
    { from: 'HOLD', to: 'FAULT_REACTION', label: 'TR_8', condition: 'a device error, NMT Stop or Reset communication' },
    { from: 'DEVICE_MODE_ACTIVE', to: 'FAULT_REACTION', label: 'TR_8', condition: 'a device error, NMT Stop or Reset communication' },
    { from: 'FAULT_REACTION', to: 'FAULT_HOLD', label: 'TR_9', condition: 'fault reaction done, hold active (option)' },
    { from: 'FAULT_REACTION', to: 'FAULT', label: 'TR_12', condition: 'fault reaction done, disabled (default)' },
    { from: 'FAULT', to: 'DISABLED', label: 'TR_10', condition: 'R 0→1 with H = 0, no error present' },
    { from: 'FAULT_HOLD', to: 'DISABLED', label: 'TR_10', condition: 'R 0→1 with H = 0, no error present' },
    { from: 'FAULT', to: 'HOLD', label: 'TR_11', condition: 'R 0→1 with H = 1, no error present' },
    { from: 'FAULT_HOLD', to: 'HOLD', label: 'TR_11', condition: 'R 0→1 with H = 1, no error present' },
  ],
};

export function edgeKey(e: DiagramEdge): string {
  return `${e.from}->${e.to}`;
}

/**
 * The edges of the last transition from `from` to `to`: the direct edge, or, when one control word
 * walked a chain (INIT → DISABLED → HOLD → DEVICE_MODE_ACTIVE on 0x0007), the shortest path.
 * Empty when the diagram has no such path.
 */
export function transitionPath(d: Diagram, from: string, to: string): DiagramEdge[] {
  if (from === to) return [];
  const prev = new Map<string, DiagramEdge>();
  const seen = new Set([from]);
  let frontier = [from];
  while (frontier.length > 0) {
    const next: string[] = [];
    for (const s of frontier) {
      for (const e of d.edges) {
        if (e.from !== s || seen.has(e.to)) continue;
        seen.add(e.to);
        prev.set(e.to, e);
        if (e.to === to) {
          const path: DiagramEdge[] = [];
          for (let at = to; at !== from; ) {
            const edge = prev.get(at)!;
            path.unshift(edge);
            at = edge.from;
          }
          return path;
        }
        next.push(e.to);
      }
    }
    frontier = next;
  }
  return [];
}

/**
 * The transition to mark: what the page saw (the state before the latest change → now) when it
 * ends in the current state and the server's last transition is its last step, else the server's.
 */
export function markedTransition(
  current: string, server: { from: string; to: string } | null, seen: { from: string; to: string } | null,
): { from: string; to: string } | null {
  if (seen && seen.to === current && (!server || server.to === current)) return seen;
  return server;
}
