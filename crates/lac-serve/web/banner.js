// Where the message (#message: a refusal, a bad link or file) goes over a stage: never on a
// control point. A mode places it (modes/: `placeMessage`) with these helpers.

/** Pixels around a control point's centre that a message keeps clear of (its disc, its
 * label beside it, a finger's reach). */
const CLEAR = 16;
/** Room kept free at the bottom of the plane: the drawable region's key. */
const KEY = 40;

const covers = (r, [x, y]) => x > r.left - CLEAR && x < r.left + r.width + CLEAR
  && y > r.top - CLEAR - 12 && y < r.top + r.height + CLEAR;

function put(box, { left, top, width }) {
  Object.assign(box.style, { left: `${left}px`, top: `${top}px`, width: `${width}px`, right: 'auto', maxWidth: 'none', maxHeight: '' });
  return { left, top, width, height: box.offsetHeight };
}

/**
 * Place `box` over `area` ({left, top, width, height}, in the stage's pixels) clear of
 * `points` (the control points' [x, y] there): across the top (where it always went), else
 * across the bottom (above the region's key), else in the top or bottom half of either side.
 * When each would cover a point it goes across the top and lets the pointer through (the
 * points beneath stay draggable), translucent.
 */
export function placeClear(box, area, points) {
  box.classList.remove('through');
  const full = Math.min(area.width - 24, 760);
  const half = Math.max(160, (area.width - 36) / 2);
  const rows = [
    [area.left + 12, full, 'top'],
    [area.left + 12, full, 'bottom'],
    [area.left + 12, half, 'top'],
    [area.left + area.width - 12 - half, half, 'top'],
    [area.left + 12, half, 'bottom'],
    [area.left + area.width - 12 - half, half, 'bottom'],
  ];
  for (const [left, width, edge] of rows) {
    let r = put(box, { left, top: area.top + 12, width });
    if (edge === 'bottom') r = put(box, { left, top: area.top + area.height - KEY - r.height, width });
    if (r.top >= area.top && !points.some((p) => covers(r, p))) return;
  }
  put(box, { left: area.left + 12, top: area.top + 12, width: full });
  box.classList.add('through');
}

/** Place `box` at the top of `area` (under its caption, `below` pixels), as wide as it is and
 * at most as tall; returns the pixels it takes from the area's top. */
export function placeTop(box, area, below) {
  box.classList.remove('through');
  const r = put(box, { left: area.left + 6, top: area.top + below, width: area.width - 12 });
  box.style.maxHeight = `${Math.max(40, area.height - below - 8)}px`;
  return below + Math.min(r.height, box.offsetHeight) + 6;
}

/** The message's default place (the stylesheet's). */
export function unplace(box) {
  box.classList.remove('through');
  Object.assign(box.style, { left: '', top: '', width: '', right: '', maxWidth: '', maxHeight: '' });
}
