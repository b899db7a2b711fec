// A spline through points with point types (smooth, tangent, corner) and straight spans,
// open or closed: /api/spline. The points grow and shrink (at least three); a point's type
// is set by a key while it is the selected one (the last dragged): S smooth, T tangent (its
// direction the curve's there now; drag it again to move it), C corner, L a straight span
// from it to the next point (again: curved). Each type is drawn with its own marker, as in
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
  /** A `lac spline` result: its types, given directions and straight spans. */
  adopt(json, design) {
    if (Array.isArray(json.at_points)) {
      design.types = json.at_points.map((p) => p.type[0]);
      design.angles = json.at_points.map((p) => p.given);
    }
    if (Array.isArray(json.lines)) design.lines = json.lines;
  },

  region: null,

  request(body) {
    return { ...body, ...fitted(body) };
  },

  /** Keys on the selected point: S smooth, T tangent, C corner, L straight span to the next. */
  init(input) {
    window.addEventListener('keydown', (e) => {
      if (e.ctrlKey || e.metaKey || e.altKey || e.target.tagName === 'INPUT') return;
      const key = e.key.toLowerCase();
      if (!'stcl'.includes(key) || key.length !== 1) return;
      const applied = input.change('spline', (d, i) => {
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
      });
      if (applied) e.preventDefault();
    });
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
