// Export frames as a candump log (`candump -L` format: "(sec.usec) iface ID#DATA"),
// the format can-utils' canplayer and log2asc read.
import type { Frame } from './types';

function hex(n: number, width: number): string {
  return n.toString(16).toUpperCase().padStart(width, '0');
}

/** One candump -L line built from the frame's fields. */
export function candumpLine(f: Frame): string {
  const sec = Math.floor(f.t_us / 1_000_000);
  const usec = f.t_us % 1_000_000;
  const id = f.ext ? hex(f.id, 8) : hex(f.id, 3);
  const payload = f.rtr ? 'R' : f.data.toUpperCase();
  return `(${sec}.${usec.toString().padStart(6, '0')}) ${f.bus} ${id}#${payload}`;
}

/** The log for the frames shown, oldest first, one line each, newline-terminated. */
export function candumpLog(frames: readonly Frame[]): string {
  if (frames.length === 0) return '';
  return frames.map((f) => (f.candump ? f.candump : candumpLine(f))).join('\n') + '\n';
}
