// What a trainee typed into the object-dictionary browser, turned into an SDO write body, or a
// reason why not (checked before anything goes on the bus; the server checks again).

export type SdoWriteBody = { index: number; sub: number; value: number } | { index: number; sub: number; data: string };

const INT_RANGES: Record<string, [number, number]> = {
  BOOLEAN: [0, 1],
  INTEGER8: [-0x80, 0x7f],
  INTEGER16: [-0x8000, 0x7fff],
  INTEGER32: [-0x80000000, 0x7fffffff],
  UNSIGNED8: [0, 0xff],
  UNSIGNED16: [0, 0xffff],
  UNSIGNED32: [0, 0xffffffff],
};

/** Parses decimal or 0x-hex integers, negative decimals included. */
export function parseInteger(text: string): number | null {
  const t = text.trim();
  if (/^0x[0-9a-f]+$/i.test(t)) return parseInt(t.slice(2), 16);
  if (/^-?\d+$/.test(t)) return parseInt(t, 10);
  return null;
}

export function sdoWriteBody(index: number, sub: number, type: string, text: string): SdoWriteBody | { error: string } {
  const range = INT_RANGES[type];
  if (range) {
    const v = parseInteger(text);
    if (v === null) return { error: `"${text}" is not an integer (decimal or 0x hex)` };
    if (v < range[0] || v > range[1]) return { error: `${v} is out of range for ${type} (${range[0]}..${range[1]})` };
    return { index, sub, value: v };
  }
  if (type === 'REAL32' || type === 'REAL64') {
    const v = Number(text.trim());
    if (text.trim() === '' || !Number.isFinite(v)) return { error: `"${text}" is not a number` };
    return { index, sub, value: v };
  }
  if (type === 'VISIBLE_STRING') {
    const data = Array.from(new TextEncoder().encode(text), (b) => b.toString(16).padStart(2, '0')).join('').toUpperCase();
    return { index, sub, data };
  }
  // Other types (INTEGER24/40/64, UNSIGNED24..64, OCTET_STRING, DOMAIN): raw little-endian bytes.
  const hex = text.trim().replace(/\s+/g, '');
  if (!/^([0-9a-f]{2})+$/i.test(hex)) return { error: `${type}: give the bytes as hex, e.g. 0F00` };
  return { index, sub, data: hex.toUpperCase() };
}

export function formatIndex(index: number, sub: number): string {
  return `${index.toString(16).toUpperCase().padStart(4, '0')}:${sub.toString(16).toUpperCase().padStart(2, '0')}`;
}

/** A value as the browser shows it: integers also in hex. */
export function formatValue(value: number | string | null, type: string): string {
  if (value === null || value === undefined) return '';
  if (typeof value === 'number' && Number.isInteger(value) && (type.startsWith('UNSIGNED') || type === 'BOOLEAN')) {
    return `${value} (0x${value.toString(16).toUpperCase()})`;
  }
  return String(value);
}
