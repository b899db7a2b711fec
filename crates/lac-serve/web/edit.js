// Changes to the design as a whole: the undo history and the page's link, switching modes,
// loading a design (link or file), and growing or shrinking a path's polygon.

import { clone, toFragment } from './design.js';
import { STAGES } from './modes/index.js';
import { state, view, undo, $, mode, design } from './state.js';
import { buildPanel, syncPanel } from './panel.js';
import { solve } from './loop.js';
import { render, fitView } from './render.js';

let lastFragment = '';

/** Whether `hash` is the link the page wrote last (not one the user typed or followed). */
export const isOwnFragment = (hash) => hash === lastFragment;

export function snapshot() {
  return { mode: state.mode, design: clone(design()) };
}

/** The design as it is now becomes a step of the history and the page's link. */
export function commit() {
  undo.push(snapshot());
  writeFragment();
  $('undo').disabled = !undo.canUndo;
  $('redo').disabled = !undo.canRedo;
}

export function writeFragment() {
  lastFragment = toFragment(state.mode, design(), state.show);
  window.history.replaceState(null, '', lastFragment);
}

/** Go back (or forward) to a snapshot of the history. */
export function restore(snap) {
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

/** Show the current mode: its stage, its panel, a fitted view, a fresh answer. */
export function enterMode() {
  state.answer = null;
  state.error = null;
  state.hover = null;
  state.region = null;
  state.fitPending = true;
  for (const stage of STAGES) $(stage).hidden = stage !== mode().stage;
  buildPanel();
  fitView();
}

export function setMode(name) {
  if (name === state.mode) return;
  state.mode = name;
  state.notice = null;
  enterMode();
  commit();
  solve();
  render();
}

/** The mode's starting design again. */
export function resetMode() {
  state.designs[state.mode] = clone(mode().defaults);
  state.notice = null;
  enterMode();
  commit();
  solve();
  render();
}

/** A design read from a link or a file (design.js: {mode, design, show} or {error}). */
export function applyLoaded(loaded, what) {
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

/** A coordinate to a tenth of a pixel at `scale` pixels per unit: all a drag can mean (fewer
 * digits keep links short). */
export function roundAt(x, scale) {
  const digits = Math.max(0, Math.min(12, Math.ceil(Math.log10(scale * 10))));
  return Number(x.toFixed(digits));
}

export const roundToView = (x) => roundAt(x, view.scale);

/** A path's polygon grows: `point` becomes P`index`. */
export function insertPoint(index, point) {
  design().points.splice(index, 0, point);
  state.selected = index;
  buildPanel();
  commit();
  solve();
  render();
}

/** A path's polygon shrinks (never below its minimum). */
export function removePoint(index) {
  const m = mode();
  const pts = design().points;
  if (m.count || pts.length <= m.minCount) return;
  pts.splice(index, 1);
  state.selected = Math.min(state.selected, pts.length - 1);
  buildPanel();
  commit();
  solve();
  render();
}

/** The point the panel's "Add point" puts after the last: the last leg again, turned as the
 * polygon turned at its last vertex (a point straight ahead would make that vertex collinear:
 * no segment there). */
export function nextPoint(pts) {
  const [o, a, b] = pts.slice(-3);
  const turn = Math.atan2(b[1] - a[1], b[0] - a[0]) - Math.atan2(a[1] - o[1], a[0] - o[0]);
  const angle = Math.atan2(Math.sin(turn), Math.cos(turn)) || 0.5;
  const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
  const [c, sn] = [Math.cos(angle), Math.sin(angle)];
  return [roundToView(b[0] + c * dx - sn * dy), roundToView(b[1] + sn * dx + c * dy)];
}

/** Where a point clicked at world position `p` goes in a path's polygon: after the vertex
 * that starts the nearest leg (the closing leg too when closed). */
export function insertionIndex(p) {
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
