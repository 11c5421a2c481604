// The node table: one row per node with its live NMT state (OFF when unpowered), device state as
// the device reports it, its process values in display units, error register and last EMCY;
// clicking a row selects the node for the diagrams, the controls and the dictionary.
import { el, hex } from '../dom';
import type { Machine, NodeInfo, ScenarioNode, SignalInfo } from '../types';
import { formatSignal } from '../units';

/** A node's process values worth a column: its measuring or commanding ports, at most two. */
const PRIMARY_PORTS = ['position', 'angle', 'speed', 'swivel_angle', 'pressure_a', 'solenoid_a_current', 'ch1.solenoid_a_current'];

export function processSignals(node: string, signals: ReadonlyMap<string, SignalInfo>): SignalInfo[] {
  return PRIMARY_PORTS.map((p) => signals.get(`${node}.${p}`)).filter((s): s is SignalInfo => s !== undefined).slice(0, 2);
}

type Bits = readonly { bit: number; name: string }[];
/** A CiA 406 node's named bits, per word, as its C++ profile serves them (GET .../machines). */
export interface BitNames { status?: Bits; alarms?: Bits; warnings?: Bits }

/** The bit names of the machines cia406.status / .alarms / .warnings. */
export function bitNamesOf(machines: readonly Machine[]): BitNames {
  const of = (id: string) => machines.find((m) => m.machine === id)?.bits;
  return { status: of('cia406.status'), alarms: of('cia406.alarms'), warnings: of('cia406.warnings') };
}

/** The set bits of `word` by name ("none" when none); a set bit the product does not name in hex. */
export function setBits(word: number, bits: Bits | undefined): string {
  if (!bits) return `${hex(word, 4)}h`;
  const names = bits.filter((b) => (word >> b.bit) & 1).map((b) => b.name);
  const unnamed = word & ~bits.reduce((m, b) => m | (1 << b.bit), 0) & 0xffff;
  if (unnamed) names.push(`${hex(unnamed, 4)}h`);
  return names.length ? names.join(' + ') : 'none';
}

export function deviceSummary(n: NodeInfo, bits: BitNames = {}): string {
  if (n.nmt === 'OFF') return 'OFF';
  const d = n.device;
  switch (d.profile) {
    case 'dsp408':
      return d.channels && d.channels.length > 1 ? d.channels.map((c) => `ch${c.channel} ${c.state}`).join(', ') : d.state;
    case 'vtvpcd': return d.faults.length ? `${d.state}; faults: ${d.faults.join(', ')}` : d.state;
    case 'cia406':
      return `status: ${setBits(d.operating_status, bits.status)}\nalarms: ${setBits(d.alarms, bits.alarms)}\nwarnings: ${setBits(d.warnings, bits.warnings)}`;
    default: return '—';
  }
}

interface RowCells { row: HTMLTableRowElement; nmt: HTMLElement; device: HTMLElement; values: HTMLElement; errreg: HTMLElement; emcy: HTMLElement }

/** Rows are built once and updated in place, so a click never lands on a row being replaced. */
export class NodeTable {
  private rows = new Map<string, RowCells>();
  private readings = new Map<string, SignalInfo[]>();
  private bits = new Map<string, BitNames>();

  constructor(host: HTMLElement, scenarioNodes: readonly ScenarioNode[], signals: ReadonlyMap<string, SignalInfo>, onSelect: (name: string) => void) {
    const body = el('tbody');
    for (const s of scenarioNodes) {
      const cells = {
        nmt: el('td', { 'data-testid': `nmt-${s.name}`, class: 'nmt' }, '?'),
        device: el('td', { 'data-testid': `device-${s.name}`, class: 'device' }, '?'),
        values: el('td', { 'data-testid': `values-${s.name}`, class: 'values' }, ''),
        errreg: el('td', { 'data-testid': `errreg-${s.name}` }, '?'),
        emcy: el('td', { 'data-testid': `emcy-${s.name}`, class: 'emcy' }, ''),
      };
      this.readings.set(s.name, processSignals(s.name, signals));
      const row = el('tr', { 'data-testid': `node-row-${s.name}`, tabindex: 0, 'aria-selected': 'false' },
        el('td', { class: 'name' }, el('strong', {}, s.name), ` ${s.node_id}`,
          el('div', { class: 'product' }, `${s.product}${s.variant ? ' ' + s.variant : ''}`)),
        cells.nmt, cells.device, cells.values, cells.errreg, cells.emcy);
      row.addEventListener('click', () => onSelect(s.name));
      row.addEventListener('keydown', (ev) => { if (ev.key === 'Enter' || ev.key === ' ') onSelect(s.name); });
      body.append(row);
      this.rows.set(s.name, { row, ...cells });
    }
    host.replaceChildren(el('div', { class: 'table-scroll' }, el('table', { class: 'nodes', 'data-testid': 'node-table', 'aria-label': 'Nodes' },
      el('thead', {}, el('tr', {}, ...['Node, product', 'NMT', 'Device state', 'Process values', 'Err. reg.', 'Last EMCY'].map((h) => el('th', { scope: 'col' }, h)))),
      body)));
  }

  /** A node's machines (for the CiA 406 words' bit names). */
  setMachines(node: string, machines: readonly Machine[]): void {
    this.bits.set(node, bitNamesOf(machines));
  }

  /** The node signals whose newest values the table shows (added to the stream's signals). */
  signalNames(): string[] {
    return [...this.readings.values()].flat().map((s) => s.name);
  }

  showReadings(latest: (name: string) => number | undefined): void {
    for (const [name, c] of this.rows) {
      const text = (this.readings.get(name) ?? []).map((s) => {
        const v = latest(s.name);
        return v === undefined || Number.isNaN(v) ? '' : `${s.name.slice(name.length + 1)} ${formatSignal(v, s)}`;
      }).filter(Boolean).join('\n');
      if (c.values.textContent !== text) c.values.textContent = text;
    }
  }

  update(live: ReadonlyMap<string, NodeInfo>, selected: string | null): void {
    for (const [name, c] of this.rows) {
      const n = live.get(name);
      const set = (e: HTMLElement, text: string) => { if (e.textContent !== text) e.textContent = text; };
      set(c.nmt, n?.nmt ?? '?');
      c.nmt.className = `nmt nmt-${(n?.nmt ?? 'unknown').toLowerCase()}`;
      set(c.device, n ? deviceSummary(n, this.bits.get(name)) : '?');
      set(c.errreg, n ? `0x${hex(n.error_register, 2)}` : "?");
      const lastEmcy = n?.emcy.length ? n.emcy[n.emcy.length - 1] : null;
      set(c.emcy, lastEmcy ? `${hex(lastEmcy.code, 4)}h ${lastEmcy.text}` : '');
      c.emcy.classList.toggle('emcy-reset', lastEmcy?.code === 0);
      c.row.classList.toggle('selected', name === selected);
      c.row.setAttribute('aria-selected', name === selected ? 'true' : 'false');
    }
  }
}
