// The shapes of the control-plane API (docs/api.md, /API-CONTRACT.md): what the server sends.

export type NmtState = 'INITIALISING' | 'PRE-OPERATIONAL' | 'OPERATIONAL' | 'STOPPED' | 'OFF';

/** One channel of a multi-channel DSP 408 device (the MD2). */
export interface Dsp408Channel { channel: number; state: string; control_word: number; status_word: number }
export interface Dsp408State {
  profile: 'dsp408';
  state: string;
  control_word: number;
  status_word: number;
  /** The MD2: every channel (channel 1 is the fields above). */
  channels?: Dsp408Channel[];
}
export interface VtvpcdState { profile: 'vtvpcd'; state: string; faults: string[] }
export interface Cia406State { profile: 'cia406'; operating_status: number; alarms: number; warnings: number }
export interface GenericState { profile: 'generic' }
export type DeviceState = Dsp408State | VtvpcdState | Cia406State | GenericState;

export interface Emcy { t_us: number; code: number; register: number; data: string; text: string }

export interface NodeInfo {
  name: string;
  node_id: number;
  bus: string;
  nmt: NmtState;
  error_register: number;
  device: DeviceState;
  emcy: Emcy[];
}

export interface ScenarioNode {
  name: string;
  product: string;
  variant: string;
  node_id: number;
  bus: string;
  profile: 'dsp408' | 'vtvpcd' | 'cia406' | 'generic';
}

export interface Scenario {
  name: string;
  description: string;
  clock: { mode: 'virtual' | 'realtime'; tick_us: number };
  buses: { name: string; wire: string; bitrate: number }[];
  nodes: ScenarioNode[];
  signals: SignalInfo[];
  faults: {
    device: { node: string; name: string; description: string }[];
    wire: string[];
    bus_off: string[];
    power: string[];
    plant: string[];
  };
  inputs: ({ node: string } & SignalInfo)[];
}

export interface OdEntry {
  index: number;
  sub: number;
  name: string;
  type: string;
  access: 'rw' | 'ro' | 'wo' | 'const';
  pdo_mappable: boolean;
  value: number | string | null;
  /** Entries with a documented product scaling: the engineering unit and the value in it, as text. */
  unit?: string;
  display?: string;
}

/** A plant signal with its SI unit and how the page shows it: display = si × display_scale + display_offset. */
export interface SignalInfo {
  name: string;
  unit: string;
  display_unit: string;
  display_scale: number;
  display_offset: number;
  /** The smallest range a plot's axis spans, in the display unit (0: any; absent from older servers). */
  display_span?: number;
}

/** One entry of a node's transition history (GET /api/nodes/{n}/transitions, the stream's `transition`). */
export interface Transition {
  seq: number;
  t_us: number;
  machine: string;
  from: string;
  to: string;
  transition: string;
  cause: string;
  value: number;
  detail: string;
  evidence: string;
}

export interface MachineState { name: string; kind: 'normal' | 'fault' | 'off' | 'init'; row: number; col: number }
export interface MachineEdge { transition: string; from: string; to: string; condition: string }
/** A state machine as the C++ profile describes it (GET /api/nodes/{n}/machines). */
export interface Machine {
  machine: string;
  title: string;
  state: string;
  states: MachineState[];
  edges: MachineEdge[];
  note: string;
  /** Bit machines (cia406.*): the named bits; `state` is then the set bits' names joined by " + ", or "none". */
  bits?: { bit: number; name: string }[];
}
export interface NodeMachines { node: string; powered: boolean; machines: Machine[] }

/** A PDO as the node's communication and mapping parameters lay it out (GET /api/nodes/{n}/pdos). */
export interface PdoEntry { object: string; name: string; bits: number; raw: string }
export interface Pdo {
  kind: 'rpdo' | 'tpdo';
  number: number;
  cob_id: number;
  extended?: boolean;
  valid: boolean;
  /** null when the node has no transmission type entry for this PDO. */
  transmission_type: number | null;
  entries: PdoEntry[];
}

export interface SdoResult { ok: boolean; abort_code?: string; abort_text?: string; data?: string; value?: number }

export interface Frame {
  t_us: number;
  bus: string;
  id: number;
  ext: boolean;
  rtr: boolean;
  dlc: number;
  data: string;
  dir: string;
  service: string;
  node: number | null;
  text: string;
  candump: string;
}

export interface ClockState {
  mode: 'virtual' | 'realtime'; t_us: number; paused: boolean; tick_us: number;
  speed?: number; end_reached?: boolean;
}

export interface ActiveFault { id: number; summary: string; since_t_us: number }

/** The stream's first event (docs/api.md, "Live stream"). */
export interface StreamHello { stream: number; shared: boolean; node: string | null }

/** The stream's `od` event: the chosen node's dictionary values (whole when `full`), keyed "6041:00". */
export interface OdEvent {
  node: string;
  t_us: number;
  full: boolean;
  values: Record<string, number | string | null>;
  /** The entries with a product scaling among `values`, in engineering units ("12.3 mm"). */
  display?: Record<string, string>;
}

export interface SignalBatch { t_us: number[]; values: Record<string, number[]> }

/** GET /api/findings: the verdict on the master (docs/masters.md, "Verdict"). */
export interface MasterFinding {
  rule: string;
  severity: 'warning' | 'error';
  t_us: number;
  bus: string;
  node: number;
  text: string;
  frames: { t_us: number; from: 'master' | 'node'; frame: string }[];
}
export interface FindingsPage {
  findings: MasterFinding[];
  next: number;
  total: number;
  dropped: number;
  rules: Record<string, { severity: string; count: number }>;
}
