// The control-plane API (docs/api.md) as typed calls. Every call goes to the page's own origin,
// relative to the page: under `vplant classroom` a seat's page is /seats/K/ and its API /seats/K/api/.
import type { ActiveFault, ClockState, FindingsPage, Frame, NodeInfo, NodeMachines, OdEntry, OdEvent, Pdo, Scenario, SdoResult, SignalBatch, StreamHello, Transition } from './types';
import type { ExerciseState } from './views/exercise_view';

export class ApiError extends Error {
  constructor(readonly status: number, message: string) {
    super(message);
  }
}

/** An API path ("/api/...") relative to the page's folder. */
export const relative = (path: string): string => path.replace(/^\//, '');

async function call<T>(method: string, path: string, body?: unknown): Promise<T> {
  const res = await fetch(relative(path), {
    method,
    headers: body === undefined ? {} : { 'Content-Type': 'application/json' },
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  const text = await res.text();
  let parsed: unknown = undefined;
  try {
    parsed = text ? JSON.parse(text) : undefined;
  } catch {
    parsed = undefined;
  }
  if (!res.ok) {
    const reason = (parsed as { error?: string } | undefined)?.error ?? (text || res.statusText);
    throw new ApiError(res.status, `${res.status}: ${reason}`);
  }
  return parsed as T;
}

export const api = {
  scenario: () => call<Scenario>('GET', '/api/scenario'),
  nodes: () => call<NodeInfo[]>('GET', '/api/nodes'),
  od: (node: string) => call<OdEntry[]>('GET', `/api/nodes/${encodeURIComponent(node)}/od`),
  sdoWrite: (node: string, body: object) => call<SdoResult>('POST', `/api/nodes/${encodeURIComponent(node)}/sdo`, body),
  sdoRead: (node: string, index: number, sub: number) =>
    call<SdoResult>('POST', `/api/nodes/${encodeURIComponent(node)}/sdo/read`, { index, sub }),
  nmt: (command: string, node: string | 0) => call<{ ok: boolean }>('POST', '/api/nmt', { command, node }),
  faults: () => call<ActiveFault[]>('GET', '/api/faults'),
  injectFault: (fault: object) => call<{ ok: boolean; id: number; active?: boolean }>('POST', '/api/faults', fault),
  clearFault: (id: number) => call<{ ok: boolean }>('DELETE', `/api/faults/${id}`),
  setInput: (node: string, name: string, value: number) =>
    call<{ ok: boolean }>('POST', `/api/nodes/${encodeURIComponent(node)}/inputs`, { name, value }),
  clock: () => call<ClockState>('GET', '/api/clock'),
  findings: (since: number) => call<FindingsPage>('GET', `/api/findings?since=${since}`),
  clockAction: (action: string, ms?: number) =>
    call<ClockState | { ok: boolean }>('POST', '/api/clock', ms === undefined ? { action } : { action, ms }),
  resume: (speed: number) => call<ClockState | { ok: boolean }>('POST', '/api/clock', { action: 'resume', speed }),
  transitions: (node: string, after?: number) =>
    call<Transition[]>('GET', `/api/nodes/${encodeURIComponent(node)}/transitions${after === undefined || after < 0 ? '' : `?after=${after}`}`),
  machines: (node: string) => call<NodeMachines>('GET', `/api/nodes/${encodeURIComponent(node)}/machines`),
  pdos: (node: string) => call<Pdo[]>('GET', `/api/nodes/${encodeURIComponent(node)}/pdos`),
  rpdo: (node: string, pdo: number, values: Record<string, number>) =>
    call<{ ok: boolean }>('POST', `/api/nodes/${encodeURIComponent(node)}/rpdo`, { pdo, values }),
  sync: () => call<{ period_ms: number }>('GET', '/api/sync'),
  setSync: (periodMs: number) => call<{ ok: boolean }>('POST', '/api/sync', { period_ms: periodMs }),
  restart: () => call<{ ok: boolean }>('POST', '/api/restart'),
  /** Which node's dictionary the stream `stream` (its id from `hello`) carries as `od` events. */
  streamNode: (stream: number, node: string | null) => call<{ ok: boolean }>('POST', '/api/events/node', { stream, node }),
};

export interface StreamHandlers {
  frames(batch: Frame[]): void;
  nodes(nodes: NodeInfo[]): void;
  signals(batch: SignalBatch): void;
  clock(c: { t_us: number; paused: boolean; end_reached?: boolean }): void;
  dropped(d: { frames: number }): void;
  transition(t: Transition & { node: string }): void;
  /** POST /api/restart by anyone: the run starts again at t = 0. */
  restart(): void;
  /** Once, first: the stream's id (to choose its node) and whether it is a shared read-only one. */
  hello(h: StreamHello): void;
  /** The chosen node's dictionary: whole on selection, then what changed. */
  od(o: OdEvent): void;
  /** The live faults, on connect and when they change. */
  faults(f: ActiveFault[]): void;
  /** The exercise and its progress (GET /api/exercise's body): on connect, on a selection, when a step is done. */
  exercise(e: ExerciseState): void;
  /** New findings of the verdict on the master, as a GET /api/findings page. */
  findings(page: FindingsPage): void;
  connection(open: boolean): void;
}

/** Opens the live stream; EventSource reconnects by itself after a drop. */
export function openStream(signals: readonly string[], rateHz: number, node: string | null, h: StreamHandlers): EventSource {
  const q = new URLSearchParams({ signals: signals.join(','), rate: String(rateHz) });
  if (node) q.set('node', node);
  const es = new EventSource(relative(`/api/events?${q}`));
  const on = <T>(name: string, fn: (v: T) => void) =>
    es.addEventListener(name, (ev) => fn(JSON.parse((ev as MessageEvent<string>).data) as T));
  on('frames', h.frames);
  on('nodes', h.nodes);
  on('signals', h.signals);
  on('clock', h.clock);
  on('dropped', h.dropped);
  on('transition', h.transition);
  on('restart', h.restart);
  on('hello', h.hello);
  on('od', h.od);
  on('faults', h.faults);
  on('exercise', h.exercise);
  on('findings', h.findings);
  es.onopen = () => h.connection(true);
  es.onerror = () => h.connection(false);
  return es;
}
