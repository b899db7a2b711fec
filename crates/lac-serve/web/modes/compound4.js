// A compound curve of two segments through four control points: /api/compound without
// "ratio". Its drawable region is that of the dragged point (or the one dragged last), over
// the visible part of the plane: /api/region/point.

import { plane } from './plane.js';

/** Pixels per side of one point's region map. */
const POINT_REGION_SIZE = 80;

export default {
  ...plane,
  name: 'compound4',
  label: 'Compound 4 points',
  endpoint: '/api/compound',
  count: 4,
  params: [
    { key: 'alpha0', label: 'α0', min: -3, max: 3, step: 0.01, hint: 'slope of the first piece' },
    { key: 'alpha1', label: 'α1', min: -3, max: 3, step: 0.01, hint: 'slope of the second piece' },
  ],
  defaults: { points: [[0, 0], [2, 0], [3, 1], [3.2, 2.4]], alpha0: -1, alpha1: 2 },

  fileRank: 30,
  recognises: (json) => 'alpha0' in json && json.points.length === 4,

  region(f) {
    const d = f.design;
    const index = f.selected;
    const extent = f.view.visible(f.canvas.clientWidth, f.canvas.clientHeight);
    const others = d.points.map((p, i) => (i === index ? null : p));
    return {
      key: JSON.stringify(['point', index, others, d.alpha0, d.alpha1, extent]),
      path: '/api/region/point',
      body: { curve: { points: d.points, alpha0: d.alpha0, alpha1: d.alpha1 }, index, extent, size: POINT_REGION_SIZE },
      canonical: false,
    };
  },
  regionInView: true,
};
