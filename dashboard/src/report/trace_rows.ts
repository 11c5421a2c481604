// The report's trace rows (engine/reporting/html/report_writer.cpp writes one array per frame to keep the
// page small) back into the dashboard's Frame, so its trace view and filters take them as they are.
import { candumpLine } from '../candump_export';
import type { Frame } from '../types';

/** [t_us, bus index, id, flags (1 extended, 2 remote), dlc, data hex, service, node, decoded text] */
export type TraceRow = [number, number, number, number, number, string, string, number | null, string];

export function framesOf(buses: readonly string[], rows: readonly TraceRow[]): Frame[] {
  return rows.map(([t_us, bus, id, flags, dlc, data, service, node, text]) => {
    const f: Frame = {
      t_us, bus: buses[bus] ?? String(bus), id, ext: (flags & 1) !== 0, rtr: (flags & 2) !== 0, dlc, data,
      dir: '', service, node, text, candump: '',
    };
    f.candump = candumpLine(f);
    return f;
  });
}
