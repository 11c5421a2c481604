// The selected node's transition list: every change its state machines recorded, newest first —
// when, which machine, from → to, the transition's name, and the cause in words with its evidence.
import { el, formatTime } from '../dom';
import type { Transition } from '../types';

/** Rows drawn at most (the store keeps more; the API has the whole bounded history). */
const ROWS = 200;

/** The text with a line-break opportunity (<wbr>) after each "_": DEVICE_MODE_ACTIVE wraps at its
 *  parts in a narrow column, not inside a word (textContent stays the same). */
export function breakable(text: string): (string | HTMLElement)[] {
  return text.split('_').flatMap((part, i, all) => (i < all.length - 1 ? [`${part}_`, el('wbr')] : [part]));
}

export class TransitionList {
  private body = el('tbody');
  private empty = el('p', { class: 'none', 'data-testid': 'transitions-empty' }, 'no transition recorded yet');

  constructor(host: HTMLElement) {
    host.replaceChildren(this.empty, el('div', { class: 'transitions-scroll' },
      el('table', { class: 'transitions', 'data-testid': 'transition-list', 'aria-label': 'Transitions of the selected node' },
        el('thead', {}, el('tr', {}, ...['Time', 'Machine', 'From → to', 'Transition', 'Cause'].map((h) => el('th', { scope: 'col' }, h)))),
        this.body)));
  }

  /** `unavailable`: the server has no transition history (a reason instead of rows). */
  show(entries: readonly Transition[], unavailable: string | null = null): void {
    this.empty.textContent = unavailable ?? 'no transition recorded yet';
    this.empty.hidden = entries.length > 0;
    this.body.replaceChildren(...entries.slice(-ROWS).reverse().map((t) =>
      el('tr', { 'data-seq': t.seq, 'data-machine': t.machine, 'data-transition': t.transition },
        el('td', { class: 'mono' }, formatTime(t.t_us)),
        el('td', { class: 'mono' }, ...t.machine.split('.').flatMap((part, i, all) => (i < all.length - 1 ? [`${part}.`, el('wbr')] : [part]))),
        el('td', { class: 'states' }, ...breakable(`${t.from} → ${t.to}`)),
        el('td', { class: 'mono' }, t.transition),
        el('td', { class: 'cause' }, t.evidence || t.cause))));
  }
}
