// A case's timeline: the assertions (passed, failed), the faults injected and the script's log
// lines as marks on the simulated time axis; hovering a mark names it.
import { svg } from '../dom';
import type { Outcome, RunEvent } from './types';

const WIDTH = 1000, HEIGHT = 92, LEFT = 90, RIGHT = 16;
const LANES = [
  { key: 'failed', label: 'failed', y: 18 },
  { key: 'passed', label: 'passed', y: 40 },
  { key: 'fault', label: 'faults', y: 62 },
] as const;

function niceStep(span: number): number {
  const raw = span / 8;
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw) ?? raw;
}

export function renderTimeline(duration: number, outcomes: readonly Outcome[], events: readonly RunEvent[]): SVGSVGElement {
  const end = Math.max(duration, ...outcomes.map((o) => o.t), ...events.map((e) => e.t), 1e-3);
  const x = (t: number) => LEFT + (t / end) * (WIDTH - LEFT - RIGHT);
  const root = svg('svg', { viewBox: `0 0 ${WIDTH} ${HEIGHT}`, class: 'timeline', role: 'img', 'aria-label': 'Assertions and faults over simulated time', 'data-testid': 'timeline' });
  for (const lane of LANES) {
    root.append(svg('text', { x: 4, y: lane.y + 4, class: `lane-label ${lane.key}` }, lane.label));
    root.append(svg('line', { x1: LEFT, x2: WIDTH - RIGHT, y1: lane.y, y2: lane.y, class: 'lane' }));
  }
  const step = niceStep(end);
  for (let t = 0; t <= end + 1e-9; t += step) {
    root.append(svg('line', { x1: x(t), x2: x(t), y1: 8, y2: 72, class: 'tick' }));
    root.append(svg('text', { x: x(t), y: 86, class: 'tick-label', 'text-anchor': 'middle' }, `${Number(t.toPrecision(6))} s`));
  }
  for (const o of outcomes) {
    const lane = o.passed ? LANES[1] : LANES[0];
    const text = o.passed ? `${o.t.toFixed(3)} s: ${o.name} (${o.where})`
      : `${o.t.toFixed(3)} s: FAILED ${o.name}: expected ${o.expected}, actual ${o.actual} (${o.where})`;
    root.append(svg('circle', { cx: x(o.t), cy: lane.y, r: o.passed ? 4 : 6, class: `mark ${o.passed ? 'passed' : 'failed'}`,
      'data-testid': o.passed ? 'timeline-passed' : 'timeline-failed' }, svg('title', {}, text)));
  }
  for (const e of events.filter((ev) => ev.kind === 'fault')) {
    const cx = x(e.t), y = LANES[2].y;
    root.append(svg('path', { d: `M${cx},${y - 6} L${cx + 6},${y} L${cx},${y + 6} L${cx - 6},${y} Z`, class: 'mark fault', 'data-testid': 'timeline-fault' },
      svg('title', {}, `${e.t.toFixed(3)} s: fault ${e.text}`)));
  }
  return root;
}
