// A path: log-aesthetic segments along a control polygon that grows and shrinks (at least three
// points), G2 or G1 at the joints, open or closed, through inflections as straight pieces:
// /api/path. No drawable region.

import { plane, planePlots } from './plane.js';
import { fmt } from '../format.js';

/** How far a segment's line in the graph goes in ln ρ: until its curvature is a twentieth of
 * its largest. A segment that runs into an inflection has κ → 0 there, and ln ρ → ∞ (28 and
 * more in doubles): drawn whole, its line would squeeze every other segment's to a stub. */
export const LCG_SPAN = Math.log(20);

export default {
  ...plane,
  name: 'path',
  label: 'Path',
  endpoint: '/api/path',
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

  fileRank: 20,
  recognises: (json) => 'g2' in json || 'closed' in json || 'segments' in json || json.points.length > 4,
  /** A `lac path` result says its slope per segment and its continuity. */
  adopt(json, design) {
    if (!('alpha' in json) && Array.isArray(json.segments) && json.segments.length) {
      design.alpha = json.segments[0].alpha;
    }
    if (!('g2' in json) && typeof json.continuity === 'string') {
      design.g2 = json.continuity === 'g2';
    }
  },

  region: null,

  /** The joints (dots), the straight pieces through inflections, the closing leg. */
  scene: (a, d) => ({
    joints: a ? a.joints.map((j) => j.point) : null,
    lines: a ? a.straight_pieces.map((l) => l.points) : null,
    closed: d.closed,
  }),

  readout(a, add) {
    add('arc length', 'arc_length', a.arc_length);
    add('segments', 'segments', a.segments.length, String(a.segments.length));
    add('continuity', 'continuity', a.continuity, a.continuity.toUpperCase());
    add('max κ jump', 'max_curvature_jump', a.max_curvature_jump, a.max_curvature_jump.toExponential(2));
    const lines = a.straight_pieces.length;
    add('inflections', 'inflections', lines, lines ? `${lines} (straight piece${lines > 1 ? 's' : ''} at κ = 0)` : 'none');
    add('κ start', 'curvature_start', a.samples[0].kappa);
    add('κ end', 'curvature_end', a.samples[a.samples.length - 1].kappa);
  },

  /** The curvature plot of the samples' κ, the joints marked; the graph is one line per
   * segment (`answer.lcg`), cut where κ → 0 (LCG_SPAN). */
  plots(a, where) {
    const plot = a ? { points: a.samples.map((r) => ({ s: r.s, kappa: r.kappa, log_rho: null, log_lcg: null })), fit: null } : null;
    const series = [];
    const graph = [];
    const vlines = [];
    let title = 'logarithmic curvature graph';
    if (plot) {
      series.push({ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label: '' });
      for (const j of a.joints) vlines.push({ x: j.s });
      let cut = false;
      a.lcg.forEach((row, k) => {
        if (!row) return;
        const { alpha, intercept, log_rho: [x0, x1] } = row;
        const lo = Math.min(x0, x1);
        const hi = Math.min(Math.max(x0, x1), lo + LCG_SPAN);
        cut ||= hi < Math.max(x0, x1);
        graph.push({ points: [[lo, alpha * lo + intercept], [hi, alpha * hi + intercept]], color: k % 2 ? '#e69138' : '#1f4e9c', width: 2, label: '' });
      });
      const slopes = [...new Set(a.segments.map((g) => fmt(g.alpha)))].join(', ');
      title = cut ? `LCG per segment, slopes ${slopes} (cut where κ → 0)` : `LCG: one line per segment, slopes ${slopes}`;
    }
    return planePlots({ plot, series, graph, vlines, title }, where);
  },

  /** Where the library found a G1 path for this polygon (else the button would lead to
   * another refusal). */
  fix(error) {
    if (error.kind !== 'no_g2_path' || !Array.isArray(error.g1_fractions)) return null;
    return { label: 'Use the G1 path', apply: (design) => { design.g2 = false; } };
  },
};
