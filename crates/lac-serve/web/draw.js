// Drawing the plane view: the curve, its control polygon, curvature comb and evolute, the
// drawable region, the quasi-aesthetic pieces, and the hover mark. Geometry is computed once
// (`geometry`) and shared with the SVG export.

import { mapTransform } from './view.js';
import { labelPlaces, inBox } from './layout.js';

export const COLORS = {
  curve: '#1b1b1b',
  faint: 'rgba(27, 27, 27, 0.22)',
  polygon: '#8a8a8a',
  comb: 'rgba(61, 133, 198, 0.55)',
  combEdge: '#3d85c6',
  evolute: '#e69138',
  joint: '#b3261e',
  line: '#0b8043',
  pieces: ['#0b8043', '#8e24aa'],
  bad: '#d93025',
  drawable: [46, 160, 67, 60],
  undrawable: [217, 48, 37, 22],
};

/** The left normal of a tangent direction θ. */
const normal = (theta) => [-Math.sin(theta), Math.cos(theta)];

/** The evolute is drawn where |κ| is at least this share of the curve's largest |κ|: beyond,
 * its points run off towards infinity (where κ → 0: at an inflection, along a nearly straight
 * stretch) and say nothing of the curve. */
export const EVOLUTE_CUT = 0.1;

/** Whether sample `r`'s centre of curvature is drawn, the largest |κ| being `kmax`. */
export const evoluteKept = (r, kmax) => r.kappa !== 0 && Math.abs(r.kappa) >= EVOLUTE_CUT * kmax;

/**
 * What is drawn of a list of samples {s, x, y, theta, kappa}: the curve's points, the comb's
 * teeth (from each point away from the centre of curvature, κ × combScale long) and the
 * evolute P + N/κ in runs, cut where |κ| is small (EVOLUTE_CUT).
 */
export function geometry(samples, combScale) {
  const curve = samples.map((r) => [r.x, r.y]);
  const teeth = samples.map((r) => {
    const [nx, ny] = normal(r.theta);
    return [[r.x, r.y], [r.x - nx * r.kappa * combScale, r.y - ny * r.kappa * combScale]];
  });
  const kmax = samples.reduce((m, r) => Math.max(m, Math.abs(r.kappa)), 0);
  const evolute = [];
  let run = [];
  for (const r of samples) {
    if (!evoluteKept(r, kmax)) {
      if (run.length > 1) evolute.push(run);
      run = [];
      continue;
    }
    const rho = 1 / r.kappa;
    const [nx, ny] = normal(r.theta);
    run.push([r.x + nx * rho, r.y + ny * rho]);
  }
  if (run.length > 1) evolute.push(run);
  return { curve, teeth, evolute };
}

/** An offscreen canvas with a region map's pixels: green where drawable, red where not. */
export function regionImage(drawable) {
  const size = drawable.length;
  const canvas = document.createElement('canvas');
  canvas.width = size;
  canvas.height = size;
  const ctx = canvas.getContext('2d');
  const image = ctx.createImageData(size, size);
  for (let row = 0; row < size; row++) {
    for (let col = 0; col < size; col++) {
      const rgba = drawable[row][col] ? COLORS.drawable : COLORS.undrawable;
      image.data.set(rgba, 4 * (row * size + col));
    }
  }
  ctx.putImageData(image, 0, 0);
  return canvas;
}

/** Size a canvas's backing store to its CSS size and the device's pixel ratio; returns the
 * 2-D context, scaled to CSS pixels, and the CSS size. */
export function sizeCanvas(c) {
  const ratio = window.devicePixelRatio || 1;
  const w = c.clientWidth;
  const h = c.clientHeight;
  if (c.width !== Math.round(w * ratio) || c.height !== Math.round(h * ratio)) {
    c.width = Math.round(w * ratio);
    c.height = Math.round(h * ratio);
  }
  const ctx = c.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  return { ctx, width: w, height: h };
}

function polyline(ctx, view, points) {
  ctx.beginPath();
  points.forEach((p, i) => {
    const [x, y] = view.toScreen(p);
    if (i) ctx.lineTo(x, y); else ctx.moveTo(x, y);
  });
  ctx.stroke();
}

/** Teeth drawn: about this many along a curve (the envelope uses every sample). */
const TEETH = 96;

function combOf(ctx, view, teeth, color, edge) {
  ctx.strokeStyle = color;
  ctx.lineWidth = 1;
  ctx.beginPath();
  const every = Math.max(1, Math.round(teeth.length / TEETH));
  for (const [i, [p, q]] of teeth.entries()) {
    if (i % every && i !== teeth.length - 1) continue;
    const a = view.toScreen(p);
    const b = view.toScreen(q);
    ctx.moveTo(a[0], a[1]);
    ctx.lineTo(b[0], b[1]);
  }
  ctx.stroke();
  ctx.strokeStyle = edge;
  polyline(ctx, view, teeth.map(([, q]) => q));
}

/** The region's key, bottom left: green where the point may go. */
function legend(ctx, height, label) {
  ctx.font = '12px system-ui, sans-serif';
  const text = [['may go here', COLORS.drawable], ['no curve', COLORS.undrawable]];
  const width = 28 + ctx.measureText(label).width + text.reduce((w, [t]) => w + ctx.measureText(t).width + 34, 0);
  ctx.fillStyle = 'rgba(255, 255, 255, 0.9)';
  ctx.fillRect(8, height - 30, width, 22);
  ctx.fillStyle = '#333';
  ctx.fillText(label, 16, height - 15);
  let x = 16 + ctx.measureText(label).width + 12;
  for (const [t, [r, g, b]] of text) {
    ctx.fillStyle = `rgba(${r}, ${g}, ${b}, 0.45)`;
    ctx.fillRect(x, height - 25, 14, 12);
    ctx.fillStyle = '#333';
    ctx.fillText(t, x + 18, height - 15);
    x += ctx.measureText(t).width + 34;
  }
}

function grid(ctx, view, width, height) {
  const [x0, x1, y0, y1] = view.visible(width, height);
  const raw = 80 / view.scale;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw);
  ctx.lineWidth = 1;
  for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
    ctx.strokeStyle = Math.abs(x) < step / 2 ? '#d5d5d5' : '#f0f0f0';
    const [sx] = view.toScreen([x, 0]);
    ctx.beginPath(); ctx.moveTo(sx, 0); ctx.lineTo(sx, height); ctx.stroke();
  }
  for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
    ctx.strokeStyle = Math.abs(y) < step / 2 ? '#d5d5d5' : '#f0f0f0';
    const [, sy] = view.toScreen([0, y]);
    ctx.beginPath(); ctx.moveTo(0, sy); ctx.lineTo(width, sy); ctx.stroke();
  }
}

/**
 * Draw the plane scene:
 * {points, samples, stale, show, combScale,
 *  region: {image, size, extent, toWorld, wide: {image, size, extent} | null} | null,
 *  joint, joints: [[x, y]] | null, lines: [[[x, y], [x, y]]] | null, closed,
 *  marks: [{at: [x, y], kind: 'corner' | 'tangent' | 'line', angle}] | undefined,
 *  pieces: [{points, weights, monotone, proven}] | null, pieceSamples, active, hover,
 *  underlay, curveWidth}.
 * `joints` are a path's joints (dots), `lines` its straight pieces through inflections, and
 * `closed` closes its control polygon. `underlay(ctx)`, if given, draws under the curve (a
 * fit's data points); `curveWidth` is the curve's width in pixels (default 2.4).
 * `samples` are the last good curve's; `stale` draws them faintly (the input is not drawable).
 * Returns what the page tells of the drawing: {evolute: 'off' | 'visible' | 'outside'}.
 */
export function drawPlane(ctx, view, width, height, scene) {
  ctx.clearRect(0, 0, width, height);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, width, height);
  grid(ctx, view, width, height);
  const { show } = scene;
  // What the page tells of the evolute: 'off' (not asked, or nothing to draw), 'visible',
  // or 'outside' the view.
  let evolute = 'off';

  if (scene.region && scene.region.wide) {
    // The map around the region's own: outside its square only (the canvas's rectangle less
    // that square, even-odd), where it is coarser.
    const { extent: [x0, x1, y0, y1], toWorld, wide } = scene.region;
    ctx.save();
    ctx.beginPath();
    ctx.rect(0, 0, width, height);
    [[x0, y1], [x1, y1], [x1, y0], [x0, y0]].forEach((p, i) => {
      const [x, y] = view.toScreen(toWorld(p));
      if (i) ctx.lineTo(x, y); else ctx.moveTo(x, y);
    });
    ctx.closePath();
    ctx.clip('evenodd');
    const [a, b, c, d, e, f] = mapTransform(view, wide.size, wide.extent, toWorld);
    ctx.transform(a, b, c, d, e, f);
    ctx.imageSmoothingEnabled = true;
    ctx.drawImage(wide.image, 0, 0);
    ctx.restore();
  }

  if (scene.region) {
    const { image, size, extent, toWorld } = scene.region;
    const [a, b, c, d, e, f] = mapTransform(view, size, extent, toWorld);
    ctx.save();
    ctx.transform(a, b, c, d, e, f);
    ctx.imageSmoothingEnabled = true;
    ctx.drawImage(image, 0, 0);
    ctx.restore();
  }

  if (scene.region && scene.region.label) legend(ctx, height, scene.region.label);
  if (scene.underlay) scene.underlay(ctx);

  const samples = scene.samples;
  if (samples && samples.length) {
    const g = geometry(samples, scene.combScale);
    if (scene.stale) {
      ctx.strokeStyle = COLORS.faint;
      ctx.lineWidth = 2;
      ctx.setLineDash([6, 4]);
      polyline(ctx, view, g.curve);
      ctx.setLineDash([]);
    } else {
      if (show.evolute && g.evolute.length) {
        // Only what lies in the view (and a little around it, for the dashes' sake).
        const runs = g.evolute.map((run) => run.map((p) => view.toScreen(p)));
        const drawn = inBox(runs, [-50, width + 50, -50, height + 50]);
        evolute = inBox(drawn, [0, width, 0, height]).length ? 'visible' : 'outside';
        ctx.strokeStyle = COLORS.evolute;
        ctx.lineWidth = 1.2;
        ctx.setLineDash([5, 3]);
        for (const run of drawn) {
          ctx.beginPath();
          run.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
          ctx.stroke();
        }
        ctx.setLineDash([]);
      }
      if (show.comb && !scene.pieces) combOf(ctx, view, g.teeth, COLORS.comb, COLORS.combEdge);
      if (show.comb && scene.pieces) {
        // The exact curve's comb envelope, for the pieces' combs to be compared with.
        ctx.strokeStyle = COLORS.faint;
        ctx.lineWidth = 1.5;
        ctx.setLineDash([3, 3]);
        polyline(ctx, view, g.teeth.map(([, q]) => q));
        ctx.setLineDash([]);
      }
      ctx.strokeStyle = COLORS.curve;
      ctx.lineWidth = scene.curveWidth ?? (scene.pieces ? 1.4 : 2.4);
      ctx.lineJoin = 'round';
      polyline(ctx, view, g.curve);
    }
  }

  if (scene.pieces && !scene.stale) {
    scene.pieces.forEach((piece, k) => {
      const color = piece.monotone === 'not_monotone' || !piece.proven ? COLORS.bad : COLORS.pieces[k % 2];
      const rows = scene.pieceSamples[k] || [];
      const g = geometry(rows, scene.combScale);
      if (show.comb) combOf(ctx, view, g.teeth, color + '66', color);
      ctx.strokeStyle = color;
      ctx.lineWidth = 3.2;
      ctx.globalAlpha = 0.75;
      polyline(ctx, view, g.curve);
      ctx.globalAlpha = 1;
      if (show.polygon) {
        ctx.strokeStyle = color;
        ctx.lineWidth = 0.8;
        ctx.setLineDash([2, 3]);
        polyline(ctx, view, piece.points);
        ctx.setLineDash([]);
        ctx.fillStyle = color;
        for (const p of piece.points) {
          const [x, y] = view.toScreen(p);
          ctx.fillRect(x - 2, y - 2, 4, 4);
        }
      }
    });
  }

  if (scene.lines && !scene.stale) {
    // A path's straight pieces (the curvature passes through zero there).
    ctx.strokeStyle = COLORS.line;
    ctx.lineWidth = 4;
    ctx.globalAlpha = 0.6;
    for (const line of scene.lines) polyline(ctx, view, line);
    ctx.globalAlpha = 1;
  }

  const joints = scene.joints || (scene.joint ? [scene.joint] : []);
  if (!scene.stale) {
    for (const joint of joints) {
      const [x, y] = view.toScreen(joint);
      ctx.fillStyle = COLORS.joint;
      ctx.beginPath();
      ctx.moveTo(x, y - 6); ctx.lineTo(x + 6, y); ctx.lineTo(x, y + 6); ctx.lineTo(x - 6, y);
      ctx.closePath();
      ctx.fill();
    }
  }

  // A spline's point types as designers know them from Spiro: a corner's square, a tangent
  // point's arrow along its direction, a half circle where a curve meets a straight span
  // (open toward the line).
  for (const mark of scene.marks || []) {
    const [x, y] = view.toScreen(mark.at);
    ctx.strokeStyle = COLORS.joint;
    ctx.fillStyle = COLORS.joint;
    ctx.lineWidth = 2;
    ctx.beginPath();
    if (mark.kind === 'corner') {
      ctx.rect(x - 9, y - 9, 18, 18);
      ctx.stroke();
    } else if (mark.kind === 'tangent') {
      const [dx, dy] = [Math.cos(mark.angle), -Math.sin(mark.angle)];
      const [tx, ty] = [x + 22 * dx, y + 22 * dy];
      ctx.moveTo(x - 22 * dx, y - 22 * dy);
      ctx.lineTo(tx, ty);
      ctx.stroke();
      ctx.beginPath();
      ctx.moveTo(tx, ty);
      ctx.lineTo(tx - 8 * dx + 5 * dy, ty - 8 * dy - 5 * dx);
      ctx.lineTo(tx - 8 * dx - 5 * dy, ty - 8 * dy + 5 * dx);
      ctx.closePath();
      ctx.fill();
    } else if (mark.kind === 'line') {
      // The half circle on the curve's side: centred on the point, its diameter across the
      // line's direction.
      const a = -mark.angle;
      ctx.arc(x, y, 11, a + Math.PI / 2, a - Math.PI / 2, false);
      ctx.stroke();
    }
  }

  if (show.polygon || scene.stale) {
    ctx.strokeStyle = COLORS.polygon;
    ctx.lineWidth = 1;
    polyline(ctx, view, scene.closed ? [...scene.points, scene.points[0]] : scene.points);
  }
  const onScreen = scene.points.map((p) => view.toScreen(p));
  ctx.font = '12px system-ui, sans-serif';
  const labels = labelPlaces(ctx, onScreen, onScreen.map((_, i) => `P${i}`), 9, [width, height]);
  onScreen.forEach(([x, y], i) => {
    ctx.beginPath();
    ctx.arc(x, y, i === scene.active ? 8 : 6.5, 0, 2 * Math.PI);
    ctx.fillStyle = i === scene.active ? '#ffe08a' : '#fff';
    ctx.fill();
    ctx.lineWidth = 1.6;
    ctx.strokeStyle = scene.stale ? COLORS.bad : '#333';
    ctx.stroke();
    ctx.fillStyle = '#333';
    ctx.fillText(`P${i}`, labels[i][0], labels[i][1]);
  });

  if (scene.hover) {
    const [x, y] = view.toScreen(scene.hover);
    ctx.strokeStyle = '#d0342c';
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.arc(x, y, 5, 0, 2 * Math.PI);
    ctx.stroke();
  }
  return { evolute };
}
