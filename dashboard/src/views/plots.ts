// Live plots of chosen plant signals, one small uPlot chart per signal (their units differ:
// metres, pascals, a fraction, rad/s), over a sliding window of simulated time.
import uPlot from 'uplot';
import { el } from '../dom';
import { formatReading } from '../signal_choice';
import { SignalSeries } from '../signal_series';
import type { SignalBatch } from '../types';

const WINDOW_US = 10_000_000;

export class Plots {
  private series: SignalSeries;
  private charts = new Map<string, { plot: uPlot; readout: HTMLElement }>();
  private grid = el('div', { class: 'plot-grid' });
  private dirty = false;

  constructor(host: HTMLElement, all: readonly string[], private chosen: string[], onChange: (chosen: string[]) => void) {
    this.series = new SignalSeries(chosen, WINDOW_US);
    const picker = el('details', { class: 'signal-picker' }, el('summary', {}, 'Choose signals'));
    for (const name of all) {
      const box = el('input', { type: 'checkbox', checked: chosen.includes(name), 'data-testid': `signal-choose-${name}` });
      box.addEventListener('change', () => {
        const next = box.checked ? [...this.chosen, name] : this.chosen.filter((n) => n !== name);
        onChange(next);
      });
      picker.append(el('label', {}, box, ` ${name}`));
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

  append(batch: SignalBatch): void {
    this.series.append(batch);
    this.dirty = true;
  }

  private rebuild(): void {
    for (const c of this.charts.values()) c.plot.destroy();
    this.charts.clear();
    this.grid.replaceChildren();
    for (const name of this.chosen) {
      const readout = el('span', { class: 'readout', 'data-testid': `plot-value-${name}` }, '');
      const box = el('figure', { class: 'plot', 'data-testid': `plot-${name}` }, el('figcaption', {}, name, ' ', readout));
      this.grid.append(box);
      const plot = new uPlot({
        width: 360, height: 150,
        legend: { show: false },
        cursor: { show: false },
        scales: { x: { time: false } },
        axes: [{ label: 't [s]', size: 30 }, { size: 78, values: (_u: uPlot, ticks: number[]) => ticks.map(formatReading) }],
        series: [{}, { label: name, stroke: '#1f6fd1', width: 1.5, spanGaps: false }],
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
      c.plot.setData([data[0], data[i + 1]] as uPlot.AlignedData);
      const v = this.series.latest(name);
      c.readout.textContent = v === undefined || Number.isNaN(v) ? '' : `= ${formatReading(v)}`;
    });
  }
}
