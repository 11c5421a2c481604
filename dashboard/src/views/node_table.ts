// The node table: one row per node with its live NMT state, device state and error register;
// clicking a row selects the node for the diagrams and the object-dictionary browser.
import { el, hex } from '../dom';
import type { NodeInfo, ScenarioNode } from '../types';

export function deviceSummary(n: NodeInfo): string {
  const d = n.device;
  switch (d.profile) {
    case 'dsp408': return `${d.state} (sw 0x${hex(d.status_word, 4)})`;
    case 'vtvpcd': return d.faults.length ? `${d.state}; faults: ${d.faults.join(', ')}` : d.state;
    case 'cia406': return `status 0x${hex(d.operating_status, 4)}, alarms 0x${hex(d.alarms, 4)}, warnings 0x${hex(d.warnings, 4)}`;
    default: return '—';
  }
}

export function renderNodeTable(
  host: HTMLElement, scenarioNodes: readonly ScenarioNode[], live: ReadonlyMap<string, NodeInfo>,
  selected: string | null, onSelect: (name: string) => void,
): void {
  const body = el('tbody');
  for (const s of scenarioNodes) {
    const n = live.get(s.name);
    const lastEmcy = n?.emcy.length ? n.emcy[n.emcy.length - 1] : null;
    const row = el('tr', {
      'data-testid': `node-row-${s.name}`,
      class: s.name === selected ? 'selected' : undefined,
      tabindex: 0,
      'aria-selected': s.name === selected ? 'true' : 'false',
    },
      el('td', {}, el('strong', {}, s.name)),
      el('td', {}, String(s.node_id)),
      el('td', {}, `${s.product}${s.variant ? ' ' + s.variant : ''}`),
      el('td', {}, s.bus),
      el('td', { 'data-testid': `nmt-${s.name}`, class: `nmt nmt-${(n?.nmt ?? 'unknown').toLowerCase()}` }, n?.nmt ?? '?'),
      el('td', { 'data-testid': `device-${s.name}` }, n ? deviceSummary(n) : '?'),
      el('td', { 'data-testid': `errreg-${s.name}` }, n ? `0x${hex(n.error_register, 2)}` : '?'),
      el('td', { 'data-testid': `emcy-${s.name}`, class: 'emcy' }, lastEmcy ? `${hex(lastEmcy.code, 4)}h ${lastEmcy.text}` : ''),
    );
    row.addEventListener('click', () => onSelect(s.name));
    row.addEventListener('keydown', (ev) => { if (ev.key === 'Enter' || ev.key === ' ') onSelect(s.name); });
    body.append(row);
  }
  const table = el('table', { class: 'nodes', 'data-testid': 'node-table', 'aria-label': 'Nodes' },
    el('thead', {}, el('tr', {}, ...['Node', 'ID', 'Product', 'Bus', 'NMT', 'Device state', 'Err. reg.', 'Last EMCY'].map((h) => el('th', { scope: 'col' }, h)))),
    body);
  host.replaceChildren(table);
}
