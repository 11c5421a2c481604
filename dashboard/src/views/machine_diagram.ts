// Draws a state machine as the C++ profile describes it (GET /api/nodes/{n}/machines): states on
// the grid of their row/col hints, edges named by their transition with the condition on hover.
// The current state is filled; each step of the latest change is drawn bold and numbered.
// Labels are placed so that none covers another or a state (label_placement.ts).
// States carry data-state / data-current, edges data-transition / data-step, for tests and readers.
import { svg } from '../dom';
import { labelWidth, placeLabels, type Box, type LabelRequest } from '../label_placement';
import type { Machine, MachineEdge, Transition } from '../types';

/** The grid and the boxes. `large` (the lesson view, a projector): the state names in 17 px
 *  instead of 11 px, each column as wide as its longest name needs (not all as wide as the
 *  widest), so the names stay large when the drawing is scaled down to its panel (style.css
 *  sets the fonts). */
interface Geometry { colW: number; rowH: number; boxH: number; charW: number; minBox: number }
const SMALL: Geometry = { colW: 190, rowH: 84, boxH: 32, charW: 7.4, minBox: 80 };
const LARGE: Geometry = { colW: 0, rowH: 88, boxH: 40, charW: 11.2, minBox: 60 };
const MARGIN = 24, LARGE_GAP = 56;  // between two columns' boxes: room for an edge and its label

function geometry(large: boolean): Geometry {
  return large ? LARGE : SMALL;
}

/** The left edge of each column, and the drawing's width. */
function columns(m: Machine, g: Geometry, cols: number): { left: number[]; widths: number[]; width: number } {
  const widths = Array.from({ length: cols }, (_, c) => g.colW > 0
    ? g.colW
    : Math.max(g.minBox, ...m.states.filter((s) => s.col === c).map((s) => s.name.length * g.charW + 18)) + LARGE_GAP);
  const left: number[] = [];
  let x = MARGIN;
  for (const w of widths) { left.push(x); x += w; }
  return { left, widths, width: x + MARGIN };
}

function boxWidth(g: Geometry, label: string): number {
  const w = Math.max(g.minBox, label.length * g.charW + 18);
  return g.colW > 0 ? Math.min(g.colW - 14, w) : w;
}

/** Point where the segment from the box centre (cx, cy) towards (tx, ty) leaves the box. */
function boxExit(g: Geometry, cx: number, cy: number, w: number, tx: number, ty: number): [number, number] {
  const dx = tx - cx, dy = ty - cy;
  if (dx === 0 && dy === 0) return [cx, cy];
  const sx = dx !== 0 ? (w / 2) / Math.abs(dx) : Infinity;
  const sy = dy !== 0 ? (g.boxH / 2) / Math.abs(dy) : Infinity;
  const s = Math.min(sx, sy);
  return [cx + dx * s, cy + dy * s];
}

export const edgeId = (e: Pick<MachineEdge, 'transition' | 'from' | 'to'>) => `${e.transition}:${e.from}->${e.to}`;

export function renderMachine(m: Machine, current: ReadonlySet<string>, chain: readonly Transition[], large = false): SVGSVGElement {
  const geo = geometry(large);
  const ROW_H = geo.rowH, BOX_H = geo.boxH;
  const rows = Math.max(1, ...m.states.map((s) => s.row + 1));
  const cols = Math.max(1, ...m.states.map((s) => s.col + 1));
  const grid = columns(m, geo, cols);
  const width = grid.width, height = rows * ROW_H + 2 * MARGIN - (ROW_H - BOX_H) / 2;
  const at = new Map(m.states.map((s) => [s.name, { x: grid.left[s.col] + grid.widths[s.col] / 2, y: MARGIN + s.row * ROW_H + BOX_H / 2, s }]));
  const step = new Map(chain.map((t, i) => [edgeId(t), i + 1]));
  const id = m.machine.replace(/[^a-z0-9]/gi, '-');
  const root = svg('svg', {
    viewBox: `0 0 ${width} ${height}`, class: large ? 'diagram large' : 'diagram', role: 'img',
    'aria-label': `${m.title}: current state ${[...current].join(' + ')}`, 'data-testid': `diagram-${m.machine}`,
    // the full console: no larger than 1.15× its drawn size; the lesson view fills its panel
    style: large ? '' : `max-width:${width * 1.15}px`,
  });
  root.append(svg('defs', {},
    svg('marker', { id: `arrow-${id}`, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 8, markerHeight: 8, markerUnits: 'userSpaceOnUse', orient: 'auto-start-reverse' },
      svg('path', { d: 'M 0 0 L 10 5 L 0 10 z', class: 'arrowhead' })),
    svg('marker', { id: `arrow-last-${id}`, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 11, markerHeight: 11, markerUnits: 'userSpaceOnUse', orient: 'auto-start-reverse' },
      svg('path', { d: 'M 0 0 L 10 5 L 0 10 z', class: 'arrowhead last' }))));
  // Several edges between one pair of states fan out: the n-th bends further.
  const seenPairs = new Map<string, number>();
  const edges = svg('g', {}), marked = svg('g', {});
  // The label fonts of style.css (.edge-label, .edge.last .edge-label; larger in the lesson view).
  const fontPx = large ? 13 : 10, lastFontPx = large ? 16 : 12;
  const drawn: { e: MachineEdge; n: number | undefined; label: string; d: string }[] = [];
  const requests: LabelRequest[] = [];
  for (const e of m.edges) {
    const a = at.get(e.from), b = at.get(e.to);
    if (!a || !b || a === b) continue;
    const pair = `${e.from}->${e.to}`;
    const nth = seenPairs.get(pair) ?? 0;
    seenPairs.set(pair, nth + 1);
    const len = Math.hypot(b.x - a.x, b.y - a.y);
    // An edge that skips states on its row or column swings wide around them.
    const skips = (a.s.col === b.s.col && Math.abs(a.s.row - b.s.row) > 1) || (a.s.row === b.s.row && Math.abs(a.s.col - b.s.col) > 1);
    const bend = (skips ? Math.min(130, 40 + len * 0.25) : Math.min(70, 14 + len * 0.1)) + nth * 18;
    const nx = -(b.y - a.y) / len, ny = (b.x - a.x) / len;
    const mx = (a.x + b.x) / 2 + nx * bend, my = (a.y + b.y) / 2 + ny * bend;
    const [x1, y1] = boxExit(geo, a.x, a.y, boxWidth(geo, e.from), mx, my);
    const [x2, y2] = boxExit(geo, b.x, b.y, boxWidth(geo, e.to), mx, my);
    const n = step.get(edgeId(e));
    const label = n === undefined ? e.transition : `${n}: ${e.transition}`;
    const font = n === undefined ? fontPx : lastFontPx;
    drawn.push({ e, n, label, d: `M ${x1} ${y1} Q ${mx} ${my} ${x2} ${y2}` });
    requests.push({ p1: { x: x1, y: y1 }, c: { x: mx, y: my }, p2: { x: x2, y: y2 }, normal: { x: nx, y: ny },
      width: labelWidth(label, font, n !== undefined), height: font, first: n !== undefined });
  }
  const boxes: Box[] = [...at.values()].map(({ x, y, s }) => {
    const w = boxWidth(geo, s.name);
    return { x0: x - w / 2, y0: y - BOX_H / 2, x1: x + w / 2, y1: y + BOX_H / 2 };
  });
  const places = placeLabels(requests, boxes);
  drawn.forEach(({ e, n, label, d }, i) => {
    const g = svg('g', { class: n === undefined ? 'edge' : 'edge last', 'data-transition': e.transition, 'data-edge': edgeId(e), 'data-step': n },
      svg('title', {}, `${e.transition} (${e.from} → ${e.to}): ${e.condition}`),
      svg('path', { d, 'marker-end': `url(#${n === undefined ? 'arrow-' : 'arrow-last-'}${id})` }),
      svg('text', { x: places[i].x, y: places[i].y, class: 'edge-label', 'text-anchor': places[i].anchor }, label));
    (n === undefined ? edges : marked).append(g);
  });
  root.append(edges, marked);  // the marked steps over the others
  for (const { x, y, s } of at.values()) {
    const w = boxWidth(geo, s.name);
    const isCurrent = current.has(s.name);
    root.append(svg('g', { class: `state kind-${s.kind}${isCurrent ? ' current' : ''}`, 'data-state': s.name, 'data-current': isCurrent ? 'true' : 'false' },
      svg('rect', { x: x - w / 2, y: y - BOX_H / 2, width: w, height: BOX_H, rx: 6 }),
      svg('text', { x, y: y + (large ? 6 : 4), 'text-anchor': 'middle' }, s.name)));
  }
  return root;
}
