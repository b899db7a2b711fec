// The editor: starts the page. What it is made of:
//   modes/      one module per curve kind (modes/index.js: the table and what a mode says)
//   state.js    the state, the plane's view, the history, the frame a mode draws from
//   loop.js     the update loop: request, answer, redraw
//   region.js   the drawable region
//   render.js   drawing the page from the state
//   panel.js    the parameters' and points' fields
//   edit.js     history and link, modes, loading, a path's points
//   input.js    pointer input
//   actions.js  the header's buttons, keys, links, resizing
// and the helpers they share: api.js, design.js, view.js, draw.js, plots.js, space.js,
// export.js, format.js, points.js. Only this module does something when loaded.

import { fromFragment, clone } from './design.js';
import { MODES } from './modes/index.js';
import { state, undo, probe, mode, design, isStale, frame } from './state.js';
import { idle, solve, latest } from './loop.js';
import { render } from './render.js';
import { enterMode, snapshot, writeFragment } from './edit.js';
import { listen, stageInput } from './input.js';
import { wire } from './actions.js';

wire();
listen();
for (const m of Object.values(MODES)) m.init(stageInput);

// For tests: the state, the probe, the design's generation, and where a control point is on
// screen.
window.lacEditor = {
  probe,
  generation: latest,
  state: () => ({ mode: state.mode, design: clone(design()), answer: state.answer, error: state.error, stale: isStale(), region: state.region ? { key: state.region.key, size: state.region.size } : null }),
  screenOf: (index, viewName) => mode().screenOf(frame(), index, viewName),
  idle,
};

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
