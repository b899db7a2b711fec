// Small line plots for the side panel: the curvature plot (κ against s) and the logarithmic
// curvature graph (ln ρ against ln(ρ ds/dρ)) with its fitted line.

/** Size a canvas's backing store to its CSS size and the device's pixel ratio; returns the
 * 2-D context, scaled to CSS pixels, and the CSS size. */
export function prepare(canvas) {
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || 300;
  const height = canvas.clientHeight || 150;
  if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
  }
  const ctx = canvas.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  return { ctx, width, height };
}

/** About `count` round tick values covering [lo, hi], each with its label. */
function ticks(lo, hi, count = 4) {
  const span = hi - lo;
  if (!(span > 0)) return [[lo, label(lo, 0)]];
  const raw = span / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw) || 10 * mag;
  const out = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) {
    const tick = Math.abs(t) < step * 1e-9 ? 0 : t;
    out.push([tick, label(tick, step)]);
  }
  return out;
}

/** A short label for a tick value, with the decimals its ticks' `step` needs to tell them
 * apart (10.402 beside 10.404, not 10.4 twice). */
function label(t, step) {
  if (Math.abs(t) >= 1e4 || (Math.abs(t) < 1e-3 && t !== 0)) return t.toExponential(0);
  const decimals = step > 0 ? Math.min(12, Math.max(0, -Math.floor(Math.log10(step) + 1e-9))) : 3;
  return String(+t.toFixed(decimals));
}

/**
 * Draw series of [x, y] points (null y: a gap) on `canvas`.
 * options: {title, xlabel, ylabel (text, or lines [{text, color}] side by side),
 *           series: [{points, color, width, dash, label}],
 *           vlines: [{x, color}], marker: [x, y] | null, empty: text when there is nothing}
 * Returns the plot's mapping {toX, toY} for tests and hover marks.
 */
export function linePlot(canvas, options) {
  const { ctx, width, height } = prepare(canvas);
  // The y axis's label: one line, or lines side by side (each in its series' colour).
  const ylines = (Array.isArray(options.ylabel) ? options.ylabel : [options.ylabel || ''])
    .map((l) => (typeof l === 'string' ? { text: l } : l));
  const pad = { left: 46 + 12 * (ylines.length - 1), right: 10, top: 20, bottom: 30 };
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillStyle = '#222';
  ctx.textBaseline = 'alphabetic';
  ctx.textAlign = 'left';
  ctx.fillText(options.title || '', 6, 13);
  const all = options.series.flatMap((s) => s.points).filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y));
  if (!all.length) {
    ctx.fillStyle = '#777';
    ctx.textAlign = 'left';
    ctx.fillText(options.empty || 'nothing to plot', pad.left, height / 2);
    return null;
  }
  let [x0, x1, y0, y1] = [Infinity, -Infinity, Infinity, -Infinity];
  for (const [x, y] of all) {
    x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  if (options.includeZero) { y0 = Math.min(y0, 0); y1 = Math.max(y1, 0); }
  if (x1 - x0 < 1e-12) { x0 -= 0.5; x1 += 0.5; }
  if (y1 - y0 < 1e-12 * Math.max(1, Math.abs(y0))) { const m = Math.max(Math.abs(y0) * 0.1, 0.5); y0 -= m; y1 += m; }
  const my = (y1 - y0) * 0.06;
  y0 -= my; y1 += my;
  const w = width - pad.left - pad.right;
  const h = height - pad.top - pad.bottom;
  const toX = (x) => pad.left + ((x - x0) / (x1 - x0)) * w;
  const toY = (y) => pad.top + (1 - (y - y0) / (y1 - y0)) * h;

  ctx.strokeStyle = '#e3e3e3';
  ctx.lineWidth = 1;
  ctx.fillStyle = '#555';
  ctx.textAlign = 'center';
  for (const [t, text] of ticks(x0, x1)) {
    ctx.beginPath(); ctx.moveTo(toX(t), pad.top); ctx.lineTo(toX(t), pad.top + h); ctx.stroke();
    ctx.fillText(text, toX(t), pad.top + h + 12);
  }
  ctx.textAlign = 'right';
  for (const [t, text] of ticks(y0, y1)) {
    ctx.beginPath(); ctx.moveTo(pad.left, toY(t)); ctx.lineTo(pad.left + w, toY(t)); ctx.stroke();
    ctx.fillText(text, pad.left - 4, toY(t) + 4);
  }
  ctx.strokeStyle = '#999';
  ctx.strokeRect(pad.left, pad.top, w, h);
  ctx.textAlign = 'center';
  ctx.fillText(options.xlabel || '', pad.left + w / 2, height - 4);
  // Each line fits the plot's height (a smaller font when it would not).
  ylines.forEach((line, k) => {
    ctx.save();
    ctx.translate(11 + 12 * k, pad.top + h / 2);
    ctx.rotate(-Math.PI / 2);
    let size = 11;
    ctx.font = `${size}px system-ui, sans-serif`;
    while (size > 8 && ctx.measureText(line.text).width > h) {
      size -= 0.5;
      ctx.font = `${size}px system-ui, sans-serif`;
    }
    ctx.fillStyle = line.color || '#555';
    ctx.fillText(line.text, 0, 0);
    ctx.restore();
  });
  ctx.font = '11px system-ui, sans-serif';

  ctx.save();
  ctx.beginPath();
  ctx.rect(pad.left, pad.top, w, h);
  ctx.clip();
  for (const v of options.vlines || []) {
    ctx.strokeStyle = v.color || '#c80';
    ctx.setLineDash([4, 3]);
    ctx.beginPath(); ctx.moveTo(toX(v.x), pad.top); ctx.lineTo(toX(v.x), pad.top + h); ctx.stroke();
    ctx.setLineDash([]);
  }
  for (const s of options.series) {
    ctx.strokeStyle = s.color || '#1f4e9c';
    ctx.lineWidth = s.width || 1.6;
    ctx.setLineDash(s.dash || []);
    ctx.beginPath();
    let pen = false;
    for (const [x, y] of s.points) {
      if (!Number.isFinite(x) || !Number.isFinite(y)) { pen = false; continue; }
      if (pen) ctx.lineTo(toX(x), toY(y)); else ctx.moveTo(toX(x), toY(y));
      pen = true;
    }
    ctx.stroke();
    ctx.setLineDash([]);
  }
  if (options.marker) {
    ctx.fillStyle = '#d0342c';
    ctx.beginPath();
    ctx.arc(toX(options.marker[0]), toY(options.marker[1]), 3.5, 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.restore();

  let ly = pad.top + 12;
  ctx.textAlign = 'right';
  for (const s of options.series) {
    if (!s.label) continue;
    ctx.fillStyle = s.color || '#1f4e9c';
    ctx.fillText(s.label, pad.left + w - 4, ly);
    ly += 13;
  }
  return { toX, toY };
}
