// Plant signals in the units an engineer reads (bar, mm, rpm, ...): the server says each signal's SI
// unit and its display unit with scale and offset (GET /api/scenario, `signals`); the page only
// multiplies. Also the numbers on plot axes: fixed decimals from the tick step, never e-notation.
import type { SignalInfo } from './types';

/** A signal the scenario does not list (no units known): shown as it comes. */
export function signalInfo(name: string): SignalInfo {
  return { name, unit: '', display_unit: '', display_scale: 1, display_offset: 0 };
}

/** A value typed in display units, back in SI for the server. */
export function fromDisplay(display: number, s: SignalInfo): number {
  return (display - s.display_offset) / s.display_scale;
}

export function toDisplay(si: number, s: SignalInfo): number {
  return si * s.display_scale + s.display_offset;
}

/** The unit the page prints: the display unit, else the SI one ("1" is no unit at all). */
export function unitLabel(s: SignalInfo): string {
  const u = s.display_unit || s.unit;
  return u === '1' ? '' : u;
}

/** Decimals that tell apart values `step` apart (step 0.25 → 2, 5 → 0, 0.001 → 3). */
export function decimalsFor(step: number): number {
  if (!(step > 0) || !Number.isFinite(step)) return 0;
  let d = 0;
  while (d < 9 && Math.abs(Math.round(step * 10 ** d) - step * 10 ** d) > 1e-6 * 10 ** d * step) ++d;
  return d;
}

function fixed(v: number, decimals: number): string {
  const t = (Math.abs(v) < 0.5 * 10 ** -decimals ? 0 : v).toFixed(decimals);
  return t === '-0' ? '0' : t;
}

/**
 * Axis tick labels: one number of decimals for the whole axis, enough that neighbouring ticks
 * differ, in plain digits (2549.3, not 2.549e+3).
 */
export function tickLabels(ticks: readonly number[]): string[] {
  if (ticks.length === 0) return [];
  let step = Infinity;
  for (let i = 1; i < ticks.length; ++i) step = Math.min(step, Math.abs(ticks[i] - ticks[i - 1]));
  let d = ticks.length > 1 ? decimalsFor(step) : decimalsFor(Math.abs(ticks[0]));
  let labels = ticks.map((t) => fixed(t, d));
  while (d < 9 && new Set(labels).size < labels.length) labels = ticks.map((t) => fixed(t, ++d));
  return labels;
}

/** A reading for people: four significant digits in plain digits (0.000123 stays readable). */
export function formatReading(v: number): string {
  if (!Number.isFinite(v)) return String(v);
  const a = Math.abs(v);
  if (a < 1e-9) return '0';
  if (a >= 1e-6) return String(Number(v.toPrecision(4)));  // plain digits down to 1e-6
  return fixed(v, Math.min(12, 3 - Math.floor(Math.log10(a))));
}

/** A plot's y range when the data moves less than the signal's span (the server's
 *  `display_span`): that span, centred on the data. Null: the data span enough (or the signal has
 *  no span, or no data yet), the plot chooses. */
export function restingRange(min: number | null, max: number | null, s: SignalInfo): [number, number] | null {
  const span = s.display_span ?? 0;
  if (!(span > 0) || min === null || max === null || !Number.isFinite(min) || !Number.isFinite(max)) return null;
  if (max - min >= span) return null;
  const mid = (min + max) / 2;
  return [mid - span / 2, mid + span / 2];
}

/** "125.3 bar": a value in SI shown in the signal's display unit. */
export function formatSignal(si: number, s: SignalInfo): string {
  const u = unitLabel(s);
  return formatReading(toDisplay(si, s)) + (u ? ` ${u}` : '');
}
