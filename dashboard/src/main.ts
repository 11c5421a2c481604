// The dashboard: loads the scenario, opens the live stream, and wires the views to the API.
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { api, ApiError, openStream } from './api';
import { el } from './dom';
import { formatIndex, sdoWriteBody } from './od_input';
import type { NodeInfo, OdEntry, Scenario } from './types';
import { ClockControls, renderNmtControls } from './views/controls';
import { FaultsPanel } from './views/faults_panel';
import { FindingsView } from './views/findings_view';
import { renderControlWordControls, renderNodeDetail } from './views/node_detail';
import { NodeTable } from './views/node_table';
import { OdBrowser } from './views/od_browser';
import { defaultSignals } from './signal_choice';
import { Plots } from './views/plots';
import { TraceView } from './views/trace_view';
import { mountExerciseView } from './views/exercise_view';

const $ = (id: string) => document.getElementById(id) as HTMLElement;

function message(text: string, ok = false): void {
  const box = $('messages');
  box.className = ok ? 'messages ok' : 'messages error';
  box.textContent = text;
}

function errorText(e: unknown): string {
  return e instanceof ApiError ? e.message : String(e);
}

async function main(): Promise<void> {
  const sc: Scenario = await api.scenario();
  const clock = await api.clock();
  document.title = `vplant: ${sc.name}`;
  $('scenario-name').textContent = sc.name;
  $('scenario-description').textContent = sc.description;

  const live = new Map<string, NodeInfo>();
  const nmtLast = new Map<string, { from: string; to: string }>();
  // The device state seen before the latest change: one control word can walk several transitions
  // between two updates (0x0007 from INIT: TR_2, TR_3, TR_4), and the diagram marks them all.
  const deviceLast = new Map<string, { from: string; to: string }>();
  let selected: string | null = sc.nodes.find((n) => n.profile === 'dsp408')?.name ?? sc.nodes[0]?.name ?? null;
  let odNode: string | null = null;

  const od = new OdBrowser($('od'), {
    write: async (e: OdEntry, text: string) => {
      if (!selected) return;
      const body = sdoWriteBody(e.index, e.sub, e.type, text);
      if ('error' in body) return od.report(false, body.error);
      await sdoWrite(selected, body, `${formatIndex(e.index, e.sub)} ${e.name}`);
    },
    read: async (e: OdEntry) => {
      if (!selected) return;
      try {
        const r = await api.sdoRead(selected, e.index, e.sub);
        if (r.ok) od.report(true, `SDO upload ${formatIndex(e.index, e.sub)} ${e.name}: ${r.value ?? ''} (data ${r.data})`);
        else od.report(false, `SDO upload ${formatIndex(e.index, e.sub)} refused: abort ${r.abort_code} ${r.abort_text}`);
      } catch (err) {
        od.report(false, errorText(err));
      }
    },
  });

  async function sdoWrite(node: string, body: object, what: string): Promise<void> {
    try {
      const r = await api.sdoWrite(node, body);
      if (r.ok) od.report(true, `SDO download ${what} on ${node}: done`);
      else od.report(false, `SDO download ${what} on ${node} refused: abort ${r.abort_code} ${r.abort_text}`);
      void refreshOd();
    } catch (err) {
      od.report(false, errorText(err));
    }
  }

  async function refreshOd(): Promise<void> {
    if (!selected) return;
    const node = selected;
    try {
      const entries = await api.od(node);
      if (node !== selected) return;
      if (odNode !== node) {
        od.show(entries);
        odNode = node;
      } else {
        od.update(entries);
      }
    } catch (err) {
      message(errorText(err));
    }
  }

  const detailActions = {
    writeControlWord: (node: string, cw: number) => void sdoWrite(node, { index: 0x6040, sub: 0, value: cw }, `6040:00 control word = 0x${cw.toString(16).toUpperCase().padStart(4, '0')}`),
    reportError: (m: string) => od.report(false, m),
  };

  const nodeTable = new NodeTable($('node-table'), sc.nodes, (name) => select(name));
  function renderNodes(): void {
    nodeTable.update(live, selected);
    renderNodeDetail($('node-detail'), selected ? live.get(selected) : undefined,
      selected ? nmtLast.get(selected) ?? null : null, selected ? deviceLast.get(selected) ?? null : null);
  }

  function select(name: string): void {
    if (name === selected) return;
    selected = name;
    $('od-node').textContent = name;
    renderControlWordControls($('cw-controls'), name, sc.nodes.find((n) => n.name === name)?.profile === 'dsp408', detailActions);
    renderNodes();
    void refreshOd();
  }

  function updateNodes(nodes: NodeInfo[]): void {
    for (const n of nodes) {
      const before = live.get(n.name);
      if (before && before.nmt !== n.nmt) nmtLast.set(n.name, { from: before.nmt, to: n.nmt });
      if (before?.device.profile === 'dsp408' && n.device.profile === 'dsp408' && before.device.state !== n.device.state) {
        deviceLast.set(n.name, { from: before.device.state, to: n.device.state });
      }
      live.set(n.name, n);
    }
    renderNodes();
  }

  renderNmtControls($('nmt-controls'), sc.nodes, async (command, node) => {
    try {
      await api.nmt(command, node);
      message(`NMT ${command} sent to ${node === 0 ? 'all nodes' : node}`, true);
    } catch (err) {
      message(errorText(err));
    }
  });

  const clockControls = new ClockControls($('clock'), clock, async (action, ms) => {
    try {
      await api.clockAction(action, ms);
      const c = await api.clock();
      clockControls.show(c.t_us, c.paused, c.end_reached ?? false);
    } catch (err) {
      message(errorText(err));
    }
  });

  const faults = new FaultsPanel($('faults'), sc, {
    inject: async (f) => {
      try {
        const r = await api.injectFault(f);
        message(r.active === false ? 'done (nothing to clear)' : `fault #${r.id} injected`, true);
      } catch (err) {
        message(errorText(err));
      }
      void refreshFaults();
    },
    clear: async (id) => {
      try {
        await api.clearFault(id);
        message(`fault #${id} cleared`, true);
      } catch (err) {
        message(errorText(err));
      }
      void refreshFaults();
    },
    setInput: async (node, name, value) => {
      try {
        await api.setInput(node, name, value);
        message(`${node}.${name} = ${value}`, true);
      } catch (err) {
        message(errorText(err));
      }
    },
    reportError: (m) => message(m),
  });
  async function refreshFaults(): Promise<void> {
    try {
      faults.showActive(await api.faults());
    } catch (err) {
      message(errorText(err));
    }
  }

  const findings = new FindingsView($('findings'));
  async function refreshFindings(): Promise<void> {
    try {
      findings.show(await api.findings(findings.since));
    } catch {
      // a run without a master monitor, or the run has ended: nothing to add
    }
  }

  const trace = new TraceView($('trace'), sc.nodes);
  let stream: EventSource | null = null;
  const plots = new Plots($('plots'), sc.signals, defaultSignals(sc.signals, sc.nodes.map((n) => n.name)), (chosen) => {
    plots.choose(chosen);
    connect(chosen);
  });

  function connect(signals: readonly string[]): void {
    stream?.close();
    stream = openStream(signals, 20, {
      frames: (batch) => trace.push(batch),
      nodes: updateNodes,
      signals: (b) => plots.append(b),
      clock: (c) => clockControls.show(c.t_us, c.paused, c.end_reached ?? false),
      dropped: (d) => trace.noteStreamDropped(d.frames),
      connection: (open) => {
        const s = $('connection');
        s.textContent = open ? 'live' : 'disconnected';
        s.dataset.open = String(open);
      },
    });
  }

  updateNodes(await api.nodes());
  if (selected) {
    const first = selected;
    selected = null;
    select(first);
  }
  await refreshFaults();
  connect(defaultSignals(sc.signals, sc.nodes.map((n) => n.name)));
  // Live values of the dictionary and the active faults: polled, they change rarely.
  setInterval(() => void refreshOd(), 1000);
  setInterval(() => void refreshFaults(), 2000);
  setInterval(() => void refreshFindings(), 2000);
  mountExerciseView(document.querySelector('main') ?? document.body);
}

main().catch((e) => {
  document.body.prepend(el('p', { class: 'messages error', role: 'alert' }, `The dashboard could not start: ${errorText(e)}`));
});
