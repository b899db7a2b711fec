"""Log-aesthetic curves (LACs) from Python, NumPy in and out.

A log-aesthetic curve has a straight logarithmic curvature graph,
log(rho ds/drho) = alpha log rho + c: the clothoid (alpha = -1), the Nielsen spiral (0),
the logarithmic spiral (1) and the circle involute (2) are members. This package wraps the
Rust library `lac`:

* `Segment`: a segment from three control points and alpha (seed 000);
* `CompoundCurve`: two pieces joined G3, from three points and a turning ratio (seed 004)
  or from four points (seed 002);
* `Curve`: what both offer (sampling, curvature plot, evolute, quasi-aesthetic cubics);
* `RationalCubic` and `QuasiCurve`: rational cubic Beziers with a proven curvature
  monotonicity verdict (seed 001);
* `SpaceSegment`: log-aesthetic space curves (seed 003);
* `Path`: G1/G2 paths from a control polygon, through inflections;
* `Spline`: G2 splines of log-aesthetic segments through points;
* `export`: any of these curves as a STEP, IGES, DXF, SVG or JSON file (`lac export`);
* `drawable_region`, `drawable_region_compound`: drawable-region maps (seed 000 Fig. 9);
* `solve_segments`: many segments in one call, on all cores, with per-curve errors.

Errors: `LacError`, with `InvalidInput` (also a `ValueError`) and `NotDrawable`.
"""

# Every public name of the extension module (typed by `_lac.pyi`): a class or function added
# there is exported here without a list to keep.
from ._lac import *  # noqa: F403
from . import _lac as _extension

__all__ = sorted(name for name in vars(_extension) if not name.startswith("_"))
