// Pointer input: on the plane canvas (drag a point, pan, zoom, hover the curve; in a path,
// Shift+click adds a point and Alt+click removes one; a right click on a point opens its menu
// in a mode that has one, as the context-menu key or Shift+F10 does for the selected point),
// and the reports of a mode's own views (modes/: `init`), which drag points and hover samples
// there.

import { state, view, canvas, $, mode, design, isStale } from './state.js';
import { fmt } from './format.js';
import { commit, insertPoint, removePoint, insertionIndex, roundAt, roundToView } from './edit.js';
import { solve, busy, autoCombScale } from './loop.js';
import { updateRegion, viewMoved } from './region.js';
import { render, renderStage, fitView } from './render.js';
import { syncPanel } from './panel.js';
import { openMenu } from './menu.js';

function hit(sx, sy, radius) {
  let best = null;
  let bestDistance = radius;
  design().points.forEach((p, i) => {
    const [x, y] = view.toScreen(p);
    const d = Math.hypot(x - sx, y - sy);
    if (d <= bestDistance) {
      best = i;
      bestDistance = d;
    }
  });
  return best;
}

function nearestSample(sx, sy) {
  if (isStale()) return null;
  const rows = mode().samples(state.answer);
  let best = null;
  let bestDistance = 16;
  rows.forEach((r, index) => {
    const [x, y] = view.toScreen([r.x, r.y]);
    const d = Math.hypot(x - sx, y - sy);
    if (d < bestDistance) {
      best = { sample: r, index };
      bestDistance = d;
    }
  });
  return best;
}

/** The hovered sample's numbers beside the pointer (or none). */
function showHover(found, clientX, clientY) {
  const box = $('hover');
  state.hover = found;
  if (!found) {
    box.hidden = true;
    return;
  }
  const r = found.sample;
  const rho = r.kappa === 0 ? Infinity : 1 / Math.abs(r.kappa);
  const lines = [`s = ${fmt(r.s)}`, `κ = ${fmt(r.kappa)}`, `ρ = ${fmt(rho)}`];
  if (r.tau !== undefined) lines.push(`τ = ${fmt(r.tau)}`);
  box.textContent = lines.join('\n');
  box.hidden = false;
  const stage = $('stage').getBoundingClientRect();
  box.style.left = `${Math.min(clientX - stage.left + 14, stage.width - 150)}px`;
  box.style.top = `${Math.min(clientY - stage.top + 14, stage.height - 70)}px`;
}

function endPointer(e) {
  if (state.drag && state.drag.pointerId === e.pointerId) {
    state.drag = null;
    // The panel shows the points where the drag left them (its last answer may be out still).
    syncPanel();
    commit();
    if (!busy()) autoCombScale();
    updateRegion();
    render();
  }
  if (state.pan && state.pan.pointerId === e.pointerId) {
    state.pan = null;
    canvas.classList.remove('grab');
    if (state.show.region === 'always') updateRegion();
  }
}

/** Open the menu of control point `index` (modes/: `menu`) at client position (`x`, `y`);
 * whether the mode has one. The point becomes the selected one. */
function pointMenu(index, x, y) {
  const menu = mode().menu(design(), index);
  if (!menu) return false;
  state.selected = index;
  render();
  openMenu(menu, x, y, (item) => stageInput.change(state.mode, (d) => item.apply(d, index)));
  return true;
}

/** Listen to the plane canvas. */
export function listen() {
  canvas.addEventListener('contextmenu', (e) => {
    const index = hit(e.offsetX, e.offsetY, 12);
    // Elsewhere than on a point: the browser's own menu.
    if (index !== null && pointMenu(index, e.clientX, e.clientY)) e.preventDefault();
  });
  window.addEventListener('keydown', (e) => {
    const asked = e.key === 'ContextMenu' || (e.key === 'F10' && e.shiftKey);
    if (!asked || e.target.tagName === 'INPUT' || mode().stage !== 'plane') return;
    const p = design().points[state.selected];
    if (!p) return;
    const [sx, sy] = view.toScreen(p);
    const box = canvas.getBoundingClientRect();
    if (pointMenu(state.selected, box.left + sx, box.top + sy)) e.preventDefault();
  });
  canvas.addEventListener('pointerdown', (e) => {
    // The right button opens a point's menu (contextmenu, above): it neither drags nor pans.
    if (e.button === 2) return;
    canvas.setPointerCapture(e.pointerId);
    const index = hit(e.offsetX, e.offsetY, e.pointerType === 'touch' ? 24 : 12);
    if (!mode().count) {
      // A path: Alt+click removes a point, Shift+click adds one on the nearest leg.
      if (index !== null && e.altKey) {
        removePoint(index);
        e.preventDefault();
        return;
      }
      if (index === null && e.shiftKey) {
        const [x, y] = view.toWorld([e.offsetX, e.offsetY]);
        const p = [roundToView(x), roundToView(y)];
        const at = insertionIndex(p);
        insertPoint(at, p);
        state.drag = { index: at, pointerId: e.pointerId, combScale: state.combScale };
        e.preventDefault();
        return;
      }
    }
    if (index !== null) {
      state.drag = { index, pointerId: e.pointerId, combScale: state.combScale };
      state.selected = index;
      showHover(null);
      updateRegion();
      render();
    } else {
      state.pan = { x: e.clientX, y: e.clientY, pointerId: e.pointerId };
      canvas.classList.add('grab');
    }
    e.preventDefault();
  });

  canvas.addEventListener('pointermove', (e) => {
    if (state.drag && state.drag.pointerId === e.pointerId) {
      const [x, y] = view.toWorld([e.offsetX, e.offsetY]);
      design().points[state.drag.index] = [roundToView(x), roundToView(y)];
      // The request goes first; the point is drawn with its answer, or now when an earlier
      // request is still out (then this move waits for it).
      const waiting = busy();
      solve(e.timeStamp);
      if (waiting) {
        syncPanel();
        render();
      }
      return;
    }
    if (state.pan && state.pan.pointerId === e.pointerId) {
      view.pan(e.clientX - state.pan.x, e.clientY - state.pan.y);
      state.pan.x = e.clientX;
      state.pan.y = e.clientY;
      render();
      return;
    }
    showHover(nearestSample(e.offsetX, e.offsetY), e.clientX, e.clientY);
    render();
  });

  canvas.addEventListener('pointerup', endPointer);
  canvas.addEventListener('pointercancel', endPointer);
  canvas.addEventListener('pointerleave', () => {
    if (state.hover) {
      showHover(null);
      render();
    }
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    view.zoomAt([e.offsetX, e.offsetY], Math.exp(-e.deltaY * 0.0015));
    viewMoved();
    updateRegion();
    render();
  }, { passive: false });
  canvas.addEventListener('dblclick', () => {
    fitView();
    render();
  });
}

/** What a mode's own views report: a point dragged (`point` null when the drag starts; its
 * view's `scale` in pixels per unit), the drag's end, a sample hovered (or null). */
export const stageInput = {
  /** A change a mode makes to its own design from a key (a spline point's type): `apply(design,
   * selected)` on the design of mode `name` when it is the one shown, then solved, a step of
   * the history and drawn. Returns whether it applied. */
  change(name, apply) {
    if (state.mode !== name) return false;
    apply(design(), state.selected);
    solve();
    commit();
    render();
    return true;
  },
  drag(index, point, time, scale) {
    if (!state.drag) {
      state.drag = { index, pointerId: null, combScale: state.combScale };
      state.selected = index;
    }
    if (point) {
      design().points[index] = point.map((x) => roundAt(x, scale));
      const waiting = busy();
      solve(time);
      if (!waiting) return;
      syncPanel();
    }
    render();
  },
  dragEnd() {
    state.drag = null;
    syncPanel();
    commit();
    autoCombScale();
    render();
  },
  hover(sample, clientX, clientY) {
    showHover(sample ? { sample, index: -1 } : null, clientX, clientY);
    renderStage();
  },
};
