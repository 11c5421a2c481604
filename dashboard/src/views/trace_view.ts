// The decoded trace: filters by node and service group, pause, clear, and export of what is
// shown as a candump log. Renders at most a few times a second and only the newest rows.
import { candumpLog } from '../candump_export';
import { button, el, formatTime, hex, spacedHex } from '../dom';
import { TraceBuffer } from '../trace_buffer';
import { applyFilter, SERVICE_GROUPS, ServiceGroup, TraceFilter } from '../trace_filter';
import type { Frame, ScenarioNode } from '../types';

/** The live page renders the newest 400 rows; the report (a fixed, bounded sample) all of them. */
export interface TraceViewOptions {
  rowsRendered?: number;
  live?: boolean;  // Pause and Clear: a stream goes on, a report's frames do not
}

export class TraceView {
  readonly buffer = new TraceBuffer(20000);
  private nodeBoxes = new Map<number, HTMLInputElement>();
  private serviceBoxes = new Map<ServiceGroup, HTMLInputElement>();
  private body = el('tbody');
  private status = el('span', { class: 'trace-status', 'data-testid': 'trace-status', role: 'status' });
  private pauseButton: HTMLButtonElement;
  private dirty = true;
  private streamDropped = 0;
  private only: number | null = null;

  private rowsRendered: number;

  constructor(host: HTMLElement, nodes: readonly Pick<ScenarioNode, 'name' | 'node_id'>[], options: TraceViewOptions = {}) {
    this.rowsRendered = options.rowsRendered ?? 400;
    const live = options.live ?? true;
    const nodeFilters = el('fieldset', { class: 'filters' }, el('legend', {}, 'Nodes'));
    for (const n of nodes) {
      const box = el('input', { type: 'checkbox', checked: true, 'data-testid': `trace-node-${n.node_id}` });
      box.addEventListener('change', () => this.invalidate());
      this.nodeBoxes.set(n.node_id, box);
      nodeFilters.append(el('label', {}, box, ` ${n.name} (${n.node_id})`));
    }
    const serviceFilters = el('fieldset', { class: 'filters' }, el('legend', {}, 'Services'));
    for (const s of SERVICE_GROUPS) {
      const box = el('input', { type: 'checkbox', checked: true, 'data-testid': `trace-service-${s}` });
      box.addEventListener('change', () => this.invalidate());
      this.serviceBoxes.set(s, box);
      serviceFilters.append(el('label', {}, box, ` ${s}`));
    }
    this.pauseButton = button('Pause', { 'data-testid': 'trace-pause', 'aria-pressed': 'false' }, () => this.togglePause());
    const controls = el('div', { class: 'trace-controls' },
      live && this.pauseButton,
      live && button('Clear', { 'data-testid': 'trace-clear' }, () => { this.buffer.clear(); this.invalidate(); }),
      button('Export candump log', { 'data-testid': 'trace-export' }, () => this.export()),
      this.status);
    const table = el('table', { class: 'trace', 'data-testid': 'trace-table', 'aria-label': 'Decoded CAN trace' },
      el('thead', {}, el('tr', {}, ...['Time', 'Bus', 'Dir', 'COB-ID', 'Service', 'Node', 'Data', 'Decoded'].map((h) => el('th', { scope: 'col' }, h)))),
      this.body);
    host.replaceChildren(el('div', { class: 'trace-filters' }, nodeFilters, serviceFilters), controls, el('div', { class: 'trace-scroll' }, table));
    setInterval(() => this.render(), 250);
  }

  push(frames: readonly Frame[]): void {
    this.buffer.push(frames);
    if (!this.buffer.paused) this.dirty = true;
  }

  noteStreamDropped(n: number): void {
    this.streamDropped += n;
    this.dirty = true;
  }

  /** The lesson view: only this node's frames (and broadcasts), whatever the boxes say; null = the boxes. */
  onlyNode(id: number | null): void {
    this.only = id;
    this.invalidate();
  }

  filter(): TraceFilter {
    const nodes = this.only !== null ? new Set([this.only]) : new Set([...this.nodeBoxes].filter(([, b]) => b.checked).map(([id]) => id));
    const services = new Set([...this.serviceBoxes].filter(([, b]) => b.checked).map(([s]) => s));
    return {
      nodes: this.only === null && nodes.size === this.nodeBoxes.size ? null : nodes,
      services: services.size === this.serviceBoxes.size ? null : services,
    };
  }

  shown(): Frame[] {
    return applyFilter(this.buffer.shown(), this.filter());
  }

  private invalidate(): void {
    this.dirty = true;
    this.render();
  }

  private togglePause(): void {
    if (this.buffer.paused) this.buffer.resume();
    else this.buffer.pause();
    this.pauseButton.textContent = this.buffer.paused ? 'Resume' : 'Pause';
    this.pauseButton.setAttribute('aria-pressed', String(this.buffer.paused));
    this.invalidate();
  }

  private export(): void {
    const blob = new Blob([candumpLog(this.shown())], { type: 'text/plain' });
    const a = el('a', { href: URL.createObjectURL(blob), download: 'vplant-trace.log' });
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }

  private render(): void {
    if (!this.dirty) return;
    this.dirty = false;
    const shown = this.shown();
    const rows = shown.slice(-this.rowsRendered).reverse().map((f) =>
      el('tr', { class: `svc-${f.service.toLowerCase()}${f.service === 'EMCY' && f.data.startsWith('0000') ? ' emcy-reset' : ''}`, 'data-service': f.service },
        el('td', { class: 'mono' }, formatTime(f.t_us)), el('td', {}, f.bus), el('td', {}, f.dir),
        el('td', { class: 'mono' }, f.ext ? hex(f.id, 8) : hex(f.id, 3)), el('td', {}, f.service),
        el('td', {}, f.node === null ? '' : String(f.node)), el('td', { class: 'mono' }, f.rtr ? `RTR dlc ${f.dlc}` : spacedHex(f.data)),
        el('td', { class: 'decoded' }, f.text)));
    this.body.replaceChildren(...rows);
    const dropped = this.buffer.dropped + this.streamDropped;
    this.status.textContent = `${shown.length} shown of ${this.buffer.shown().length}${this.buffer.paused ? ' (paused)' : ''}` +
      (dropped ? `; ${dropped} older frames dropped` : '');
  }
}
