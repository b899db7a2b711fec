// The drawable region (seed 000 Fig. 9): the mode's map (modes/: `region`), the canonical map of
// the middle point drawn onto the current ends, with the map around it that covers the rest of
// the visible canvas, or (four-point compound curves) the map of the dragged point over the
// view; asked once per key (cached), drawn when it arrives.

import { post } from './api.js';
import { regionImage } from './draw.js';
import { state, probe, mode, frame, regionWanted } from './state.js';
import { render } from './render.js';

const regionCache = new Map();
const pending = new Map();

const regionRequest = () => mode().region(frame());

/** The report of a map request {key, path, body}: cached, asked once while out; null when
 * the server refuses. */
async function report(want) {
  if (regionCache.has(want.key)) return regionCache.get(want.key);
  if (!pending.has(want.key)) {
    pending.set(want.key, post(want.path, want.body).then((result) => {
      pending.delete(want.key);
      if (!result.ok) return null;
      if (regionCache.size > 64) regionCache.clear();
      regionCache.set(want.key, result.ok);
      probe.regionAnswers += 1;
      return result.ok;
    }));
  }
  return pending.get(want.key);
}

const shown = (key, r) => ({ key, image: regionImage(r.drawable), size: r.size, extent: r.extent });

/** Ask for the region the page should shade now (or drop it), and draw it when it comes:
 * the mode's map, then the map around it (`wide`) if any. */
export async function updateRegion() {
  if (!regionWanted()) {
    state.region = null;
    return;
  }
  const want = regionRequest();
  if (!state.region || state.region.key !== want.key) {
    const r = await report(want);
    if (!r || !regionWanted() || regionRequest().key !== want.key) return;
    if (!state.region || state.region.key !== want.key) {
      state.region = { ...shown(want.key, r), canonical: want.canonical, wide: null };
      render();
    }
  }
  if (!want.wide || (state.region.wide && state.region.wide.key === want.wide.key)) return;
  const w = await report(want.wide);
  const now = regionWanted() && regionRequest();
  if (!w || !now || now.key !== want.key || !now.wide || now.wide.key !== want.wide.key) return;
  if (!state.region || state.region.key !== want.key) return;
  state.region.wide = shown(want.wide.key, w);
  render();
}

/** The view moved: a region over the visible plane is out of date. */
export function viewMoved() {
  if (mode().regionInView) state.region = null;
}
