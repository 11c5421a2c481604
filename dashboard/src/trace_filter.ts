// Which decoded frames the trace view shows: by node-ID and by service group.
import type { Frame } from './types';

/** The service groups a trainee filters by; TPDO1..4 / RPDO1..4 are one "PDO" group, SDO_RX/TX one "SDO". */
export const SERVICE_GROUPS = ['NMT', 'SYNC', 'EMCY', 'TIME', 'PDO', 'SDO', 'HEARTBEAT', 'LSS', 'OTHER'] as const;
export type ServiceGroup = (typeof SERVICE_GROUPS)[number];

export function serviceGroup(service: string): ServiceGroup {
  if (/^[TR]PDO[1-4]$/.test(service)) return 'PDO';
  if (service === 'SDO_RX' || service === 'SDO_TX') return 'SDO';
  if ((SERVICE_GROUPS as readonly string[]).includes(service)) return service as ServiceGroup;
  return 'OTHER';
}

export interface TraceFilter {
  /** node-IDs to show; null = every node. Broadcast frames (node null: NMT, SYNC, TIME) always pass. */
  nodes: ReadonlySet<number> | null;
  /** service groups to show; null = every service. */
  services: ReadonlySet<ServiceGroup> | null;
}

export const SHOW_ALL: TraceFilter = { nodes: null, services: null };

export function matches(frame: Frame, filter: TraceFilter): boolean {
  if (filter.services && !filter.services.has(serviceGroup(frame.service))) return false;
  if (filter.nodes && frame.node !== null && !filter.nodes.has(frame.node)) return false;
  return true;
}

export function applyFilter(frames: readonly Frame[], filter: TraceFilter): Frame[] {
  return frames.filter((f) => matches(f, filter));
}
