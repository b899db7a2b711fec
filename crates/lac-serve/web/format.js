// How the panel writes numbers: eight significant digits, or a dash for what is not a number.

export const fmt = (x) => (typeof x === 'number' && Number.isFinite(x) ? String(+x.toPrecision(8)) : '—');

/** An angle in radians, written in degrees. */
export const deg = (rad) => `${fmt((rad * 180) / Math.PI)}°`;
