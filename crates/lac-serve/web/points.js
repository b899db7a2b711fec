// Points to fit, read from what a user pastes or imports: text ("x y" one a line, CSV, a JSON
// array) or an SVG path, whose nodes (where its segments end) and points along its length
// become the points, in order.

/** Points taken at equal lengths along an imported SVG path (its nodes come besides). */
export const SVG_SAMPLES = 200;

/** The points of a text: "x y" (or "x,y", "x;y", tabs) one a line, `#` comments, a header
 * line skipped; or a JSON array of [x, y]. {points} or {error}, naming the line. */
export function readPoints(text) {
  const t = text.trim();
  if (t.startsWith('[')) {
    let json;
    try {
      json = JSON.parse(t);
    } catch (e) {
      return { error: `not JSON: ${e.message}` };
    }
    const bad = json.findIndex((p) => !Array.isArray(p) || p.length < 2 || !p.slice(0, 2).every(Number.isFinite));
    if (bad >= 0) return { error: `point ${bad} is not [x, y]` };
    return { points: json.map((p) => [p[0], p[1]]) };
  }
  const points = [];
  const lines = t.split(/\r?\n/);
  for (const [i, raw] of lines.entries()) {
    const line = raw.split('#')[0].trim();
    if (!line) continue;
    const fields = line.split(/[\s,;]+/).filter(Boolean);
    const [x, y] = fields.slice(0, 2).map(Number);
    if (fields.length < 2 || !Number.isFinite(x) || !Number.isFinite(y)) {
      if (!points.length && i === lines.findIndex((l) => l.split('#')[0].trim())) continue; // a header
      return { error: `line ${i + 1} is not "x y": ${raw.trim().slice(0, 40)}` };
    }
    points.push([x, y]);
  }
  return { points };
}

/** The text of points, "x y" one a line (what readPoints reads back to the same doubles). */
export const pointsText = (points) => points.map(([x, y]) => `${x} ${y}`).join('\n');

/** How many numbers each command of a path takes (SVG 1.1, section 8.3). */
const ARITY = { M: 2, L: 2, H: 1, V: 1, C: 6, S: 4, Q: 4, T: 2, A: 7, Z: 0 };

const NUMBER = /[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?/y;

/** The commands of a path's "d" as [letter, numbers], one per segment: a command's repeats
 * become commands of their own, a moveto's further pairs linetos. Null where the text is not
 * a path (browsers draw nothing of it either). */
function commands(d) {
  const out = [];
  let i = 0;
  let letter = null;
  const skip = () => {
    while (i < d.length && /[\s,]/.test(d[i])) i += 1;
  };
  const number = () => {
    skip();
    NUMBER.lastIndex = i;
    const m = NUMBER.exec(d);
    if (!m) return null;
    i += m[0].length;
    return Number(m[0]);
  };
  // An arc's two flags are one character each, and may be written without separators.
  const flag = () => {
    skip();
    if (d[i] !== '0' && d[i] !== '1') return null;
    i += 1;
    return Number(d[i - 1]);
  };
  for (;;) {
    skip();
    if (i >= d.length) return out;
    if (/[A-Za-z]/.test(d[i])) {
      letter = d[i];
      i += 1;
      const upper = letter.toUpperCase();
      if (!(upper in ARITY) || (!out.length && upper !== 'M')) return null;
      if (upper === 'Z') {
        out.push([letter, []]);
        continue;
      }
    } else if (letter === null || letter.toUpperCase() === 'Z') {
      return null;
    }
    const upper = letter.toUpperCase();
    const args = [];
    for (let k = 0; k < ARITY[upper]; k++) {
      const x = upper === 'A' && (k === 3 || k === 4) ? flag() : number();
      if (x === null) return null;
      args.push(x);
    }
    out.push([letter, args]);
    if (upper === 'M') letter = letter === 'M' ? 'L' : 'l';
  }
}

/**
 * The nodes of a path's "d": its first point and the end of each of its segments, in order,
 * each with that segment as an absolute path of its own (`piece`, null for a moveto), which
 * the browser measures; and whether the path ends closed (with Z). Null where "d" is not a
 * path.
 */
export function pathNodes(d) {
  const list = commands(d);
  if (!list || !list.length) return null;
  let current = [0, 0];
  let start = [0, 0];
  // The last control point of a cubic or a quadratic, which S and T reflect.
  let control = null;
  const nodes = [];
  for (const [letter, a] of list) {
    const upper = letter.toUpperCase();
    const relative = letter !== upper;
    const at = (x, y) => (relative ? [current[0] + x, current[1] + y] : [x, y]);
    const mirror = (kind) => (control && control.kind === kind
      ? [2 * current[0] - control.point[0], 2 * current[1] - control.point[1]]
      : current);
    let end;
    let piece;
    let next = null;
    if (upper === 'M') {
      end = at(a[0], a[1]);
      start = end;
    } else if (upper === 'Z') {
      end = start;
      piece = `L${end}`;
    } else if (upper === 'L') {
      end = at(a[0], a[1]);
      piece = `L${end}`;
    } else if (upper === 'H') {
      end = [relative ? current[0] + a[0] : a[0], current[1]];
      piece = `L${end}`;
    } else if (upper === 'V') {
      end = [current[0], relative ? current[1] + a[0] : a[0]];
      piece = `L${end}`;
    } else if (upper === 'C' || upper === 'S') {
      const first = upper === 'C' ? at(a[0], a[1]) : mirror('cubic');
      const rest = upper === 'C' ? a.slice(2) : a;
      const second = at(rest[0], rest[1]);
      end = at(rest[2], rest[3]);
      piece = `C${first} ${second} ${end}`;
      next = { kind: 'cubic', point: second };
    } else if (upper === 'Q' || upper === 'T') {
      const q = upper === 'Q' ? at(a[0], a[1]) : mirror('quadratic');
      end = upper === 'Q' ? at(a[2], a[3]) : at(a[0], a[1]);
      piece = `Q${q} ${end}`;
      next = { kind: 'quadratic', point: q };
    } else {
      end = at(a[5], a[6]);
      piece = `A${a.slice(0, 5).join(' ')} ${end}`;
    }
    nodes.push({ point: end, piece: upper === 'M' ? null : `M${current}${piece}` });
    current = end;
    control = next;
  }
  return { nodes, closed: list[list.length - 1][0].toUpperCase() === 'Z' };
}

/**
 * The points of the first path of an SVG document, y turned up: its nodes (pathNodes) and
 * SVG_SAMPLES points at equal lengths along it (the browser's own getTotalLength and
 * getPointAtLength), in order along the path; a sample within a thousandth of the samples'
 * spacing of a node gives way to it. A path closed with Z does not repeat its first point at
 * its end. {points, closed} or {error}.
 */
export function svgPoints(text) {
  const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
  const source = doc.querySelector('path');
  const d = source && source.getAttribute('d');
  if (!d) return { error: 'the SVG has no path with a "d"' };
  const read = pathNodes(d);
  if (!read) return { error: `the SVG's first path is not a path ("d" = ${d.slice(0, 40)})` };
  const ns = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(ns, 'svg');
  svg.style.position = 'absolute';
  svg.style.visibility = 'hidden';
  const path = document.createElementNS(ns, 'path');
  svg.append(path);
  document.body.append(svg);
  try {
    const lengthOf = (piece) => {
      path.setAttribute('d', piece);
      return path.getTotalLength();
    };
    let s = 0;
    const along = read.nodes.map(({ point, piece }) => {
      if (piece) s += lengthOf(piece);
      return { s, point, node: true };
    });
    const length = lengthOf(d);
    if (!(length > 0)) return { error: 'the SVG\'s first path has no length' };
    for (let k = 0; k < SVG_SAMPLES; k++) {
      const at = (length * k) / (SVG_SAMPLES - 1);
      const p = path.getPointAtLength(at);
      along.push({ s: at, point: [p.x, p.y], node: false });
    }
    along.sort((a, b) => a.s - b.s || b.node - a.node);
    const near = (1e-3 * length) / (SVG_SAMPLES - 1);
    const same = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1]) <= near;
    const kept = [];
    for (const p of along) {
      const last = kept[kept.length - 1];
      if (!last || !same(p.point, last.point)) kept.push(p);
      else if (p.node && !last.node) kept[kept.length - 1] = p;
    }
    if (read.closed && kept.length > 1 && same(kept[0].point, kept[kept.length - 1].point)) kept.pop();
    const points = kept.map(({ point: [x, y] }) => [+x.toPrecision(8), +(-y).toPrecision(8)]);
    return { points, closed: read.closed };
  } finally {
    svg.remove();
  }
}
