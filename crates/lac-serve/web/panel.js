// The panel: a slider and a number field for every parameter of the mode (greyed out where it
// does not apply), number fields for the points (and, where the polygon grows, buttons to add
// and remove points) or the mode's own points box; the display options the mode has. A field's
// text that the curve cannot use is marked, not used (fields.js).

import { state, $, mode, design } from './state.js';
import { commit, insertPoint, removePoint, nextPoint } from './edit.js';
import { solve } from './loop.js';
import { render, fitView } from './render.js';
import { numberField, fieldNote, showValue } from './fields.js';

/** The points' fieldset of a mode that has its own (modes/: `pointsPanel`): what shows them. */
let showPoints = null;

function paramRow(param) {
  const row = document.createElement('div');
  row.className = 'param';
  row.dataset.row = param.key;
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
      syncPanel();
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
  const field = numberField({
    id: `param-${param.key}`,
    name: param.label,
    range: param.valid,
    step: param.step,
    log: param.log,
    inUse: () => design()[param.key],
    onValue: (value, time) => {
      design()[param.key] = value;
      range.value = String(param.log ? Math.log10(value) : value);
      solve(time);
    },
    onCommit: () => commit(),
  });
  field.dataset.param = param.key;
  range.addEventListener('input', (e) => {
    const v = Number(range.value);
    const value = param.log ? +(10 ** v).toPrecision(3) : v;
    design()[param.key] = value;
    showValue(field, value);
    solve(e.timeStamp);
  });
  range.addEventListener('change', () => commit());
  row.append(range, field, fieldNote(`note-param-${param.key}`, [field]));
  return row;
}

export function buildPanel() {
  const m = mode();
  const params = $('params');
  params.replaceChildren(params.querySelector('legend'), ...m.params.map(paramRow));
  const points = $('points');
  points.querySelector('legend').textContent = m.pointsLegend || 'Control points';
  // The display options this mode has.
  $('show-polygon').parentElement.hidden = !m.controlPolygon;
  $('show-region').parentElement.hidden = !m.region;
  showPoints = null;
  if (m.pointsPanel) {
    const apply = (list, more = {}) => {
      Object.assign(design(), more, { points: list });
      // A fit of other points is no fit of these, and its request is of no use: the new
      // points are shown alone, in view, until their fit comes.
      state.answer = null;
      state.error = null;
      state.fitPending = true;
      fitView();
      syncPanel();
      commit();
      solve(performance.now(), { supersede: true });
      render();
    };
    const { elements, show } = m.pointsPanel({ points: design().points, apply });
    showPoints = show;
    points.replaceChildren(points.querySelector('legend'), ...elements);
    for (const button of $('modes').children) button.setAttribute('aria-pressed', String(button.dataset.mode === state.mode));
    syncPanel();
    return;
  }
  const rows = design().points.map((p, i) => {
    const row = document.createElement('div');
    row.className = 'point';
    row.style.setProperty('--dims', String(m.dims));
    const name = document.createElement('span');
    name.textContent = `P${i}`;
    row.append(name);
    const fields = p.map((_, axis) => {
      const field = numberField({
        ariaLabel: `P${i} ${'xyz'[axis]}`,
        name: `P${i} ${'xyz'[axis]}`,
        inUse: () => design().points[i][axis],
        onValue: (value, time) => {
          design().points[i][axis] = value;
          render();
          solve(time);
        },
        onCommit: () => commit(),
      });
      field.dataset.point = String(i);
      field.dataset.axis = String(axis);
      return field;
    });
    row.append(...fields);
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
    row.append(fieldNote(`note-point-${i}`, fields));
    return row;
  });
  if (!m.count) {
    const add = document.createElement('button');
    add.type = 'button';
    add.id = 'add-point';
    add.textContent = 'Add point';
    add.title = 'Add a point after the last one (or Shift+click the drawing: a point on the nearest leg)';
    add.addEventListener('click', () => insertPoint(design().points.length, nextPoint(design().points)));
    rows.push(add);
  }
  points.replaceChildren(points.querySelector('legend'), ...rows);
  for (const button of $('modes').children) button.setAttribute('aria-pressed', String(button.dataset.mode === state.mode));
  syncPanel();
}

/** Put the design's numbers into the panel (not into the field being typed in). */
export function syncPanel() {
  const d = design();
  const focused = document.activeElement;
  for (const el of document.querySelectorAll('[data-param]')) {
    if (el === focused) continue;
    const value = d[el.dataset.param];
    if (el.type === 'checkbox') el.checked = !!value;
    else if (el.classList.contains('num')) showValue(el, value);
    else el.value = String(value);
  }
  for (const param of mode().params) {
    const range = document.querySelector(`[data-slider="${param.key}"]`);
    if (range && param.bounds) Object.assign(range, param.bounds(d));
    if (range && range !== focused) range.value = String(param.log ? Math.log10(d[param.key]) : d[param.key]);
    if (!param.enabled) continue;
    const row = document.querySelector(`[data-row="${param.key}"]`);
    const on = param.enabled(d);
    row.classList.toggle('off', !on);
    for (const input of row.querySelectorAll('input, select')) input.disabled = !on;
  }
  if (showPoints) showPoints(d.points);
  for (const el of document.querySelectorAll('[data-point]')) {
    if (el === focused) continue;
    showValue(el, d.points[Number(el.dataset.point)][Number(el.dataset.axis)]);
  }
  $('show-comb').checked = state.show.comb;
  $('show-evolute').checked = state.show.evolute;
  $('show-polygon').checked = state.show.polygon;
  $('show-region').value = state.show.region;
}
