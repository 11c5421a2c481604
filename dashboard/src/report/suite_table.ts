// The index's suite table as data: which cases a filter shows and in what order (failures first
// unless the reader sorts by a column).
import type { CaseResult, CaseSummary } from './types';

export type SortKey = 'result' | 'name' | 'simulated_s' | 'wall_s' | 'speed';

export interface SuiteView {
  text: string;                 // substring of the case name or file, case-insensitive
  result: CaseResult | 'all';
  sort: SortKey;
  descending: boolean;
}

export const DEFAULT_VIEW: SuiteView = { text: '', result: 'all', sort: 'result', descending: false };

const RESULT_ORDER: Record<CaseResult, number> = { error: 0, failed: 1, passed: 2 };

/** Simulated seconds per wall second (NaN when unknown). */
export function speed(c: CaseSummary): number {
  return c.simulated_s !== undefined && c.wall_s !== undefined && c.wall_s > 0 ? c.simulated_s / c.wall_s : NaN;
}

function value(c: CaseSummary, key: SortKey): number | string {
  switch (key) {
    case 'result': return RESULT_ORDER[c.result] ?? 0;
    case 'name': return c.name;
    case 'simulated_s': return c.simulated_s ?? NaN;
    case 'wall_s': return c.wall_s ?? NaN;
    case 'speed': return speed(c);
  }
}

function compare(a: number | string, b: number | string, descending: boolean): number {
  if (typeof a === 'number' && typeof b === 'number' && (Number.isNaN(a) || Number.isNaN(b))) {
    return Number.isNaN(a) ? (Number.isNaN(b) ? 0 : 1) : -1;  // unknown values last either way
  }
  const order = typeof a === 'string' || typeof b === 'string' ? String(a).localeCompare(String(b)) : a - b;
  return descending ? -order : order;
}

export function suiteRows(cases: readonly CaseSummary[], view: SuiteView): CaseSummary[] {
  const text = view.text.trim().toLowerCase();
  const shown = cases.filter((c) =>
    (view.result === 'all' || c.result === view.result) &&
    (!text || c.name.toLowerCase().includes(text) || (c.file ?? '').toLowerCase().includes(text)));
  return shown.sort((a, b) => {
    const primary = compare(value(a, view.sort), value(b, view.sort), view.descending);
    if (primary !== 0) return primary;
    return a.name.localeCompare(b.name);  // ties (e.g. every case passed) in name order
  });
}

export function counts(cases: readonly CaseSummary[]): Record<CaseResult, number> {
  const n: Record<CaseResult, number> = { passed: 0, failed: 0, error: 0 };
  for (const c of cases) n[c.result] = (n[c.result] ?? 0) + 1;
  return n;
}
