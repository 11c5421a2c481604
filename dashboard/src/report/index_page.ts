// The report's index: the suite table (case, result, assertions, simulated and wall time, speed)
// with a text filter, a result filter and sortable columns; failures first.
import { el } from '../dom';
import { counts, DEFAULT_VIEW, SortKey, speed, suiteRows, SuiteView } from './suite_table';
import type { IndexData } from './types';

const COLUMNS: { key: SortKey | null; label: string }[] = [
  { key: 'name', label: 'Case' }, { key: 'result', label: 'Result' }, { key: null, label: 'Assertions' },
  { key: 'simulated_s', label: 'Simulated [s]' }, { key: 'wall_s', label: 'Wall [s]' }, { key: 'speed', label: 'Speed [× real time]' },
  { key: null, label: 'First failure' },
];

function fixed(v: number | undefined, digits: number): string {
  return v === undefined || Number.isNaN(v) ? '' : v.toFixed(digits);
}

export function renderIndex(host: HTMLElement, data: IndexData): void {
  const view: SuiteView = { ...DEFAULT_VIEW };
  const n = counts(data.cases);
  const text = el('input', { type: 'search', placeholder: 'filter by name or file', 'aria-label': 'Filter cases', 'data-testid': 'suite-filter' });
  const result = el('select', { 'aria-label': 'Result', 'data-testid': 'suite-result' },
    ...(['all', 'failed', 'error', 'passed'] as const).map((r) => el('option', { value: r }, r)));
  const head = el('tr');
  const body = el('tbody');
  const status = el('span', { class: 'muted', 'data-testid': 'suite-status', role: 'status' });
  const render = () => {
    head.replaceChildren(...COLUMNS.map((c) => {
      const arrow = c.key === view.sort ? (view.descending ? ' ▼' : ' ▲') : '';
      const th = el('th', { scope: 'col', class: c.key ? 'sortable' : undefined, 'aria-sort': c.key === view.sort ? (view.descending ? 'descending' : 'ascending') : undefined }, c.label + arrow);
      if (c.key) {
        const key = c.key;
        th.addEventListener('click', () => {
          view.descending = view.sort === key ? !view.descending : false;
          view.sort = key;
          render();
        });
      }
      return th;
    }));
    const rows = suiteRows(data.cases, view);
    body.replaceChildren(...rows.map((c) => {
      const failure = c.first_failure
        ? `${c.first_failure.where}: ${c.first_failure.name}: expected ${c.first_failure.expected ?? ''}, actual ${c.first_failure.actual ?? ''}`
        : c.error ?? '';
      return el('tr', { class: `result-${c.result}`, 'data-testid': `case-row-${c.id}` },
        el('td', {}, el('a', { href: c.page }, c.name)),
        el('td', {}, el('span', { class: `badge ${c.result}` }, c.result)),
        el('td', { class: 'num' }, c.assertions === undefined ? '' : `${c.assertions - (c.failures ?? 0)} / ${c.assertions}`),
        el('td', { class: 'num' }, fixed(c.simulated_s, 3)),
        el('td', { class: 'num' }, fixed(c.wall_s, 3)),
        el('td', { class: 'num' }, fixed(speed(c), 1)),
        el('td', { class: 'failure' }, failure));
    }));
    status.textContent = `${rows.length} of ${data.cases.length} cases shown`;
  };
  text.addEventListener('input', () => { view.text = text.value; render(); });
  result.addEventListener('change', () => { view.result = result.value as SuiteView['result']; render(); });
  host.replaceChildren(
    el('header', {}, el('h1', {}, 'vplant report'),
      el('p', { class: 'totals', 'data-testid': 'suite-totals' },
        `${data.cases.length} cases: ${n.passed} passed, ${n.failed} failed, ${n.error} errors`)),
    el('div', { class: 'report-body' },
      el('div', { class: 'suite-controls' }, text, result, status),
      el('table', { class: 'suite', 'data-testid': 'suite-table', 'aria-label': 'Cases' }, el('thead', {}, head), body)));
  render();
}
