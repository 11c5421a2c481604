// The selected node: its NMT diagram, for DSP 408 valves the device control diagram with the last
// transition and the control word that caused it, control-word buttons, and the EMCY history.
import { CW_PRESETS, describeControlWord } from '../control_word';
import { button, el, formatTime, hex } from '../dom';
import { channelLine, channelsOf } from '../dsp408_channels';
import { DSP408_DIAGRAM, markedTransition, NMT_DIAGRAM } from '../state_diagrams';
import type { NodeInfo } from '../types';
import { renderDiagram } from './diagram_view';

export interface NodeDetailActions {
  writeControlWord(node: string, cw: number): void;
  reportError(message: string): void;
}

export function renderNodeDetail(
  host: HTMLElement, node: NodeInfo | undefined, nmtLast: { from: string; to: string } | null,
  deviceSeen: { from: string; to: string } | null,
): void {
  if (!node) {
    host.replaceChildren(el('p', {}, 'Select a node in the table.'));
    return;
  }
  const parts: (Node | string)[] = [el('h3', {}, `${node.name} (node ${node.node_id})`)];
  const nmtBox = el('figure', { class: 'diagram-box' },
    renderDiagram(NMT_DIAGRAM, node.nmt, nmtLast),
    el('figcaption', { 'data-testid': 'nmt-last-transition' },
      nmtLast ? `NMT: last transition ${nmtLast.from} → ${nmtLast.to}` : `NMT: ${node.nmt}`));
  parts.push(nmtBox);
  const d = node.device;
  if (d.profile === 'dsp408') {
    const lt = d.last_transition;
    const caption = lt
      ? `Last transition ${lt.from} → ${lt.to} at ${formatTime(lt.t_us)}, control word ${describeControlWord(lt.control_word)}`
      : 'No transition yet';
    parts.push(el('figure', { class: 'diagram-box' },
      renderDiagram(DSP408_DIAGRAM, d.state, markedTransition(d.state, lt, deviceSeen)),
      el('figcaption', {},
        el('div', { 'data-testid': 'device-last-transition' }, caption),
        el('div', { 'data-testid': 'device-words' },
          `State ${d.state}; control word ${describeControlWord(d.control_word)}; status word 0x${hex(d.status_word, 4)}`))));
    const channels = channelsOf(d);
    if (channels.length) {
      parts.push(el('p', {}, 'The diagram shows channel 1. Every channel:'),
        el('ul', { class: 'channels', 'data-testid': 'device-channels' },
          ...channels.map((c) => el('li', { 'data-testid': `device-channel-${c.channel}` }, channelLine(c)))));
    }
  } else if (d.profile === 'vtvpcd') {
    parts.push(el('p', { 'data-testid': 'device-words' }, `VT-VPCD state ${d.state}; active faults: ${d.faults.length ? d.faults.join(', ') : 'none'}`));
  } else if (d.profile === 'cia406') {
    parts.push(el('p', { 'data-testid': 'device-words' },
      `CiA 406 operating status 0x${hex(d.operating_status, 4)}, alarms 0x${hex(d.alarms, 4)}, warnings 0x${hex(d.warnings, 4)}`));
  }
  const emcy = node.emcy.slice().reverse();
  parts.push(el('h4', {}, 'EMCY history (newest first)'),
    emcy.length
      ? el('ol', { class: 'emcy-list', 'data-testid': 'emcy-list' },
          ...emcy.map((e) => el('li', {}, `${formatTime(e.t_us)}  ${hex(e.code, 4)}h  reg 0x${hex(e.register, 2)}  ${e.data}  ${e.text}`)))
      : el('p', { 'data-testid': 'emcy-list' }, 'none'));
  host.replaceChildren(...parts);
}

/** The control-word buttons of a DSP 408 node; rendered once per selection so typing survives updates. */
export function renderControlWordControls(host: HTMLElement, node: string | null, isDsp408: boolean, actions: NodeDetailActions): void {
  if (!node || !isDsp408) {
    host.replaceChildren();
    return;
  }
  const cwInput = el('input', { type: 'text', value: '0x0007', size: 8, 'aria-label': 'Control word 6040h', 'data-testid': 'cw-input' });
  const presets = CW_PRESETS.map((p) =>
    button(p.label, { 'data-testid': `cw-preset-0x${hex(p.value, 4)}`, 'aria-label': `Write control word ${p.label}` },
      () => actions.writeControlWord(node, p.value)));
  host.replaceChildren(el('div', { class: 'cw-controls', role: 'group', 'aria-label': 'Control word (SDO write 6040:00)' },
    el('span', {}, 'Control word 6040h by SDO: '), ...presets, cwInput,
    button('Write', { 'data-testid': 'cw-write' }, () => {
      const v = cwInput.value.trim();
      const n = /^0x[0-9a-f]+$/i.test(v) ? parseInt(v.slice(2), 16) : /^\d+$/.test(v) ? parseInt(v, 10) : NaN;
      if (Number.isInteger(n) && n >= 0 && n <= 0xffff) actions.writeControlWord(node, n);
      else actions.reportError(`control word "${v}": give 0..65535 or 0x0000..0xFFFF`);
    })));
}
