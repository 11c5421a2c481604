// The dashboard: loads the scenario into the store, opens the one live stream, and wires each view
// to the store topics it draws and to the API calls it makes.
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { api, ApiError, openStream } from './api';
import { el } from './dom';
import { formatIndex, sdoWriteBody } from './od_input';
import { defaultSignals } from './signal_choice';
import { Store } from './store';
import type { OdEntry, OdEvent, SdoResult } from './types';
import { ClockControls, renderNmtControls } from './views/controls';
import { FaultsPanel } from './views/faults_panel';
import { FindingsView } from './views/findings_view';
import { renderControlWord, PdoPanel, SyncControls } from './views/node_controls';
import { NodeDetail } from './views/node_detail';
import { NodeTable } from './views/node_table';
import { OdBrowser } from './views/od_browser';
import { Plots } from './views/plots';
import { TraceView } from './views/trace_view';
import { mountExerciseView } from './views/exercise_view';
import { TransitionList } from './views/transition_list';

const $ = (id: string) => document.getElementById(id) as HTMLElement;

function message(text: string, ok = false): void {
  const box = $('messages');
  box.className = ok ? 'messages ok' : 'messages error';
  box.textContent = text;
}

function errorText(e: unknown): string {
  return e instanceof ApiError ? e.message : String(e);
}

/** An SDO that went wrong, in words: the node's abort, or no answer at all (a timeout is no refusal). */
export function sdoFailure(what: string, r: SdoResult): string {
  if (r.abort_code?.toLowerCase() === '0x05040000') return `${what}: timeout, the node did not answer (SDO protocol timed out, abort 0x05040000)`;
  return `${what} refused by the node: abort ${r.abort_code} ${r.abort_text}`;
}

async function main(): Promise<void> {
  const store = new Store(await api.scenario(), await api.clock());
  const sc = store.scenario;
  document.title = `vplant: ${sc.name}`;
  $('scenario-name').textContent = sc.name;
  $('scenario-description').textContent = sc.description;
  const nodeOf = (name: string | null) => sc.nodes.find((n) => n.name === name);

  // --- the object dictionary -------------------------------------------------------------------
  let odNode: string | null = null;
  const odPending: OdEvent[] = [];  // the stream's `od` events for a node whose rows are loading
  const od = new OdBrowser($('od'), {
    write: async (e: OdEntry, text: string) => {
      if (!store.selected) return;
      const body = sdoWriteBody(e.index, e.sub, e.type, text);
      if ('error' in body) return od.report(false, body.error);
      await sdoWrite(store.selected, body, `${formatIndex(e.index, e.sub)} ${e.name}`);
    },
    read: async (e: OdEntry) => {
      if (!store.selected) return;
      const what = `SDO upload ${formatIndex(e.index, e.sub)} ${e.name}`;
      try {
        const r = await api.sdoRead(store.selected, e.index, e.sub);
        if (r.ok) od.report(true, `${what}: ${r.value ?? ''} (data ${r.data})`);
        else od.report(false, sdoFailure(what, r));
      } catch (err) {
        od.report(false, err instanceof ApiError && err.status === 504 ? `${what}: timeout, the node did not answer` : errorText(err));
      }
    },
  });

  async function sdoWrite(node: string, body: object, what: string): Promise<void> {
    const text = `SDO download ${what} on ${node}`;
    try {
      const r = await api.sdoWrite(node, body);
      if (r.ok) od.report(true, `${text}: done`);
      else od.report(false, sdoFailure(text, r));
      if (streamShared) void refreshOd();  // a shared stream carries no dictionary
    } catch (err) {
      od.report(false, err instanceof ApiError && err.status === 504 ? `${text}: timeout, the node did not answer` : errorText(err));
    }
  }

  async function refreshOd(): Promise<void> {
    const node = store.selected;
    if (!node) return;
    try {
      const entries = await api.od(node);
      if (node !== store.selected) return;
      if (odNode !== node) od.show(entries);
      else od.update(entries);
      odNode = node;
      // what the stream sent while the rows were loading, in its order (the newest value wins)
      for (const o of odPending.splice(0)) if (o.node === node) od.updateValues(o.values, o.display ?? {});
    } catch (err) {
      message(errorText(err));
    }
  }

  // --- the selected node: machines, transitions, controls, PDOs ---------------------------------
  const unavailable = new Map<string, string>();  // what the server could not give, in words
  const detail = new NodeDetail($('node-detail'), () => drawDetail());
  const transitions = new TransitionList($('transitions'));
  function drawDetail(): void {
    const node = store.selected;
    const history = node ? store.history(node).all() : [];
    detail.render(node ? store.live.get(node) : undefined, node ? store.machines.get(node) : undefined, history, unavailable.get('machines') ?? null);
    transitions.show(history, unavailable.get('transitions') ?? null);
  }
  store.on('transitions', drawDetail);
  store.on('machines', drawDetail);

  async function loadMachines(node: string): Promise<void> {
    try {
      store.setMachines(await api.machines(node));
      unavailable.delete('machines');
    } catch (err) {
      unavailable.set('machines', `The server does not describe its state machines (${errorText(err)}).`);
      drawDetail();
    }
  }

  let machinesTimer: ReturnType<typeof setTimeout> | undefined;
  function machinesSoon(node: string): void {
    clearTimeout(machinesTimer);
    machinesTimer = setTimeout(() => { if (node === store.selected) void loadMachines(node); }, 150);
  }

  async function loadTransitions(node: string, after?: number): Promise<void> {
    try {
      store.addTransitions(node, await api.transitions(node, after));
      unavailable.delete('transitions');
    } catch (err) {
      unavailable.set('transitions', `The server keeps no transition history (${errorText(err)}).`);
      drawDetail();
    }
  }

  const pdoPanel = new PdoPanel($('pdos'), {
    sendRpdo: (node, pdo, values) => void sendRpdo(node, pdo, values),
    reportError: (m) => message(m),
  });
  async function loadPdos(node: string): Promise<void> {
    try {
      const pdos = await api.pdos(node);
      if (node === store.selected) pdoPanel.show(node, pdos);
    } catch (err) {
      pdoPanel.unavailable(`The server does not decode the PDO mapping (${errorText(err)}).`);
    }
  }
  async function sendRpdo(node: string, pdo: number, values: Record<string, number>): Promise<void> {
    try {
      await api.rpdo(node, pdo, values);
      message(`RPDO${pdo} sent to ${node}: ${Object.entries(values).map(([k, v]) => `${k} = ${v}`).join(', ')}`, true);
    } catch (err) {
      message(errorText(err));
    }
  }

  const controlActions = {
    writeControlWord: (node: string, cw: number) =>
      void sdoWrite(node, { index: 0x6040, sub: 0, value: cw }, `6040:00 control word = 0x${cw.toString(16).toUpperCase().padStart(4, '0')}`),
    sendRpdo: (node: string, pdo: number, values: Record<string, number>) => void sendRpdo(node, pdo, values),
    reportError: (m: string) => message(m),
  };

  const nodeChoice = el('select', { 'aria-label': 'Selected node', 'data-testid': 'node-choice' },
    ...sc.nodes.map((n) => el('option', { value: n.name }, `${n.name} (${n.node_id})`)));
  nodeChoice.addEventListener('change', () => store.select(nodeChoice.value));
  $('node-choice').replaceChildren(el('label', { class: 'node-choice' }, 'Node ', nodeChoice));

  const nodeTable = new NodeTable($('node-table'), sc.nodes, store.signals, (name) => store.select(name));
  store.on('nodes', () => {
    nodeTable.update(store.live, store.selected);
    drawDetail();
  });
  // The CiA 406 words' bit names come from the devices' descriptions, read once per node.
  for (const n of sc.nodes.filter((n) => n.profile === 'cia406')) {
    api.machines(n.name).then((m) => {
      nodeTable.setMachines(n.name, m.machines);
      nodeTable.update(store.live, store.selected);
    }).catch(() => undefined);  // without them the words stay in hex
  }

  function onSelected(): void {
    const node = store.selected;
    if (!node) return;
    nodeChoice.value = node;
    for (const s of document.querySelectorAll('.selected-node')) s.textContent = node;
    renderControlWord($('cw-controls'), node, nodeOf(node)?.profile === 'dsp408', controlActions);
    nodeTable.update(store.live, node);
    if (lesson) trace.onlyNode(nodeOf(node)?.node_id ?? null);
    drawDetail();
    void loadMachines(node);
    void loadTransitions(node);
    void loadPdos(node);
    void refreshOd();  // names, types and access; the stream's `od` events carry the values from here on
    if (streamId !== null && !streamShared) api.streamNode(streamId, node).catch((err) => message(errorText(err)));
  }
  store.on('selected', onSelected);

  renderNmtControls($('nmt-controls'), sc.nodes, async (command, node) => {
    try {
      await api.nmt(command, node);
      message(`NMT ${command} sent to ${node === 0 ? 'all nodes' : node}`, true);
    } catch (err) {
      message(errorText(err));
    }
  }, () => (lesson ? store.selected : null));

  // --- SYNC, clock, restart ----------------------------------------------------------------------
  const sync = new SyncControls($('sync-controls'), async (periodMs) => {
    try {
      await api.setSync(periodMs);
      sync.show(periodMs);
      message(periodMs > 0 ? `SYNC every ${periodMs} ms` : 'SYNC off', true);
    } catch (err) {
      message(errorText(err));
    }
  });
  api.sync().then((s) => sync.show(s.period_ms), () => sync.show(null));

  const clockAction = async (call: () => Promise<unknown>) => {
    try {
      await call();
      const c = await api.clock();
      store.setClock(c);
    } catch (err) {
      message(errorText(err));
    }
  };
  const clockControls = new ClockControls($('clock'), store.clock, {
    act: (action, ms) => void clockAction(() => api.clockAction(action, ms)),
    resume: (speed) => void clockAction(() => api.resume(speed)),
    restart: () => void restart(),
  });
  store.on('clock', () => {
    const c = store.clock;
    clockControls.show(c.t_us, c.paused, c.end_reached ?? false);
  });

  function afterRestart(): void {
    store.forgetHistory();
    trace.buffer.clear();
    findings.clear();
    if (store.selected) {
      void loadMachines(store.selected);
      void loadTransitions(store.selected);
      void refreshOd();
    }
  }
  // The stream's `restart` event (for a restart from here or by another viewer) clears the history,
  // once: it comes before the new run's frames, which the POST's answer may come after.
  async function restart(): Promise<void> {
    try {
      await api.restart();
      message('restarted: the scenario runs again from t = 0', true);
    } catch (err) {
      message(errorText(err));
    }
  }

  // --- faults, findings ----------------------------------------------------------------------------
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
    setInput: async (node, name, value, shown) => {
      try {
        await api.setInput(node, name, value);
        message(`${node}.${name} = ${shown}`, true);
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
  // The findings so far, page by page (on connect, after a gap); new ones come on the stream.
  let readingFindings = false;
  async function readFindings(): Promise<void> {
    if (readingFindings) return;
    readingFindings = true;
    try {
      for (let i = 0; i < 100; ++i) {  // bounded: the monitor stores a bounded number of findings
        const page = await api.findings(findings.since);
        findings.show(page);
        if (page.next >= page.total || page.findings.length === 0) break;
      }
    } catch {
      // a run without a master monitor, or the run has ended: nothing to add
    } finally {
      readingFindings = false;
    }
  }

  // --- the stream ----------------------------------------------------------------------------------
  const trace = new TraceView($('trace'), sc.nodes);
  let stream: EventSource | null = null;
  let streamId: number | null = null;
  let streamShared = false;  // a viewer beyond the server's limit: no dictionary in its stream
  const plotDefault = defaultSignals([...store.signals.keys()], sc.nodes.map((n) => n.name));
  const plots = new Plots($('plots'), store.signals, plotDefault, (chosen) => {
    plots.choose(chosen);
    connect(chosen);
  });
  const readings = new Map<string, number>();
  setInterval(() => nodeTable.showReadings((name) => readings.get(name)), 250);

  function connect(chosen: readonly string[]): void {
    stream?.close();
    streamId = null;
    stream = openStream([...new Set([...chosen, ...nodeTable.signalNames()])], 20, store.selected, {
      frames: (batch) => trace.push(batch),
      nodes: (nodes) => store.setNodes(nodes),
      signals: (b) => {
        plots.append(b);
        for (const [name, values] of Object.entries(b.values)) if (values.length) readings.set(name, values[values.length - 1]);
      },
      clock: (c) => store.setClock(c),
      dropped: (d) => trace.noteStreamDropped(d.frames),
      transition: (t) => {
        const h = store.history(t.node);
        // the stream skips what did not fit: fill the gap from the node's history
        if (t.node === store.selected && h.lastSeq >= 0 && t.seq > h.lastSeq + 1) void loadTransitions(t.node, h.lastSeq);
        store.addTransitions(t.node, [t]);
        if (t.node === store.selected) machinesSoon(t.node);  // bit machines' states, power
      },
      restart: () => afterRestart(),
      hello: (h) => {
        streamId = h.stream;
        streamShared = h.shared;
        // selected while connecting: the stream was opened for another node
        if (!h.shared && h.node !== store.selected) api.streamNode(h.stream, store.selected).catch((err) => message(errorText(err)));
      },
      od: (o) => {
        if (o.node !== store.selected) return;
        if (o.node === odNode) od.updateValues(o.values, o.display ?? {});
        else if (odPending.push(o) > 64) odPending.shift();  // bounded: a full event comes with every selection
      },
      faults: (f) => faults.showActive(f),
      exercise: (e) => exercise.show(e),
      findings: (page) => {
        if (!findings.show(page)) void readFindings();
      },
      connection: (open) => {
        const s = $('connection');
        s.textContent = open ? 'live' : 'disconnected';
        s.dataset.open = String(open);
        // after a reconnect, what the stream missed meanwhile
        if (open && store.selected) void loadTransitions(store.selected);
        if (open) void readFindings();
      },
    });
  }

  // --- the lesson view: one node's diagram, controls, transitions and trace on one screen --------
  let lesson = false;
  const toggle = $('view-toggle');
  function setLesson(on: boolean): void {
    lesson = on;
    document.body.classList.toggle('lesson', on);
    toggle.textContent = on ? 'Full console' : 'Lesson view';
    toggle.setAttribute('aria-pressed', String(on));
    trace.onlyNode(on ? nodeOf(store.selected)?.node_id ?? null : null);
    detail.setLesson(on);
    history.replaceState(null, '', on ? '#lesson' : location.pathname + location.search);
  }
  toggle.addEventListener('click', () => setLesson(!lesson));
  document.addEventListener('keydown', (ev) => {
    const t = ev.target as HTMLElement | null;
    if (ev.ctrlKey || ev.metaKey || ev.altKey || (t && /^(INPUT|SELECT|TEXTAREA)$/.test(t.tagName))) return;
    if (ev.key === 'l' || ev.key === 'L') setLesson(!lesson);
  });
  if (location.hash === '#lesson') setLesson(true);

  store.setNodes(await api.nodes());
  onSelected();
  const exercise = mountExerciseView(document.querySelector('main') ?? document.body);
  connect(plotDefault);
  // A shared read-only stream carries no dictionary (its backlog is kept small): it reads it.
  setInterval(() => { if (streamShared && !lesson) void refreshOd(); }, 1000);
}

main().catch((e) => {
  document.body.prepend(el('p', { class: 'messages error', role: 'alert' }, `The dashboard could not start: ${errorText(e)}`));
});
