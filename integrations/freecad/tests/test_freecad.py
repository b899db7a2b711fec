"""The FreeCAD workbench, headless: `freecadcmd integrations/freecad/tests/test_freecad.py`.

Each kind is built through `lac_freecad` as FreeCAD imports it from its Mod folder (`make
integrations` installs it there), then read back through FreeCAD's own API (`curvatureAt`,
`getParameterByLength`, `Length`, `distToShape`) and compared with what lac reports for the
same input.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
import unittest

import FreeCAD
import Part
import lac
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
import testing  # noqa: E402 (integrations/testing.py)

import lac_freecad  # noqa: E402 (from FreeCAD's Mod folder)
from lac_freecad import features  # noqa: E402

Vector = FreeCAD.Vector
TOL = 1e-6
SEGMENT = [(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)]
POLYGON = [(0, 0), (1.5, 0), (3, 0.8), (6, 3.2), (7.5, 4), (9, 4)]
CLOSED = [(0, 0), (3, 0), (4, 2), (2, 4), (-1, 2)]
THROUGH = [(0, 0), (2, 0.3), (3.5, 1.5), (4, 3)]
WAVE = [(0, 0.3), (1, 0.93), (2, 0.86), (3, 0.14), (4, -0.69), (5, -1)]
SPACE = [(0, 0, 0), (3, 0, 0), (3, 3, 1.5), (0, 3, 3)]


def curvature_at_s(edge: Part.Edge, s: float) -> float:
    """FreeCAD's curvature at arc length `s` (clamped to the edge: lac's arc length and
    FreeCAD's differ by the tolerance)."""
    return edge.curvatureAt(edge.getParameterByLength(min(max(s, 0.0), edge.Length)))


def curvature_deviation(edge: Part.Edge, curve: lac.Curve) -> float:
    """The largest relative difference between FreeCAD's curvature of the edge and lac's of
    the curve, at 101 stations equally spaced in arc length."""
    worst = 0.0
    for s in np.linspace(0, curve.arc_length, 101):
        expected = abs(curve.curvature_at_s(s))
        got = curvature_at_s(edge, s * edge.Length / curve.arc_length)
        worst = max(worst, abs(got - expected) / expected)
    return worst


def interior_knots(edge: Part.Edge) -> list[float]:
    knots = edge.Curve.getKnots()
    return knots[1:-1]


def distance(edge: Part.Edge, point: np.ndarray) -> float:
    p = Vector(*point) if len(point) == 3 else Vector(point[0], point[1], 0)
    return edge.distToShape(Part.Vertex(p))[0]


class Kinds(unittest.TestCase):
    """Every kind as lac draws it: within the tolerance, its length and ends as lac's."""

    def assert_follows(
        self, edge: Part.Edge, points: np.ndarray, length: float, rational: bool = True
    ) -> None:
        self.assertIsInstance(edge, Part.Edge)
        self.assertEqual(edge.Curve.TypeId, "Part::GeomBSplineCurve")
        self.assertEqual(edge.Curve.Degree, 3)
        self.assertEqual(edge.Curve.isRational(), rational)
        worst = max(distance(edge, p) for p in points)
        self.assertLess(worst, TOL)
        self.assertAlmostEqual(edge.Length, length, delta=10 * TOL)
        self.assertLess(distance(edge, points[0]) + distance(edge, points[-1]), 1e-9)

    def test_segment_curvature_agrees_with_lac_at_101_stations(self) -> None:
        seg = lac.Segment(SEGMENT, 0.5)
        edge = lac_freecad.segment(SEGMENT, 0.5)
        self.assert_follows(edge, seg.sample(101).points, seg.arc_length)
        worst = curvature_deviation(edge, seg)
        print(f"\n  segment alpha 0.5: max relative curvature deviation {worst:.2e}", end=" ")
        self.assertLess(worst, 1e-5)
        # The ends keep lac's curvature (each piece is a G2 Hermite fit of its ends).
        self.assertAlmostEqual(
            edge.curvatureAt(edge.FirstParameter), seg.curvature_start, delta=1e-12
        )
        self.assertAlmostEqual(edge.curvatureAt(edge.LastParameter), seg.curvature_end, delta=1e-12)

    def test_compound_from_three_and_four_points(self) -> None:
        for points, ratio in [
            ([(0, 0), (2, 0), (2.6, 1.2)], 0.5),
            ([(0, 0), (1, 0), (2, 0.5), (2.5, 1.5)], None),
        ]:
            c = lac.CompoundCurve(points, -1, 2, ratio)
            edge = lac_freecad.compound(points, -1, 2, ratio)
            self.assert_follows(edge, c.sample(101).points, c.arc_length)
            worst = curvature_deviation(edge, c)
            print(
                f"\n  compound, {len(points)} points: max relative curvature deviation {worst:.2e}",
                end=" ",
            )
            self.assertLess(worst, 1e-4)

    def test_space_segment(self) -> None:
        s = lac.SpaceSegment(SPACE, 0.5, 0, 0.3)
        edge = lac_freecad.space(SPACE, 0.5, 0, 0.3)
        frames = s.sample(101)
        # Cubic Hermite pieces (docs/cad.md): polynomial, C1.
        self.assert_follows(edge, frames.points, s.arc_length, rational=False)
        worst = max(
            abs(curvature_at_s(edge, si) - k) / k for si, k in zip(frames.s, frames.curvature)
        )
        print(f"\n  space segment: max relative curvature deviation {worst:.2e}", end=" ")
        self.assertLess(worst, 1e-2)

    def test_fit_to_points_of_a_segment(self) -> None:
        seg = lac.Segment(SEGMENT, 0.5)
        points = seg.sample(40).points
        edge = lac_freecad.fit(points, tolerance=1e-3)
        self.assertLess(max(distance(edge, p) for p in points), 1e-3)
        self.assertAlmostEqual(edge.Length, seg.arc_length, delta=1e-3)

    def test_a_tilted_plane_gives_the_same_curve(self) -> None:
        rotation = FreeCAD.Rotation(Vector(1, 2, 3), 40)
        shift = Vector(5, -2, 7)
        tilted = [rotation.multVec(Vector(x, y, 0)) + shift for x, y in THROUGH]
        flat = lac_freecad.spline(THROUGH, 0.5)
        edge = lac_freecad.spline(tilted, 0.5)
        self.assertAlmostEqual(edge.Length, flat.Length, delta=1e-9)
        for p in tilted:
            self.assertLess(edge.distToShape(Part.Vertex(p))[0], 1e-9)
        off = list(tilted)
        off[2] = off[2] + rotation.multVec(Vector(0, 0, 0.1))
        with self.assertRaisesRegex(lac_freecad.PlaneError, "point 3 is 0.1 off the plane"):
            lac_freecad.spline(off, 0.5)


class G2(unittest.TestCase):
    """Paths and splines are G2 as FreeCAD reads them: the curvature on both sides of every
    knot agrees, and the ends have lac's curvature."""

    def assert_g2(self, edge: Part.Edge, closed: bool) -> float:
        """The largest curvature jump at a knot, relative to the edge's largest curvature.
        Where lac's export writes the middle of an inflection as a straight span (curvature
        exactly 0 on one side), the other side's curvature is what the segment has there:
        below 2e-3 of the largest (docs/cad.md, "Splines")."""
        kmax = max(curvature_at_s(edge, edge.Length * i / 400) for i in range(401))
        worst = 0.0
        span = edge.LastParameter - edge.FirstParameter
        for k in interior_knots(edge):
            left = edge.curvatureAt(k - 1e-9 * span)
            right = edge.curvatureAt(k + 1e-9 * span)
            if min(left, right) == 0.0:
                self.assertLess(max(left, right), 2e-3 * kmax)
            else:
                worst = max(worst, abs(left - right) / kmax)
        if closed:
            a, b = edge.curvatureAt(edge.FirstParameter), edge.curvatureAt(edge.LastParameter)
            worst = max(worst, abs(a - b) / kmax)
            self.assertLess(
                edge.valueAt(edge.FirstParameter).distanceToPoint(edge.valueAt(edge.LastParameter)),
                1e-12,
            )
        self.assertLess(worst, 1e-6)
        return worst

    def test_open_path_through_an_inflection(self) -> None:
        path = lac.Path(POLYGON, -0.5)
        edge = lac_freecad.path(POLYGON, -0.5)
        jump = self.assert_g2(edge, closed=False)
        print(f"\n  open path: largest relative curvature jump at a knot {jump:.1e}", end=" ")
        ends = path.end_curvatures
        self.assertAlmostEqual(edge.curvatureAt(edge.FirstParameter), abs(ends[0][0]), delta=1e-9)
        self.assertAlmostEqual(edge.curvatureAt(edge.LastParameter), abs(ends[-1][1]), delta=1e-9)
        self.assertAlmostEqual(edge.Length, path.arc_length, delta=10 * TOL)
        self.assertLess(max(distance(edge, p) for p in path.sample(201).points), TOL)

    def test_closed_path(self) -> None:
        path = lac.Path(CLOSED, 0.5, closed=True)
        edge = lac_freecad.path(CLOSED, 0.5, closed=True)
        self.assert_g2(edge, closed=True)
        self.assertTrue(edge.isClosed())
        self.assertAlmostEqual(edge.Length, path.arc_length, delta=10 * TOL)

    def test_splines_open_closed_and_through_inflections(self) -> None:
        for points, alpha, closed in [
            (THROUGH, 0.5, False),
            (CLOSED, 0.5, True),
            (WAVE, -0.5, False),
        ]:
            spline = lac.Spline(points, alpha, closed=closed)
            edge = lac_freecad.spline(points, alpha, closed=closed)
            self.assert_g2(edge, closed)
            self.assertAlmostEqual(edge.Length, spline.arc_length, delta=10 * TOL)
            for p in points:
                self.assertLess(distance(edge, np.array(p, float)), 1e-9)

    def test_g1_path_jumps_as_lac_says(self) -> None:
        path = lac.Path(CLOSED, [1, 0.5, 0.8], g2=False)
        edge = lac_freecad.path(CLOSED, [1, 0.5, 0.8], g2=False)
        ends = path.end_curvatures
        jumps = sorted(abs(abs(ends[i][1]) - abs(ends[i + 1][0])) for i in range(len(ends) - 1))
        span = edge.LastParameter - edge.FirstParameter
        seen = sorted(
            abs(edge.curvatureAt(k - 1e-9 * span) - edge.curvatureAt(k + 1e-9 * span))
            for k in interior_knots(edge)
        )
        # Every path joint is a knot; the other knots join pieces of one segment, G2.
        self.assertTrue(np.allclose(seen[-len(jumps) :], jumps, atol=1e-6), (seen, jumps))
        self.assertGreater(max(jumps), 0.05)


class Analysis(unittest.TestCase):
    """The comb and the logarithmic curvature graph of any edge, sampled by FreeCAD."""

    def test_comb_teeth_are_the_curvature_times_the_scale(self) -> None:
        seg = lac.Segment(SEGMENT, 0.5)
        edge = lac_freecad.segment(SEGMENT, 0.5)
        comb = lac_freecad.curvature_comb(edge, samples=21, scale=2.0)
        teeth = comb.Edges[:21]
        self.assertEqual(len(comb.Edges), 21 + 20)
        for i, tooth in enumerate(teeth):
            s = seg.arc_length * i / 20
            self.assertAlmostEqual(tooth.Length, 2.0 * abs(seg.curvature_at_s(s)), delta=1e-5)
            # Away from the centre of curvature: the tip is farther from it than the foot.
            centre = edge.centerOfCurvatureAt(
                edge.getParameterByLength(s * edge.Length / seg.arc_length)
            )
            foot, tip = tooth.Vertexes[0].Point, tooth.Vertexes[1].Point
            self.assertGreater((tip - centre).Length, (foot - centre).Length)

    def test_comb_default_scale_is_a_fifth_of_the_length(self) -> None:
        edge = lac_freecad.path(POLYGON, -0.5)
        comb = lac_freecad.curvature_comb(edge)
        longest = max(e.Length for e in comb.Edges[:101])
        self.assertAlmostEqual(longest, 0.2 * edge.Length, delta=1e-9)

    def test_graph_of_a_segment_gives_its_alpha_back(self) -> None:
        for alpha in (-1.0, 0.0, 0.5, 2.0):
            edge = lac_freecad.segment(SEGMENT, alpha)
            graph = lac_freecad.log_curvature_graph(edge)
            self.assertTrue(graph.monotone, graph.not_monotone)
            self.assertAlmostEqual(graph.alpha, alpha, delta=1e-4)
            self.assertGreater(len(graph.points), 150)

    def test_graph_of_freecad_curves(self) -> None:
        circle = lac_freecad.log_curvature_graph(Part.makeCircle(2))
        self.assertTrue(circle.monotone)
        self.assertIsNone(circle.alpha)
        ellipse = Part.Ellipse(Vector(), 3, 1).toShape()
        graph = lac_freecad.log_curvature_graph(ellipse)
        self.assertFalse(graph.monotone)
        self.assertIn("dκ/ds changes sign", graph.not_monotone)
        # A quarter of the ellipse, from the end of its minor axis to the end of its major
        # axis: curvature increasing all along.
        quarter = Part.Ellipse(Vector(), 3, 1).toShape(math.pi / 2, math.pi)
        self.assertTrue(lac_freecad.log_curvature_graph(quarter).monotone)

    def test_inflection_is_named(self) -> None:
        edge = lac_freecad.spline(WAVE, -0.5)
        graph = lac_freecad.log_curvature_graph(edge)
        self.assertFalse(graph.monotone)
        self.assertRegex(graph.not_monotone, "inflection|changes sign")


class BadInput(unittest.TestCase):
    """Scripts get lac's exceptions with lac's message; objects keep lac's message in their
    `Error` property and their last shape, with no exception out of the recompute."""

    CASES = [
        ([(0, 0)], 0.5, lac.InvalidInput),
        ([(0, 0), (0, 0), (1, 1)], 0.5, lac.InvalidInput),
        (SEGMENT, 50.0, lac.NotDrawable),
    ]

    def test_scripts_get_lacs_message(self) -> None:
        for points, alpha, error in self.CASES:
            try:
                lac.Segment(points, alpha)
            except lac.LacError as e:
                expected = e.message
            with self.assertRaises(error) as raised:
                lac_freecad.segment(points, alpha)
            self.assertEqual(raised.exception.message, expected)

    def test_objects_keep_the_message_and_their_shape(self) -> None:
        doc = FreeCAD.newDocument("bad")
        obj = features.make_curve("segment", SEGMENT, doc, Alpha=0.5)
        length = obj.Shape.Length
        for points, alpha, _ in self.CASES:
            obj.Points = [Vector(x, y, 0) for x, y in points]
            obj.Alpha = alpha
            doc.recompute()
            self.assertIn(obj.Error.split(":")[0].split(" ")[0], ("points", "control", "not"))
            self.assertAlmostEqual(obj.Shape.Length, length)
        obj.Points = [Vector(x, y, 0) for x, y in SEGMENT]
        obj.Alpha = 0.5
        doc.recompute()
        self.assertEqual(obj.Error, "")
        FreeCAD.closeDocument(doc.Name)


class Objects(unittest.TestCase):
    """Parametric objects: properties in, shape out, updated on change, saved and reopened."""

    def test_every_kind_builds_and_updates(self) -> None:
        doc = FreeCAD.newDocument("kinds")
        for kind in features.KINDS.values():
            points = kind.example or [tuple(p) for p in lac.Segment(SEGMENT, 0.5).sample(30).points]
            obj = features.make_curve(kind.name, points, doc)
            self.assertEqual(obj.Error, "", kind.name)
            self.assertTrue(obj.Shape.isValid(), kind.name)
            self.assertGreater(obj.Pieces, 0)
            self.assertLess(obj.MaxDeviation, obj.Tolerance)
            self.assertAlmostEqual(obj.Shape.Length, obj.ArcLength, delta=1e-5)
        FreeCAD.closeDocument(doc.Name)

    def test_alpha_edit_rebuilds_the_path_and_its_comb(self) -> None:
        doc = FreeCAD.newDocument("edit")
        obj = features.make_curve("path", POLYGON, doc, Alpha=-0.5)
        comb = features.make_comb(obj)
        before = obj.Shape.Length, comb.Shape.BoundBox.YMax
        obj.Alpha = -1.0
        doc.recompute()
        self.assertAlmostEqual(obj.ArcLength, lac.Path(POLYGON, -1.0).arc_length, delta=1e-9)
        self.assertNotAlmostEqual(obj.Shape.Length, before[0], delta=1e-6)
        self.assertNotAlmostEqual(comb.Shape.BoundBox.YMax, before[1], delta=1e-6)
        self.assertFalse(comb.Monotone)
        path = tempfile.mktemp(suffix=".FCStd")
        doc.saveAs(path)
        FreeCAD.closeDocument(doc.Name)
        doc = FreeCAD.openDocument(path)
        obj = doc.getObject("Path")
        obj.Alpha = -0.5
        doc.recompute()
        self.assertAlmostEqual(obj.Shape.Length, before[0], delta=1e-12)
        self.assertTrue(all(o.isValid() for o in doc.Objects))
        FreeCAD.closeDocument(doc.Name)
        os.remove(path)


class Installed(unittest.TestCase):
    def test_lac_freecad_is_imported_from_the_mod_folder(self) -> None:
        mods = [
            os.path.join(FreeCAD.getUserAppDataDir(), "Mod"),
            os.path.join(FreeCAD.getHomePath(), "Mod"),
        ]
        self.assertTrue(any(lac_freecad.__file__.startswith(m) for m in mods), lac_freecad.__file__)
        self.assertTrue(
            os.path.exists(os.path.join(os.path.dirname(lac_freecad.__file__), "..", "InitGui.py"))
        )


testing.run(sys.modules[__name__])
