// One seat on the trainer's overview: its nodes' states at a glance, its exercise progress, a
// read-only view of its page and a restart.
import { button, el, formatTime } from '../dom';
import type { SeatSummary } from './types';

export interface SeatActions {
  restart(seat: number): void;
}

/** The NMT state and the device's own state of one node as a chip: green when operational. */
function nodeChip(node: SeatSummary['nodes'][number]): HTMLElement {
  const device = node.device && 'state' in node.device ? node.device.state : '';
  const kind = node.nmt === 'OPERATIONAL' ? 'ok' : node.nmt === 'STOPPED' || /FAULT/.test(device) ? 'bad' : 'idle';
  return el(
    'li',
    { class: `chip ${kind}`, 'data-testid': `node-${node.name}`, title: `${node.name}: ${node.nmt}${device ? ', ' + device : ''}` },
    el('b', {}, node.name),
    ` ${node.nmt}`,
    device ? el('span', { class: 'device' }, ` ${device}`) : null,
  );
}

function progress(s: SeatSummary): HTMLElement {
  const ex = s.exercise;
  if (!ex || !ex.name) return el('p', { class: 'muted', 'data-testid': 'progress' }, 'no exercise selected');
  const done = ex.steps.filter((st) => st.done).length;
  return el(
    'div',
    { class: 'progress', 'data-testid': 'progress' },
    el('p', {}, el('b', {}, ex.title ?? ex.name), ` ${done}/${ex.steps.length} steps done`),
    el('progress', { max: ex.steps.length, value: done }),
    el(
      'ol',
      { class: 'steps' },
      ...ex.steps.map((st) =>
        el('li', { class: st.done ? 'done' : 'open' }, st.done ? '✓ ' : '○ ', st.title, st.done && st.t_us != null ? ` (${formatTime(st.t_us)})` : ''),
      ),
    ),
  );
}

export function seatCard(s: SeatSummary, actions: SeatActions): HTMLElement {
  const late = s.lateness_us ? `tick lateness p99 ${s.lateness_us.p99} µs` : '';
  return el(
    'article',
    { class: 'seat', 'data-testid': `seat-${s.seat}` },
    el(
      'header',
      {},
      el('h3', {}, `Seat ${s.seat}`),
      el('span', { class: 'muted' }, s.clock ? formatTime(s.clock.t_us) : s.running ? '' : 'stopped', late ? ` · ${late}` : ''),
    ),
    el('ul', { class: 'chips' }, ...s.nodes.map(nodeChip)),
    progress(s),
    el(
      'div',
      { class: 'actions' },
      // The trainer's cookie only looks at a seat: the server refuses its changes (docs/classroom.md).
      el('a', { href: `seats/${s.seat}/`, target: '_blank', rel: 'noopener', 'data-testid': 'view' }, 'View (read-only)'),
      button('Restart', { 'data-testid': 'restart' }, () => actions.restart(s.seat)),
    ),
  );
}
