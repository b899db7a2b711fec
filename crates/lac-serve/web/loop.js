// The update loop: at most one request in flight; inputs meanwhile are folded into the next.
// An answer becomes the state and is drawn; the probe keeps the latencies.

import { post } from './api.js';
import { request } from './design.js';
import { state, probe, mode, design, frame } from './state.js';
import { updateRegion } from './region.js';
import { render, fitView } from './render.js';
import { syncPanel } from './panel.js';

/** Samples of a curve (and points of its curvature plot, at the same arc lengths). */
const SAMPLES = 257;

let inFlight = false;
let queued = false;
let firstEvent = null; // {event, handler}: when the oldest input not yet drawn happened

/** A request is out. */
export const busy = () => inFlight;
/** Nothing is out or waiting. */
export const idle = () => !inFlight && !queued;

/** Solve the design as it is now; `eventTime`, when the input that changed it happened. */
export function solve(eventTime = performance.now()) {
  if (firstEvent === null) firstEvent = { event: eventTime, handler: performance.now() };
  if (inFlight) {
    queued = true;
    return;
  }
  send();
}

async function send() {
  inFlight = true;
  const name = state.mode;
  const body = request(name, design(), SAMPLES);
  const started = firstEvent;
  firstEvent = null;
  const sent = performance.now();
  const result = await post(mode().endpoint, body);
  const answered = performance.now();
  inFlight = false;
  if (name === state.mode) {
    if (result.ok) {
      state.answer = result.ok;
      state.error = null;
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
