// The bodies of POST /api/faults: a fault as a scenario writes it, as JSON (docs/scenarios.md,
// "faults[]"; docs/api.md, "Faults"), e.g. {"drop": {"bus": "main", "id": "0x181"}}.

export type FaultBody = Record<string, unknown>;

export function deviceFault(node: string, fault: string): FaultBody {
  return { device_fault: { node, fault } };
}

/** `action`: power_off, power_on, power_cycle or reset (the scenario catalogue's `power`). */
export function powerFault(action: string, node: string): FaultBody {
  return { [action]: node };
}

export function busOffFault(node: string): FaultBody {
  return { bus_off: node };
}

/** `action`: drop, delay or corrupt; delay by 10 ms, corrupt inverts byte 0 (the panel's amounts). */
export function wireFault(action: string, bus: string, id: string): FaultBody {
  const amount = action === 'delay' ? { by: '10ms' } : action === 'corrupt' ? { byte: 0, xor: 255 } : {};
  return { [action]: { bus, id, ...amount } };
}

export function plantFault(parameter: string, value: number): FaultBody {
  return { plant: { parameter, value } };
}
