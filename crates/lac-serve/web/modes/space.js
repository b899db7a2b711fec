// A space curve: the log-aesthetic space segment of four control points (seed 003), in four
// views of its own (#space: perspective, top, front, side; space.js): /api/space.

import { SpaceViews, combTips } from '../space.js';
import { spaceSvg } from '../export.js';
import { placeTop, unplace } from '../banner.js';

/** Least-squares slope of points [x, y] (for the space curve's graphs, drawn by the page). */
function slope(points) {
  const n = points.length;
  if (n < 2) return NaN;
  const mx = points.reduce((s, p) => s + p[0], 0) / n;
  const my = points.reduce((s, p) => s + p[1], 0) / n;
  let sxx = 0;
  let sxy = 0;
  for (const [x, y] of points) {
    sxx += (x - mx) * (x - mx);
    sxy += (x - mx) * (y - my);
  }
  return sxx > 0 ? sxy / sxx : NaN;
}

/** The four views, once the page has started (`init`). */
let views = null;

export default {
  name: 'space',
  label: 'Space curve',
  endpoint: '/api/space',
  stage: 'space',
  dims: 3,
  count: 4,
  params: [
    { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01, hint: 'slope of the logarithmic curvature graph' },
    { key: 'beta', label: 'β', min: -3, max: 3, step: 0.01, hint: 'slope of the logarithmic torsion graph' },
    { key: 'omega', label: 'Ω', min: 0, max: 2, step: 0.01, valid: { from: 0 }, hint: 'torsion parameter (0: constant torsion)' },
    { key: 'type', label: 'type', choices: [1, 2], hint: 'torsion type of seed 003' },
  ],
  defaults: {
    points: [[0, 0, 0], [3, 0, 0], [3, 3, 1.5], [0, 3, 3]],
    alpha: 0.5, beta: 0, omega: 0.3, type: 1,
  },

  /** Points of three numbers: a space curve, whatever else the file says. */
  fileRank: 10,
  recognises: (json) => (json.points[0] && json.points[0].length) === 3,

  /** The views drag the control points in the top, front and side views and orbit the
   * perspective one; they report to the page through `input`. */
  init(input) {
    const $ = (id) => document.getElementById(id);
    views = new SpaceViews({ '3d': $('view-3d'), top: $('view-top'), front: $('view-front'), side: $('view-side') }, input);
  },

  draw(f) {
    return views.draw({
      points: f.design.points,
      samples: f.answer ? f.answer.samples : [],
      stale: f.stale,
      show: f.show,
      combScale: f.combScale,
      active: f.active,
      hover: f.hover ? f.hover.sample : null,
    });
  },

  combLimit: (f) => (f.answer ? views.combLimit(f.answer.samples) : Infinity),

  fit(f) {
    const rows = f.answer ? f.answer.samples : [];
    const tips = f.show.comb ? combTips(rows, f.combScale) : [];
    views.fit([...f.design.points, ...rows.map((r) => [r.x, r.y, r.z]), ...tips]);
  },

  /** The message goes into the perspective view, under its caption, which draws below it:
   * the views where points are dragged, and their captions, stay clear. */
  placeMessage(box) {
    if (box.hidden) {
      unplace(box);
      views.setInset(0);
      return;
    }
    const figure = document.getElementById('view-3d').parentElement.getBoundingClientRect();
    const stage = document.getElementById('stage').getBoundingClientRect();
    const area = { left: figure.left - stage.left, top: figure.top - stage.top, width: figure.width, height: figure.height };
    views.setInset(placeTop(box, area, 22));
  },

  /** Where control point `index` is in the window, in view `name` (top by default). */
  screenOf(f, index, name) {
    const [x, y] = views.screenOf(name || 'top', index);
    const r = document.getElementById(`view-${name || 'top'}`).getBoundingClientRect();
    return [r.left + x, r.top + y];
  },

  readout(a, add) {
    add('arc length', 'arc_length', a.arc_length);
    const first = a.samples[0];
    const last = a.samples[a.samples.length - 1];
    add('κ start', 'kappa_start', first.kappa);
    add('κ end', 'kappa_end', last.kappa);
    add('τ start', 'tau_start', first.tau);
    add('τ end', 'tau_end', last.tau);
    if (a.standard_form) {
      add('Λ', 'lambda', a.standard_form.lambda);
      add('ν', 'nu', a.standard_form.nu);
    }
    add('planar', 'planar', a.planar ? 1 : 0, a.planar ? 'yes (coplanar points)' : 'no');
  },

  /** κ and τ against s; the logarithmic curvature and torsion graphs with their slopes. */
  plots(a, { hover, error }) {
    const rows = a ? a.samples : [];
    const lcg = a ? a.graphs.curvature.map((p) => [p.x, p.y]) : [];
    const ltg = a ? a.graphs.torsion.map((p) => [p.x, p.y]) : [];
    const bits = [];
    // Slopes to six decimals: the graphs are straight, a slope of 1e-29 is a zero.
    const six = (x) => String(+x.toFixed(6));
    if (lcg.length) bits.push(`LCG slope ${six(slope(lcg))}`);
    if (ltg.length) bits.push(`LTG slope ${six(slope(ltg))}`);
    return {
      kplot: {
        title: 'curvature κ and torsion τ against arc length',
        xlabel: 's', ylabel: 'κ, τ', includeZero: true,
        series: [
          { points: rows.map((r) => [r.s, r.kappa]), color: '#1f4e9c', label: 'κ' },
          { points: rows.map((r) => [r.s, r.tau]), color: '#b3261e', label: 'τ' },
        ],
        marker: hover ? [hover.sample.s, hover.sample.kappa] : null,
        empty: error ? 'not drawable' : 'waiting for the server',
      },
      lcg: {
        title: bits.join(', ') || 'logarithmic curvature and torsion graphs',
        // One line per graph, in its colour: as one line it is longer than the plot is tall.
        xlabel: 'ln ρ, ln μ',
        ylabel: [{ text: 'ln(ρ ds/dρ)', color: '#1f4e9c' }, { text: 'ln(μ ds/dμ)', color: '#b3261e' }],
        series: [
          { points: lcg, color: '#1f4e9c', label: lcg.length ? 'curvature' : '' },
          { points: ltg, color: '#b3261e', label: ltg.length ? 'torsion' : '' },
        ],
        empty: a ? 'ρ and μ are constant: no graph' : 'not drawable',
      },
    };
  },

  /** No segment at this Ω: the library says where the Ω = 0 segment's branch ends. */
  fix(error) {
    if (typeof error.omega_max !== 'number') return null;
    const omega = +error.omega_max.toPrecision(6);
    return { label: `Use Ω = ${omega}`, apply: (design) => { design.omega = omega; } };
  },

  svg: ({ design, answer, title }) => spaceSvg({ points: design.points, samples: answer.samples, title }),
};
