// The editor: state, the panel, dragging, the update loop (request, solve, response, redraw),
// the drawable region, undo/redo, the URL fragment, import and export.

import { post, postFile } from './api.js';
import {
  MODES, DEFAULT_SHOW, REGION_CHOICES, defaultDesigns, clone, request,
  toFragment, fromFragment, toFile, fromFile, History,
} from './design.js';
import { View, bounds, similarity } from './view.js';
import { drawPlane, regionImage, geometry } from './draw.js';
import { linePlot } from './plots.js';
import { SpaceViews, combTips } from './space.js';
import { planeSvg, spaceSvg, download, cadRequest } from './export.js';

/** Samples of a curve (and points of its curvature plot, at the same arc lengths). */
const SAMPLES = 257;
/** Pixels per side of the canonical region map, and of one point's region. */
const REGION_SIZE = 200;
const POINT_REGION_SIZE = 80;

const $ = (id) => document.getElementById(id);

const state = {
  mode: 'segment',
  designs: defaultDesigns(),
  show: { ...DEFAULT_SHOW },
  answer: null, // the last good answer in this mode
  error: null, // the latest answer's error, when it failed
  notice: null, // a message of the page's own (a bad link or file)
  drag: null, // {index, pointerId} while a control point is dragged
  pan: null, // {x, y, pointerId} while the view is panned
  selected: 1, // the control point dragged last
  hover: null, // {sample, index} under the pointer
  region: null, // {key, image, size, extent, canonical}
  combScale: 1,
  fitPending: false, // fit the view to the first curve of a mode
};

const view = new View();
const undo = new History();
const regionCache = new Map();
let lastFragment = '';

// For tests and the curious: counts and the drag-update latencies (ms).
const probe = {
  renders: 0,
  updates: 0,
  latencies: [], // input event (its timeStamp) to the end of the redraw of its answer
  work: [], // the page's handler to the end of that redraw: request, solve, response, redraw
  phases: [], // [handler to request sent, request to answer, answer to redrawn]
  regionAnswers: 0,
};

const design = () => state.designs[state.mode];
const isStale = () => state.error !== null;
const canvas = $('plane');

// ---------------------------------------------------------------------------------------
// The update loop: at most one request in flight; inputs meanwhile are folded into the next.

let inFlight = false;
let queued = false;
let firstEvent = null; // {event, handler}: when the oldest input not yet drawn happened

function solve(eventTime = performance.now()) {
  if (firstEvent === null) firstEvent = { event: eventTime, handler: performance.now() };
  if (inFlight) {
    queued = true;
    return;
  }
  send();
}

async function send() {
  inFlight = true;
  const mode = state.mode;
  const body = request(mode, design(), SAMPLES);
  const started = firstEvent;
  firstEvent = null;
  const sent = performance.now();
  const result = await post(MODES[mode].endpoint, body);
  const answered = performance.now();
  inFlight = false;
  if (mode === state.mode) {
    if (result.ok) {
      state.answer = result.ok;
      state.error = null;
      if (!state.drag) autoCombScale();
      if (state.fitPending) {
        state.fitPending = false;
        fitView();
      }
    } else {
      state.error = result.error;
    }
    state.hover = null;
    if (state.drag) syncPanel();
    if (!state.drag) updateRegion();
    render();
    if (started !== null) {
      const drawn = performance.now();
      probe.latencies.push(drawn - started.event);
      probe.work.push(drawn - started.handler);
      probe.phases.push([sent - started.handler, answered - sent, drawn - answered]);
      probe.updates += 1;
    }
  }
  if (queued) {
    queued = false;
    send();
  }
}

/** Comb teeth at most a fifth of the drawing's size. */
function autoCombScale() {
  const rows = samplesOf(state.answer);
  if (!rows.length) return;
  const kmax = Math.max(...rows.map((r) => Math.abs(r.kappa)));
  const pts = rows.map((r) => [r.x, r.y, r.z ?? 0]);
  const span = Math.max(...[0, 1, 2].map((i) => Math.max(...pts.map((p) => p[i])) - Math.min(...pts.map((p) => p[i]))));
  state.combScale = kmax > 0 ? (0.15 * span) / kmax : 1;
}

/** The samples of the exact curve in an answer. */
function samplesOf(answer) {
  if (!answer) return [];
  return (state.mode === 'quasi' ? answer.curve && answer.curve.samples : answer.samples) || [];
}

/** The curvature plot of the exact curve in an answer (a path's: its samples' κ; its
 * graph is one line per segment, `answer.lcg`). */
function plotOf(answer) {
  if (!answer) return null;
  if (state.mode === 'path') {
    return { points: answer.samples.map((r) => ({ s: r.s, kappa: r.kappa, log_rho: null, log_lcg: null })), fit: null };
  }
  return state.mode === 'quasi' ? answer.curve.plot : answer.plot;
}

// ---------------------------------------------------------------------------------------
// The drawable region (seed 000 Fig. 9): the canonical map of the middle point, mapped onto
// the current ends, or (four-point compound curves) the map of the dragged point.

function regionWanted() {
  if (state.mode === 'space' || state.mode === 'path' || state.show.region === 'off') return false;
  // While dragging, always if asked, and whenever the input is not drawable: it shows where
  // to move the point.
  const undrawable = state.error !== null && state.error.kind === 'not_drawable';
  return state.show.region === 'always' || state.drag !== null || undrawable;
}

function regionRequest() {
  const d = design();
  if (state.mode === 'compound4') {
    const index = state.drag ? state.drag.index : state.selected;
    const extent = view.visible(canvas.clientWidth, canvas.clientHeight);
    const others = d.points.map((p, i) => (i === index ? null : p));
    return {
      key: JSON.stringify(['point', index, others, d.alpha0, d.alpha1, extent]),
      path: '/api/region/point',
      body: { curve: { points: d.points, alpha0: d.alpha0, alpha1: d.alpha1 }, index, extent, size: POINT_REGION_SIZE },
      canonical: false,
    };
  }
  const body = state.mode === 'compound'
    ? { alpha: d.alpha0, alpha1: d.alpha1, ratio: d.ratio, size: REGION_SIZE }
    : { alpha: d.alpha, size: REGION_SIZE };
  return { key: JSON.stringify(body), path: '/api/region', body, canonical: true };
}

async function updateRegion() {
  if (!regionWanted()) {
    state.region = null;
    return;
  }
  const want = regionRequest();
  if (state.region && state.region.key === want.key) return;
  let report = regionCache.get(want.key);
  if (!report) {
    const result = await post(want.path, want.body);
    if (!result.ok) return;
    report = result.ok;
    if (regionCache.size > 64) regionCache.clear();
    regionCache.set(want.key, report);
    probe.regionAnswers += 1;
  }
  if (!regionWanted() || regionRequest().key !== want.key) return;
  state.region = {
    key: want.key,
    image: regionImage(report.drawable),
    size: report.size,
    extent: report.extent,
    canonical: want.canonical,
  };
  render();
}

// ---------------------------------------------------------------------------------------
// Drawing

function sizeCanvas(c) {
  const ratio = window.devicePixelRatio || 1;
  const w = c.clientWidth;
  const h = c.clientHeight;
  if (c.width !== Math.round(w * ratio) || c.height !== Math.round(h * ratio)) {
    c.width = Math.round(w * ratio);
    c.height = Math.round(h * ratio);
  }
  const ctx = c.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  return { ctx, width: w, height: h };
}

function render() {
  probe.renders += 1;
  if (state.mode === 'space') renderSpace();
  else renderPlane();
  renderMessage();
  renderReadout();
  renderPlots();
  $('undo').disabled = !undo.canUndo;
  $('redo').disabled = !undo.canRedo;
}

function renderPlane() {
  const { ctx, width, height } = sizeCanvas(canvas);
  const d = design();
  const a = state.answer;
  let region = null;
  if (state.region && regionWanted()) {
    const pts = d.points;
    const index = state.region.canonical ? 1 : (state.drag ? state.drag.index : state.selected);
    region = {
      ...state.region,
      toWorld: state.region.canonical ? similarity(pts[0], pts[pts.length - 1]) : (p) => p,
      label: `Where P${index} may go:`,
    };
  }
  drawPlane(ctx, view, width, height, {
    points: d.points,
    samples: samplesOf(a),
    stale: isStale(),
    show: state.show,
    combScale: state.combScale,
    region,
    joint: a && a.joint ? a.joint : null,
    joints: state.mode === 'path' && a ? a.joints.map((j) => j.point) : null,
    lines: state.mode === 'path' && a ? a.straight_pieces.map((l) => l.points) : null,
    closed: state.mode === 'path' && d.closed,
    pieces: state.mode === 'quasi' && a ? a.pieces : null,
    pieceSamples: state.mode === 'quasi' && a ? a.piece_samples : null,
    active: state.drag ? state.drag.index : null,
    hover: state.hover ? [state.hover.sample.x, state.hover.sample.y] : null,
  });
}

let space = null;

function renderSpace() {
  space.draw({
    points: design().points,
    samples: state.answer ? state.answer.samples : [],
    stale: isStale(),
    show: state.show,
    combScale: state.combScale,
    active: state.drag ? state.drag.index : null,
    hover: state.hover ? state.hover.sample : null,
  });
}

const TITLES = {
  not_drawable: 'Not drawable:',
  network: 'No server:',
  timeout: 'Busy:',
};

function renderMessage() {
  const box = $('message');
  const fix = $('message-fix');
  const problem = state.error || state.notice;
  box.hidden = !problem;
  fix.hidden = true;
  if (!problem) return;
  $('message-title').textContent = problem.title || TITLES[problem.kind] || 'Cannot draw:';
  // The library's messages for undrawable input start with "not drawable: ", as the title does.
  let text = problem.message.replace(/^not drawable: /, '');
  if (state.error && state.answer) text += ' (the last good curve is drawn faintly).';
  $('message-text').textContent = text;
  // Only where the library found a G1 path for this polygon (else the button would lead
  // to another refusal).
  if (state.error && state.error.kind === 'no_g2_path' && state.mode === 'path'
      && Array.isArray(state.error.g1_fractions)) {
    fix.hidden = false;
    fix.textContent = 'Use the G1 path';
    fix.onclick = () => {
      design().g2 = false;
      syncPanel();
      commit();
      solve();
    };
  }
  if (state.error && typeof state.error.omega_max === 'number') {
    const omega = state.error.omega_max;
    fix.hidden = false;
    fix.textContent = `Use Ω = ${+omega.toPrecision(6)}`;
    fix.onclick = () => {
      design().omega = +omega.toPrecision(6);
      syncPanel();
      commit();
      solve();
    };
  }
}

const fmt = (x) => (typeof x === 'number' && Number.isFinite(x) ? String(+x.toPrecision(8)) : '—');
const deg = (rad) => `${fmt((rad * 180) / Math.PI)}°`;

function renderReadout() {
  const dl = $('readout');
  const rows = [];
  const a = state.answer;
  const add = (label, key, value, text) => rows.push([label, key, value, text ?? fmt(value)]);
  if (a && !isStale()) {
    const c = state.mode === 'quasi' ? a.curve : a;
    if (state.mode === 'space') {
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
    } else if (state.mode === 'path') {
      add('arc length', 'arc_length', a.arc_length);
      add('segments', 'segments', a.segments.length, String(a.segments.length));
      add('continuity', 'continuity', a.continuity, a.continuity.toUpperCase());
      add('max κ jump', 'max_curvature_jump', a.max_curvature_jump, a.max_curvature_jump.toExponential(2));
      const lines = a.straight_pieces.length;
      add('inflections', 'inflections', lines, lines ? `${lines} (straight piece${lines > 1 ? 's' : ''} at κ = 0)` : 'none');
      add('κ start', 'curvature_start', a.samples[0].kappa);
      add('κ end', 'curvature_end', a.samples[a.samples.length - 1].kappa);
    } else {
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
      if (state.mode === 'quasi') {
        add('Bézier pieces', 'pieces', a.pieces.length, `${a.pieces.length} ${a.kind}`);
        add('max deviation', 'max', a.max, `${a.max.toExponential(3)} × length`);
        add('rms deviation', 'rms', a.rms, `${a.rms.toExponential(3)} × length`);
        const pfit = a.piece_plot && a.piece_plot.fit;
        if (pfit) add('pieces\' LCG slope', 'piece_fit_alpha', pfit.alpha);
      }
    }
  }
  dl.replaceChildren(...rows.flatMap(([label, key, value, text]) => {
    const dt = document.createElement('dt');
    dt.textContent = label;
    const dd = document.createElement('dd');
    dd.textContent = text;
    dd.dataset.key = key;
    dd.dataset.value = String(value);
    return [dt, dd];
  }));
  const pieces = $('pieces');
  pieces.replaceChildren();
  if (state.mode === 'quasi' && a && !isStale()) {
    const table = document.createElement('table');
    table.innerHTML = '<thead><tr><th>piece</th><th>curvature</th><th>max deviation</th></tr></thead>';
    const body = document.createElement('tbody');
    a.pieces.forEach((p, k) => {
      const tr = document.createElement('tr');
      const good = p.monotone !== 'not_monotone' && p.proven;
      const cells = [
        String(k + 1),
        `${p.monotone.replace('_', ' ')}${p.proven ? ' (proven)' : ' (not proven)'}`,
        p.max_deviation.toExponential(2),
      ];
      cells.forEach((text, i) => {
        const td = document.createElement('td');
        td.textContent = text;
        if (i === 1) td.className = good ? 'good' : 'bad';
        tr.append(td);
      });
      body.append(tr);
    });
    table.append(body);
    const caption = document.createElement('caption');
    caption.textContent = `tolerance ${design().tolerance} × arc length`;
    table.prepend(caption);
    pieces.append(table);
  }
}

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

function renderPlots() {
  const a = isStale() ? null : state.answer;
  const hover = state.hover;
  if (state.mode === 'space') {
    const rows = a ? a.samples : [];
    linePlot($('kplot'), {
      title: 'curvature κ and torsion τ against arc length',
      xlabel: 's', ylabel: 'κ, τ', includeZero: true,
      series: [
        { points: rows.map((r) => [r.s, r.kappa]), color: '#1f4e9c', label: 'κ' },
        { points: rows.map((r) => [r.s, r.tau]), color: '#b3261e', label: 'τ' },
      ],
      marker: hover ? [hover.sample.s, hover.sample.kappa] : null,
      empty: state.error ? 'not drawable' : 'waiting for the server',
    });
    const lcg = a ? a.graphs.curvature.map((p) => [p.x, p.y]) : [];
    const ltg = a ? a.graphs.torsion.map((p) => [p.x, p.y]) : [];
    const bits = [];
    // Slopes to six decimals: the graphs are straight, a slope of 1e-29 is a zero.
    const six = (x) => String(+x.toFixed(6));
    if (lcg.length) bits.push(`LCG slope ${six(slope(lcg))}`);
    if (ltg.length) bits.push(`LTG slope ${six(slope(ltg))}`);
    linePlot($('lcg'), {
      title: bits.join(', ') || 'logarithmic curvature and torsion graphs',
      xlabel: 'ln ρ, ln μ', ylabel: 'ln(ρ ds/dρ), ln(μ ds/dμ)',
      series: [
        { points: lcg, color: '#1f4e9c', label: lcg.length ? 'curvature' : '' },
        { points: ltg, color: '#b3261e', label: ltg.length ? 'torsion' : '' },
      ],
      empty: a ? 'ρ and μ are constant: no graph' : 'not drawable',
    });
    return;
  }
  const plot = plotOf(a);
  const series = [];
  const graph = [];
  const vlines = [];
  if (plot && state.mode === 'path') {
    series.push({ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label: '' });
    for (const j of a.joints) vlines.push({ x: j.s });
    a.lcg.forEach((row, k) => {
      if (!row) return;
      const { alpha, intercept, log_rho: [x0, x1] } = row;
      graph.push({ points: [[x0, alpha * x0 + intercept], [x1, alpha * x1 + intercept]], color: k % 2 ? '#e69138' : '#1f4e9c', width: 2, label: '' });
    });
  } else if (plot) {
    series.push({ points: plot.points.map((p) => [p.s, p.kappa]), color: '#1f4e9c', label: state.mode === 'quasi' ? 'exact curve' : '' });
    graph.push({ points: plot.points.map((p) => [p.log_rho ?? NaN, p.log_lcg ?? NaN]), color: '#1f4e9c', label: state.mode === 'quasi' ? 'exact curve' : '' });
    const line = ({ alpha, intercept, log_rho: [x0, x1] }, label) => ({
      points: [[x0, alpha * x0 + intercept], [x1, alpha * x1 + intercept]],
      color: '#e69138', dash: [5, 3], width: 1.2, label,
    });
    // A compound curve's graph is two straight pieces: their lines, not one fitted across.
    if (a && a.lcg) a.lcg.filter(Boolean).forEach((row, k) => graph.push(line(row, k ? '' : 'pieces\' lines')));
    else if (plot.fit) graph.push(line(plot.fit, ''));
    if (a && a.joint_s !== undefined) vlines.push({ x: a.joint_s });
  }
  if (state.mode === 'quasi' && a) {
    series.push({ points: a.piece_plot.points.map((p) => [p.s, p.kappa]), color: '#0b8043', dash: [4, 3], label: 'Bézier pieces' });
    graph.push({ points: a.piece_plot.points.map((p) => [p.log_rho ?? NaN, p.log_lcg ?? NaN]), color: '#0b8043', dash: [4, 3], label: 'Bézier pieces' });
    let s = 0;
    for (const rows of a.piece_samples.slice(0, -1)) {
      s = rows[rows.length - 1].s;
      vlines.push({ x: s, color: '#0b8043' });
    }
  }
  const hoverRow = hover && plot ? plot.points[hover.index] : null;
  linePlot($('kplot'), {
    title: 'curvature plot: κ against arc length s',
    xlabel: 's', ylabel: 'κ', includeZero: true, series, vlines,
    marker: hoverRow ? [hoverRow.s, hoverRow.kappa] : null,
    empty: state.error ? 'not drawable' : 'waiting for the server',
  });
  const fit = plot && plot.fit;
  let title = 'logarithmic curvature graph';
  if (a && state.mode === 'path') title = `LCG: one line per segment, slopes ${[...new Set(a.segments.map((g) => fmt(g.alpha)))].join(', ')}`;
  else if (a && a.lcg) title = `LCG: slopes ${a.lcg.map((r) => (r ? fmt(r.alpha) : 'circle')).join(' then ')}`;
  else if (fit) title = `logarithmic curvature graph: fitted slope α = ${fmt(fit.alpha)}`;
  linePlot($('lcg'), {
    title,
    xlabel: 'ln ρ', ylabel: 'ln(ρ ds/dρ)', series: graph,
    marker: hoverRow && hoverRow.log_rho !== null ? [hoverRow.log_rho, hoverRow.log_lcg] : null,
    empty: plot ? 'the curvature is constant (circular arcs): no graph' : 'not drawable',
  });
}

// ---------------------------------------------------------------------------------------
// The panel: a slider and a number field for every parameter, number fields for the points.

function paramRow(param) {
  const row = document.createElement('div');
  row.className = 'param';
  row.title = param.hint || '';
  const label = document.createElement('label');
  label.textContent = param.label;
  label.htmlFor = `param-${param.key}`;
  row.append(label);
  if (param.boolean) {
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.id = `param-${param.key}`;
    box.dataset.param = param.key;
    box.addEventListener('change', () => {
      design()[param.key] = box.checked;
      commit();
      solve();
    });
    row.append(box);
    return row;
  }
  if (param.choices) {
    const select = document.createElement('select');
    select.id = `param-${param.key}`;
    select.dataset.param = param.key;
    for (const c of param.choices) select.append(new Option(String(c), String(c)));
    select.addEventListener('change', () => {
      design()[param.key] = Number(select.value);
      commit();
      solve();
    });
    row.append(select);
    return row;
  }
  const range = document.createElement('input');
  range.type = 'range';
  range.min = param.min;
  range.max = param.max;
  range.step = param.step;
  range.dataset.slider = param.key;
  range.setAttribute('aria-label', `${param.label} slider`);
  const field = document.createElement('input');
  field.type = 'number';
  field.step = 'any';
  field.id = `param-${param.key}`;
  field.dataset.param = param.key;
  range.addEventListener('input', (e) => {
    const v = Number(range.value);
    const value = param.log ? +(10 ** v).toPrecision(3) : v;
    design()[param.key] = value;
    field.value = String(value);
    solve(e.timeStamp);
  });
  range.addEventListener('change', () => commit());
  field.addEventListener('input', (e) => {
    if (field.value.trim() === '') return;
    const value = Number(field.value);
    if (!Number.isFinite(value)) return;
    design()[param.key] = value;
    range.value = String(param.log ? Math.log10(value) : value);
    solve(e.timeStamp);
  });
  field.addEventListener('change', () => commit());
  row.append(range, field);
  return row;
}

function buildPanel() {
  const m = MODES[state.mode];
  const params = $('params');
  params.replaceChildren(params.querySelector('legend'), ...m.params.map(paramRow));
  const points = $('points');
  const rows = design().points.map((p, i) => {
    const row = document.createElement('div');
    row.className = 'point';
    row.style.setProperty('--dims', String(m.dims));
    const name = document.createElement('span');
    name.textContent = `P${i}`;
    row.append(name);
    p.forEach((_, axis) => {
      const field = document.createElement('input');
      field.type = 'number';
      field.step = 'any';
      field.dataset.point = String(i);
      field.dataset.axis = String(axis);
      field.setAttribute('aria-label', `P${i} ${'xyz'[axis]}`);
      field.addEventListener('input', (e) => {
        if (field.value.trim() === '') return;
        const value = Number(field.value);
        if (!Number.isFinite(value)) return;
        design().points[i][axis] = value;
        render();
        solve(e.timeStamp);
      });
      field.addEventListener('change', () => commit());
      row.append(field);
    });
    if (!m.count) {
      const remove = document.createElement('button');
      remove.type = 'button';
      remove.className = 'remove';
      remove.textContent = '×';
      remove.title = `Remove P${i} (Alt+click it on the drawing)`;
      remove.setAttribute('aria-label', `remove P${i}`);
      remove.disabled = design().points.length <= m.minCount;
      remove.addEventListener('click', () => removePoint(i));
      row.append(remove);
    }
    return row;
  });
  if (!m.count) {
    const add = document.createElement('button');
    add.type = 'button';
    add.id = 'add-point';
    add.textContent = 'Add point';
    add.title = 'Add a point after the last one (or Shift+click the drawing: a point on the nearest leg)';
    add.addEventListener('click', () => {
      // The last leg again, turned as the polygon turned at its last vertex (a point
      // straight ahead would make that vertex collinear: no segment there).
      const pts = design().points;
      const [o, a, b] = pts.slice(-3);
      const turn = Math.atan2(b[1] - a[1], b[0] - a[0]) - Math.atan2(a[1] - o[1], a[0] - o[0]);
      const angle = Math.atan2(Math.sin(turn), Math.cos(turn)) || 0.5;
      const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
      const [c, sn] = [Math.cos(angle), Math.sin(angle)];
      insertPoint(pts.length, [roundToView(b[0] + c * dx - sn * dy), roundToView(b[1] + sn * dx + c * dy)]);
    });
    rows.push(add);
  }
  points.replaceChildren(points.querySelector('legend'), ...rows);
  for (const button of $('modes').children) button.setAttribute('aria-pressed', String(button.dataset.mode === state.mode));
  $('plane').hidden = state.mode === 'space';
  $('space').hidden = state.mode !== 'space';
  syncPanel();
}

/** Put the design's numbers into the panel (not into the field being typed in). */
function syncPanel() {
  const d = design();
  const focused = document.activeElement;
  for (const el of document.querySelectorAll('[data-param]')) {
    if (el === focused) continue;
    const value = d[el.dataset.param];
    if (el.type === 'checkbox') el.checked = !!value;
    else el.value = String(value);
  }
  for (const param of MODES[state.mode].params) {
    const range = document.querySelector(`[data-slider="${param.key}"]`);
    if (range && range !== focused) range.value = String(param.log ? Math.log10(d[param.key]) : d[param.key]);
  }
  for (const el of document.querySelectorAll('[data-point]')) {
    if (el === focused) continue;
    el.value = String(d.points[Number(el.dataset.point)][Number(el.dataset.axis)]);
  }
  $('show-comb').checked = state.show.comb;
  $('show-evolute').checked = state.show.evolute;
  $('show-polygon').checked = state.show.polygon;
  $('show-region').value = state.show.region;
}

// ---------------------------------------------------------------------------------------
// History, the URL fragment, modes

function snapshot() {
  return { mode: state.mode, design: clone(design()) };
}

/** The design as it is now becomes a step of the history and the page's link. */
function commit() {
  undo.push(snapshot());
  writeFragment();
  $('undo').disabled = !undo.canUndo;
  $('redo').disabled = !undo.canRedo;
}

function writeFragment() {
  lastFragment = toFragment(state.mode, design(), state.show);
  window.history.replaceState(null, '', lastFragment);
}

function restore(snap) {
  if (!snap) return;
  const modeChanged = snap.mode !== state.mode;
  state.mode = snap.mode;
  state.designs[snap.mode] = clone(snap.design);
  if (modeChanged) enterMode();
  else syncPanel();
  writeFragment();
  state.region = null;
  solve();
  render();
}

/** Show the current mode: its panel, a fitted view, a fresh answer. */
function enterMode() {
  state.answer = null;
  state.error = null;
  state.hover = null;
  state.region = null;
  state.fitPending = true;
  buildPanel();
  fitView();
}

/** A path's polygon grows: `point` becomes P`index`. */
function insertPoint(index, point) {
  design().points.splice(index, 0, point);
  state.selected = index;
  buildPanel();
  commit();
  solve();
  render();
}

/** A path's polygon shrinks (never below its minimum). */
function removePoint(index) {
  const m = MODES[state.mode];
  const pts = design().points;
  if (m.count || pts.length <= m.minCount) return;
  pts.splice(index, 1);
  state.selected = Math.min(state.selected, pts.length - 1);
  buildPanel();
  commit();
  solve();
  render();
}

/** Where a point clicked at world position `p` goes in a path's polygon: after the vertex
 * that starts the nearest leg (the closing leg too when closed). */
function insertionIndex(p) {
  const pts = design().points;
  const legs = design().closed ? pts.length : pts.length - 1;
  let best = pts.length;
  let bestDistance = Infinity;
  for (let i = 0; i < legs; i++) {
    const a = pts[i];
    const b = pts[(i + 1) % pts.length];
    const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
    const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy || 1)));
    const d = Math.hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
    if (d < bestDistance) {
      bestDistance = d;
      best = i + 1;
    }
  }
  // Beyond an open polygon's ends: a new first or last point.
  if (!design().closed) {
    const dFirst = Math.hypot(pts[0][0] - p[0], pts[0][1] - p[1]);
    const dLast = Math.hypot(pts[pts.length - 1][0] - p[0], pts[pts.length - 1][1] - p[1]);
    if (best === 1 && dFirst <= bestDistance + 1e-12) return 0;
    if (best === pts.length - 1 && dLast <= bestDistance + 1e-12) return pts.length;
  }
  return best;
}

function fitView() {
  const d = design();
  if (state.mode === 'space') {
    const rows = state.answer ? state.answer.samples : [];
    const tips = state.show.comb ? combTips(rows, state.combScale) : [];
    space.fit([...d.points, ...rows.map((r) => [r.x, r.y, r.z]), ...tips]);
    return;
  }
  const rows = samplesOf(state.answer);
  const tips = state.show.comb ? geometry(rows, state.combScale, Infinity).teeth.map(([, q]) => q) : [];
  view.fit(bounds([...d.points, ...rows.map((r) => [r.x, r.y]), ...tips]), canvas.clientWidth, canvas.clientHeight);
}

function setMode(mode) {
  if (mode === state.mode) return;
  state.mode = mode;
  state.notice = null;
  enterMode();
  commit();
  solve();
  render();
}

function applyLoaded(loaded, what) {
  if (!loaded) return;
  if (loaded.error) {
    state.notice = { title: `Cannot read the ${what}:`, message: loaded.error };
    render();
    return;
  }
  state.notice = null;
  state.mode = loaded.mode;
  state.designs[loaded.mode] = loaded.design;
  if (loaded.show) state.show = loaded.show;
  enterMode();
  commit();
  solve();
  render();
}

// ---------------------------------------------------------------------------------------
// Pointer input on the plane

function roundToView(x) {
  // A tenth of a pixel is all a drag can mean; fewer digits keep links short.
  const digits = Math.max(0, Math.min(12, Math.ceil(Math.log10(view.scale * 10))));
  return Number(x.toFixed(digits));
}

function hit(sx, sy, radius) {
  let best = null;
  let bestDistance = radius;
  design().points.forEach((p, i) => {
    const [x, y] = view.toScreen(p);
    const d = Math.hypot(x - sx, y - sy);
    if (d <= bestDistance) {
      best = i;
      bestDistance = d;
    }
  });
  return best;
}

function nearestSample(sx, sy) {
  if (isStale()) return null;
  const rows = samplesOf(state.answer);
  let best = null;
  let bestDistance = 16;
  rows.forEach((r, index) => {
    const [x, y] = view.toScreen([r.x, r.y]);
    const d = Math.hypot(x - sx, y - sy);
    if (d < bestDistance) {
      best = { sample: r, index };
      bestDistance = d;
    }
  });
  return best;
}

function showHover(found, clientX, clientY) {
  const box = $('hover');
  state.hover = found;
  if (!found) {
    box.hidden = true;
    return;
  }
  const r = found.sample;
  const rho = r.kappa === 0 ? Infinity : 1 / Math.abs(r.kappa);
  const lines = [`s = ${fmt(r.s)}`, `κ = ${fmt(r.kappa)}`, `ρ = ${fmt(rho)}`];
  if (r.tau !== undefined) lines.push(`τ = ${fmt(r.tau)}`);
  box.textContent = lines.join('\n');
  box.hidden = false;
  const stage = $('stage').getBoundingClientRect();
  box.style.left = `${Math.min(clientX - stage.left + 14, stage.width - 150)}px`;
  box.style.top = `${Math.min(clientY - stage.top + 14, stage.height - 70)}px`;
}

canvas.addEventListener('pointerdown', (e) => {
  canvas.setPointerCapture(e.pointerId);
  const index = hit(e.offsetX, e.offsetY, e.pointerType === 'touch' ? 24 : 12);
  if (!MODES[state.mode].count) {
    // A path: Alt+click removes a point, Shift+click adds one on the nearest leg.
    if (index !== null && e.altKey) {
      removePoint(index);
      e.preventDefault();
      return;
    }
    if (index === null && e.shiftKey) {
      const [x, y] = view.toWorld([e.offsetX, e.offsetY]);
      const p = [roundToView(x), roundToView(y)];
      const at = insertionIndex(p);
      insertPoint(at, p);
      state.drag = { index: at, pointerId: e.pointerId };
      e.preventDefault();
      return;
    }
  }
  if (index !== null) {
    state.drag = { index, pointerId: e.pointerId };
    state.selected = index;
    showHover(null);
    updateRegion();
    render();
  } else {
    state.pan = { x: e.clientX, y: e.clientY, pointerId: e.pointerId };
    canvas.classList.add('grab');
  }
  e.preventDefault();
});

canvas.addEventListener('pointermove', (e) => {
  if (state.drag && state.drag.pointerId === e.pointerId) {
    const [x, y] = view.toWorld([e.offsetX, e.offsetY]);
    design().points[state.drag.index] = [roundToView(x), roundToView(y)];
    // The request goes first; the point is drawn with its answer, or now when an earlier
    // request is still out (then this move waits for it).
    const waiting = inFlight;
    solve(e.timeStamp);
    if (waiting) {
      syncPanel();
      render();
    }
    return;
  }
  if (state.pan && state.pan.pointerId === e.pointerId) {
    view.pan(e.clientX - state.pan.x, e.clientY - state.pan.y);
    state.pan.x = e.clientX;
    state.pan.y = e.clientY;
    render();
    return;
  }
  showHover(nearestSample(e.offsetX, e.offsetY), e.clientX, e.clientY);
  render();
});

function endPointer(e) {
  if (state.drag && state.drag.pointerId === e.pointerId) {
    state.drag = null;
    commit();
    if (!inFlight) autoCombScale();
    updateRegion();
    render();
  }
  if (state.pan && state.pan.pointerId === e.pointerId) {
    state.pan = null;
    canvas.classList.remove('grab');
    if (state.show.region === 'always' && state.mode === 'compound4') updateRegion();
  }
}
canvas.addEventListener('pointerup', endPointer);
canvas.addEventListener('pointercancel', endPointer);
canvas.addEventListener('pointerleave', () => {
  if (state.hover) {
    showHover(null);
    render();
  }
});
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  view.zoomAt([e.offsetX, e.offsetY], Math.exp(-e.deltaY * 0.0015));
  state.region = state.mode === 'compound4' ? null : state.region;
  updateRegion();
  render();
}, { passive: false });
canvas.addEventListener('dblclick', () => {
  fitView();
  render();
});

// ---------------------------------------------------------------------------------------
// Buttons, keys, links, files

function toast(text) {
  const t = $('toast');
  t.textContent = text;
  t.hidden = false;
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => { t.hidden = true; }, 1800);
}

function exportTitle() {
  const d = design();
  const params = MODES[state.mode].params.map((p) => `${p.key} ${d[p.key]}`).join(', ');
  return `lac editor, ${MODES[state.mode].label}: points ${JSON.stringify(d.points)}, ${params}`;
}

function wire() {
  for (const [mode, m] of Object.entries(MODES)) {
    const button = document.createElement('button');
    button.type = 'button';
    button.textContent = m.label;
    button.dataset.mode = mode;
    button.addEventListener('click', () => setMode(mode));
    $('modes').append(button);
  }
  $('undo').addEventListener('click', () => restore(undo.undo()));
  $('redo').addEventListener('click', () => restore(undo.redo()));
  $('reset').addEventListener('click', () => {
    state.designs[state.mode] = clone(MODES[state.mode].defaults);
    state.notice = null;
    enterMode();
    commit();
    solve();
    render();
  });
  $('share').addEventListener('click', async () => {
    writeFragment();
    const link = window.location.href;
    try {
      await navigator.clipboard.writeText(link);
      toast('Link copied: it reproduces this design exactly');
    } catch {
      toast('The address bar holds the link to this design');
    }
  });
  $('export-svg').addEventListener('click', () => {
    const a = state.answer;
    if (!a) return toast('Nothing drawn yet');
    const d = design();
    const svg = state.mode === 'space'
      ? spaceSvg({ points: d.points, samples: a.samples, title: exportTitle() })
      : planeSvg({
        points: d.points, samples: samplesOf(a), combScale: state.combScale, show: state.show,
        pieces: state.mode === 'quasi' ? a.pieces : null,
        pieceSamples: state.mode === 'quasi' ? a.piece_samples : null,
        joint: a.joint || null, title: exportTitle(),
      });
    download(`lac-${state.mode}.svg`, svg, 'image/svg+xml');
  });
  $('export-json').addEventListener('click', () => {
    const report = isStale() ? null : state.answer;
    download(`lac-${state.mode}.json`, toFile(state.mode, design(), report), 'application/json');
  });
  $('export-cad').addEventListener('change', async (e) => {
    const format = e.target.value;
    e.target.value = '';
    if (!format) return;
    if (isStale()) return toast('Fix the curve first: this design has no curve to export');
    const result = await postFile('/api/export', cadRequest(state.mode, design(), format));
    if (result.error) return toast(`Export failed: ${result.error.message}`);
    const { text, type, name, report } = result.ok;
    download(name, text, type);
    if (report) {
      toast(`${format.toUpperCase()}: ${report.pieces} pieces, deviation ${report.max_deviation.toExponential(1)} (≤ ${report.tolerance.toExponential(0)})`);
    }
  });
  $('import').addEventListener('change', async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    const text = await file.text();
    e.target.value = '';
    applyLoaded(fromFile(text), 'file');
  });
  for (const key of ['comb', 'evolute', 'polygon']) {
    $(`show-${key}`).addEventListener('change', (e) => {
      state.show[key] = e.target.checked;
      writeFragment();
      render();
    });
  }
  $('show-region').addEventListener('change', (e) => {
    state.show.region = REGION_CHOICES.includes(e.target.value) ? e.target.value : 'drag';
    writeFragment();
    state.region = null;
    updateRegion();
    render();
  });
  window.addEventListener('keydown', (e) => {
    if (!(e.ctrlKey || e.metaKey) || e.target.tagName === 'INPUT') return;
    const key = e.key.toLowerCase();
    if (key === 'z' && !e.shiftKey) restore(undo.undo());
    else if ((key === 'z' && e.shiftKey) || key === 'y') restore(undo.redo());
    else return;
    e.preventDefault();
  });
  window.addEventListener('hashchange', () => {
    if (window.location.hash === lastFragment) return;
    applyLoaded(fromFragment(window.location.hash), 'link');
  });
  let resizeTimer = null;
  window.addEventListener('resize', () => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => {
      fitView();
      state.region = state.mode === 'compound4' ? null : state.region;
      updateRegion();
      render();
    }, 60);
  });
  space = new SpaceViews({
    '3d': $('view-3d'), top: $('view-top'), front: $('view-front'), side: $('view-side'),
  }, {
    drag(index, point, time, scale) {
      if (!state.drag) {
        state.drag = { index, pointerId: null };
        state.selected = index;
      }
      if (point) {
        const digits = Math.max(0, Math.min(12, Math.ceil(Math.log10(scale * 10))));
        design().points[index] = point.map((x) => Number(x.toFixed(digits)));
        const waiting = inFlight;
        solve(time);
        if (!waiting) return;
        syncPanel();
      }
      render();
    },
    dragEnd() {
      state.drag = null;
      commit();
      autoCombScale();
      render();
    },
    hover(sample, clientX, clientY) {
      showHover(sample ? { sample, index: -1 } : null, clientX, clientY);
      renderSpace();
    },
  });
}

// For tests: the state, the probe, and where a control point is on screen.
window.lacEditor = {
  probe,
  state: () => ({ mode: state.mode, design: clone(design()), answer: state.answer, error: state.error, stale: isStale(), region: state.region ? { key: state.region.key, size: state.region.size } : null }),
  screenOf(index, viewName) {
    if (state.mode === 'space') {
      const [x, y] = space.screenOf(viewName || 'top', index);
      const r = $(`view-${viewName || 'top'}`).getBoundingClientRect();
      return [r.left + x, r.top + y];
    }
    const [x, y] = view.toScreen(design().points[index]);
    const r = canvas.getBoundingClientRect();
    return [r.left + x, r.top + y];
  },
  idle: () => !inFlight && !queued,
};

wire();
const loaded = fromFragment(window.location.hash);
if (loaded && !loaded.error) {
  state.mode = loaded.mode;
  state.designs[loaded.mode] = loaded.design;
  if (loaded.show) state.show = loaded.show;
} else if (loaded && loaded.error) {
  state.notice = { title: 'Cannot read the link:', message: loaded.error };
}
enterMode();
undo.push(snapshot());
writeFragment();
solve();
render();
