// Designs: what the designer chose in each mode (control points and parameters), as the API's
// input shapes; their defaults (from the modes, modes/); the URL fragment and the design file
// that carry one exactly; and the undo history.
//
// A design is plain data: {points: [[x, y], ...], alpha: 0.5, ...}. Numbers are written with
// String(x), the shortest decimal that reads back to the same double, and read with Number(),
// so a link or a file reproduces a design bit for bit.

import { MODES, recognise } from './modes/index.js';

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
  body.samples = samples;
  return MODES[mode].request(body);
}

/** The text of a number that reads back to the same double. */
const num = (x) => String(x);

/** The URL fragment of a design and the display options, e.g.
 * `#mode=segment&points=-1,0;-0.2,0.8;1,0&alpha=0.5&show=comb,evolute,polygon&region=drag`;
 * after the parameters, what the mode says of its own (`link`: a spline's point types). */
export function toFragment(mode, design, show) {
  const parts = [`mode=${mode}`];
  parts.push(`points=${design.points.map((p) => p.map(num).join(',')).join(';')}`);
  for (const param of MODES[mode].params) {
    const value = design[param.key];
    parts.push(`${param.key}=${param.boolean ? (value ? 1 : 0) : num(value)}`);
  }
  for (const [key, value] of MODES[mode].link(design)) parts.push(`${key}=${value}`);
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
  const error = m.fromLink(fields, design);
  if (error) return { error };
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
  const mode = MODES[json.mode] ? json.mode : recognise(json).name;
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
  m.adopt(json, design);
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
