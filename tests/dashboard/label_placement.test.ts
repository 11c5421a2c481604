import assert from 'node:assert/strict';
import { test } from 'node:test';
import { labelWidth, placeLabels, type Box, type LabelRequest } from '../../dashboard/src/label_placement';

const overlaps = (a: Box, b: Box) => Math.min(a.x1, b.x1) > Math.max(a.x0, b.x0) && Math.min(a.y1, b.y1) > Math.max(a.y0, b.y0);

/** A straight-ish edge from (x1, y) to (x2, y), bending up by `bend`. */
function edge(x1: number, x2: number, y: number, bend: number, text: string, first = false): LabelRequest {
  return { p1: { x: x1, y }, c: { x: (x1 + x2) / 2, y: y - bend }, p2: { x: x2, y }, normal: { x: 0, y: -1 },
    width: labelWidth(text, 10), height: 10, first };
}

test('a label alone sits at its curve\'s middle, beside the bend', () => {
  const [p] = placeLabels([edge(0, 200, 100, 40, 'TR_2')], []);
  assert.equal(p.anchor, 'middle');
  assert.equal(p.x, 100);
  assert.ok(p.y < 100 - 20 && p.y > 100 - 40, `beside the curve's apex: ${p.y}`);
});

test('labels of edges that cross at their middles move apart along their curves', () => {
  // Three edges over the same span, the same bend: every middle at one point.
  const reqs = [edge(0, 300, 100, 40, 'TR_8'), edge(0, 300, 100, 40, 'TR_11'), edge(0, 300, 100, 40, 'TR_567')];
  const placed = placeLabels(reqs, []);
  for (let i = 0; i < placed.length; ++i) {
    for (let k = i + 1; k < placed.length; ++k) assert.ok(!overlaps(placed[i].box, placed[k].box), `${i} and ${k} overlap`);
  }
});

test('a label does not cover a state box, and the latest change keeps the middle', () => {
  const state: Box = { x0: 80, y0: 60, x1: 120, y1: 90 };  // over the middle of the curve's apex
  const [p] = placeLabels([edge(0, 200, 100, 40, 'TR_5')], [state]);
  assert.ok(!overlaps(p.box, state));
  const both = placeLabels([edge(0, 200, 100, 40, 'TR_6'), edge(0, 200, 100, 40, '1: TR_7', true)], []);
  const [alone] = placeLabels([edge(0, 200, 100, 40, '1: TR_7', true)], []);
  assert.deepEqual(both[1], alone, 'the marked step is placed first: where it would be alone');
  assert.ok(!overlaps(both[0].box, both[1].box));
});

test('with no free place a label takes the one it overlaps least, never none', () => {
  const wall: Box = { x0: -1000, y0: -1000, x1: 1000, y1: 1000 };
  const placed = placeLabels([edge(0, 200, 100, 40, 'TR_1')], [wall]);
  assert.equal(placed.length, 1);
  assert.ok(Number.isFinite(placed[0].x) && Number.isFinite(placed[0].y));
});
