// What the plane modes share: the curve drawn on the plane canvas (#plane) with its comb,
// evolute and drawable region; the exact curve's readout and plots; its SVG. A plane mode is
// `{ ...plane, name, label, ... }` with its own data and whatever it shows differently.
//
// The functions that draw get the page's frame (see state.js: design, answer, stale, show,
// combScale, active, selected, hover, region, view, canvas).

import { drawPlane, geometry, sizeCanvas } from '../draw.js';
import { bounds, similarity } from '../view.js';
import { planeSvg } from '../export.js';
import { fmt, deg } from '../format.js';
import { placeClear } from '../banner.js';
import { combRoom } from '../layout.js';

/** Pixels per side of the canonical region map. */
export const REGION_SIZE = 200;

/** Pixels per side of the map around the canonical one (the most /api/region/point draws). */
const WIDE_SIZE = 128;

/** The half-side, in the canonical map's units (the ends at (−1, 0) and (1, 0)), of a square
 * about its centre that holds the visible canvas: a power of two, so that it changes seldom
 * as the view or the ends move; 0 when the canonical map holds it all. */
function canonicalReach(f) {
  const pts = f.design.points;
  const [a, b] = [pts[0], pts[pts.length - 1]];
  const [cx, cy] = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
  const [ex, ey] = [(b[0] - a[0]) / 2, (b[1] - a[1]) / 2];
  const e2 = ex * ex + ey * ey;
  if (!(e2 > 0)) return 0;
  const [x0, x1, y0, y1] = f.view.visible(f.canvas.clientWidth, f.canvas.clientHeight);
  let reach = 0;
  for (const [x, y] of [[x0, y0], [x0, y1], [x1, y0], [x1, y1]]) {
    const [dx, dy] = [x - cx, y - cy];
    reach = Math.max(reach, Math.abs(dx * ex + dy * ey) / e2, Math.abs(dx * ey - dy * ex) / e2);
  }
  return reach > 1 ? 2 ** Math.min(16, Math.ceil(Math.log2(reach))) : 0;
}

/** The request of a canonical region map (`/api/region`, `body`: where P1 may go between
 * ends at (−1, 0) and (1, 0)), drawn onto the current ends; and, when the view shows more than
 * its square, `wide`: the map of P1 over a square that holds the view, from
 * `/api/region/point` for the curve of the same ends and parameters (`curve`: its fields but
 * the points), drawn around it, so the shading covers the visible canvas. */
export function canonicalRegion(body, curve, f) {
  const reach = canonicalReach(f);
  const wideBody = {
    curve: { points: [[-1, 0], [0, 0.5], [1, 0]], ...curve },
    index: 1,
    extent: [-reach, reach, -reach, reach],
    size: WIDE_SIZE,
  };
  const wide = reach ? { key: JSON.stringify(wideBody), path: '/api/region/point', body: wideBody } : null;
  return { key: JSON.stringify(body), path: '/api/region', body, canonical: true, wide };
}

/** The straight line of an LCG row {alpha, intercept, log_rho: [x0, x1]}. */
const lineOf = ({ alpha, intercept, log_rho: [x0, x1] }) => [[x0, alpha * x0 + intercept], [x1, alpha * x1 + intercept]];

/** The exact curve's lines in the two plots: κ against s, ln ρ against ln(ρ ds/dρ), the
 * pieces' lines (compound) or the fitted line, the joint; and the graph's title. */
export function exactPlots(answer, plot, label = '') {
  const series = [];
  const graph = [];
  const vlines = [];
  if (plot) {
    series.push({ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label });
    graph.push({ points: plot.points.map((p) => [p.log_rho ?? NaN, p.log_lcg ?? NaN]), color: '#1f4e9c', label });
    const line = (row, text) => ({ points: lineOf(row), color: '#e69138', dash: [5, 3], width: 1.2, label: text });
    // A compound curve's graph is two straight pieces: their lines, not one fitted across.
    if (answer && answer.lcg) answer.lcg.filter(Boolean).forEach((row, k) => graph.push(line(row, k ? '' : 'pieces\' lines')));
    else if (plot.fit) graph.push(line(plot.fit, ''));
    if (answer && answer.joint_s !== undefined) vlines.push({ x: answer.joint_s });
  }
  const fit = plot && plot.fit;
  let title = 'logarithmic curvature graph';
  if (answer && answer.lcg) title = `LCG: slopes ${answer.lcg.map((r) => (r ? fmt(r.alpha) : 'circle')).join(' then ')}`;
  else if (fit) title = `logarithmic curvature graph: fitted slope α = ${fmt(fit.alpha)}`;
  return { series, graph, vlines, title };
}

/** The options of the panel's two plots (plots.js linePlot) of a plane curve: `plot` the
 * curvature plot {points, fit} the hover mark is looked up in, `series` and `vlines` the
 * curvature plot's lines, `graph` and `title` the logarithmic curvature graph's. */
export function planePlots({ plot, series, graph, vlines, title }, { hover, error }) {
  const hoverRow = hover && plot ? plot.points[hover.index] : null;
  return {
    kplot: {
      title: 'curvature plot: κ against arc length s',
      xlabel: 's', ylabel: 'κ', includeZero: true, series, vlines,
      marker: hoverRow ? [hoverRow.s, hoverRow.kappa] : null,
      empty: error ? 'not drawable' : 'waiting for the server',
    },
    lcg: {
      title,
      xlabel: 'ln ρ', ylabel: 'ln(ρ ds/dρ)', series: graph,
      marker: hoverRow && hoverRow.log_rho !== null ? [hoverRow.log_rho, hoverRow.log_lcg] : null,
      empty: plot ? 'the curvature is constant (circular arcs): no graph' : 'not drawable',
    },
  };
}

/** The readout rows of an exact curve's report `c` (a segment or a compound curve). */
export function curveReadout(c, add) {
  add('arc length', 'arc_length', c.arc_length);
  add('κ start', 'curvature_start', c.curvature_start);
  if ('curvature_joint' in c) {
    add('κ joint', 'curvature_joint', c.curvature_joint);
    add('joint at s', 'joint_s', c.joint_s);
  }
  add('κ end', 'curvature_end', c.curvature_end);
  add('turning', 'turning_angle', c.turning_angle, deg(c.turning_angle));
  add('Λ', 'lambda', c.lambda);
  // A compound curve's graph is two lines (in the plot); one fitted across says little.
  const fit = c.plot && c.plot.fit;
  if (fit && !('lcg' in c)) add('LCG slope (fit)', 'fit_alpha', fit.alpha);
}

export const plane = {
  stage: 'plane',
  dims: 2,

  /** The exact curve's report in an answer. */
  curve: (answer) => answer,

  /** The samples {s, x, y, theta, kappa} of the exact curve in an answer (or none). */
  samples(answer) {
    const c = answer && this.curve(answer);
    return (c && c.samples) || [];
  },

  /** The curvature plot {points: [{s, kappa, log_rho, log_lcg}], fit} of the exact curve. */
  plot(answer) {
    return answer ? this.curve(answer).plot : null;
  },

  /** What else drawPlane draws of an answer (which may be null) and the design:
   * {joints, lines, closed, pieces, pieceSamples} (draw.js). */
  scene: () => ({}),

  draw(f) {
    const { ctx, width, height } = sizeCanvas(f.canvas);
    const d = f.design;
    const a = f.answer;
    let region = null;
    if (f.region) {
      const pts = d.points;
      const index = f.region.canonical ? 1 : f.selected;
      region = {
        ...f.region,
        toWorld: f.region.canonical ? similarity(pts[0], pts[pts.length - 1]) : (p) => p,
        label: `Where P${index} may go:`,
      };
    }
    return drawPlane(ctx, f.view, width, height, {
      points: d.points,
      samples: this.samples(a),
      stale: f.stale,
      show: f.show,
      combScale: f.combScale,
      region,
      joint: a && a.joint ? a.joint : null,
      joints: null,
      lines: null,
      closed: false,
      pieces: null,
      pieceSamples: null,
      ...this.scene(a, d),
      active: f.active,
      hover: f.hover ? [f.hover.sample.x, f.hover.sample.y] : null,
    });
  },

  /** Fit the view to the control points, the curve and its comb. */
  fit(f) {
    const rows = this.samples(f.answer);
    const tips = f.show.comb ? geometry(rows, f.combScale).teeth.map(([, q]) => q) : [];
    f.view.fit(bounds([...f.design.points, ...rows.map((r) => [r.x, r.y]), ...tips]), f.canvas.clientWidth, f.canvas.clientHeight);
  },

  /** The largest comb scale at which the teeth stay in the view (layout.js). */
  combLimit(f) {
    const s = f.view.scale;
    const teeth = this.samples(f.answer).map((r) => [
      f.view.toScreen([r.x, r.y]),
      [Math.sin(r.theta) * r.kappa * s, Math.cos(r.theta) * r.kappa * s],
    ]);
    return combRoom(teeth, f.canvas.clientWidth, f.canvas.clientHeight);
  },

  /** Put the message (#message, over #stage as the canvas is) where it covers no control
   * point (banner.js). */
  placeMessage(box, f) {
    if (box.hidden) return;
    const area = { left: 0, top: 0, width: f.canvas.clientWidth, height: f.canvas.clientHeight };
    placeClear(box, area, f.design.points.map((p) => f.view.toScreen(p)));
  },

  /** Where control point `index` is in the window. */
  screenOf(f, index) {
    const [x, y] = f.view.toScreen(f.design.points[index]);
    const r = f.canvas.getBoundingClientRect();
    return [r.left + x, r.top + y];
  },

  readout(answer, add) {
    curveReadout(this.curve(answer), add);
  },

  plots(answer, where) {
    const plot = this.plot(answer);
    return planePlots({ plot, ...exactPlots(answer, plot) }, where);
  },

  svg({ design, answer, combScale, show, title }) {
    const scene = this.scene(answer, design);
    return planeSvg({
      points: design.points, samples: this.samples(answer), combScale, show,
      pieces: scene.pieces || null, pieceSamples: scene.pieceSamples || null,
      joint: answer.joint || null, title,
    });
  },
};
