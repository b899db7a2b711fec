"""lac in FreeCAD: log-aesthetic curves as `Part` edges, and the curvature of any edge.

Each kind returns one `Part.Edge` holding one rational degree-3 B-spline within `tolerance`
(model units, default 1e-6) of the exact curve, as `lac export` writes it (a `Part.Wire`
should lac ever write several curves). Errors are lac's: `lac.InvalidInput` (also a
`ValueError`) and `lac.NotDrawable`, with lac's message; `PlaneError` for 3-D points of a
planar kind that are not in one plane.

    import lac_freecad
    edge = lac_freecad.path([(0, 0), (1.5, 0), (3, 0.8), (6, 3.2), (7.5, 4), (9, 4)], -0.5)
    Part.show(edge); Part.show(lac_freecad.curvature_comb(edge))
    lac_freecad.log_curvature_graph(edge).not_monotone   # "the curvature changes sign …"
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Optional, Union

import Part

from . import curves
from .analysis import LogCurvatureGraph, curvature_comb, log_curvature_graph
from .curves import TOLERANCE, Alphas, PlaneError, PointLike

Shape = Union[Part.Edge, Part.Wire]

__all__ = [
    "LogCurvatureGraph",
    "PlaneError",
    "TOLERANCE",
    "compound",
    "curvature_comb",
    "fit",
    "log_curvature_graph",
    "path",
    "segment",
    "space",
    "spline",
]


def segment(points: Iterable[PointLike], alpha: float, tolerance: float = TOLERANCE) -> Shape:
    """The log-aesthetic segment of slope `alpha` from three control points (`lac segment`)."""
    return curves.build_segment(points, alpha, tolerance).shape


def compound(
    points: Iterable[PointLike],
    alpha0: float,
    alpha1: float,
    ratio: Optional[float] = None,
    tolerance: float = TOLERANCE,
) -> Shape:
    """The compound-rhythm curve of slopes `alpha0` then `alpha1`: from three control points
    and the share `ratio` of the turning taken by the first piece, or from four points
    without it (`lac compound`)."""
    return curves.build_compound(points, alpha0, alpha1, ratio, tolerance).shape


def path(
    polygon: Iterable[PointLike],
    alpha: Alphas,
    g2: bool = True,
    closed: bool = False,
    tolerance: float = TOLERANCE,
) -> Shape:
    """The G2 (or with `g2=False` G1) path of log-aesthetic segments from a control polygon,
    one `alpha` or one per segment (`lac path`)."""
    return curves.build_path(polygon, alpha, g2, closed, tolerance).shape


def spline(
    points: Iterable[PointLike], alpha: float, closed: bool = False, tolerance: float = TOLERANCE
) -> Shape:
    """The G2 spline of log-aesthetic segments through the points (`lac spline`)."""
    return curves.build_spline(points, alpha, closed, tolerance).shape


def space(
    points: Iterable[PointLike],
    alpha: float,
    beta: float,
    omega: float = 0.0,
    tolerance: float = TOLERANCE,
) -> Shape:
    """The log-aesthetic space segment from four 3-D control points, curvature slope
    `alpha`, torsion slope `beta` and `omega` (`lac space`)."""
    return curves.build_space(points, alpha, beta, omega, tolerance).shape


def fit(
    points: Iterable[PointLike],
    tolerance: Optional[float] = None,
    closed: bool = False,
    max_segments: Optional[int] = None,
    alpha: Optional[float] = None,
    export_tolerance: float = TOLERANCE,
) -> Shape:
    """The log-aesthetic path fitted to the points (`lac fit`): the fewest G2 segments
    within `tolerance` of them, or one least-squares segment without it; written within
    `export_tolerance` of the fitted curve."""
    return curves.build_fit(
        points, tolerance, closed, max_segments, alpha, export_tolerance
    ).shape
