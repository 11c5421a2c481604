// Sliding-window time series for the plots: samples of the chosen plant signals, kept for the last
// `windowUs` of simulated time, in the column layout uPlot draws ([x[], y1[], y2[], ...]).
import type { SignalBatch } from './types';

export class SignalSeries {
  private t: number[] = [];
  private columns: number[][];

  constructor(readonly names: readonly string[], readonly windowUs: number) {
    this.columns = names.map(() => []);
  }

  /** Appends a batch; a signal missing from it gets NaN (a gap), and time going backwards
   *  (a restarted clock) starts the window afresh. */
  append(batch: SignalBatch): void {
    for (let i = 0; i < batch.t_us.length; ++i) {
      const t = batch.t_us[i];
      if (this.t.length && t < this.t[this.t.length - 1]) this.reset();
      this.t.push(t);
      this.names.forEach((name, c) => {
        const v = batch.values[name]?.[i];
        this.columns[c].push(typeof v === 'number' ? v : NaN);
      });
    }
    this.trim();
  }

  private trim(): void {
    if (!this.t.length) return;
    const from = this.t[this.t.length - 1] - this.windowUs;
    let drop = 0;
    while (drop < this.t.length && this.t[drop] < from) ++drop;
    if (drop) {
      this.t.splice(0, drop);
      for (const c of this.columns) c.splice(0, drop);
    }
  }

  reset(): void {
    this.t = [];
    this.columns = this.names.map(() => []);
  }

  get length(): number {
    return this.t.length;
  }

  /** The newest value of a signal, or undefined. */
  latest(name: string): number | undefined {
    const c = this.names.indexOf(name);
    if (c < 0 || !this.t.length) return undefined;
    return this.columns[c][this.t.length - 1];
  }

  /** uPlot data: time in seconds, then one column per signal. */
  plotData(): number[][] {
    return [this.t.map((us) => us / 1e6), ...this.columns];
  }
}
