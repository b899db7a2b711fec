// The editor's state: the current mode and every mode's design, the last answer, what is being
// dragged or hovered, the drawable region, the plane's view, the undo history; and the frame,
// what a mode draws from.

import { defaultDesigns, DEFAULT_SHOW, History } from './design.js';
import { View } from './view.js';
import { MODES } from './modes/index.js';

export const $ = (id) => document.getElementById(id);

export const state = {
  mode: 'segment',
  designs: defaultDesigns(),
  show: { ...DEFAULT_SHOW },
  answer: null, // the last good answer in this mode
  error: null, // the latest answer's error, when it failed
  notice: null, // a message of the page's own (a bad link or file)
  drag: null, // {index, pointerId, combScale: the comb's scale when it started} while a control point is dragged
  pan: null, // {x, y, pointerId} while the view is panned
  selected: 1, // the control point dragged last
  hover: null, // {sample, index} under the pointer
  region: null, // {key, image, size, extent, canonical}
  combScale: 1,
  fitPending: false, // fit the view to the first curve of a mode
};

/** The plane's view and canvas. */
export const view = new View();
export const canvas = $('plane');

export const undo = new History();

// For tests and the curious: counts and the drag-update latencies (ms).
export const probe = {
  renders: 0,
  updates: 0,
  latencies: [], // input event (its timeStamp) to the end of the redraw of its answer
  work: [], // the page's handler to the end of that redraw: request, solve, response, redraw
  phases: [], // [handler to request sent, request to answer, answer to redrawn]
  drawn: [], // {generation, at}: each answer drawn, the design's generation (loop.js) and when
  regionAnswers: 0,
};

/** The current mode (modes/) and its design. */
export const mode = () => MODES[state.mode];
export const design = () => state.designs[state.mode];
export const isStale = () => state.error !== null;

/** Whether the drawable region is shown now (seed 000 Fig. 9): in a mode that has one, when
 * asked always, while dragging, and whenever the input is not drawable (it shows where to move
 * the point). */
export function regionWanted() {
  if (!mode().region || state.show.region === 'off') return false;
  const undrawable = state.error !== null && state.error.kind === 'not_drawable';
  return state.show.region === 'always' || state.drag !== null || undrawable;
}

/** What a mode draws from: the design, the last good answer (`stale` when the latest input
 * failed), the display options, the dragged (`active`) or last dragged (`selected`) point, the
 * hovered sample, the region to shade, and the plane's view and canvas. */
export function frame() {
  return {
    design: design(),
    answer: state.answer,
    stale: isStale(),
    show: state.show,
    combScale: state.combScale,
    active: state.drag ? state.drag.index : null,
    selected: state.drag ? state.drag.index : state.selected,
    hover: state.hover,
    region: state.region && regionWanted() ? state.region : null,
    view,
    canvas,
  };
}
