// A quasi-aesthetic curve: the segment of three control points as rational (or plain) cubic
// Bézier pieces within a tolerance, each piece's curvature checked for monotony: /api/quasi.

import { plane, canonicalRegion, REGION_SIZE, exactPlots, planePlots, curveReadout } from './plane.js';

export default {
  ...plane,
  name: 'quasi',
  label: 'Quasi-aesthetic',
  endpoint: '/api/quasi',
  count: 3,
  params: [
    { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01, hint: 'slope of the exact curve' },
    { key: 'tolerance', label: 'tolerance', min: -10, max: -1, step: 0.1, log: true, valid: { from: 1e-12, to: 1 },
      hint: 'largest deviation of the Bézier pieces, relative to the arc length' },
    { key: 'cubic', label: 'cubics', boolean: true, hint: 'plain cubics: all weights 1 (no rational pieces)' },
  ],
  defaults: { points: [[0, 0], [3, 0], [4, 1.5]], alpha: -1, tolerance: 0.0001, cubic: false },

  /** "cubic" only when asked for. */
  request(body) {
    if (!body.cubic) delete body.cubic;
    return body;
  },
  /** The CAD file is the exact segment's, not the Bézier pieces': no relative tolerance. */
  cad(body) {
    delete body.tolerance;
    delete body.cubic;
    return body;
  },

  fileRank: 40,
  recognises: (json) => 'tolerance' in json,

  region: (f) => canonicalRegion({ alpha: f.design.alpha, size: REGION_SIZE }, { alpha: f.design.alpha }, f),

  /** The answer's exact curve is its `curve`. */
  curve: (answer) => answer.curve,

  scene: (a) => ({ pieces: a ? a.pieces : null, pieceSamples: a ? a.piece_samples : null }),

  readout(a, add) {
    curveReadout(a.curve, add);
    add('Bézier pieces', 'pieces', a.pieces.length, `${a.pieces.length} ${a.kind}`);
    add('max deviation', 'max', a.max, `${a.max.toExponential(3)} × length`);
    add('rms deviation', 'rms', a.rms, `${a.rms.toExponential(3)} × length`);
    const pfit = a.piece_plot && a.piece_plot.fit;
    if (pfit) add('pieces\' LCG slope', 'piece_fit_alpha', pfit.alpha);
  },

  /** The pieces' verdicts: monotone curvature, proven or not, and their deviations. */
  table(a, design) {
    const table = document.createElement('table');
    table.innerHTML = '<thead><tr><th>piece</th><th>curvature</th><th>max deviation</th></tr></thead>';
    const body = document.createElement('tbody');
    a.pieces.forEach((p, k) => {
      const tr = document.createElement('tr');
      const good = p.monotone !== 'not_monotone' && p.proven;
      const cells = [
        String(k + 1),
        `${p.monotone.replace('_', ' ')}${p.proven ? ' (proven)' : ' (not proven)'}`,
        p.max_deviation.toExponential(2),
      ];
      cells.forEach((text, i) => {
        const td = document.createElement('td');
        td.textContent = text;
        if (i === 1) td.className = good ? 'good' : 'bad';
        tr.append(td);
      });
      body.append(tr);
    });
    table.append(body);
    const caption = document.createElement('caption');
    caption.textContent = `tolerance ${design.tolerance} × arc length`;
    table.prepend(caption);
    return table;
  },

  /** The exact curve's plots with the pieces' (dashed green) over them. */
  plots(a, where) {
    const plot = this.plot(a);
    const p = exactPlots(a, plot, 'exact curve');
    if (a) {
      p.series.push({ points: a.piece_plot.points.map((q) => [q.s, q.kappa]), color: '#0b8043', dash: [4, 3], label: 'Bézier pieces' });
      p.graph.push({ points: a.piece_plot.points.map((q) => [q.log_rho ?? NaN, q.log_lcg ?? NaN]), color: '#0b8043', dash: [4, 3], label: 'Bézier pieces' });
      for (const rows of a.piece_samples.slice(0, -1)) p.vlines.push({ x: rows[rows.length - 1].s, color: '#0b8043' });
    }
    return planePlots({ plot, ...p }, where);
  },
};
