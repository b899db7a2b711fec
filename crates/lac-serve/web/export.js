// Export: the current curve as an SVG drawing (in the design's own coordinates), the design
// file as JSON, the request of a CAD file (/api/export: DXF, STEP, IGES, NURBS JSON); and
// saving text to a file in the browser.

import { geometry, COLORS } from './draw.js';
import { bounds } from './view.js';

const f = (x) => +x.toPrecision(10);
const path = (points) => points.map(([x, y], i) => `${i ? 'L' : 'M'}${f(x)} ${f(y)}`).join(' ');

/** An SVG of a plane curve: curve, comb, evolute, polygon and (quasi) Bézier pieces, in the
 * design's coordinates (y up), with the numbers that made it in a comment. */
export function planeSvg({ points, samples, combScale, show, pieces, pieceSamples, joint, title }) {
  const g = geometry(samples, combScale);
  const all = [...points, ...g.curve, ...(show.comb ? g.teeth.map(([, q]) => q) : [])];
  const [x0, x1, y0, y1] = bounds(all);
  const margin = 0.05 * Math.max(x1 - x0, y1 - y0);
  const box = [x0 - margin, y0 - margin, x1 - x0 + 2 * margin, y1 - y0 + 2 * margin];
  const stroke = box[2] / 400;
  const width = 800;
  const height = Math.round((width * box[3]) / box[2]);
  const out = [];
  out.push(`<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="${box.map(f).join(' ')}">`);
  out.push(`<!-- ${title.replace(/--/g, '- -')} -->`);
  out.push(`<g transform="translate(0 ${f(box[1] * 2 + box[3])}) scale(1 -1)" fill="none" stroke-linecap="round" stroke-linejoin="round">`);
  const evolute = g.evolute.filter((run) => run.every(([x, y]) => x > box[0] - box[2] && x < box[0] + 2 * box[2] && y > box[1] - box[3] && y < box[1] + 2 * box[3]));
  if (show.evolute) for (const run of evolute) out.push(`<path d="${path(run)}" stroke="${COLORS.evolute}" stroke-width="${f(stroke)}" stroke-dasharray="${f(stroke * 4)} ${f(stroke * 3)}"/>`);
  const combs = pieces ? pieces.map((_, k) => geometry(pieceSamples[k], combScale)) : [g];
  if (show.comb) {
    combs.forEach((c, k) => {
      const color = pieces ? COLORS.pieces[k % 2] : COLORS.combEdge;
      out.push(`<path d="${c.teeth.map(([p, q]) => path([p, q])).join(' ')}" stroke="${color}" stroke-opacity="0.5" stroke-width="${f(stroke * 0.6)}"/>`);
      out.push(`<path d="${path(c.teeth.map(([, q]) => q))}" stroke="${color}" stroke-width="${f(stroke * 0.8)}"/>`);
    });
  }
  out.push(`<path d="${path(g.curve)}" stroke="${COLORS.curve}" stroke-width="${f(stroke * 2)}"/>`);
  if (pieces) {
    pieces.forEach((piece, k) => {
      // A plain cubic (all weights 1) is exact in SVG; a rational one is drawn sampled.
      const [a, b, c, d] = piece.points;
      const exact = piece.weights.every((w) => w === 1);
      const dpath = exact
        ? `M${f(a[0])} ${f(a[1])} C${f(b[0])} ${f(b[1])} ${f(c[0])} ${f(c[1])} ${f(d[0])} ${f(d[1])}`
        : path(pieceSamples[k].map((r) => [r.x, r.y]));
      out.push(`<path d="${dpath}" stroke="${COLORS.pieces[k % 2]}" stroke-opacity="0.8" stroke-width="${f(stroke * 3)}"/>`);
    });
  }
  if (show.polygon) out.push(`<path d="${path(points)}" stroke="${COLORS.polygon}" stroke-width="${f(stroke)}"/>`);
  for (const [x, y] of points) out.push(`<circle cx="${f(x)}" cy="${f(y)}" r="${f(stroke * 3)}" fill="#fff" stroke="#333" stroke-width="${f(stroke)}"/>`);
  if (joint) out.push(`<circle cx="${f(joint[0])}" cy="${f(joint[1])}" r="${f(stroke * 3)}" fill="${COLORS.joint}"/>`);
  out.push('</g></svg>');
  return out.join('\n') + '\n';
}

/** An SVG of a space curve: top (x–y), front (x–z) and side (y–z) views side by side. */
export function spaceSvg({ points, samples, title }) {
  const curve = samples.map((r) => [r.x, r.y, r.z]);
  const views = [['top (x–y)', 0, 1], ['front (x–z)', 0, 2], ['side (y–z)', 1, 2]];
  const all = [...points, ...curve];
  const lo = [0, 1, 2].map((i) => Math.min(...all.map((p) => p[i])));
  const hi = [0, 1, 2].map((i) => Math.max(...all.map((p) => p[i])));
  const span = Math.max(...hi.map((h, i) => h - lo[i]), 1e-9);
  const cell = 300;
  const k = (cell - 40) / span;
  const out = [`<svg xmlns="http://www.w3.org/2000/svg" width="${3 * cell}" height="${cell}" viewBox="0 0 ${3 * cell} ${cell}" font-family="sans-serif" font-size="12">`];
  out.push(`<!-- ${title.replace(/--/g, '- -')} -->`);
  views.forEach(([name, a, b], v) => {
    const to = (p) => [v * cell + 20 + (p[a] - lo[a]) * k, cell - 20 - (p[b] - lo[b]) * k];
    out.push(`<text x="${v * cell + 20}" y="14">${name}</text>`);
    out.push(`<path d="${path(points.map(to))}" fill="none" stroke="${COLORS.polygon}"/>`);
    out.push(`<path d="${path(curve.map(to))}" fill="none" stroke="${COLORS.curve}" stroke-width="2"/>`);
    for (const p of points) {
      const [x, y] = to(p);
      out.push(`<circle cx="${f(x)}" cy="${f(y)}" r="3.5" fill="#fff" stroke="#333"/>`);
    }
  });
  out.push('</svg>');
  return out.join('\n') + '\n';
}

/** Offer `text` as a file download named `name`. */
export function download(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** The /api/export request for `design` in `mode` (a mode object, modes/): the exact
 * curve's fields (the mode's `cad`: quasi mode exports its exact segment, not its Bézier
 * pieces, so its relative `tolerance` and `cubic` go; a fit sends its result, `answer`), the
 * format, and 1e-6 model units. */
export function cadRequest(mode, design, format, answer) {
  const body = mode.cad(JSON.parse(JSON.stringify(design)), answer);
  return { ...body, format, tolerance: 1e-6, name: `lac-${mode.name}` };
}
