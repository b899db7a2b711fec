// The header's buttons (modes, undo, redo, reset, link, exports, import), the display
// options, the keys, the link followed and the window resized.

import { postFile } from './api.js';
import { REGION_CHOICES, toFile, fromFile, fromFragment } from './design.js';
import { MODES } from './modes/index.js';
import { download, cadRequest } from './export.js';
import { state, undo, $, mode, design, isStale } from './state.js';
import { restore, setMode, resetMode, applyLoaded, writeFragment, isOwnFragment } from './edit.js';
import { updateRegion, viewMoved } from './region.js';
import { render, fitView } from './render.js';

function toast(text) {
  const t = $('toast');
  t.textContent = text;
  t.hidden = false;
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => { t.hidden = true; }, 1800);
}

/** The numbers that made an exported drawing, for its comment. */
function exportTitle() {
  const d = design();
  const params = mode().params.map((p) => `${p.key} ${d[p.key]}`).join(', ');
  return `lac editor, ${mode().label}: points ${JSON.stringify(d.points)}, ${params}`;
}

export function wire() {
  for (const [name, m] of Object.entries(MODES)) {
    const button = document.createElement('button');
    button.type = 'button';
    button.textContent = m.label;
    button.dataset.mode = name;
    button.addEventListener('click', () => setMode(name));
    $('modes').append(button);
  }
  $('undo').addEventListener('click', () => restore(undo.undo()));
  $('redo').addEventListener('click', () => restore(undo.redo()));
  $('reset').addEventListener('click', resetMode);
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
    const svg = mode().svg({ design: design(), answer: a, combScale: state.combScale, show: state.show, title: exportTitle() });
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
    const result = await postFile('/api/export', cadRequest(mode(), design(), format, state.answer));
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
    if (isOwnFragment(window.location.hash)) return;
    applyLoaded(fromFragment(window.location.hash), 'link');
  });
  let resizeTimer = null;
  window.addEventListener('resize', () => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => {
      fitView();
      viewMoved();
      updateRegion();
      render();
    }, 60);
  });
}
