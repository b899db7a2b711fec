// Laying things out on a canvas: the labels beside points, the parts of polylines that lie in a
// box (what of a curve's evolute is in view), the comb scale that keeps the teeth in view.

/**
 * Where the labels of points go (`texts` beside screen `points`, in `ctx`'s font): `gap`
 * pixels above right of each, else below right, above left, below left: the first place that
 * covers no label placed before and no other point (points that coincide in a view get their
 * labels apart) and lies in the canvas ([width, height]). Returns each label's [x, y] (its
 * text's left end, on the baseline).
 */
export function labelPlaces(ctx, points, texts, gap, [width, height] = [Infinity, Infinity]) {
  const placed = [];
  const size = parseFloat(ctx.font) || 12;
  return points.map(([x, y], i) => {
    const w = ctx.measureText(texts[i]).width;
    const box = ([lx, ly]) => [lx, ly - size, lx + w, ly + 2];
    const clear = (b) => b[0] >= 0 && b[1] >= 0 && b[2] <= width && b[3] <= height
      && !placed.some((o) => b[0] < o[2] && o[0] < b[2] && b[1] < o[3] && o[1] < b[3])
      && !points.some(([px, py], j) => j !== i && px > b[0] - 6 && px < b[2] + 6 && py > b[1] - 6 && py < b[3] + 6);
    const options = [[x + gap, y - gap], [x + gap, y + gap + size], [x - gap - w, y - gap], [x - gap - w, y + gap + size]];
    const at = options.find((o) => clear(box(o))) || options[0];
    placed.push(box(at));
    return at;
  });
}

/** Whether the segment from screen point `a` to `b` meets the box [x0, x1, y0, y1]
 * (Liang–Barsky). */
export function meetsBox([ax, ay], [bx, by], [x0, x1, y0, y1]) {
  let t0 = 0;
  let t1 = 1;
  const dx = bx - ax;
  const dy = by - ay;
  for (const [p, q] of [[-dx, ax - x0], [dx, x1 - ax], [-dy, ay - y0], [dy, y1 - ay]]) {
    if (p === 0) {
      if (q < 0) return false;
    } else {
      const t = q / p;
      if (p < 0) t0 = Math.max(t0, t); else t1 = Math.min(t1, t);
      if (t0 > t1) return false;
    }
  }
  return true;
}

/** The parts of screen polylines `runs` that lie in the box [x0, x1, y0, y1]: runs of the
 * segments that meet it. */
export function inBox(runs, box) {
  const out = [];
  for (const run of runs) {
    let part = [];
    for (let i = 1; i < run.length; i++) {
      if (meetsBox(run[i - 1], run[i], box)) {
        if (!part.length) part.push(run[i - 1]);
        part.push(run[i]);
      } else if (part.length) {
        out.push(part);
        part = [];
      }
    }
    if (part.length) out.push(part);
  }
  return out;
}

/**
 * The largest comb scale at which the teeth stay in a `width` × `height` canvas: `teeth` are
 * [[x, y], [dx, dy]], a sample's screen position and its tooth at scale 1, in pixels. Samples
 * less than `inner` pixels inside the canvas are let be (their teeth would shrink the comb to
 * nothing); the others' teeth end at least `edge` pixels inside. Infinity when none limits.
 */
export function combRoom(teeth, width, height, inner = 24, edge = 4) {
  let room = Infinity;
  for (const [[x, y], [dx, dy]] of teeth) {
    if (!(x >= inner && x <= width - inner && y >= inner && y <= height - inner)) continue;
    if (dx > 0) room = Math.min(room, (width - edge - x) / dx);
    if (dx < 0) room = Math.min(room, (edge - x) / dx);
    if (dy > 0) room = Math.min(room, (height - edge - y) / dy);
    if (dy < 0) room = Math.min(room, (edge - y) / dy);
  }
  return room;
}
