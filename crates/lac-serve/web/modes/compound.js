// A compound curve of two segments through three control points, the first making the share
// r_θ of the turning: /api/compound with "ratio".

import { plane, canonicalRegion, REGION_SIZE } from './plane.js';

export default {
  ...plane,
  name: 'compound',
  label: 'Compound r_θ',
  endpoint: '/api/compound',
  count: 3,
  params: [
    { key: 'alpha0', label: 'α0', min: -3, max: 3, step: 0.01, hint: 'slope of the first piece' },
    { key: 'alpha1', label: 'α1', min: -3, max: 3, step: 0.01, hint: 'slope of the second piece' },
    { key: 'ratio', label: 'r_θ', min: 0.01, max: 0.99, step: 0.01, valid: { above: 0, below: 1 },
      hint: 'share of the turning made by the first piece' },
  ],
  defaults: { points: [[0, 0], [2, 0], [2.6, 1.2]], alpha0: -1, alpha1: 2, ratio: 0.5 },

  fileRank: 30,
  recognises: (json) => 'alpha0' in json && json.points.length !== 4,

  region(f) {
    const { alpha0, alpha1, ratio } = f.design;
    return canonicalRegion({ alpha: alpha0, alpha1, ratio, size: REGION_SIZE }, { alpha0, alpha1, ratio }, f);
  },
};
