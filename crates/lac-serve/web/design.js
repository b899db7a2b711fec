// Designs: what the designer chose in each mode (control points and parameters), as the API's
// input shapes; their defaults; the URL fragment and the design file that carry one exactly;
// and the undo history.
//
// A design is plain data: {points: [[x, y], ...], alpha: 0.5, ...}. Numbers are written with
// String(x), the shortest decimal that reads back to the same double, and read with Number(),
// so a link or a file reproduces a design bit for bit.

/** The editor's modes: endpoint, number of control points (`count`, or at least `minCount`
 * for a path, whose polygon grows and shrinks), parameters with slider ranges. */
export const MODES = {
  segment: {
    label: 'Segment',
    endpoint: '/api/segment',
    dims: 2,
    count: 3,
    params: [
      { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01,
        hint: 'slope of the logarithmic curvature graph: −1 clothoid, 0 Nielsen spiral, 1 log spiral, 2 circle involute' },
    ],
    defaults: { points: [[-1, 0], [-0.2, 0.8], [1, 0]], alpha: 0.5 },
  },
  compound: {
    label: 'Compound r_θ',
    endpoint: '/api/compound',
    dims: 2,
    count: 3,
    params: [
      { key: 'alpha0', label: 'α0', min: -3, max: 3, step: 0.01, hint: 'slope of the first piece' },
      { key: 'alpha1', label: 'α1', min: -3, max: 3, step: 0.01, hint: 'slope of the second piece' },
      { key: 'ratio', label: 'r_θ', min: 0.01, max: 0.99, step: 0.01,
        hint: 'share of the turning made by the first piece' },
    ],
    defaults: { points: [[0, 0], [2, 0], [2.6, 1.2]], alpha0: -1, alpha1: 2, ratio: 0.5 },
  },
  compound4: {
    label: 'Compound 4 points',
    endpoint: '/api/compound',
    dims: 2,
    count: 4,
    params: [
      { key: 'alpha0', label: 'α0', min: -3, max: 3, step: 0.01, hint: 'slope of the first piece' },
      { key: 'alpha1', label: 'α1', min: -3, max: 3, step: 0.01, hint: 'slope of the second piece' },
    ],
    defaults: { points: [[0, 0], [2, 0], [3, 1], [3.2, 2.4]], alpha0: -1, alpha1: 2 },
  },
  path: {
    label: 'Path',
    endpoint: '/api/path',
    dims: 2,
    count: null,
    minCount: 3,
    params: [
      { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01,
        hint: 'slope of every segment; below 0 the path passes through inflections (where the polygon turns the other way)' },
      { key: 'g2', label: 'G2', boolean: true,
        hint: 'joints solved for continuous curvature (off: at the legs\' midpoints, G1)' },
      { key: 'closed', label: 'closed', boolean: true, hint: 'the last point joins the first' },
    ],
    defaults: {
      points: [[0, 0], [1.5, 0], [3, 0.8], [6, 3.2], [7.5, 4], [9, 4]],
      alpha: -0.5, g2: true, closed: false,
    },
  },
  quasi: {
    label: 'Quasi-aesthetic',
    endpoint: '/api/quasi',
    dims: 2,
    count: 3,
    params: [
      { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01, hint: 'slope of the exact curve' },
      { key: 'tolerance', label: 'tolerance', min: -10, max: -1, step: 0.1, log: true,
        hint: 'largest deviation of the Bézier pieces, relative to the arc length' },
      { key: 'cubic', label: 'cubics', boolean: true, hint: 'plain cubics: all weights 1 (no rational pieces)' },
    ],
    defaults: { points: [[0, 0], [3, 0], [4, 1.5]], alpha: -1, tolerance: 0.0001, cubic: false },
  },
  space: {
    label: 'Space curve',
    endpoint: '/api/space',
    dims: 3,
    count: 4,
    params: [
      { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01, hint: 'slope of the logarithmic curvature graph' },
      { key: 'beta', label: 'β', min: -3, max: 3, step: 0.01, hint: 'slope of the logarithmic torsion graph' },
      { key: 'omega', label: 'Ω', min: 0, max: 2, step: 0.01, hint: 'torsion parameter (0: constant torsion)' },
      { key: 'type', label: 'type', choices: [1, 2], hint: 'torsion type of seed 003' },
    ],
    defaults: {
      points: [[0, 0, 0], [3, 0, 0], [3, 3, 1.5], [0, 3, 3]],
      alpha: 0.5, beta: 0, omega: 0.3, type: 1,
    },
  },
};

/** When the drawable region is shaded: while a point is dragged, always, or never. */
export const REGION_CHOICES = ['drag', 'always', 'off'];

/** The display options of a new page. */
export const DEFAULT_SHOW = { comb: true, evolute: true, polygon: true, region: 'drag' };

/** Whether `n` control points suit mode `m`, and how many it takes, in words. */
export const countFits = (m, n) => (m.count ? n === m.count : n >= m.minCount);
export const countWords = (m) => (m.count ? `${m.count}` : `at least ${m.minCount}`);

/** A deep copy of plain data. */
export const clone = (value) => JSON.parse(JSON.stringify(value));

/** The default design of every mode. */
export function defaultDesigns() {
  return Object.fromEntries(Object.entries(MODES).map(([name, m]) => [name, clone(m.defaults)]));
}

/** The API request for `design` in `mode`, with `samples`. */
export function request(mode, design, samples) {
  const body = clone(design);
  if (mode === 'quasi' && !body.cubic) delete body.cubic;
  body.samples = samples;
  return body;
}

/** The text of a number that reads back to the same double. */
const num = (x) => String(x);

/** The URL fragment of a design and the display options, e.g.
 * `#mode=segment&points=-1,0;-0.2,0.8;1,0&alpha=0.5&show=comb,evolute,polygon&region=drag`. */
export function toFragment(mode, design, show) {
  const parts = [`mode=${mode}`];
  parts.push(`points=${design.points.map((p) => p.map(num).join(',')).join(';')}`);
  for (const param of MODES[mode].params) {
    const value = design[param.key];
    parts.push(`${param.key}=${param.boolean ? (value ? 1 : 0) : num(value)}`);
  }
  const on = Object.entries(show).filter(([, v]) => v === true).map(([k]) => k);
  parts.push(`show=${on.join(',')}`);
  parts.push(`region=${show.region}`);
  return '#' + parts.join('&');
}

/** The mode, design and display options of a fragment, or an error message. */
export function fromFragment(fragment) {
  const text = fragment.replace(/^#/, '');
  if (!text) return null;
  const fields = new Map(text.split('&').map((kv) => {
    const i = kv.indexOf('=');
    return i < 0 ? [kv, ''] : [decodeURIComponent(kv.slice(0, i)), decodeURIComponent(kv.slice(i + 1))];
  }));
  const mode = fields.get('mode');
  if (!MODES[mode]) return { error: `the link names no mode of the editor (${mode})` };
  const m = MODES[mode];
  const design = clone(m.defaults);
  if (fields.has('points')) {
    const points = fields.get('points').split(';').map((p) => p.split(',').map(Number));
    if (!countFits(m, points.length) || points.some((p) => p.length !== m.dims || p.some((x) => !Number.isFinite(x)))) {
      return { error: `the link's points are not ${countWords(m)} points of ${m.dims} numbers` };
    }
    design.points = points;
  }
  for (const param of m.params) {
    if (!fields.has(param.key)) continue;
    const raw = fields.get(param.key);
    if (param.boolean) {
      design[param.key] = raw === '1' || raw === 'true';
      continue;
    }
    const value = Number(raw);
    if (raw === '' || !Number.isFinite(value)) return { error: `the link's ${param.key} is not a number (${raw})` };
    design[param.key] = value;
  }
  let show = null;
  if (fields.has('show')) {
    const on = new Set(fields.get('show').split(',').filter(Boolean));
    const region = REGION_CHOICES.includes(fields.get('region')) ? fields.get('region') : 'drag';
    show = { comb: on.has('comb'), evolute: on.has('evolute'), polygon: on.has('polygon'), region };
  }
  return { mode, design, show };
}

/** The design file of the current curve: the design (the API's input shape, so `lac segment
 * --batch` and the editor both read it) with its mode, and the server's report. */
export function toFile(mode, design, report) {
  return JSON.stringify({ mode, ...design, report }, null, 1) + '\n';
}

/** A mode and design from a design file, an API request, or a `lac segment` / `lac compound`
 * report (or a `lac path` result); or {error}. */
export function fromFile(text) {
  let json;
  try {
    json = JSON.parse(text);
  } catch (e) {
    return { error: `the file is not JSON: ${e.message}` };
  }
  if (!json || typeof json !== 'object' || !Array.isArray(json.points)) {
    return { error: 'the file has no "points": expected a design saved by the editor, or a lac segment / compound result' };
  }
  const dims = json.points[0] && json.points[0].length;
  let mode = MODES[json.mode] ? json.mode : null;
  if (!mode) {
    if (dims === 3) mode = 'space';
    else if ('g2' in json || 'closed' in json || 'segments' in json || json.points.length > 4) mode = 'path';
    else if ('alpha0' in json) mode = json.points.length === 4 ? 'compound4' : 'compound';
    else if ('tolerance' in json) mode = 'quasi';
    else mode = 'segment';
  }
  const m = MODES[mode];
  const design = clone(m.defaults);
  const points = json.points;
  if (!countFits(m, points.length) || points.some((p) => !Array.isArray(p) || p.length !== m.dims || p.some((x) => typeof x !== 'number'))) {
    return { error: `a ${m.label.toLowerCase()} takes ${countWords(m)} points of ${m.dims} numbers` };
  }
  design.points = points;
  for (const param of m.params) {
    if (!(param.key in json)) continue;
    const value = json[param.key];
    if (param.boolean ? typeof value !== 'boolean' : typeof value !== 'number') {
      return { error: `"${param.key}" must be ${param.boolean ? 'true or false' : 'a number'}` };
    }
    design[param.key] = value;
  }
  // A `lac path` result says its slope per segment and its continuity.
  if (mode === 'path' && !('alpha' in json) && Array.isArray(json.segments) && json.segments.length) {
    design.alpha = json.segments[0].alpha;
  }
  if (mode === 'path' && !('g2' in json) && typeof json.continuity === 'string') {
    design.g2 = json.continuity === 'g2';
  }
  return { mode, design };
}

/** Undo and redo over snapshots (plain data compared as JSON). */
export class History {
  constructor(limit = 200) {
    this.limit = limit;
    this.done = [];
    this.undone = [];
  }

  /** Record `snapshot` as the new present (nothing when it equals the present). */
  push(snapshot) {
    const text = JSON.stringify(snapshot);
    if (this.done.length && this.done[this.done.length - 1] === text) return;
    this.done.push(text);
    if (this.done.length > this.limit) this.done.shift();
    this.undone = [];
  }

  /** The snapshot before the present, which becomes the present. */
  undo() {
    if (this.done.length < 2) return null;
    this.undone.push(this.done.pop());
    return JSON.parse(this.done[this.done.length - 1]);
  }

  /** The snapshot undone last, which becomes the present again. */
  redo() {
    if (!this.undone.length) return null;
    const text = this.undone.pop();
    this.done.push(text);
    return JSON.parse(text);
  }

  get canUndo() { return this.done.length > 1; }
  get canRedo() { return this.undone.length > 0; }
}
