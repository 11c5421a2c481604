// Which plant signals the plots show first (and the reading format the report shares, units.ts).
export { formatReading } from './units';

/** The signals shown by default: cylinder position, pressures, swivel angle, shaft speed, taken
 *  from the plant's ports (`component.port`), not from the nodes' ports (`node.port`). */
export function defaultSignals(all: readonly string[], nodeNames: readonly string[]): string[] {
  const plant = all.filter((s) => !nodeNames.includes(s.split('.')[0]));
  const pick = (re: RegExp, max: number) => plant.filter((s) => re.test(s)).slice(0, max);
  const chosen = [
    ...pick(/cyl[a-z_]*\.position$/i, 1),
    ...pick(/swivel_angle$/i, 1),
    ...pick(/supply[a-z_]*\.pressure$|p_supply/i, 1),
    ...pick(/cyl[a-z_]*\.pressure_[ab]$/i, 2),
    ...pick(/shaft[a-z_]*\.speed$/i, 1),
  ];
  return [...new Set(chosen)];
}
