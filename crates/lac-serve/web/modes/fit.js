// A fit: the log-aesthetic path nearest measured points (pasted or imported, ../points.js),
// the fewest segments within a tolerance, G2 or G1, open or closed, α fitted in a range (each
// segment's, or one for all) or fixed: /api/fit (lac-io's FitInput, as `lac fit` takes it).
// The points are coloured by their distance to the fit.

import { plane, planePlots } from './plane.js';
import { LCG_SPAN } from './path.js';
import { drawPlane, sizeCanvas, COLORS } from '../draw.js';
import { planeSvg } from '../export.js';
import { fmt } from '../format.js';
import { bounds } from '../view.js';
import { readPoints, svgPoints, pointsText } from '../points.js';

/** The most segments a fit may use (the library's MAX_FIT_SEGMENTS). */
const MOST_SEGMENTS = 64;

/** Point colours: within half the tolerance, green; from there to the tolerance through amber
 * to red; beyond it, dark red. In between, in STEPS steps (a colour is one fill of the
 * canvas, whatever the number of points). */
export const NEAR = [30, 158, 58];
const HALF = [240, 160, 0];
const AT = [217, 48, 37];
const BEYOND = [120, 0, 0];
const STEPS = 16;

const mix = (a, b, t) => a.map((x, i) => Math.round(x + (b[i] - x) * t));
const rgb = ([r, g, b]) => `rgb(${r}, ${g}, ${b})`;

/** The colour of a point at `share` of the tolerance from the fit. */
export function distanceColor(share) {
  if (!(share <= 1)) return BEYOND;
  if (share <= 0.5) return NEAR;
  const u = Math.round((STEPS * (share - 0.5)) / 0.5) / STEPS;
  return u < 0.5 ? mix(NEAR, HALF, 2 * u) : mix(HALF, AT, 2 * u - 1);
}

/** Points on a logarithmic spiral (α = 1), moved by a little deterministic noise: the first
 * design. */
function spiral(n = 80) {
  const points = [];
  for (let k = 0; k < n; k++) {
    const t = (1.4 * Math.PI * k) / (n - 1);
    const r = Math.exp(0.2 * t) * (1 + 0.0015 * Math.sin(7.3 * k));
    points.push([+(r * Math.cos(t)).toFixed(4), +(r * Math.sin(t)).toFixed(4)]);
  }
  return points;
}

/** The graph ln(ρ ds/dρ) against ln ρ of each piece, from the samples by central differences
 * within the piece (a joint's curvature has no one derivative): an S's two halves apart (the
 * slope changes sign at the inflection), each cut where ln ρ is LCG_SPAN beyond its least (as
 * a path's, ./path.js). {series, cut}: cut when a half was. */
function graphOf(a) {
  const series = [];
  let cut = false;
  a.pieces.forEach((piece, k) => {
    // A circular arc (κ constant to rounding) has no graph.
    const [k0, k1] = piece.curvature;
    if (!(Math.abs(k1 - k0) > 1e-6 * Math.max(Math.abs(k0), Math.abs(k1)))) return;
    const rows = a.samples.filter((r) => r.s > piece.s && r.s < piece.s + piece.arc_length && r.kappa !== 0);
    for (const half of [rows.filter((r) => r.kappa > 0), rows.filter((r) => r.kappa < 0)]) {
      const logRho = half.map((r) => -Math.log(Math.abs(r.kappa)));
      const least = Math.min(...logRho);
      const line = [];
      for (let i = 1; i + 1 < half.length; i++) {
        if (logRho[i] > least + LCG_SPAN) {
          cut = true;
          continue;
        }
        const slope = (Math.exp(logRho[i + 1]) - Math.exp(logRho[i - 1])) / (half[i + 1].s - half[i - 1].s);
        const value = logRho[i] - Math.log(Math.abs(slope));
        if (Number.isFinite(value) && Number.isFinite(logRho[i])) line.push([logRho[i], value]);
      }
      if (line.length > 1) series.push({ points: line, color: k % 2 ? '#e69138' : '#1f4e9c', width: 2, label: '' });
    }
  });
  return { series, cut };
}

/** The tolerance slider's ends (log10): from a millionth to a tenth of the points' size, so
 * that points in millimetres or in an SVG's pixels have a slider of use. */
function toleranceBounds(d) {
  const [x0, x1, y0, y1] = bounds(d.points);
  const extent = Math.max(x1 - x0, y1 - y0);
  const size = extent > 0 ? Math.log10(extent) : 0;
  return { min: Math.floor(size) - 6, max: Math.ceil(size) - 1 };
}

/** Which of the α rows apply: the range's when α is fitted, else the fixed α's. */
const fitted = (d) => d.free;
const fixed = (d) => !d.free;

export default {
  ...plane,
  name: 'fit',
  label: 'Fit',
  endpoint: '/api/fit',
  count: null,
  minCount: 3,
  controlPolygon: false,
  pointsLegend: 'Points',
  params: [
    { key: 'tolerance', label: 'tolerance', min: -6, max: 0, step: 0.01, log: true, valid: { above: 0 }, bounds: toleranceBounds,
      hint: 'largest distance of a point from the fit (the points\' units): the fewest segments that keep every point within it' },
    { key: 'max_segments', label: 'segments ≤', min: 1, max: MOST_SEGMENTS, step: 1, valid: { from: 1, to: MOST_SEGMENTS, whole: true },
      hint: `the most segments the fit may use (1 to ${MOST_SEGMENTS}; lac fit --max-segments)` },
    { key: 'g1', label: 'G1 joins', boolean: true,
      hint: 'joints with continuous tangent only (lac fit --g1); off: continuous curvature too, G2' },
    { key: 'closed', label: 'closed', boolean: true, hint: 'the points go round once: a closed path' },
    { key: 'free', label: 'α fitted', boolean: true,
      hint: 'each segment\'s α fitted within the range below; off: every segment takes the fixed α' },
    { key: 'alpha_min', label: 'α from', min: -5, max: 10, step: 0.1, enabled: fitted,
      hint: 'the smallest α a fitted segment may take (lac fit --alpha-range)' },
    { key: 'alpha_max', label: 'α to', min: -5, max: 10, step: 0.1, enabled: fitted,
      hint: 'the largest α a fitted segment may take (lac fit --alpha-range)' },
    { key: 'shared', label: 'one α', boolean: true, enabled: fitted,
      hint: 'one fitted α for every segment (lac fit --shared-alpha)' },
    { key: 'alpha', label: 'α fixed', min: -3, max: 3, step: 0.01, enabled: fixed,
      hint: 'every segment\'s α, when α is not fitted (lac fit --alpha)' },
  ],
  defaults: {
    points: spiral(), tolerance: 0.01, max_segments: 16, g1: false, closed: false,
    free: true, alpha_min: -5, alpha_max: 10, shared: false, alpha: 1,
  },

  // Before a path's: a lac fit input (one line of `lac fit --batch`) says closed too.
  fileRank: 15,
  recognises: (json) => ['free', 'rms', 'max_segments', 'alpha_range', 'shared_alpha', 'g1'].some((key) => key in json),
  /** lac-io's FitInput in its own words: α's range as a pair, a fixed α as α alone. */
  adopt(json, design) {
    if (Array.isArray(json.alpha_range) && json.alpha_range.length === 2 && json.alpha_range.every(Number.isFinite)) {
      [design.alpha_min, design.alpha_max] = json.alpha_range;
    }
    if (typeof json.shared_alpha === 'boolean') design.shared = json.shared_alpha;
    if (!('free' in json) && typeof json.alpha === 'number') design.free = false;
  },

  /** lac-io's FitInput: α fixed, or fitted in the design's range. */
  request(body) {
    const input = {
      points: body.points, tolerance: body.tolerance, max_segments: body.max_segments,
      g1: body.g1, closed: body.closed, samples: body.samples,
    };
    if (body.free) {
      input.alpha_range = [body.alpha_min, body.alpha_max];
      input.shared_alpha = body.shared;
    } else {
      input.alpha = body.alpha;
    }
    return input;
  },
  /** A range the wrong way round, said in the panel's words (the library's words are the
   * range's width). */
  check(d) {
    if (!d.free || d.alpha_min <= d.alpha_max) return null;
    return {
      kind: 'invalid_input',
      title: 'Cannot fit:',
      message: `α from (${fmt(d.alpha_min)}) is above α to (${fmt(d.alpha_max)}): lower α from or raise α to`,
    };
  },
  /** The fit's result, which /api/export places again from its segments (lac-io's FitKind):
   * no refit. Its `tolerance`, `samples` and `pieces` would be the export's options. */
  cad(body, answer) {
    const { distances, tolerance, samples, pieces, ...result } = answer;
    return result;
  },
  /** Too few segments for the tolerance: twice as many (at most MOST_SEGMENTS). */
  fix(error, design) {
    if (error.kind !== 'fit_tolerance_not_met' || design.max_segments >= MOST_SEGMENTS) return null;
    const more = Math.min(MOST_SEGMENTS, 2 * design.max_segments);
    return { label: `Allow ${more} segments`, apply: (d) => { d.max_segments = more; } };
  },

  region: null,

  draw(f) {
    const { ctx, width, height } = sizeCanvas(f.canvas);
    const a = f.answer;
    const current = a && !f.stale;
    const points = f.design.points;
    // The colours are of the answer's own tolerance (the slider may have moved on since).
    const distances = current && a.distances && a.distances.length === points.length ? a.distances : null;
    const tolerance = a && (a.tolerance ?? f.design.tolerance);
    // The points under the fitted path (which a thousand points would hide), one fill a colour.
    const underlay = () => {
      const groups = new Map();
      points.forEach((p, i) => {
        const color = distances ? rgb(distanceColor(distances[i] / tolerance)) : '#888';
        if (!groups.has(color)) groups.set(color, []);
        groups.get(color).push(i);
      });
      for (const [color, indices] of groups) {
        ctx.fillStyle = color;
        ctx.beginPath();
        for (const i of indices) {
          const [x, y] = f.view.toScreen(points[i]);
          const r = i === f.active ? 5 : 2.5;
          ctx.moveTo(x + r, y);
          ctx.arc(x, y, r, 0, 2 * Math.PI);
        }
        ctx.fill();
      }
    };
    const drawn = drawPlane(ctx, f.view, width, height, {
      points: [], samples: this.samples(a), stale: f.stale, show: { ...f.show, polygon: false },
      combScale: f.combScale, region: null, joint: null,
      joints: current ? a.joints.map((j) => j.point) : null,
      lines: null, closed: false, pieces: null, pieceSamples: null, active: null,
      hover: f.hover ? [f.hover.sample.x, f.hover.sample.y] : null,
      underlay, curveWidth: 1.4,
    });
    if (distances) {
      const [x, y] = f.view.toScreen(points[a.worst_point]);
      ctx.strokeStyle = '#333';
      ctx.lineWidth = 1.2;
      ctx.beginPath();
      ctx.arc(x, y, 7, 0, 2 * Math.PI);
      ctx.stroke();
    }
    key(ctx, height, {
      distances: !!distances,
      joints: current && a.joints.length > 0,
      evolute: drawn.evolute === 'visible',
    });
    return drawn;
  },

  /** No control point to keep clear of: the message goes top left. */
  placeMessage: () => {},

  readout(a, add, d) {
    add('points', 'point_count', a.point_count, String(a.point_count));
    add('segments', 'fitted_segments', a.fitted_segments, `${a.fitted_segments} (${a.continuity.toUpperCase()})`);
    const alphas = a.pieces.map((p) => p.alpha);
    // Four digits a slope: three of them fit on the line.
    const short = (x) => fmt(+x.toPrecision(4));
    let alphaText = alphas.length > 3 ? `${short(Math.min(...alphas))} … ${short(Math.max(...alphas))}` : alphas.map(short).join(', ');
    // α at an end of its range: the range, not the points, chose it.
    if (d.free && alphas.some((x) => x === d.alpha_min || x === d.alpha_max)) alphaText += ' (range end)';
    add('α', 'alphas', alphas.join(','), alphaText);
    add('RMS distance', 'rms', a.rms, a.rms.toExponential(2));
    // Against the answer's own tolerance (the slider may have moved on while it was out).
    const within = a.max_distance <= a.tolerance ? '≤' : '>';
    add('largest distance', 'max_distance', a.max_distance, `${a.max_distance.toExponential(2)} ${within} ${fmt(a.tolerance)}`);
    add('farthest point', 'worst_point', a.worst_point, `${a.worst_point} (ringed)`);
    add('arc length', 'arc_length', a.arc_length);
    add('max κ jump', 'max_curvature_jump', a.max_curvature_jump, a.max_curvature_jump.toExponential(2));
  },

  /** κ against s with the joints marked; the graph is each piece's, from the samples. */
  plots(a, where) {
    const plot = a ? { points: a.samples.map((r) => ({ s: r.s, kappa: r.kappa, log_rho: null, log_lcg: null })), fit: null } : null;
    const series = plot ? [{ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label: '' }] : [];
    const vlines = a ? a.joints.map((j) => ({ x: j.s })) : [];
    const { series: graph, cut } = a ? graphOf(a) : { series: [], cut: false };
    const title = a && a.pieces.length > 1 ? 'LCG per segment' : 'logarithmic curvature graph';
    const options = planePlots({ plot, series, graph, vlines, title: cut ? `${title} (cut where κ → 0)` : title }, where);
    options.kplot.empty = where.error ? 'no fit' : options.kplot.empty;
    options.lcg.empty = plot ? 'no segment whose curvature changes' : options.kplot.empty;
    return options;
  },

  /** A text area for the points (pasted or imported, and rewritten whenever they change) and
   * the button that fits them. */
  pointsPanel({ points, apply }) {
    const area = document.createElement('textarea');
    area.id = 'fit-points';
    area.rows = 6;
    area.spellcheck = false;
    area.setAttribute('aria-label', 'points: "x y" one a line, CSV, or a JSON array');
    area.title = 'x y one a line (or x,y; a header line and # comments are skipped), or a JSON array [[x, y], …]';
    const show = (list) => {
      const text = pointsText(list);
      if (document.activeElement !== area && area.value !== text) area.value = text;
    };
    show(points);
    const note = document.createElement('div');
    note.className = 'field-note bad';
    note.id = 'fit-points-note';
    note.hidden = true;
    const use = (reading) => {
      note.hidden = !reading.error;
      if (reading.error) note.textContent = reading.error;
      else if (reading.points.length < 3) {
        note.hidden = false;
        note.textContent = `${reading.points.length} points: a fit needs at least 3`;
      } else apply(reading.points, 'closed' in reading ? { closed: reading.closed } : {});
    };
    const fitButton = document.createElement('button');
    fitButton.type = 'button';
    fitButton.id = 'fit-apply';
    fitButton.textContent = 'Fit these points';
    fitButton.addEventListener('click', () => use(readPoints(area.value)));
    const file = document.createElement('input');
    file.type = 'file';
    file.id = 'fit-import';
    file.accept = '.txt,.csv,.xy,.json,.svg,text/plain,text/csv,image/svg+xml';
    file.addEventListener('change', async () => {
      const chosen = file.files[0];
      if (!chosen) return;
      const text = await chosen.text();
      const svg = /\.svg$/i.test(chosen.name) || /^\s*(<\?xml[^>]*>\s*)?<svg/i.test(text);
      use(svg ? svgPoints(text) : readPoints(text));
      file.value = '';
    });
    const label = document.createElement('label');
    label.className = 'button';
    label.title = 'Points from a file: text, CSV, JSON, or an SVG (its first path: its nodes, and 200 points along its length)';
    label.append('Import points…', file);
    const row = document.createElement('div');
    row.className = 'fit-actions';
    row.append(fitButton, label);
    return { elements: [area, row, note], show };
  },

  svg({ design, answer, combScale, show, title }) {
    return planeSvg({ points: design.points, samples: this.samples(answer), combScale, show: { ...show, polygon: false }, pieces: null, pieceSamples: null, joint: null, title });
  },
};

/** The key, bottom left: a point's colour (its distance as a share of the tolerance), and
 * the marks that are drawn: joints, the farthest point's ring, the evolute. */
function key(ctx, height, { distances, joints, evolute }) {
  const marks = [
    joints && ['joint', (x, y) => {
      ctx.fillStyle = COLORS.joint;
      ctx.beginPath();
      ctx.moveTo(x, y - 5); ctx.lineTo(x + 5, y); ctx.lineTo(x, y + 5); ctx.lineTo(x - 5, y);
      ctx.closePath();
      ctx.fill();
    }],
    distances && ['farthest point', (x, y) => {
      ctx.strokeStyle = '#333';
      ctx.lineWidth = 1.2;
      ctx.beginPath();
      ctx.arc(x, y, 6, 0, 2 * Math.PI);
      ctx.stroke();
    }],
    evolute && ['evolute (centres of curvature)', (x, y) => {
      ctx.strokeStyle = COLORS.evolute;
      ctx.lineWidth = 1.2;
      ctx.setLineDash([5, 3]);
      ctx.beginPath();
      ctx.moveTo(x - 8, y); ctx.lineTo(x + 10, y);
      ctx.stroke();
      ctx.setLineDash([]);
    }],
  ].filter(Boolean);
  if (!distances && !marks.length) return;
  ctx.font = '12px system-ui, sans-serif';
  const x0 = 8;
  const bar = 120;
  const markWidth = marks.reduce((w, [text]) => w + 34 + ctx.measureText(text).width, 0);
  const rows = (distances ? 2 : 0) + (marks.length ? 1 : 0);
  const boxHeight = 8 + 17 * rows;
  const top = height - 8 - boxHeight;
  ctx.fillStyle = 'rgba(255, 255, 255, 0.9)';
  ctx.fillRect(x0, top, Math.max(distances ? 262 : 0, markWidth + 12), boxHeight);
  let y = top + 16;
  if (distances) {
    ctx.fillStyle = '#333';
    ctx.fillText('distance', x0 + 8, y);
    const left = x0 + 70;
    for (let i = 0; i < bar; i++) {
      ctx.fillStyle = rgb(distanceColor((1.1 * i) / bar));
      ctx.fillRect(left + i, y - 10, 1, 12);
    }
    ctx.fillStyle = '#333';
    ctx.textAlign = 'center';
    for (const [share, text] of [[0, '0'], [0.5, '½ tol'], [1, 'tol']]) ctx.fillText(text, left + (share * bar) / 1.1, y + 15);
    ctx.textAlign = 'start';
    ctx.fillText('beyond', left + bar + 6, y);
    y += 34;
  }
  let x = x0 + 14;
  for (const [text, draw] of marks) {
    draw(x, y - 4);
    ctx.fillStyle = '#333';
    ctx.fillText(text, x + 14, y);
    x += 34 + ctx.measureText(text).width;
  }
}
