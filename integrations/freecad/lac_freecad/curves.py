"""Log-aesthetic curves as FreeCAD edges: each kind solved by lac, written as `lac export`
writes it (rational degree-3 B-splines within a tolerance in model units, built in memory
from the NURBS JSON of `lac.export`) and made into a `Part.Edge`.

Planar kinds take points in any plane: 2-D points are in the XY plane; 3-D points must lie
in one plane (within the tolerance), and the curve is solved in that plane's coordinates and
placed back.
"""

from __future__ import annotations

import itertools
import json
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any, Optional, Union

import FreeCAD
import Part
import lac

Vector = FreeCAD.Vector
PointLike = Union[Vector, Sequence[float]]
Alphas = Union[float, Sequence[float]]

#: The default deviation of the B-spline from the exact curve, in model units (mm), as
#: `lac export`'s.
TOLERANCE = 1e-6


class PlaneError(ValueError):
    """Points of a planar kind that do not lie in one plane."""


@dataclass(frozen=True)
class Frame:
    """The plane of a planar curve: `origin` and the unit axes `u`, `v` (its normal is
    u × v). Local (x, y) is origin + x u + y v."""

    origin: Vector
    u: Vector
    v: Vector

    def local(self, p: Vector) -> tuple[float, float]:
        d = p - self.origin
        return (d.dot(self.u), d.dot(self.v))

    def point(self, x: float, y: float) -> Vector:
        return self.origin + self.u * x + self.v * y

    @property
    def normal(self) -> Vector:
        return self.u.cross(self.v)


def vectors(points: Iterable[PointLike]) -> list[Vector]:
    """FreeCAD vectors from vectors, vertices or (x, y) / (x, y, z) sequences."""
    out = []
    for p in points:
        if isinstance(p, Vector):
            out.append(Vector(p))
        elif hasattr(p, "Point"):  # a Part.Vertex
            out.append(Vector(p.Point))
        else:
            c = [float(x) for x in p]
            if len(c) not in (2, 3):
                raise ValueError(f"a point must have 2 or 3 coordinates, got {len(c)}")
            out.append(Vector(c[0], c[1], c[2] if len(c) == 3 else 0.0))
    return out


def plane_of(points: Sequence[Vector], tolerance: float) -> Frame:
    """The plane the points lie in. Points at one height z keep their coordinates (the XY
    plane at that height); other planes take the first point as origin and the direction to
    the farthest point as u. Raises `PlaneError` when a point is off the plane by more than
    `tolerance`."""
    if not points:
        raise ValueError("no points were given")
    if all(abs(p.z - points[0].z) <= tolerance for p in points):
        return Frame(Vector(0, 0, points[0].z), Vector(1, 0, 0), Vector(0, 1, 0))
    origin = points[0]
    far = max(points, key=lambda p: (p - origin).Length)
    u = far - origin
    # The normal of the largest triangle with the first two points chosen: the best
    # conditioned plane through three of them.
    normal = max((u.cross(p - origin) for p in points), key=lambda n: n.Length)
    if normal.Length == 0:
        raise PlaneError("the points are collinear: they span no plane")
    normal.normalize()
    u.normalize()
    frame = Frame(origin, u, normal.cross(u))
    for i, p in enumerate(points):
        off = abs((p - origin).dot(normal))
        if off > tolerance:
            raise PlaneError(
                f"the points are not in one plane: point {i + 1} is {off:.3g} off the plane "
                f"through the others (tolerance {tolerance:g})"
            )
    return frame


def bspline(curve: dict[str, Any], place: Optional[Frame] = None) -> Part.BSplineCurve:
    """One curve of `lac.export`'s NURBS JSON (`degree`, `control_points`, `weights` and the
    full clamped knot vector `knots`) as a FreeCAD B-spline, its 2-D points placed on `place`."""
    knots, mults = [], []
    for knot, run in itertools.groupby(curve["knots"]):
        knots.append(knot)
        mults.append(len(list(run)))
    if curve["dimension"] == 2:
        frame = place or Frame(Vector(0, 0, 0), Vector(1, 0, 0), Vector(0, 1, 0))
        poles = [frame.point(x, y) for x, y in curve["control_points"]]
    else:
        poles = [Vector(*p) for p in curve["control_points"]]
    b = Part.BSplineCurve()
    b.buildFromPolesMultsKnots(poles, mults, knots, False, curve["degree"], curve["weights"])
    return b


@dataclass(frozen=True)
class Built:
    """A curve made into a FreeCAD shape: the edge (or a wire of several), the lac curve
    it was made from and `lac.export`'s report (`pieces`, `max_deviation`, …)."""

    shape: Union[Part.Edge, Part.Wire]
    curve: Any
    report: dict[str, Any]


def build(curve: Any, tolerance: float = TOLERANCE, place: Optional[Frame] = None) -> Built:
    """Export a lac curve (Segment, CompoundCurve, Path, Spline, SpaceSegment or Fit) within
    `tolerance` and make it a FreeCAD shape: one edge, one rational B-spline."""
    text, report = lac.export(curve, format="json", tolerance=tolerance)
    edges = [bspline(c, place).toShape() for c in json.loads(text)["curves"]]
    shape = edges[0] if len(edges) == 1 else Part.Wire(edges)
    return Built(shape, curve, report)


def planar(
    points: Iterable[PointLike], tolerance: float
) -> tuple[list[tuple[float, float]], Frame]:
    """Points of a planar kind in their plane's coordinates, and the plane."""
    vs = vectors(points)
    frame = plane_of(vs, tolerance)
    return [frame.local(p) for p in vs], frame


def segment(points: Iterable[PointLike], alpha: float, tolerance: float = TOLERANCE) -> Built:
    """The log-aesthetic segment of slope `alpha` from three control points (`lac segment`)."""
    xy, frame = planar(points, tolerance)
    return build(lac.Segment(xy, alpha), tolerance, frame)


def compound(
    points: Iterable[PointLike],
    alpha0: float,
    alpha1: float,
    ratio: Optional[float] = None,
    tolerance: float = TOLERANCE,
) -> Built:
    """The compound-rhythm curve of slopes `alpha0` then `alpha1`: from three control points
    and the share `ratio` of the turning taken by the first piece, or from four points
    without it (`lac compound`)."""
    xy, frame = planar(points, tolerance)
    return build(lac.CompoundCurve(xy, alpha0, alpha1, ratio), tolerance, frame)


def path(
    polygon: Iterable[PointLike],
    alpha: Alphas,
    g2: bool = True,
    closed: bool = False,
    tolerance: float = TOLERANCE,
) -> Built:
    """The G2 (or with `g2=False` G1) path of log-aesthetic segments from a control polygon,
    one `alpha` or one per segment (`lac path`)."""
    xy, frame = planar(polygon, tolerance)
    return build(lac.Path(xy, alpha, closed=closed, g2=g2), tolerance, frame)


def spline(
    points: Iterable[PointLike], alpha: float, closed: bool = False, tolerance: float = TOLERANCE
) -> Built:
    """The G2 spline of log-aesthetic segments through the points (`lac spline`)."""
    xy, frame = planar(points, tolerance)
    return build(lac.Spline(xy, alpha, closed=closed), tolerance, frame)


def space(
    points: Iterable[PointLike],
    alpha: float,
    beta: float,
    omega: float = 0.0,
    tolerance: float = TOLERANCE,
) -> Built:
    """The log-aesthetic space segment from four 3-D control points, curvature slope
    `alpha`, torsion slope `beta` and `omega` (`lac space`)."""
    xyz = [(p.x, p.y, p.z) for p in vectors(points)]
    return build(lac.SpaceSegment(xyz, alpha, beta, omega), tolerance)


def fit(
    points: Iterable[PointLike],
    tolerance: Optional[float] = None,
    closed: bool = False,
    max_segments: Optional[int] = None,
    alpha: Optional[float] = None,
    export_tolerance: float = TOLERANCE,
) -> Built:
    """The log-aesthetic path fitted to the points (`lac fit`): the fewest G2 segments
    within `tolerance` of them, or one least-squares segment without it; written within
    `export_tolerance` of the fitted curve."""
    # The points need to be in one plane only as far as the fit's own tolerance.
    xy, frame = planar(points, max(tolerance or 0.0, export_tolerance))
    fitted = lac.fit(xy, tolerance=tolerance, max_segments=max_segments, alpha=alpha, closed=closed)
    return build(fitted, export_tolerance, frame)
