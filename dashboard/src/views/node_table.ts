// The node table: one row per node with its live NMT state, device state and error register;
// clicking a row selects the node for the diagrams and the object-dictionary browser.
import { el, hex } from '../dom';
import { dsp408Summary } from '../dsp408_channels';
import type { NodeInfo, ScenarioNode } from '../types';

export function deviceSummary(n: NodeInfo): string {
  const d = n.device;
  switch (d.profile) {
    case 'dsp408': return dsp408Summary(d);
    case 'vtvpcd': return d.faults.length ? `${d.state}; faults: ${d.faults.join(', ')}` : d.state;
    case 'cia406': return `status 0x${hex(d.operating_status, 4)}, alarms 0x${hex(d.alarms, 4)}, warnings 0x${hex(d.warnings, 4)}`;
    default: return '—';
  }
}

interface RowCells { row: HTMLTableRowElement; nmt: HTMLElement; device: HTMLElement; errreg: HTMLElement; emcy: HTMLElement }

/** Rows are built once and updated in place, so a click never lands on a row being replaced. */
export class NodeTable {
  private rows = new Map<string, RowCells>();

  constructor(host: HTMLElement, scenarioNodes: readonly ScenarioNode[], onSelect: (name: string) => void) {
    const body = el('tbody');
    for (const s of scenarioNodes) {
      const cells = {
        nmt: el('td', { 'data-testid': `nmt-${s.name}`, class: 'nmt' }, '?'),
        device: el('td', { 'data-testid': `device-${s.name}` }, '?'),
        errreg: el('td', { 'data-testid': `errreg-${s.name}` }, '?'),
        emcy: el('td', { 'data-testid': `emcy-${s.name}`, class: 'emcy' }, ''),
      };
      const row = el('tr', { 'data-testid': `node-row-${s.name}`, tabindex: 0, 'aria-selected': 'false' },
        el('td', {}, el('strong', {}, s.name)),
        el('td', {}, String(s.node_id)),
        el('td', {}, `${s.product}${s.variant ? ' ' + s.variant : ''}`),
        el('td', {}, s.bus),
        cells.nmt, cells.device, cells.errreg, cells.emcy);
      row.addEventListener('click', () => onSelect(s.name));
      row.addEventListener('keydown', (ev) => { if (ev.key === 'Enter' || ev.key === ' ') onSelect(s.name); });
      body.append(row);
      this.rows.set(s.name, { row, ...cells });
    }
    host.replaceChildren(el('table', { class: 'nodes', 'data-testid': 'node-table', 'aria-label': 'Nodes' },
      el('thead', {}, el('tr', {}, ...['Node', 'ID', 'Product', 'Bus', 'NMT', 'Device state', 'Err. reg.', 'Last EMCY'].map((h) => el('th', { scope: 'col' }, h)))),
      body));
  }

  update(live: ReadonlyMap<string, NodeInfo>, selected: string | null): void {
    for (const [name, c] of this.rows) {
      const n = live.get(name);
      const set = (e: HTMLElement, text: string) => { if (e.textContent !== text) e.textContent = text; };
      set(c.nmt, n?.nmt ?? '?');
      c.nmt.className = `nmt nmt-${(n?.nmt ?? 'unknown').toLowerCase()}`;
      set(c.device, n ? deviceSummary(n) : '?');
      set(c.errreg, n ? `0x${hex(n.error_register, 2)}` : '?');
      const lastEmcy = n?.emcy.length ? n.emcy[n.emcy.length - 1] : null;
      set(c.emcy, lastEmcy ? `${hex(lastEmcy.code, 4)}h ${lastEmcy.text}` : '');
      c.row.classList.toggle('selected', name === selected);
      c.row.setAttribute('aria-selected', name === selected ? 'true' : 'false');
    }
  }
}
