// A log-aesthetic segment through three control points (seed 000): /api/segment.

import { plane, canonicalRegion, REGION_SIZE } from './plane.js';

export default {
  ...plane,
  name: 'segment',
  label: 'Segment',
  endpoint: '/api/segment',
  count: 3,
  params: [
    { key: 'alpha', label: 'α', min: -3, max: 3, step: 0.01,
      hint: 'slope of the logarithmic curvature graph: −1 clothoid, 0 Nielsen spiral, 1 log spiral, 2 circle involute' },
  ],
  defaults: { points: [[-1, 0], [-0.2, 0.8], [1, 0]], alpha: 0.5 },

  /** Any other file of three points is a segment's design: this mode is asked last. */
  fileRank: 90,
  recognises: () => true,

  region: (f) => canonicalRegion({ alpha: f.design.alpha, size: REGION_SIZE }, { alpha: f.design.alpha }, f),
};
