// Drawing the page from the state: the mode's stage (modes/: `draw`), the message, the
// readout and the plots, the undo buttons.

import { linePlot } from './plots.js';
import { fmt } from './format.js';
import { state, undo, probe, $, mode, design, isStale, frame } from './state.js';
import { syncPanel } from './panel.js';
import { commit } from './edit.js';
import { solve } from './loop.js';

export function render() {
  probe.renders += 1;
  renderStage();
  renderMessage();
  renderReadout();
  renderPlots();
  $('undo').disabled = !undo.canUndo;
  $('redo').disabled = !undo.canRedo;
}

/** The drawing alone. */
export function renderStage() {
  const drawn = mode().draw(frame()) || {};
  // The evolute is asked for but lies outside the view: say so beside its box.
  const note = $('evolute-note');
  note.hidden = drawn.evolute !== 'outside';
}

/** Fit the mode's view(s) to the design and its curve. */
export function fitView() {
  mode().fit(frame());
}

const TITLES = {
  not_drawable: 'Not drawable:',
  network: 'No server:',
  timeout: 'Busy:',
  fit_tolerance_not_met: 'Cannot fit:',
  fit_not_closed: 'Cannot fit:',
};

function renderMessage() {
  const box = $('message');
  const fix = $('message-fix');
  const problem = state.error || state.notice;
  box.hidden = !problem;
  fix.hidden = true;
  if (problem) fillMessage(problem);
  // Never over a control point (the mode knows where they are).
  mode().placeMessage(box, frame());
}

function fillMessage(problem) {
  const fix = $('message-fix');
  $('message-title').textContent = problem.title || TITLES[problem.kind] || 'Cannot draw:';
  // The library's messages for undrawable input start with "not drawable: ", as the title does.
  let text = problem.message.replace(/^not drawable: /, '');
  if (state.error && state.answer) text += ' (the last good curve is drawn faintly).';
  $('message-text').textContent = text;
  // The mode's way out of a refusal, as a button.
  const way = state.error && mode().fix(state.error, design());
  if (way) {
    fix.hidden = false;
    fix.textContent = way.label;
    fix.onclick = () => {
      way.apply(design());
      syncPanel();
      commit();
      solve();
    };
  }
}

function renderReadout() {
  const dl = $('readout');
  const rows = [];
  const a = state.answer;
  const add = (label, key, value, text) => rows.push([label, key, value, text ?? fmt(value)]);
  const current = a && !isStale();
  if (current) mode().readout(a, add, design());
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
  const table = current ? mode().table(a, design()) : null;
  if (table) pieces.append(table);
}

function renderPlots() {
  const a = isStale() ? null : state.answer;
  const { kplot, lcg } = mode().plots(a, { hover: state.hover, error: state.error });
  linePlot($('kplot'), kplot);
  linePlot($('lcg'), lcg);
}
