"""Curvature analysis of any FreeCAD edge: sampled by FreeCAD's own evaluation of its curve
(`Edge.curvatureAt`, `derivative1At` … `derivative3At`, `getParameterByLength`), analysed
by lac (`lac.CurvaturePlot.from_samples`: the logarithmic curvature graph, its fitted slope
and the monotonicity verdict that `lac lcg` prints).

The samples are equally spaced in arc length. On a planar edge the curvature is signed
(positive where the edge turns left about its plane's normal), so that an inflection shows;
on a space edge it is FreeCAD's unsigned curvature. dκ/ds comes from the derivatives:
with d1, d2, d3 the derivatives in the edge's parameter t and n the plane's normal,
κ = (d1 × d2)·n / |d1|³ and dκ/ds = ((d1 × d3)·n / |d1|³ − 3κ (d1·d2) / |d1|²) / |d1|;
for a space edge the same with |d1 × d2| and (d1 × d2)·(d1 × d3) / |d1 × d2| in place of
the products with n.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import FreeCAD
import Part
import lac

Vector = FreeCAD.Vector

#: Samples of the comb and of the graph unless told.
COMB_SAMPLES = 101
GRAPH_SAMPLES = 201


@dataclass(frozen=True)
class CurvatureSamples:
    """An edge's curvature at `len(s)` points equally spaced in arc length."""

    s: list[float]
    points: list[Vector]
    kappa: list[float]
    dkappa_ds: list[float]
    #: Unit principal normals (towards the centre of curvature), zero where κ = 0.
    normals: list[Vector]
    #: The plane's unit normal when the edge is planar, else None (κ unsigned).
    plane_normal: Optional[Vector]

    def plot(self) -> lac.CurvaturePlot:
        """The samples as lac's curvature plot (with the points' x and y)."""
        xy = [(p.x, p.y) for p in self.points]
        return lac.CurvaturePlot.from_samples(self.s, self.kappa, self.dkappa_ds, xy)


def plane_normal(edge: Part.Edge) -> Optional[Vector]:
    """The unit normal of the plane an edge lies in, or None for a straight or space edge."""
    if edge.Curve.TypeId == "Part::GeomLine":
        return None
    plane = edge.findPlane()
    return None if plane is None else Vector(plane.Axis).normalize()


def sample_curvature(edge: Part.Edge, samples: int) -> CurvatureSamples:
    """The edge's curvature at `samples` points equally spaced in arc length."""
    if samples < 2:
        raise ValueError(f"samples must be at least 2, got {samples}")
    length = edge.Length
    if not length > 0:
        raise ValueError("the edge has no length")
    n = plane_normal(edge)
    out = CurvatureSamples([], [], [], [], [], n)
    for i in range(samples):
        s = length * i / (samples - 1)
        t = edge.getParameterByLength(s)
        d1, d2, d3 = edge.derivative1At(t), edge.derivative2At(t), edge.derivative3At(t)
        speed = d1.Length
        if speed == 0:
            raise ValueError(f"the edge has a cusp (zero speed) at arc length {s:.6g}")
        kappa = edge.curvatureAt(t)
        cross, cross3 = d1.cross(d2), d1.cross(d3)
        if n is not None:
            signed = math.copysign(kappa, cross.dot(n)) if kappa > 0 else 0.0
            dk_dt = cross3.dot(n) / speed**3 - 3 * signed * d1.dot(d2) / speed**2
        else:
            signed = kappa
            dk_dt = (
                cross.dot(cross3) / (cross.Length * speed**3) - 3 * kappa * d1.dot(d2) / speed**2
                if cross.Length > 0
                else 0.0
            )
        # (FreeCAD's `normalize` refuses short vectors: near an inflection this one is.)
        normal = cross.cross(d1)
        normal = normal * (1 / normal.Length) if normal.Length > 0 else Vector()
        out.s.append(s)
        out.points.append(edge.valueAt(t))
        out.kappa.append(signed)
        out.dkappa_ds.append(dk_dt / speed)
        out.normals.append(normal)
    return out


def curvature_comb(
    edge: Part.Edge, samples: int = COMB_SAMPLES, scale: Optional[float] = None
) -> Part.Compound:
    """The curvature comb of an edge as a compound of lines: a tooth at each of `samples`
    points, of length `scale` × |κ| away from the centre of curvature, and the polyline
    through the teeth's tips. Without `scale` the longest tooth is a fifth of the edge's
    length."""
    c = sample_curvature(edge, samples)
    kmax = max(abs(k) for k in c.kappa)
    if scale is None:
        scale = 0.2 * edge.Length / kmax if kmax > 0 else 0.0
    tips = [p - nrm * (scale * abs(k)) for p, nrm, k in zip(c.points, c.normals, c.kappa)]
    lines = [Part.LineSegment(p, q).toShape() for p, q in zip(c.points, tips) if p != q]
    lines += [Part.LineSegment(p, q).toShape() for p, q in zip(tips, tips[1:]) if p != q]
    return Part.makeCompound(lines)


@dataclass(frozen=True)
class LogCurvatureGraph:
    """An edge's logarithmic curvature graph as lac measures it: the points (ln ρ,
    ln(ρ |ds/dρ|)), the least-squares line's slope `alpha` (None when the graph has no
    line: a circle, a straight line), its intercept and RMS residual, and whether the
    curvature is monotone (if not, `not_monotone` says where it turns)."""

    points: list[tuple[float, float]]
    alpha: Optional[float]
    intercept: Optional[float]
    rms_residual: Optional[float]
    monotone: bool
    not_monotone: Optional[str]


def log_curvature_graph(edge: Part.Edge, samples: int = GRAPH_SAMPLES) -> LogCurvatureGraph:
    """The logarithmic curvature graph of any edge, sampled at `samples` points."""
    plot = sample_curvature(edge, samples).plot()
    graph = plot.log_curvature_graph()
    why = plot.not_monotone()
    fit = graph.fit
    return LogCurvatureGraph(
        points=[(float(x), float(y)) for x, y in graph.points],
        alpha=None if fit is None else fit.alpha,
        intercept=None if fit is None else fit.intercept,
        rms_residual=None if fit is None else fit.rms_residual,
        monotone=why is None,
        not_monotone=why,
    )
