// The plane view: world coordinates (y up) to canvas pixels (y down), fitted to a box,
// zoomed about a point and panned; and the similarity of the drawable-region map.

/** A uniform scale and offset from world to CSS pixels. */
export class View {
  constructor() {
    this.scale = 100; // CSS pixels per world unit
    this.ox = 0; // screen x of world x = 0
    this.oy = 0; // screen y of world y = 0
  }

  /** Show the box [x0, x1] × [y0, y1] in a `width` × `height` canvas, with a margin. */
  fit([x0, x1, y0, y1], width, height, margin = 48) {
    const w = Math.max(x1 - x0, 1e-9);
    const h = Math.max(y1 - y0, 1e-9);
    this.scale = Math.min((width - 2 * margin) / w, (height - 2 * margin) / h);
    if (!(this.scale > 0 && Number.isFinite(this.scale))) this.scale = 1;
    this.ox = width / 2 - this.scale * (x0 + x1) / 2;
    this.oy = height / 2 + this.scale * (y0 + y1) / 2;
  }

  /** Screen position of a world point. */
  toScreen([x, y]) {
    return [this.ox + this.scale * x, this.oy - this.scale * y];
  }

  /** World point at a screen position. */
  toWorld([sx, sy]) {
    return [(sx - this.ox) / this.scale, (this.oy - sy) / this.scale];
  }

  /** Zoom by `factor` keeping the world point under screen position `at` in place. */
  zoomAt([sx, sy], factor) {
    this.ox = sx - (sx - this.ox) * factor;
    this.oy = sy - (sy - this.oy) * factor;
    this.scale *= factor;
  }

  /** Move the picture by (dx, dy) screen pixels. */
  pan(dx, dy) {
    this.ox += dx;
    this.oy += dy;
  }

  /** The world box visible in a `width` × `height` canvas: [x0, x1, y0, y1]. */
  visible(width, height) {
    const [x0, y1] = this.toWorld([0, 0]);
    const [x1, y0] = this.toWorld([width, height]);
    return [x0, x1, y0, y1];
  }
}

/** The bounding box [x0, x1, y0, y1] of points [x, y]. */
export function bounds(points) {
  let box = [Infinity, -Infinity, Infinity, -Infinity];
  for (const [x, y] of points) {
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    box = [Math.min(box[0], x), Math.max(box[1], x), Math.min(box[2], y), Math.max(box[3], y)];
  }
  return Number.isFinite(box[0]) ? box : [-1, 1, -1, 1];
}

/**
 * The canvas transform [a, b, c, d, e, f] that draws pixel (px, py) of a `size` × `size` map
 * of [x0, x1] × [y0, y1] (row 0 at the top) where it belongs on screen, after `toWorld`, a map
 * from the map's coordinates to the world (for the canonical region, the similarity taking
 * (−1, 0) and (1, 0) to the curve's ends).
 */
export function mapTransform(view, size, [x0, x1, y0, y1], toWorld = (p) => p) {
  const at = (px, py) => view.toScreen(toWorld([x0 + (px / size) * (x1 - x0), y1 - (py / size) * (y1 - y0)]));
  const o = at(0, 0);
  const u = at(1, 0);
  const v = at(0, 1);
  return [u[0] - o[0], u[1] - o[1], v[0] - o[0], v[1] - o[1], o[0], o[1]];
}

/** The similarity taking (−1, 0) to `first` and (1, 0) to `last`. */
export function similarity(first, last) {
  const cx = (first[0] + last[0]) / 2;
  const cy = (first[1] + last[1]) / 2;
  const ex = (last[0] - first[0]) / 2;
  const ey = (last[1] - first[1]) / 2;
  return ([u, v]) => [cx + u * ex - v * ey, cy + u * ey + v * ex];
}
