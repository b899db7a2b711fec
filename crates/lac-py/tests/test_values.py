"""The bindings answer exactly what the library answers: every number equals the `lac`
command line's (the same Rust code; JSON numbers round-trip), and the alpha = -1 segments
agree with the independent Clothoids library."""

import math
import os
import sys

import numpy as np
import pytest

import lac
from conftest import points_arg

SEGMENTS = [
    ([(-1.0, 0.0), (-0.2, 0.8), (1.0, 0.0)], 0.5),
    ([(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)], -1.0),
    ([(0.0, 0.0), (1.0, 0.0), (1.6, 0.9)], 2.0),
    ([(1e3, -2e3), (1.3e3, -1.1e3), (2.5e3, -0.7e3)], 0.0),
    ([(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], 1.0),
]


@pytest.mark.parametrize("points,alpha", SEGMENTS)
def test_segment_equals_the_command_line(cli, points, alpha):
    ref = cli("segment", "--points", points_arg(points), "--alpha", repr(alpha),
              "--samples", "17")
    seg = lac.Segment(points, alpha)
    assert seg.alpha == ref["alpha"]
    assert seg.lambda_ == ref["lambda"]
    assert seg.arc_length == ref["arc_length"]
    assert seg.curvature_start == ref["curvature_start"]
    assert seg.curvature_end == ref["curvature_end"]
    assert seg.turning_angle == ref["turning_angle"]
    samples = seg.sample(17)
    rows = ref["samples"]
    assert samples.s.tolist() == [r["s"] for r in rows]
    assert samples.points.tolist() == [[r["x"], r["y"]] for r in rows]
    assert samples.theta.tolist() == [r["theta"] for r in rows]
    assert samples.kappa.tolist() == [r["kappa"] for r in rows]


@pytest.mark.parametrize("points,alpha", SEGMENTS)
def test_vectorised_equals_single_calls(points, alpha):
    batch = lac.solve_segments(np.array([points] * 3), alpha, samples=9)
    seg = lac.Segment(points, alpha)
    assert batch.ok.tolist() == [True] * 3
    assert batch.arc_length.tolist() == [seg.arc_length] * 3
    assert batch.lambda_.tolist() == [seg.lambda_] * 3
    assert batch.curvature_start.tolist() == [seg.curvature_start] * 3
    assert batch.curvature_end.tolist() == [seg.curvature_end] * 3
    assert batch.turning.tolist() == [seg.turning] * 3
    assert batch.points is not None and batch.kappa is not None
    assert batch.points.shape == (3, 9, 2)
    assert (batch.points[2] == seg.sample(9).points).all()
    assert (batch.kappa[1] == seg.sample(9).kappa).all()


def test_compound_equals_the_command_line(cli):
    three = [(0.0, 0.0), (2.0, 0.0), (2.6, 1.2)]
    ref = cli("compound", "--points", points_arg(three), "--alpha0", "-1", "--alpha1", "2",
              "--ratio", "0.5", "--samples", "9")
    c = lac.CompoundCurve(three, -1.0, 2.0, 0.5)
    assert (c.alpha0, c.alpha1) == (ref["alpha0"], ref["alpha1"])
    assert c.arc_length == ref["arc_length"]
    assert c.joint_s == ref["joint_s"]
    assert c.lambda_ == ref["lambda"]
    assert c.curvature_joint == ref["curvature_joint"]
    assert c.joint.tolist() == ref["joint"]
    assert c.joints.tolist() == [ref["joint_s"]]
    assert c.sample(9).points.tolist() == [[r["x"], r["y"]] for r in ref["samples"]]
    lcg = c.lcg()
    for mine, theirs in zip(lcg, ref["lcg"]):
        assert mine is not None and theirs is not None
        assert mine.alpha == theirs["alpha"]
        assert mine.intercept == theirs["intercept"]

    four = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.5), (2.5, 1.5)]
    ref = cli("compound", "--points", points_arg(four), "--alpha0", "0.5", "--alpha1", "1.5",
              "--samples", "5")
    c = lac.CompoundCurve.from_four_points(four, 0.5, 1.5)
    assert c.arc_length == ref["arc_length"]
    assert c.sample(5).kappa.tolist() == [r["kappa"] for r in ref["samples"]]
    assert len(c.pieces) == 2
    assert sum(p.arc_length for p in c.pieces) == pytest.approx(c.arc_length, rel=1e-15)


def test_quasi_fit_equals_the_command_line(cli):
    points = [(0.0, 0.0), (3.0, 0.0), (4.0, 1.5)]
    ref = cli("quasi", "--points", points_arg(points), "--alpha", "-1", "--tolerance", "1e-5")
    q = lac.Segment(points, -1.0).to_rational_cubics(1e-5)
    assert len(q) == len(ref["pieces"])
    assert q.control_points.tolist() == [p["points"] for p in ref["pieces"]]
    assert q.weights.tolist() == [p["weights"] for p in ref["pieces"]]
    for piece, row in zip(q.pieces, ref["pieces"]):
        assert piece.monotonicity.verdict == row["monotone"]
        assert piece.monotonicity.proven == row["proven"]
        assert list(piece.turning) == row["turning"]
        assert piece.max_deviation == row["max_deviation"]
    assert q.is_monotone
    # Plain cubics: all weights 1.
    cubics = lac.Segment(points, -1.0).to_cubics(1e-5)
    assert (cubics.weights == 1.0).all()
    # The seed's single rational cubic.
    ref = cli("quasi", "--points", points_arg(points), "--alpha", "-1")
    one = lac.Segment(points, -1.0).to_rational_cubic()
    assert one.control_points.tolist() == [p["points"] for p in ref["pieces"]]


def test_monotonicity_equals_the_command_line(cli):
    points = [(0.0, 0.0), (1.0, 0.0), (2.0, 1.0), (3.0, 3.0)]
    ref = cli("monotone", "--points", points_arg(points), "--weights", "1,2,1,1")
    report = lac.RationalCubic(points, [1, 2, 1, 1]).curvature_monotonicity()
    assert report.verdict == ref["verdict"] == "not_monotone"
    assert report.proven == ref["proven"]
    assert report.t == ref["t"]
    assert not report.is_monotone


def test_space_segment_equals_the_command_line(cli):
    points = [(0.0, 0.0, 0.0), (3.0, 0.0, 0.0), (3.0, 3.0, 1.5), (0.0, 3.0, 3.0)]
    ref = cli("space", "--points", points_arg(points), "--alpha", "0.5", "--beta", "0",
              "--omega", "0.3", "--samples", "7", "--frames")
    seg = lac.SpaceSegment(points, 0.5, 0.0, omega=0.3)
    assert seg.arc_length == ref["arc_length"]
    assert seg.is_planar == ref["planar"]
    frames = seg.sample(7)
    rows = ref["samples"]
    assert frames.points.tolist() == [[r["x"], r["y"], r["z"]] for r in rows]
    assert frames.curvature.tolist() == [r["kappa"] for r in rows]
    assert frames.torsion.tolist() == [r["tau"] for r in rows]
    assert frames.tangents.tolist() == [r["t"] for r in rows]
    assert frames.normals.tolist() == [r["n"] for r in rows]
    assert frames.binormals.tolist() == [r["b"] for r in rows]


@pytest.mark.parametrize("args", [(-1.0,), (0.5,), (2.0,), (-1.0, 2.0, 0.5)])
def test_region_equals_the_command_line(cli, args):
    if len(args) == 1:
        ref = cli("region", "--alpha", repr(args[0]), "--size", "48", "--format", "json")
        mine = lac.drawable_region(args[0], 48)
    else:
        ref = cli("region", "--alpha0", repr(args[0]), "--alpha1", repr(args[1]), "--ratio",
                  repr(args[2]), "--size", "48", "--format", "json")
        mine = lac.drawable_region_compound(*args, size=48)
    assert mine.dtype == np.bool_ and mine.shape == (48, 48)
    assert mine.tolist() == ref["drawable"]
    assert lac.pixel_center(48, 0, 0) == (-1 + 1 / 48, 1 - 1 / 48)
    row, col = 20, 30
    x, y = lac.pixel_center(48, row, col)
    if len(args) == 1:
        assert lac.is_drawable(args[0], (x, y)) == mine[row, col]


def test_curvature_plot_and_lcg():
    seg = lac.Segment([(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)], 0.5)
    plot = seg.curvature_plot(65)
    assert plot.kappa.tolist() == seg.sample(65).kappa.tolist()
    graph = plot.log_curvature_graph()
    assert graph.fit is not None
    assert graph.fit.alpha == pytest.approx(0.5, abs=1e-9)
    line = seg.lcg()
    assert line is not None and line.alpha == 0.5
    # The line through the graph's points is the segment's LCG line.
    x, y = graph.points[:, 0], graph.points[:, 1]
    assert np.max(np.abs(line.alpha * x + line.intercept - y)) < 1e-9
    # The same from a quasi-aesthetic chain's Bezier pieces, by the module function.
    q = seg.to_rational_cubics(1e-8)
    chain_plot = lac.curvature_plot([p.curve for p in q.pieces], 32)
    fit = lac.log_curvature_graph(chain_plot).fit
    assert fit is not None and fit.alpha == pytest.approx(0.5, abs=1e-3)


def test_curvature_plot_from_samples_is_the_plot_it_was_given():
    seg = lac.Segment([(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)], 0.5)
    plot = seg.curvature_plot(65)
    again = lac.CurvaturePlot.from_samples(plot.s, plot.kappa, plot.dkappa_ds, plot.points)
    assert again.points.tolist() == plot.points.tolist()
    assert again.log_curvature_graph().points.tolist() == plot.log_curvature_graph().points.tolist()
    assert again.not_monotone() is None
    # Without points they are zeros; an inflection is named as `lac lcg` names it.
    s = np.linspace(0.0, 2.0, 21)
    wave = lac.CurvaturePlot.from_samples(s, 1.0 - s, -np.ones(21))
    assert wave.points.tolist() == [[0.0, 0.0]] * 21
    assert wave.not_monotone() == "the curvature changes sign near s = 1.1, an inflection"
    bump = lac.CurvaturePlot.from_samples(s, 2.0 - (s - 1.0) ** 2, -2.0 * (s - 1.0))
    assert bump.not_monotone() == "dκ/ds changes sign near s = 1.1"
    with pytest.raises(lac.InvalidInput, match="one length, got 21, 20, 21 and 21"):
        lac.CurvaturePlot.from_samples(s, s[1:], s)
    with pytest.raises(lac.InvalidInput, match="finite"):
        lac.CurvaturePlot.from_samples(s, s, np.full(21, np.nan))


def test_standard_form_and_evolute():
    seg = lac.Segment([(-1.0, 0.0), (-0.2, 0.8), (1.0, 0.0)], 0.5)
    form = seg.standard_form
    assert form.alpha == 0.5 and form.lambda_ == seg.lambda_
    assert form.rho_at_s(0.0) == 1.0 and form.theta_at_s(0.0) == 0.0
    assert form.point_at_s(0.0).tolist() == [0.0, 0.0]
    ev = seg.evolute(5)
    smp = seg.sample(5)
    normal = np.stack([-np.sin(smp.theta), np.cos(smp.theta)], axis=1)
    assert np.allclose(ev, smp.points + normal / smp.kappa[:, None], rtol=0, atol=1e-12)
    assert seg.point_at_s(seg.arc_length).tolist() == pytest.approx([1.0, 0.0], abs=1e-12)
    assert seg.theta_at_s(0.0) == pytest.approx(math.atan2(0.8, 0.8))
    assert seg.turn == "right" and not seg.is_circle


def test_adaptive_and_given_arc_lengths():
    seg = lac.Segment([(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)], -1.0)
    at = np.linspace(0.0, seg.arc_length, 11)
    given = seg.sample_at(at)
    # s is recomputed from the nearer end of the piece: within an ulp or two of the input.
    assert np.allclose(given.s, at, rtol=1e-14, atol=0)
    assert np.allclose(given.points, seg.sample(11).points, atol=1e-12, rtol=0)
    adaptive = seg.sample_adaptive(1e-4)
    assert len(adaptive) > 2 and adaptive.points.shape == (len(adaptive), 2)


sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "tools",
                                "reference"))


def test_clothoid_case_agrees_with_clothoids_to_1e_12():
    """alpha = -1 against Bertolazzi's Clothoids (an independent implementation)."""
    cases = pytest.importorskip("clothoid_cases")
    configs = cases.configurations()
    curves = [cases.g1_clothoid(*c) for c in configs]
    keep = [i for i, c in enumerate(curves) if np.prod(cases.end_curvatures(c)) > 0]
    points = np.array([configs[i] for i in keep])
    batch = lac.solve_segments(points, -1.0)
    assert batch.ok.all()
    length = np.array([curves[i].length() for i in keep])
    kappa0 = np.array([cases.end_curvatures(curves[i])[0] for i in keep])
    assert np.max(np.abs(batch.arc_length / length - 1)) < 1e-12
    assert np.max(np.abs(batch.curvature_start * length - kappa0 * length)) < 1e-9


def test_thread_counts_agree():
    points = np.array([p for p, _ in SEGMENTS if len(p) == 3] * 50)
    alpha = np.tile([a for _, a in SEGMENTS], 50)
    runs = [lac.solve_segments(points, alpha, samples=5, threads=t) for t in (None, 1, 3)]
    for other in runs[1:]:
        assert np.array_equal(other.arc_length, runs[0].arc_length)
        assert other.points is not None and runs[0].points is not None
        assert np.array_equal(other.points, runs[0].points)
    with pytest.raises(lac.InvalidInput, match="threads"):
        lac.solve_segments(points, alpha, threads=0)
