// A spline through points with point types (smooth, tangent, corner) and straight spans,
// open or closed: /api/spline. The points grow and shrink (at least three); a point's type
// is set by a key while it is the selected one (the last dragged), or from its menu (right
// click): S smooth, T tangent (its direction the curve's there now; drag it again to move
// it), C corner, L a straight span from it to the next point (again: curved). The link
// carries the types, directions, straight spans and open ends' conditions (link, fromLink). Each type is drawn with its own marker, as in
// Spiro: a corner's square, a tangent point's arrow, a half circle where a curve meets a
// straight span. No drawable region.

import { plane, planePlots } from './plane.js';
import { LCG_SPAN } from './path.js';
import { fmt } from '../format.js';

/** The design's types, angles and lines made to fit its points (after a point was added or
 * removed). */
function fitted(d) {
  const n = d.points.length;
  const types = (d.types || []).slice(0, n);
  while (types.length < n) types.push('s');
  const angles = (d.angles || []).slice(0, n);
  while (angles.length < n) angles.push([null, null]);
  const spans = d.closed ? n : n - 1;
  const lines = [...new Set((d.lines || []).filter((i) => Number.isInteger(i) && i >= 0 && i < spans))];
  return { types, angles, lines };
}

/** The link's text of a direction or curvature: empty for free (null). */
const opt = (x) => (x === null || x === undefined ? '' : String(x));

/** A number of the link, empty for free (null); undefined when it is not a number. */
function optNumber(text) {
  if (text === '') return null;
  const x = Number(text);
  return Number.isFinite(x) ? x : undefined;
}

/** An open end {angle, curvature} from the link's "θ/κ" (either empty), or undefined. */
function endOf(text) {
  const parts = text.split('/');
  if (parts.length !== 2) return undefined;
  const [angle, curvature] = parts.map(optNumber);
  if (angle === undefined || curvature === undefined) return undefined;
  return { angle, curvature };
}

/** Whether an open end {angle, curvature} gives anything. */
const givesEnd = (e) => !!e && (opt(e.angle) !== '' || opt(e.curvature) !== '');

/** Every point smooth, no straight span, the ends free: what a design without types is. */
function smooth(d) {
  d.types = d.points.map(() => 's');
  d.angles = d.points.map(() => [null, null]);
  d.lines = [];
  delete d.start;
  delete d.end;
}

/** The link's words for the design's point types. */
const LINK_KEYS = ['types', 'angles', 'lines', 'start', 'end'];

export default {
  ...plane,
  name: 'spline',
  label: 'Spline',
  endpoint: '/api/spline',
  count: null,
  minCount: 3,
  params: [
    { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01,
      hint: 'slope of every segment; straight spans need α < 0 (the curve meets them with zero curvature)' },
    { key: 'closed', label: 'closed', boolean: true, hint: 'the last point joins the first' },
  ],
  defaults: {
    points: [[0, 4], [0, 1.5], [1, 0], [2, 1.5], [2, 4]],
    alpha: -1, closed: false,
    types: ['s', 's', 't', 's', 's'],
    angles: [[null, null], [null, null], [0, null], [null, null], [null, null]],
    lines: [0, 3],
  },

  fileRank: 25,
  recognises: (json) => 'at_points' in json || 'types' in json,
  /** A `lac spline` result (its types and given directions at `at_points`) or a design
   * file (`types`, `angles`): with the straight spans and the open ends' conditions; a file
   * that gives none of them is all smooth. */
  adopt(json, design) {
    smooth(design);
    if (Array.isArray(json.at_points)) {
      design.types = json.at_points.map((p) => p.type[0]);
      design.angles = json.at_points.map((p) => p.given);
    } else if (Array.isArray(json.types)) {
      design.types = json.types.map((t) => (['s', 't', 'c'].includes(t) ? t : 's'));
      if (Array.isArray(json.angles)) design.angles = json.angles;
    }
    if (Array.isArray(json.lines)) design.lines = json.lines;
    for (const key of ['start', 'end']) {
      const e = json[key];
      if (e && typeof e === 'object' && givesEnd(e)) design[key] = { angle: e.angle ?? null, curvature: e.curvature ?? null };
    }
  },

  /** A spline's link, in lac spline's words and left out where it says nothing (so that a
   * link of smooth points reads as before point types): `types=sstss` (a letter a point),
   * `angles=2:0,4:/1.5` (as --angles: a tangent point's direction, a corner's sides in/out,
   * either empty for free), `lines=0,3` (the first point of each straight span), and an
   * open end's `start=θ/κ`, `end=θ/κ` (either empty for free). */
  link(d) {
    const { types, angles, lines } = fitted(d);
    const out = [];
    if (types.some((t) => t !== 's')) out.push(['types', types.join('')]);
    const given = angles.flatMap(([a, b], i) => {
      if (types[i] === 't' && a !== null) return [`${i}:${a}`];
      if (types[i] === 'c' && (a !== null || b !== null)) return [`${i}:${opt(a)}/${opt(b)}`];
      return [];
    });
    if (given.length) out.push(['angles', given.join(',')]);
    if (lines.length) out.push(['lines', [...lines].sort((a, b) => a - b).join(',')]);
    for (const key of ['start', 'end']) {
      if (givesEnd(d[key])) out.push([key, `${opt(d[key].angle)}/${opt(d[key].curvature)}`]);
    }
    return out;
  },

  /** The design's types, directions, spans and ends from a link's `fields` (link(), above):
   * a link that gives the points but none of these is all smooth, as links were before
   * point types; one that gives neither keeps the starting design's. An error message for
   * what does not read. */
  fromLink(fields, d) {
    if (!fields.has('points') && !LINK_KEYS.some((k) => fields.has(k))) return null;
    smooth(d);
    const n = d.points.length;
    if (fields.has('types')) {
      const text = fields.get('types');
      if (!/^[stc]*$/.test(text) || text.length !== n) {
        return `the link's types are not a letter s, t or c for each of its ${n} points (${text})`;
      }
      d.types = [...text];
    }
    for (const item of (fields.get('angles') || '').split(',').filter(Boolean)) {
      const m = item.match(/^(\d+):([^/]*)(?:\/(.*))?$/);
      const i = m ? Number(m[1]) : NaN;
      const sides = m ? [optNumber(m[2]), m[3] === undefined ? null : optNumber(m[3])] : [];
      if (!m || i >= n || sides.includes(undefined)) {
        return `the link's angles are not i:θ or i:in/out for points 0 to ${n - 1} (${item})`;
      }
      d.angles[i] = sides;
    }
    const spans = d.closed ? n : n - 1;
    for (const item of (fields.get('lines') || '').split(',').filter(Boolean)) {
      const i = Number(item);
      if (!/^\d+$/.test(item) || i >= spans) {
        return `the link's lines are not the first points of spans 0 to ${spans - 1} (${item})`;
      }
      if (!d.lines.includes(i)) d.lines.push(i);
    }
    for (const key of ['start', 'end']) {
      if (!fields.has(key)) continue;
      const end = endOf(fields.get(key));
      if (!end) return `the link's ${key} is not θ/κ, either empty (${fields.get(key)})`;
      if (givesEnd(end)) d[key] = end;
    }
    return null;
  },

  region: null,

  request(body) {
    return { ...body, ...fitted(body) };
  },
  /** The CAD file is the spline the page shows, as /api/spline solves it (its `types` tell
   * /api/export it is one, as --through tells lac export), not a path through its points. */
  cad(body) {
    return { ...body, ...fitted(body) };
  },

  /** Point `i` of design `d` made smooth, tangent or a corner (`key` s, t or c), or the
   * span from it to the next made straight or curved again (l). */
  setType(d, i, key) {
    Object.assign(d, fitted(d));
    if (i < 0 || i >= d.points.length) return;
    if (key === 'l') {
      d.lines = d.lines.includes(i) ? d.lines.filter((l) => l !== i) : [...d.lines, i];
      return;
    }
    d.types[i] = key;
    if (key === 't') {
      // The direction the curve has there now (else the chord's).
      const p = d.points;
      const [a, b] = [p[Math.max(0, i - 1)], p[Math.min(p.length - 1, i + 1)]];
      const now = this.lastAngles ? this.lastAngles[i] : null;
      d.angles[i] = [now ?? Math.atan2(b[1] - a[1], b[0] - a[0]), null];
    } else {
      d.angles[i] = [null, null];
    }
  },

  /** Keys on the selected point: S smooth, T tangent, C corner, L straight span to the next. */
  init(input) {
    window.addEventListener('keydown', (e) => {
      if (e.ctrlKey || e.metaKey || e.altKey || e.target.tagName === 'INPUT') return;
      const key = e.key.toLowerCase();
      if (!'stcl'.includes(key) || key.length !== 1) return;
      const applied = input.change('spline', (d, i) => this.setType(d, i, key));
      if (applied) e.preventDefault();
    });
  },

  /** Point i's menu (right click): its type, as the keys set it, and whether the span to
   * the next point is straight (a checkbox; none after an open spline's last point). */
  menu(d, i) {
    const { types, lines } = fitted(d);
    const n = d.points.length;
    const next = d.closed || i < n - 1 ? (i + 1) % n : null;
    const item = (key, label, checked, disabled = false) => ({
      key: key.toUpperCase(), label, checked, disabled,
      apply: (design, at) => this.setType(design, at, key),
    });
    return {
      title: `P${i}`,
      items: [
        item('s', 'Smooth', types[i] === 's'),
        item('t', 'Tangent', types[i] === 't'),
        item('c', 'Corner', types[i] === 'c'),
        { ...item('l', next === null ? 'Straight span (no next point)' : `Straight span to P${next}`,
          lines.includes(i), next === null), checkbox: true },
      ],
    };
  },

  /** The knots (dots), the straight spans, the closing span; each point's marker. */
  scene(a, d) {
    const { types, angles, lines } = fitted(d);
    const p = d.points;
    const n = p.length;
    if (a) this.lastAngles = a.angles;
    const marks = [];
    types.forEach((t, i) => {
      if (t === 'c') marks.push({ at: p[i], kind: 'corner' });
      if (t === 't' && angles[i][0] !== null) marks.push({ at: p[i], kind: 'tangent', angle: angles[i][0] });
    });
    for (const i of lines) {
      const j = (i + 1) % n;
      const dir = Math.atan2(p[j][1] - p[i][1], p[j][0] - p[i][0]);
      // Open away from the line: the half circle on the curve's side of each end.
      // (Where a curve meets it: not at a corner, nor at an open spline's end.)
      if (types[i] !== 'c' && (d.closed || i > 0)) marks.push({ at: p[i], kind: 'line', angle: dir + Math.PI });
      if (types[j] !== 'c' && (d.closed || j < n - 1)) marks.push({ at: p[j], kind: 'line', angle: dir });
    }
    return {
      joints: a ? a.knots.map((k) => k.point) : null,
      lines: lines.map((i) => [p[i], p[(i + 1) % n]]),
      closed: d.closed,
      marks,
    };
  },

  readout(a, add) {
    add('arc length', 'arc_length', a.arc_length);
    add('pieces', 'pieces', a.pieces.length, String(a.pieces.length));
    add('knots', 'knots', a.knots.length, String(a.knots.length));
    add('max κ jump', 'max_curvature_jump', a.max_curvature_jump, a.max_curvature_jump.toExponential(2));
    const flat = a.at_points
      .flatMap((p) => p.curvatures.filter((k, side) => k !== null && p.straight[1 - side] && !p.straight[side]))
      .reduce((m, k) => Math.max(m, Math.abs(k)), 0);
    if (a.lines.length) add('κ at straight spans', 'straight_curvature', flat, flat.toExponential(1));
    add('types', 'types', 0, a.at_points.map((p) => p.type[0]).join(' '));
  },

  /** The curvature plot of the samples' κ, the knots marked; the graph one line per piece
   * (cut where κ → 0). */
  plots(a, where) {
    const plot = a ? { points: a.samples.map((r) => ({ s: r.s, kappa: r.kappa, log_rho: null, log_lcg: null })), fit: null } : null;
    const series = [];
    const graph = [];
    let title = 'logarithmic curvature graph';
    if (plot) {
      series.push({ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label: '' });
      a.lcg.forEach((row, k) => {
        if (!row) return;
        const { alpha, intercept, log_rho: [x0, x1] } = row;
        const lo = Math.min(x0, x1);
        const hi = Math.min(Math.max(x0, x1), lo + LCG_SPAN);
        graph.push({ points: [[lo, alpha * lo + intercept], [hi, alpha * hi + intercept]], color: k % 2 ? '#e69138' : '#1f4e9c', width: 2, label: '' });
      });
      title = `LCG per piece, slope ${fmt(a.alpha)} (cut where κ → 0)`;
    }
    return planePlots({ plot, series, graph, vlines: [], title }, where);
  },
};
