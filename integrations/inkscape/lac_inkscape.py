"""What lac's Inkscape extensions share: the selected paths' nodes and Bézier pieces, a
tolerance in document units made local to a path, lac's curves written back as SVG path
data, and lac's refusals shown as Inkscape's error dialog (`inkex.AbortExtension`) with
lac's message, never a traceback."""

from __future__ import annotations

import math
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

import inkex

try:
    import lac
except ImportError as e:  # told in Inkscape's error dialog by `selected_paths`
    lac = None
    MISSING = str(e)

Point = tuple[float, float]
#: A cubic Bézier piece: its four control points.
Cubic = tuple[Point, Point, Point, Point]


@dataclass(frozen=True)
class Subpath:
    """The nodes of one subpath (end points of its commands) and whether it is closed (a
    closed subpath's closing node, back on its first, is left out)."""

    nodes: list[Point]
    closed: bool


def subpaths(element: inkex.PathElement) -> list[Subpath]:
    """The subpaths of a path element, in its own coordinates."""
    path = element.path.to_absolute()
    out: list[Subpath] = []
    for command, end in zip(path, path.end_points):
        if command.letter == "M" or not out:
            out.append(Subpath([(end.x, end.y)], False))
        elif command.letter == "Z":
            nodes = out[-1].nodes
            if len(nodes) > 1 and nodes[-1] == nodes[0]:
                nodes.pop()
            out[-1] = Subpath(nodes, True)
        else:
            out[-1].nodes.append((end.x, end.y))
    return out


def cubics(element: inkex.PathElement) -> list[list[Cubic]]:
    """Each subpath as cubic Bézier pieces (lines and arcs converted by inkex), without
    the pieces of zero length and with a non-zero derivative at both ends (`regular`);
    Inkscape's error dialog for a path of no length."""
    out = []
    for sub in element.path.to_absolute().to_superpath():
        pieces = []
        for a, b in zip(sub, sub[1:]):
            piece = tuple((float(p[0]), float(p[1])) for p in (a[1], a[2], b[0], b[1]))
            if len(set(piece)) > 1:
                pieces.append(regular(piece))
        if pieces:
            out.append(pieces)
    if not out:
        raise inkex.AbortExtension(
            f"lac: path {element.get_id()} has no length: draw two nodes apart"
        )
    return out


#: The parameter where a piece with a retracted handle (zero speed at its end, where the
#: curvature formula divides by zero) is cut: the comb leaves out that sliver of the piece.
RETRACTED_CUT = 1e-6


def split(c: Cubic, t: float) -> tuple[Cubic, Cubic]:
    """De Casteljau: the piece before and after t."""

    def lerp(p: Point, q: Point) -> Point:
        return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))

    a, b, c2 = lerp(c[0], c[1]), lerp(c[1], c[2]), lerp(c[2], c[3])
    d, e = lerp(a, b), lerp(b, c2)
    f = lerp(d, e)
    return (c[0], a, d, f), (f, e, c2, c[3])


def regular(c: Cubic) -> Cubic:
    """The piece with a non-zero derivative at both ends: a straight piece with its handles
    at the thirds (the same line), a retracted handle cut off (RETRACTED_CUT)."""
    p0, p1, p2, p3 = c
    cross = lambda u, v: u[0] * v[1] - u[1] * v[0]  # noqa: E731
    d = (p3[0] - p0[0], p3[1] - p0[1])
    if all(
        abs(cross(d, (q[0] - p0[0], q[1] - p0[1]))) <= 1e-12 * (d[0] ** 2 + d[1] ** 2)
        for q in (p1, p2)
    ):
        return (
            p0,
            (p0[0] + d[0] / 3, p0[1] + d[1] / 3),
            (p0[0] + 2 * d[0] / 3, p0[1] + 2 * d[1] / 3),
            p3,
        )
    if p1 == p0:
        c = split(c, RETRACTED_CUT)[1]
    if c[2] == c[3]:
        c = split(c, 1 - RETRACTED_CUT)[0]
    return c


def local_tolerance(ext: inkex.EffectExtension, element: inkex.BaseElement, value: float) -> float:
    """A length in document units (Inkscape's Document Properties), in the element's own
    coordinates: through the viewBox's scale and the element's transforms (their mean
    scale, the square root of the determinant)."""
    unit = ext.svg.document_unit
    user = ext.svg.viewport_to_unit(f"{value}{unit}", "px")
    (a, c, _), (b, d, _) = element.composed_transform().matrix
    return user / math.sqrt(abs(a * d - b * c))


def path_data(curve: Any, tolerance: float) -> str:
    """A lac curve (Spline, Fit, …) as SVG path data of plain cubic Béziers within
    `tolerance` of it, as `lac export --format svg` writes them; closed with Z when the
    curve is closed (its last point is its first)."""
    text, _ = lac.export(curve, format="svg", tolerance=tolerance)
    d = " ".join(re.findall(r' d="([^"]*)"', text))
    return f"{d} Z" if curve.closed else d


@contextmanager
def lac_errors(element: inkex.BaseElement) -> Iterator[None]:
    """lac's refusals inside, as Inkscape's error dialog naming the path."""
    try:
        yield
    except lac.LacError as e:
        raise inkex.AbortExtension(f"lac: path {element.get_id()}: {e.message}") from None


def selected_paths(ext: inkex.EffectExtension) -> list[inkex.PathElement]:
    """The selected paths, or Inkscape's error dialog when there are none (or when lac is
    not installed)."""
    if lac is None:
        raise inkex.AbortExtension(
            "lac's Python bindings are not installed where Inkscape's Python finds them "
            f"({MISSING}): run `make integrations` in lac's repository"
        )
    paths = list(ext.svg.selection.filter(inkex.PathElement).values())
    if not paths:
        raise inkex.AbortExtension("lac: select one or more paths first")
    return paths


def replace(element: inkex.PathElement, d: str, keep: bool) -> inkex.PathElement:
    """Give the element the path data `d`, or with `keep` a copy of it placed just above."""
    if not keep:
        element.set("d", d)
        return element
    copy = element.duplicate()
    copy.set("d", d)
    return copy
