// Draws a state diagram (state_diagrams.ts) as SVG: the current state filled, the edges of the
// last transition bold. States carry data-state and data-current for tests and screen readers.
import { svg } from '../dom';
import { Diagram, DiagramEdge, edgeKey, transitionPath } from '../state_diagrams';

const BOX_H = 30;

function boxWidth(label: string): number {
  return Math.max(70, label.length * 7.2 + 16);
}

/** Point where the segment from the box centre (cx, cy) towards (tx, ty) leaves the box. */
function boxExit(cx: number, cy: number, w: number, tx: number, ty: number): [number, number] {
  const dx = tx - cx, dy = ty - cy;
  if (dx === 0 && dy === 0) return [cx, cy];
  const sx = Math.abs(dx) > 0 ? (w / 2) / Math.abs(dx) : Infinity;
  const sy = Math.abs(dy) > 0 ? (BOX_H / 2) / Math.abs(dy) : Infinity;
  const s = Math.min(sx, sy);
  return [cx + dx * s, cy + dy * s];
}

export function renderDiagram(d: Diagram, current: string | null, last: { from: string; to: string } | null): SVGSVGElement {
  const byId = new Map(d.states.map((s) => [s.id, s]));
  const lastEdges = new Set(last ? transitionPath(d, last.from, last.to).map(edgeKey) : []);
  const root = svg('svg', {
    viewBox: `0 0 ${d.width} ${d.height}`,
    class: 'diagram',
    role: 'img',
    'aria-label': `${d.title}: current state ${current ?? 'unknown'}`,
    'data-testid': `diagram-${d.id}`,
  });
  root.append(
    svg('defs', {},
      svg('marker', { id: `arrow-${d.id}`, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' },
        svg('path', { d: 'M 0 0 L 10 5 L 0 10 z', class: 'arrowhead' })),
      svg('marker', { id: `arrow-last-${d.id}`, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse' },
        svg('path', { d: 'M 0 0 L 10 5 L 0 10 z', class: 'arrowhead last' }))),
  );
  // Edges first, boxes over them.
  d.edges.forEach((e: DiagramEdge) => {
    const a = byId.get(e.from)!, b = byId.get(e.to)!;
    const len = Math.hypot(b.x - a.x, b.y - a.y);
    // Bend each edge to its left: A→B and B→A then run on opposite sides; longer edges bend more.
    const bend = Math.min(60, 12 + len * 0.12);
    const nx = -(b.y - a.y) / len, ny = (b.x - a.x) / len;
    const mx = (a.x + b.x) / 2 + nx * bend, my = (a.y + b.y) / 2 + ny * bend;
    const [x1, y1] = boxExit(a.x, a.y, boxWidth(a.label), mx, my);
    const [x2, y2] = boxExit(b.x, b.y, boxWidth(b.label), mx, my);
    const isLast = lastEdges.has(edgeKey(e));
    const g = svg('g', { class: isLast ? 'edge last' : 'edge', 'data-edge': `${edgeKey(e)}` },
      svg('title', { }, `${e.label}: ${e.condition}`),
      svg('path', { d: `M ${x1} ${y1} Q ${mx} ${my} ${x2} ${y2}`, 'marker-end': `url(#${isLast ? 'arrow-last-' : 'arrow-'}${d.id})` }),
      svg('text', { x: (x1 + 2 * mx + x2) / 4, y: (y1 + 2 * my + y2) / 4, class: 'edge-label', 'text-anchor': 'middle' }, e.label));
    root.append(g);
  });
  for (const s of d.states) {
    const w = boxWidth(s.label);
    const isCurrent = s.id === current;
    const cls = ['state', s.fault ? 'fault' : '', isCurrent ? 'current' : ''].filter(Boolean).join(' ');
    root.append(svg('g', { class: cls, 'data-state': s.id, 'data-current': isCurrent ? 'true' : 'false' },
      svg('rect', { x: s.x - w / 2, y: s.y - BOX_H / 2, width: w, height: BOX_H, rx: 6 }),
      svg('text', { x: s.x, y: s.y + 4, 'text-anchor': 'middle' }, s.label)));
  }
  return root;
}
