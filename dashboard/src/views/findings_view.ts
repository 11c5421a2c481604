// The verdict on the master: per rule its count, then each finding with its time, node, text and
// evidence frames, newest last. New findings come on the stream (`findings` pages); the earlier
// ones are read once, page by page, from GET /api/findings?since=. A page may overlap what is
// shown (the stream and a read cross): each finding is shown once, by its index in the run.
import { el, formatTime } from '../dom';
import type { FindingsPage, MasterFinding } from '../types';

/** At most this many findings are kept on the page (the report file has them all). */
const kMaxShown = 500;

export class FindingsView {
  private summary = el('p', { class: 'findings-summary', 'data-testid': 'findings-summary' }, 'no findings');
  private list = el('ul', { class: 'findings', 'data-testid': 'findings', 'aria-label': 'Findings on the master' });
  private next = 0;

  constructor(host: HTMLElement) {
    host.append(this.summary, this.list);
  }

  /** The index of the first finding not shown yet (GET /api/findings?since=). */
  get since(): number {
    return this.next;
  }

  /** False when the page starts after what is shown (findings between are missing: read them). */
  show(page: FindingsPage): boolean {
    const first = page.next - page.findings.length;
    if (first > this.next) return false;
    for (const f of page.findings.slice(this.next - first)) this.list.append(this.item(f));
    while (this.list.childElementCount > kMaxShown) this.list.firstElementChild?.remove();
    this.next = Math.max(this.next, page.next);
    const counted = Object.entries(page.rules).filter(([, r]) => r.count > 0);
    this.summary.textContent = counted.length === 0
      ? 'no findings'
      : counted.map(([rule, r]) => `${rule} (${r.severity}): ${r.count}`).join(', ') +
        (page.dropped > 0 ? `; ${page.dropped} not stored` : '');
    return true;
  }

  /** A restarted run: its findings start at 0. */
  clear(): void {
    this.list.replaceChildren();
    this.next = 0;
    this.summary.textContent = 'no findings';
  }

  private item(f: MasterFinding): HTMLElement {
    const frames = f.frames.map((x) => `${formatTime(x.t_us)} ${x.from} ${x.frame}`).join('\n');
    return el('li', { class: `finding ${f.severity}`, 'data-rule': f.rule, title: frames },
      el('span', { class: 'mono' }, formatTime(f.t_us)), ' ',
      el('strong', {}, f.rule), ` ${f.severity}, bus ${f.bus}${f.node ? `, node ${f.node}` : ''}: ${f.text}`);
  }
}
