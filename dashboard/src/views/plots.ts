// Live plots of chosen plant signals, one small uPlot chart per signal in its display unit (bar,
// mm, rpm, ...: units.ts), over a sliding window of simulated time; axis ticks in plain digits.
import uPlot from 'uplot';
import { el } from '../dom';
import { SignalSeries } from '../signal_series';
import type { SignalBatch, SignalInfo } from '../types';
import { formatSignal, restingRange, signalInfo, tickLabels, toDisplay, unitLabel } from '../units';

const WINDOW_US = 10_000_000;

/** The y axis as wide as its longest tick label (uPlot measures nothing itself). */
function axisWidth(_u: uPlot, values: string[] | null): number {
  return 16 + 7 * Math.max(3, ...(values ?? []).map((v) => v.length));
}

export class Plots {
  private series: SignalSeries;
  private charts = new Map<string, { plot: uPlot; readout: HTMLElement }>();
  private grid = el('div', { class: 'plot-grid' });
  private dirty = false;

  constructor(host: HTMLElement, private signals: ReadonlyMap<string, SignalInfo>, private chosen: string[], onChange: (chosen: string[]) => void) {
    this.series = new SignalSeries(chosen, WINDOW_US);
    const all = [...signals.keys()];
    const picker = el('details', { class: 'signal-picker' }, el('summary', {}, 'Choose signals'));
    for (const name of all) {
      const box = el('input', { type: 'checkbox', checked: chosen.includes(name), 'data-testid': `signal-choose-${name}` });
      box.addEventListener('change', () => {
        const next = box.checked ? [...this.chosen, name] : this.chosen.filter((n) => n !== name);
        onChange(next);
      });
      const info = this.info(name);
      const u = unitLabel(info);
      picker.append(el('label', {}, box, ` ${name}${u ? ` [${u}]` : ''}`));
    }
    host.replaceChildren(picker, this.grid);
    this.rebuild();
    setInterval(() => this.redraw(), 200);
  }

  /** New choice: new series and charts (the stream is reopened with the new names). */
  choose(chosen: string[]): void {
    this.chosen = chosen;
    this.series = new SignalSeries(chosen, WINDOW_US);
    this.rebuild();
  }

  private info(name: string): SignalInfo {
    return this.signals.get(name) ?? signalInfo(name);
  }

  /** The newest value (SI) of a chosen signal. */
  latest(name: string): number | undefined {
    return this.series.latest(name);
  }

  append(batch: SignalBatch): void {
    this.series.append(batch);
    this.dirty = true;
  }

  private rebuild(): void {
    for (const c of this.charts.values()) c.plot.destroy();
    this.charts.clear();
    this.grid.replaceChildren();
    for (const name of this.chosen) {
      const info = this.info(name);
      const u = unitLabel(info);
      const readout = el('span', { class: 'readout', 'data-testid': `plot-value-${name}` }, '');
      const box = el('figure', { class: 'plot', 'data-testid': `plot-${name}` }, el('figcaption', {}, name, u ? ` [${u}]` : '', ' ', readout));
      this.grid.append(box);
      const plot = new uPlot({
        width: 330, height: 140,
        legend: { show: false },
        cursor: { show: false },
        // a value at rest is drawn flat at its level, not its last digits' noise across the axis
        scales: { x: { time: false }, y: { range: (_u, min, max) => restingRange(min, max, info) ?? uPlot.rangeNum(min, max, 0.1, true) } },
        axes: [{ label: 't [s]', size: 30, values: (_u: uPlot, ticks: number[]) => tickLabels(ticks) },
          { size: axisWidth, values: (_u: uPlot, ticks: number[]) => tickLabels(ticks) }],
        series: [{}, { label: name, stroke: '#1f6fd1', width: 1.5, spanGaps: false, points: { show: false } }],
      }, [[], []], box);
      this.charts.set(name, { plot, readout });
    }
  }

  private redraw(): void {
    if (!this.dirty) return;
    this.dirty = false;
    const data = this.series.plotData();
    this.chosen.forEach((name, i) => {
      const c = this.charts.get(name);
      if (!c) return;
      const info = this.info(name);
      c.plot.setData([data[0], data[i + 1].map((v) => toDisplay(v, info))] as uPlot.AlignedData);
      const v = this.series.latest(name);
      c.readout.textContent = v === undefined || Number.isNaN(v) ? '' : `= ${formatSignal(v, info)}`;
    });
  }
}
