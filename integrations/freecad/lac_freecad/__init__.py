"""lac in FreeCAD: log-aesthetic curves as `Part` edges, and the curvature of any edge.

Each kind returns one `Part.Edge` holding one rational degree-3 B-spline within `tolerance`
(model units, default 1e-6) of the exact curve, as `lac export` writes it (a `Part.Wire`
should lac ever write several curves); `curves.<kind>` takes the same arguments and returns
the edge with the lac curve and the export's report. Errors are lac's: `lac.InvalidInput`
(also a `ValueError`) and `lac.NotDrawable`, with lac's message; `PlaneError` for 3-D points
of a planar kind that are not in one plane.

    import lac_freecad
    edge = lac_freecad.path([(0, 0), (1.5, 0), (3, 0.8), (6, 3.2), (7.5, 4), (9, 4)], -0.5)
    Part.show(edge); Part.show(lac_freecad.curvature_comb(edge))
    lac_freecad.log_curvature_graph(edge).not_monotone   # "dκ/ds changes sign near s = 2.63363"
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import ParamSpec, Union

import Part

from . import curves
from .analysis import LogCurvatureGraph, curvature_comb, log_curvature_graph
from .curves import TOLERANCE, PlaneError

Shape = Union[Part.Edge, Part.Wire]
P = ParamSpec("P")

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


def _shape_of(build: Callable[P, curves.Built]) -> Callable[P, Shape]:
    """A kind of `curves` that returns only its FreeCAD shape."""

    @functools.wraps(build)
    def shape(*args: P.args, **kwargs: P.kwargs) -> Shape:
        return build(*args, **kwargs).shape

    return shape


segment = _shape_of(curves.segment)
compound = _shape_of(curves.compound)
path = _shape_of(curves.path)
spline = _shape_of(curves.spline)
space = _shape_of(curves.space)
fit = _shape_of(curves.fit)
