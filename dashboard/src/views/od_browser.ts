// The object-dictionary browser: every entry of the selected node with the value the node holds
// (in engineering units where the product documents a scaling); writable
// entries get an input that writes over the bus by SDO (the frames show in the trace), and every
// entry a read-by-SDO button. Refusals show the SDO abort code and its CiA 301 text.
import { button, el } from '../dom';
import { formatIndex, formatValue } from '../od_input';
import type { OdEntry } from '../types';

export interface OdActions {
  write(entry: OdEntry, text: string): void;
  read(entry: OdEntry): void;
}

/** The Value column: what the dictionary holds now, in engineering units when the server gives them. */
export function valueText(e: OdEntry): string {
  const raw = formatValue(e.value, e.type);
  return e.display !== undefined ? `${e.display}${e.unit && !e.display.endsWith(e.unit) ? ` ${e.unit}` : ''} (${raw})` : raw;
}

function testId(e: OdEntry): string {
  return formatIndex(e.index, e.sub).replace(':', '-');
}

export class OdBrowser {
  private rows = new Map<string, { value: HTMLTableCellElement; entry: OdEntry }>();
  private filterInput = el('input', { type: 'search', placeholder: 'filter: index or name', 'aria-label': 'Filter objects', 'data-testid': 'od-filter' });
  private table = el('table', { class: 'od', 'data-testid': 'od-table', 'aria-label': 'Object dictionary' });
  readonly result = el('div', { class: 'od-result', 'data-testid': 'od-result', role: 'status', 'aria-live': 'polite' });

  constructor(host: HTMLElement, private actions: OdActions) {
    this.filterInput.addEventListener('input', () => this.applyFilter());
    host.replaceChildren(el('div', { class: 'od-bar' }, this.filterInput), this.result, el('div', { class: 'od-scroll' }, this.table));
  }

  /** A new node (or the first load): rebuild the rows. */
  show(entries: readonly OdEntry[]): void {
    this.rows.clear();
    const body = el('tbody');
    for (const e of entries) {
      const id = testId(e);
      const value = el('td', { 'data-testid': `od-value-${id}`, class: 'value' }, valueText(e));
      const writable = e.access === 'rw' || e.access === 'wo';
      const input = writable ? el('input', { type: 'text', size: 10, 'aria-label': `New value for ${formatIndex(e.index, e.sub)} ${e.name}`, 'data-testid': `od-input-${id}` }) : null;
      const cell = el('td', { class: 'actions' },
        input,
        input && button('Write', { 'data-testid': `od-write-${id}`, 'aria-label': `Write ${formatIndex(e.index, e.sub)} by SDO` }, () => this.actions.write(e, input.value)),
        e.access !== 'wo' && button('Read', { 'data-testid': `od-read-${id}`, 'aria-label': `Read ${formatIndex(e.index, e.sub)} by SDO` }, () => this.actions.read(e)));
      input?.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') this.actions.write(e, input.value); });
      const row = el('tr', { 'data-testid': `od-row-${id}`, 'data-search': `${formatIndex(e.index, e.sub)} ${e.name}`.toLowerCase() },
        el('td', { class: 'mono' }, formatIndex(e.index, e.sub)), el('td', {}, e.name), el('td', {}, e.type),
        el('td', {}, e.access + (e.pdo_mappable ? ', PDO' : '')), value, cell);
      body.append(row);
      this.rows.set(id, { value, entry: e });
    }
    this.table.replaceChildren(
      el('thead', {}, el('tr', {}, ...['Index:sub', 'Name', 'Type', 'Access', 'Held now', 'Over the bus (SDO)'].map((h) => el('th', { scope: 'col' }, h)))),
      body);
    this.applyFilter();
  }

  /** Live values of the same node (all, or the changed ones): update the value cells only, so inputs keep what is typed. */
  update(entries: readonly OdEntry[]): void {
    for (const e of entries) {
      const r = this.rows.get(testId(e));
      if (!r) continue;
      const text = valueText(e);
      if (r.value.textContent !== text) r.value.textContent = text;
      r.entry = e;
    }
  }

  /** The stream's values ("6041:00" → value, and the scaled ones' text) for the node shown: update those cells. */
  updateValues(values: Record<string, number | string | null>, display: Record<string, string>): void {
    for (const [key, value] of Object.entries(values)) {
      const r = this.rows.get(key.replace(':', '-').toUpperCase());
      if (!r) continue;
      this.update([{ ...r.entry, value, display: display[key] }]);
    }
  }

  report(ok: boolean, text: string): void {
    this.result.className = ok ? 'od-result ok' : 'od-result refused';
    this.result.textContent = text;
  }

  private applyFilter(): void {
    const q = this.filterInput.value.trim().toLowerCase();
    for (const tr of this.table.querySelectorAll<HTMLTableRowElement>('tbody tr')) {
      tr.hidden = q !== '' && !(tr.dataset.search ?? '').includes(q);
    }
  }
}
