// One case's page: its verdict, the assertions on a timeline with their failure text and
// file:line:col, plots of its signals (uPlot, with the failures and faults marked), bus load,
// the faults and log lines, and the decoded trace with the dashboard's trace view and filters.
import uPlot from 'uplot';
import { el, hex } from '../dom';
import { formatReading } from '../signal_choice';
import { TraceView } from '../views/trace_view';
import { renderTimeline } from './timeline';
import { framesOf } from './trace_rows';
import type { CaseData, CasePlot, Outcome } from './types';

const COLOURS = ['#1f6fd1', '#c62828', '#1a7f37', '#9a6700', '#7b1fa2', '#00838f', '#5d4037', '#455a64'];

function section(id: string, title: string, ...children: (Node | string | null | false)[]): HTMLElement {
  return el('section', { id, 'aria-labelledby': `${id}-h` }, el('h2', { id: `${id}-h` }, title), ...children);
}

function failureText(o: Outcome): string {
  return `${o.where}: FAILED at ${o.t.toFixed(3)} s: ${o.name}: expected ${o.expected ?? ''}, actual ${o.actual ?? ''}`;
}

function assertions(data: CaseData): HTMLElement {
  const failed = data.outcomes.filter((o) => !o.passed);
  const list = failed.length
    ? el('ul', { class: 'failures', 'data-testid': 'failures' }, ...failed.map((o) => el('li', { class: 'mono' }, failureText(o))))
    : el('p', { class: 'ok' }, data.outcomes.length ? 'Every assertion held.' : 'No assertions.');
  const table = el('table', { class: 'outcomes', 'data-testid': 'outcomes' },
    el('thead', {}, el('tr', {}, ...['Time [s]', 'Assertion', 'Result', 'Where', 'Expected', 'Actual'].map((h) => el('th', { scope: 'col' }, h)))),
    el('tbody', {}, ...data.outcomes.map((o) => el('tr', { class: o.passed ? '' : 'result-failed' },
      el('td', { class: 'num' }, o.t.toFixed(3)), el('td', {}, o.name),
      el('td', {}, el('span', { class: `badge ${o.passed ? 'passed' : 'failed'}` }, o.passed ? 'passed' : 'failed')),
      el('td', { class: 'mono' }, o.where), el('td', {}, o.expected ?? ''), el('td', {}, o.actual ?? '')))));
  return section('assertions', 'Assertions',
    renderTimeline(data.simulated_s ?? 0, data.outcomes, data.events),
    list,
    data.outcomes_left_out ? el('p', { class: 'muted' }, `${data.outcomes_left_out} passed assertions left out of the report`) : null,
    el('details', { open: failed.length === 0 && data.outcomes.length <= 50 }, el('summary', {}, `All ${data.outcomes.length} assertions`), table));
}

/** Vertical lines at the failures (red) and faults (orange) on every plot. */
function markers(times: { t: number; colour: string }[]): uPlot.Plugin {
  return {
    hooks: {
      draw: [(u: uPlot) => {
        const ctx = u.ctx;
        ctx.save();
        ctx.lineWidth = 1.5 * devicePixelRatio;
        ctx.setLineDash([5 * devicePixelRatio, 4 * devicePixelRatio]);
        for (const m of times) {
          const x = u.valToPos(m.t, 'x', true);
          if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) continue;
          ctx.strokeStyle = m.colour;
          ctx.beginPath();
          ctx.moveTo(x, u.bbox.top);
          ctx.lineTo(x, u.bbox.top + u.bbox.height);
          ctx.stroke();
        }
        ctx.restore();
      }],
    },
  };
}

function plotWidth(box: HTMLElement): number {
  return Math.max(360, Math.min(box.clientWidth, 1400));
}

function plots(data: CaseData): { section: HTMLElement; draw: () => void } {
  const marks = [
    ...data.outcomes.filter((o) => !o.passed).map((o) => ({ t: o.t, colour: '#c62828' })),
    ...data.events.filter((e) => e.kind === 'fault').map((e) => ({ t: e.t, colour: '#e65100' })),
  ];
  const grid = el('div', { class: 'report-plots' });
  const draw = () => {
    const charts: uPlot[] = [];
    for (const [i, p] of data.plots.entries()) {
      const figure = el('figure', { class: 'report-plot', 'data-testid': `plot-${i}` }, el('figcaption', {}, p.title || data.name));
      grid.append(figure);
      charts.push(chart(p, data, figure, plotWidth(grid), marks));
    }
    window.addEventListener('resize', () => { for (const c of charts) c.setSize({ width: plotWidth(grid), height: 240 }); });
  };
  const note = data.signals.t.length ? null : el('p', { class: 'muted' }, 'No samples were recorded.');
  return { section: section('plots', 'Signals', note, grid), draw };
}

function chart(p: CasePlot, data: CaseData, figure: HTMLElement, width: number, marks: { t: number; colour: string }[]): uPlot {
  const series: uPlot.Series[] = [{ label: 't [s]' }, ...p.labels.map((label, k) => ({
    label, stroke: COLOURS[k % COLOURS.length], width: 1.5, spanGaps: false,
  }))];
  const columns = [data.signals.t, ...p.series.map((s) => data.signals.values[s] ?? [])] as uPlot.AlignedData;
  return new uPlot({
    width, height: 240,
    scales: { x: { time: false } },
    legend: { show: true },
    axes: [{ label: 'time [s]', size: 34 }, { label: p.y_label || undefined, size: 80, values: (_u: uPlot, ticks: number[]) => ticks.map(formatReading) }],
    series,
    plugins: [markers(marks)],
  }, columns, figure);
}

function busLoad(data: CaseData): HTMLElement {
  return section('buses', 'Bus load', ...data.buses.map((b) => el('div', { class: 'bus', 'data-testid': `bus-${b.name}` },
    el('h3', {}, `${b.name} (${b.wire}, ${b.bit_rate / 1000} kbit/s)`),
    el('p', {}, `${b.frames} frames, mean load ${(b.mean_load * 100).toFixed(2)} %` +
      (b.error_frames ? `, ${b.error_frames} error frames` : '') + (b.tx_queue_overflow ? `, ${b.tx_queue_overflow} transmit queue overflows` : '')),
    b.ids.length ? el('table', { class: 'ids' },
      el('thead', {}, el('tr', {}, ...['COB-ID', 'Frames', 'Load [%]'].map((h) => el('th', { scope: 'col' }, h)))),
      el('tbody', {}, ...b.ids.map((i) => el('tr', {},
        el('td', { class: 'mono' }, i.ext ? hex(i.id, 8) : hex(i.id, 3)), el('td', { class: 'num' }, String(i.frames)),
        el('td', { class: 'num' }, (i.load * 100).toFixed(2)))))) : null)));
}

function events(data: CaseData): HTMLElement {
  const faults = data.events.filter((e) => e.kind === 'fault');
  const logs = data.events.filter((e) => e.kind === 'log');
  const list = (items: typeof faults, testid: string) => el('ul', { class: 'events', 'data-testid': testid },
    ...items.map((e) => el('li', {}, el('span', { class: 'mono' }, `${e.t.toFixed(3)} s `), e.text)));
  return section('faults', 'Faults injected',
    faults.length ? list(faults, 'faults') : el('p', { class: 'muted', 'data-testid': 'faults' }, 'No faults were injected.'),
    logs.length ? el('details', {}, el('summary', {}, `Log (${logs.length} lines)`), list(logs, 'log')) : null,
    data.events_left_out ? el('p', { class: 'muted' }, `${data.events_left_out} later events left out of the report`) : null);
}

function trace(data: CaseData): HTMLElement {
  const host = el('div', { 'data-testid': 'trace' });
  const frames = framesOf(data.trace.buses, data.trace.rows);
  const kept = frames.length;
  const note = kept < data.trace.seen
    ? `${data.trace.seen} frames crossed the buses; the report keeps the first and the last ${kept / 2} (the ${data.trace.seen - kept} in between are in the candump trace, --trace).`
    : `${data.trace.seen} frames.`;
  const sec = section('trace', 'Decoded trace', el('p', { class: 'muted' }, note), host);
  const view = new TraceView(host, data.nodes, { rowsRendered: kept, live: false });
  view.push(frames);
  return sec;
}

export function renderCase(host: HTMLElement, data: CaseData): void {
  document.title = `${data.name} - vplant report`;
  const meta = [
    data.file ? `${data.file}` : '',
    data.seed !== undefined ? `seed ${data.seed}` : '',
    data.simulated_s !== undefined ? `${data.simulated_s.toFixed(3)} s simulated` : '',
    data.wall_s !== undefined ? `${data.wall_s.toFixed(3)} s wall` : '',
    data.interrupted ? 'interrupted' : '',
  ].filter(Boolean).join(' · ');
  const p = plots(data);
  host.replaceChildren(
    el('header', {},
      el('a', { href: '../../index.html', class: 'back' }, '← all cases'),
      el('h1', { 'data-testid': 'case-name' }, data.name),
      el('span', { class: `badge ${data.result}`, 'data-testid': 'case-result' }, data.result),
      el('p', { class: 'muted' }, meta)),
    el('div', { class: 'report-body' },
      data.error ? el('p', { class: 'error' }, data.error) : null,
      assertions(data), p.section, events(data), busLoad(data), trace(data)));
  p.draw();
}
