// A fit: the log-aesthetic path nearest measured points (pasted as "x y" lines, CSV or a JSON
// array, or imported from a file, an SVG path sampled along its length), within a tolerance,
// α fixed or fitted: /api/fit. The points are coloured by their distance to the fit.

import { plane, planePlots } from './plane.js';
import { drawPlane, sizeCanvas } from '../draw.js';
import { planeSvg } from '../export.js';
import { fmt } from '../format.js';

/** The most segments a fit may use. */
const MAX_SEGMENTS = 16;

/** Points taken along an imported SVG path. */
const SVG_SAMPLES = 200;

/** Point colours: within half the tolerance, green; from there to the tolerance through amber
 * to red; beyond it, dark red. */
export const NEAR = [30, 158, 58];
const HALF = [240, 160, 0];
const AT = [217, 48, 37];
const BEYOND = [120, 0, 0];

const mix = (a, b, t) => a.map((x, i) => Math.round(x + (b[i] - x) * t));
const rgb = ([r, g, b]) => `rgb(${r}, ${g}, ${b})`;

/** The colour of a point at `share` of the tolerance from the fit. */
export function distanceColor(share) {
  if (!(share <= 1)) return BEYOND;
  if (share <= 0.5) return NEAR;
  const u = (share - 0.5) / 0.5;
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

/** The points along the first path of an SVG document: SVG_SAMPLES at equal lengths (the
 * browser's own getPointAtLength), y turned up. {points} or {error}. */
export function svgPoints(text) {
  const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
  const source = doc.querySelector('path');
  if (!source || !source.getAttribute('d')) return { error: 'the SVG has no path with a "d"' };
  const ns = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(ns, 'svg');
  svg.style.position = 'absolute';
  svg.style.visibility = 'hidden';
  const path = document.createElementNS(ns, 'path');
  path.setAttribute('d', source.getAttribute('d'));
  svg.append(path);
  document.body.append(svg);
  try {
    const length = path.getTotalLength();
    if (!(length > 0)) return { error: 'the SVG\'s first path has no length' };
    const points = [];
    for (let k = 0; k < SVG_SAMPLES; k++) {
      const p = path.getPointAtLength((length * k) / (SVG_SAMPLES - 1));
      points.push([+p.x.toPrecision(8), +(-p.y).toPrecision(8)]);
    }
    return { points };
  } finally {
    svg.remove();
  }
}

const textOf = (points) => points.map(([x, y]) => `${x} ${y}`).join('\n');

/** The graph ln(ρ ds/dρ) against ln ρ of each piece, from the samples by central differences
 * within the piece (a joint's curvature has no one derivative). */
function graphOf(a) {
  const series = [];
  a.pieces.forEach((piece, k) => {
    // A circular arc (κ constant to rounding) has no graph.
    const [k0, k1] = piece.curvature;
    if (!(Math.abs(k1 - k0) > 1e-6 * Math.max(Math.abs(k0), Math.abs(k1)))) return;
    const rows = a.samples.filter((r) => r.s > piece.s && r.s < piece.s + piece.arc_length);
    const line = [];
    for (let i = 1; i + 1 < rows.length; i++) {
      const rho = (r) => 1 / Math.abs(r.kappa);
      const slope = (rho(rows[i + 1]) - rho(rows[i - 1])) / (rows[i + 1].s - rows[i - 1].s);
      const value = Math.log(rho(rows[i]) / Math.abs(slope));
      if (Number.isFinite(value) && Number.isFinite(Math.log(rho(rows[i])))) line.push([Math.log(rho(rows[i])), value]);
    }
    if (line.length > 1) series.push({ points: line, color: k % 2 ? '#e69138' : '#1f4e9c', width: 2, label: '' });
  });
  return series;
}

export default {
  ...plane,
  name: 'fit',
  label: 'Fit',
  endpoint: '/api/fit',
  count: null,
  minCount: 3,
  pointsLegend: 'Points',
  params: [
    { key: 'tolerance', label: 'tolerance', min: -5, max: 0, step: 0.01, log: true, valid: { above: 0 },
      hint: 'largest distance of a point from the fit (the points\' units): the fewest segments that keep every point within it' },
    { key: 'free', label: 'α free', boolean: true, hint: 'each segment\'s α fitted (in −5 … 10); off: every segment takes α below' },
    { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01, hint: 'every segment\'s α, when not free' },
    { key: 'closed', label: 'closed', boolean: true, hint: 'the points go round once: a closed path' },
  ],
  defaults: { points: spiral(), tolerance: 0.01, free: true, alpha: 1, closed: false },

  fileRank: 35,
  recognises: (json) => 'free' in json || 'rms' in json || 'max_segments' in json,

  /** lac-io's FitInput: α fixed, or fitted in the library's default range. */
  request(body) {
    const input = { points: body.points, tolerance: body.tolerance, max_segments: MAX_SEGMENTS, closed: body.closed, samples: body.samples };
    if (!body.free) input.alpha = body.alpha;
    return input;
  },
  /** The fit's result, which /api/export places again from its segments (lac-io's FitKind):
   * no refit. Its `tolerance`, `samples` and `pieces` would be the export's options. */
  cad(body, answer) {
    const { distances, tolerance, samples, pieces, ...result } = answer;
    return result;
  },

  region: null,

  draw(f) {
    const { ctx, width, height } = sizeCanvas(f.canvas);
    const a = f.answer;
    const drawn = drawPlane(ctx, f.view, width, height, {
      points: [], samples: this.samples(a), stale: f.stale, show: { ...f.show, polygon: false },
      combScale: f.combScale, region: null, joint: null,
      joints: a && !f.stale ? a.joints.map((j) => j.point) : null,
      lines: null, closed: false, pieces: null, pieceSamples: null, active: null,
      hover: f.hover ? [f.hover.sample.x, f.hover.sample.y] : null,
    });
    const points = f.design.points;
    const distances = a && !f.stale && a.distances && a.distances.length === points.length ? a.distances : null;
    points.forEach((p, i) => {
      const [x, y] = f.view.toScreen(p);
      ctx.beginPath();
      ctx.arc(x, y, i === f.active ? 5 : 2.2, 0, 2 * Math.PI);
      ctx.fillStyle = distances ? rgb(distanceColor(distances[i] / f.design.tolerance)) : '#888';
      ctx.fill();
    });
    if (distances) {
      const [x, y] = f.view.toScreen(points[a.worst_point]);
      ctx.strokeStyle = '#333';
      ctx.lineWidth = 1.2;
      ctx.beginPath();
      ctx.arc(x, y, 7, 0, 2 * Math.PI);
      ctx.stroke();
      scale(ctx, height);
    }
    return drawn;
  },

  /** No control point to keep clear of: the message goes top left. */
  placeMessage: () => {},

  readout(a, add, d) {
    add('points', 'point_count', a.point_count, String(a.point_count));
    add('segments', 'fitted_segments', a.fitted_segments, String(a.fitted_segments));
    const alphas = a.pieces.map((p) => p.alpha);
    const alphaText = alphas.length > 3 ? `${fmt(Math.min(...alphas))} … ${fmt(Math.max(...alphas))}` : alphas.map(fmt).join(', ');
    add('α', 'alphas', alphas.join(','), alphaText);
    add('RMS distance', 'rms', a.rms, a.rms.toExponential(2));
    const within = a.max_distance <= d.tolerance ? '≤' : '>';
    add('largest distance', 'max_distance', a.max_distance,
      `${a.max_distance.toExponential(2)} at point ${a.worst_point} (${within} tolerance)`);
    add('arc length', 'arc_length', a.arc_length);
    add('max κ jump', 'max_curvature_jump', a.max_curvature_jump, a.max_curvature_jump.toExponential(2));
  },

  /** κ against s with the joints marked; the graph is each piece's, from the samples. */
  plots(a, where) {
    const plot = a ? { points: a.samples.map((r) => ({ s: r.s, kappa: r.kappa, log_rho: null, log_lcg: null })), fit: null } : null;
    const series = plot ? [{ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label: '' }] : [];
    const vlines = a ? a.joints.map((j) => ({ x: j.s })) : [];
    const graph = a ? graphOf(a) : [];
    const title = a ? `LCG per segment (${a.pieces.length}, from the samples)` : 'logarithmic curvature graph';
    return planePlots({ plot, series, graph, vlines, title }, where);
  },

  /** A text area for the points (pasted or imported) and the button that fits them. */
  pointsPanel({ points, apply }) {
    const area = document.createElement('textarea');
    area.id = 'fit-points';
    area.rows = 6;
    area.spellcheck = false;
    area.value = textOf(points);
    area.setAttribute('aria-label', 'points: "x y" one a line, CSV, or a JSON array');
    area.title = 'x y one a line (or x,y; a header line and # comments are skipped), or a JSON array [[x, y], …]';
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
      } else apply(reading.points);
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
      const reading = svg ? svgPoints(text) : readPoints(text);
      if (reading.points) area.value = textOf(reading.points);
      use(reading);
      file.value = '';
    });
    const label = document.createElement('label');
    label.className = 'button';
    label.title = 'Points from a file: text, CSV, JSON, or an SVG (its first path, sampled along its length)';
    label.append('Import points…', file);
    const row = document.createElement('div');
    row.className = 'fit-actions';
    row.append(fitButton, label);
    return [area, row, note];
  },

  svg({ design, answer, combScale, show, title }) {
    return planeSvg({ points: design.points, samples: this.samples(answer), combScale, show: { ...show, polygon: false }, pieces: null, pieceSamples: null, joint: null, title });
  },
};

/** The colour key, bottom left: a point's distance as a share of the tolerance. */
function scale(ctx, height) {
  ctx.font = '12px system-ui, sans-serif';
  const x0 = 8;
  const y0 = height - 30;
  ctx.fillStyle = 'rgba(255, 255, 255, 0.9)';
  ctx.fillRect(x0, y0 - 12, 220, 34);
  ctx.fillStyle = '#333';
  ctx.fillText('distance:', x0 + 8, y0 + 3);
  const bar = 120;
  const left = x0 + 70;
  for (let i = 0; i < bar; i++) {
    ctx.fillStyle = rgb(distanceColor((1.1 * i) / bar));
    ctx.fillRect(left + i, y0 - 7, 1, 12);
  }
  ctx.fillStyle = '#333';
  ctx.textAlign = 'center';
  for (const [share, text] of [[0, '0'], [0.5, '½ tol'], [1, 'tol']]) ctx.fillText(text, left + (share * bar) / 1.1, y0 + 18);
  ctx.textAlign = 'start';
}
