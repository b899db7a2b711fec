// The update loop. A design is solved by one request at a time: inputs made while it is out
// are folded into the next (the newest design is sent when it answers), so that no stale
// request waits in a queue and answers are drawn in the order of the designs they solve. A
// request that a change makes useless (another mode, a new set of points) is aborted and the
// new one sent at once. An answer becomes the state and is drawn; the probe keeps the
// latencies.

import { post } from './api.js';
import { request } from './design.js';
import { state, probe, mode, design, frame, $ } from './state.js';
import { updateRegion } from './region.js';
import { render, fitView } from './render.js';
import { syncPanel } from './panel.js';

/** Samples of a curve (and points of its curvature plot, at the same arc lengths). */
const SAMPLES = 257;

/** A request out longer than this (ms) says so on the stage. */
const SLOW = 250;

let generation = 0; // the design's: one more at every change solved
let out = null; // the request out: {mode, generation, started, abort, timer}
let queued = false;
let firstEvent = null; // {event, handler}: when the oldest input not yet sent happened

/** A request is out. */
export const busy = () => out !== null;
/** Nothing is out or waiting. */
export const idle = () => out === null && !queued;
/** The generation of the design as it is now. */
export const latest = () => generation;

/**
 * Solve the design as it is now; `eventTime`, when the input that changed it happened. While
 * a request is out this waits for it, unless `supersede` (or another mode) makes it useless:
 * then it is aborted. A design the mode refuses itself (`check`) is not sent.
 */
export function solve(eventTime = performance.now(), { supersede = false } = {}) {
  generation += 1;
  if (firstEvent === null) firstEvent = { event: eventTime, handler: performance.now() };
  const refusal = mode().check(design());
  if (refusal) {
    // What the page knows to be wrong needs no server: said at once, the last good curve kept.
    queued = false;
    firstEvent = null;
    state.error = refusal;
    probe.updates += 1;
    render();
    return;
  }
  if (out && !supersede && out.mode === state.mode) {
    queued = true;
    return;
  }
  if (out) {
    firstEvent = out.started ?? firstEvent;
    stop(out);
    out.abort.abort();
  }
  send();
}

function stop(request) {
  clearTimeout(request.timer);
  $('working').hidden = true;
  if (out === request) out = null;
}

async function send() {
  const mine = {
    mode: state.mode, generation, started: firstEvent, abort: new AbortController(),
    timer: setTimeout(() => { $('working').hidden = false; }, SLOW),
  };
  out = mine;
  queued = false;
  firstEvent = null;
  const body = request(mine.mode, design(), SAMPLES);
  const sent = performance.now();
  const result = await post(mode().endpoint, body, mine.abort.signal);
  // Aborted: a newer request is out in its place.
  if (out !== mine) return;
  stop(mine);
  const answered = performance.now();
  if (mine.mode === state.mode) {
    if (result.ok) {
      state.answer = result.ok;
      // The design may have changed since into one the mode refuses (then the answer is the
      // last good curve, drawn faintly).
      state.error = mode().check(design());
      if (state.drag) keepCombInView();
      else autoCombScale();
      if (state.fitPending) {
        state.fitPending = false;
        fitView();
      }
    } else {
      state.error = result.error;
    }
    state.hover = null;
    if (state.drag) syncPanel();
    updateRegion();
    render();
    const drawn = performance.now();
    probe.drawn.push({ generation: mine.generation, at: drawn });
    if (mine.started !== null) {
      probe.latencies.push(drawn - mine.started.event);
      probe.work.push(drawn - mine.started.handler);
      probe.phases.push([sent - mine.started.handler, answered - sent, drawn - answered]);
      probe.updates += 1;
    }
  }
  if (queued) send();
}

/** While a point is dragged: the comb's scale at the drag's start, or less where the teeth
 * would leave the view (toward a hook, where κ grows without end). */
export function keepCombInView() {
  const start = state.drag.combScale ?? state.combScale;
  state.combScale = Math.min(start, mode().combLimit(frame()));
}

/** Comb teeth at most a fifth of the drawing's size. */
export function autoCombScale() {
  const rows = mode().samples(state.answer);
  if (!rows.length) return;
  const kmax = Math.max(...rows.map((r) => Math.abs(r.kappa)));
  const pts = rows.map((r) => [r.x, r.y, r.z ?? 0]);
  const span = Math.max(...[0, 1, 2].map((i) => Math.max(...pts.map((p) => p[i])) - Math.min(...pts.map((p) => p[i]))));
  state.combScale = kmax > 0 ? (0.15 * span) / kmax : 1;
}
