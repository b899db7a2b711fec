// The drawable region (seed 000 Fig. 9): the mode's map (modes/: `region`), the canonical map of
// the middle point drawn onto the current ends, or (four-point compound curves) the map of the
// dragged point; asked once per key (cached), drawn when it arrives.

import { post } from './api.js';
import { regionImage } from './draw.js';
import { state, probe, mode, frame, regionWanted } from './state.js';
import { render } from './render.js';

const regionCache = new Map();

const regionRequest = () => mode().region(frame());

/** Ask for the region the page should shade now (or drop it), and draw it when it comes. */
export async function updateRegion() {
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

/** The view moved: a region over the visible plane is out of date. */
export function viewMoved() {
  if (mode().regionInView) state.region = null;
}
