// Where a state diagram's edge labels go so that none covers another or a state box: each label
// slides along its own curve (a quadratic Bézier) from the middle outwards and takes the first
// place that is free; the steps of the latest change are placed first, so they keep the middle.
// Pure geometry (no DOM): the widths are estimated from the text, as the font is known (style.css).

export interface Box { x0: number; y0: number; x1: number; y1: number }
export interface Point { x: number; y: number }

/** One label to place: its curve from p1 over control point c to p2, its text's size, and the
 *  unit normal on the outer side of the bend (the label sits beside the curve on that side). */
export interface LabelRequest {
  p1: Point; c: Point; p2: Point;
  normal: Point;
  width: number; height: number;
  first?: boolean;  ///< placed before the others (the latest change's steps)
}

export interface PlacedLabel { x: number; y: number; anchor: 'start' | 'middle' | 'end'; box: Box }

/** Where along the curve a label may sit, best first: the middle, then further out each side. */
const ALONG = [0.5, 0.42, 0.58, 0.34, 0.66, 0.27, 0.73, 0.2, 0.8, 0.14, 0.86];
/** How far beside the curve, best first. */
const BESIDE = [4, 12, 20];

function pointOn(r: LabelRequest, t: number): Point {
  const u = 1 - t;
  return { x: u * u * r.p1.x + 2 * u * t * r.c.x + t * t * r.p2.x, y: u * u * r.p1.y + 2 * u * t * r.c.y + t * t * r.p2.y };
}

function overlap(a: Box, b: Box): number {
  const w = Math.min(a.x1, b.x1) - Math.max(a.x0, b.x0);
  const h = Math.min(a.y1, b.y1) - Math.max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0;
}

/** The text's box for an SVG text at (x, y) (y the baseline) with that anchor. */
function textBox(x: number, y: number, anchor: PlacedLabel['anchor'], width: number, height: number): Box {
  const x0 = anchor === 'start' ? x : anchor === 'end' ? x - width : x - width / 2;
  // the glyphs' extent (ascent 0.93 em, descent 0.24 em) and a pixel of air round it
  return { x0: x0 - 1, y0: y - height * 0.93 - 1, x1: x0 + width + 1, y1: y + height * 0.24 + 1 };
}

/** One place per request, in the requests' order. `obstacles`: what no label may cover (the
 *  state boxes). A label that finds no free place takes the one it overlaps least. */
export function placeLabels(requests: readonly LabelRequest[], obstacles: readonly Box[]): PlacedLabel[] {
  const order = requests.map((_, i) => i).sort((a, b) => Number(!!requests[b].first) - Number(!!requests[a].first) || a - b);
  const placed: Box[] = [];
  const out: PlacedLabel[] = new Array(requests.length);
  for (const i of order) {
    const r = requests[i];
    const anchor: PlacedLabel['anchor'] = Math.abs(r.normal.x) > 0.5 ? (r.normal.x > 0 ? 'start' : 'end') : 'middle';
    let best: PlacedLabel | null = null, bestCost = Infinity;
    for (const t of ALONG) {
      for (const d of BESIDE) {
        const p = pointOn(r, t);
        const x = p.x + r.normal.x * d, y = p.y + r.normal.y * d + r.height * 0.35;
        const box = textBox(x, y, anchor, r.width, r.height);
        let cost = 0;
        for (const b of placed) cost += overlap(box, b);
        for (const b of obstacles) cost += overlap(box, b);
        if (cost < bestCost) {
          bestCost = cost;
          best = { x, y, anchor, box };
        }
        if (cost === 0) break;
      }
      if (bestCost === 0) break;
    }
    out[i] = best!;
    placed.push(best!.box);
  }
  return out;
}

/** A label's width in px for a font of `fontPx`, on the safe side: the diagram's sans-serif
 *  (DejaVu Sans in Debian's Chromium) is 0.55–0.7 em a character, bold up to 0.75 em; the
 *  transitions' names are capitals, digits and '_'. */
export function labelWidth(text: string, fontPx: number, bold = false): number {
  return text.length * fontPx * (bold ? 0.75 : 0.68);
}
