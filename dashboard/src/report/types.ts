// The report's data as vplant writes it (engine/reporting/html/report_writer.cpp): a case's summary
// (cases/<id>/case.json, listed by the index) and the whole case inlined in its page.
import type { TraceRow } from './trace_rows';

export type CaseResult = 'passed' | 'failed' | 'error';

export interface Outcome {
  name: string;
  where: string;  // file:line:col
  passed: boolean;
  t: number;      // s
  expected?: string;
  actual?: string;
}

export interface CaseSummary {
  id: string;
  name: string;
  file?: string;
  result: CaseResult;
  exit_code: number;
  error?: string;
  simulated_s?: number;
  wall_s?: number;
  seed?: number;
  interrupted?: boolean;
  assertions?: number;
  failures?: number;
  first_failure?: Outcome | null;
  faults?: number;
  frames?: number;
  page: string;
}

export interface IndexData {
  version: number;
  cases: CaseSummary[];
}

export interface CasePlot {
  title: string;
  y_label: string;
  labels: string[];
  series: number[];  // into signals.values
}

export interface BusLoad {
  name: string;
  wire: string;
  bit_rate: number;
  frames: number;
  error_frames: number;
  tx_queue_overflow: number;
  mean_load: number;
  ids: { id: number; ext: boolean; frames: number; load: number }[];
}

export interface RunEvent {
  t: number;
  kind: 'fault' | 'log';
  text: string;
}

export interface CaseData extends CaseSummary {
  outcomes: Outcome[];
  outcomes_left_out: number;
  nodes: { name: string; bus: string; node_id: number }[];
  signals: { names: string[]; t: number[]; values: (number | null)[][] };
  plots: CasePlot[];
  trace: { seen: number; buses: string[]; rows: TraceRow[] };
  buses: BusLoad[];
  events: RunEvent[];
  events_left_out: number;
}
