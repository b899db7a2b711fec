"""`lac.Path`, `lac.Spline` and `lac.export` answer what `lac path`, `lac spline` and
`lac export` answer (the same Rust code): G1 and G2 paths through inflections, warm-started,
splines through points, CAD files in every format; and raise the library's errors."""

import json
import math
import re
import subprocess

import numpy as np
import pytest

import lac
from conftest import lac_bin

S_POLYGON = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.5), (5.0, 2.5), (6.0, 3.0), (7.0, 3.0)]


def arg(points):
    return " ".join(f"{x!r},{y!r}" for x, y in points)


def test_g2_path_through_an_inflection_equals_the_command_line(cli):
    ref = cli("path", "--polygon", arg(S_POLYGON), "--alpha", "-1", "--g2", "--samples", "9")
    path = lac.Path(S_POLYGON, -1.0)
    assert path.continuity == "g2"
    assert path.arc_length == ref["arc_length"]
    assert path.max_curvature_jump == ref["max_curvature_jump"]
    tri = path.control_triangles
    assert tri.shape == (4, 3, 2)
    assert tri.tolist() == [s["control_points"] for s in ref["segments"]]
    assert path.end_curvatures.tolist() == [s["curvature"] for s in ref["segments"]]
    (leg, start, end), = path.straight_pieces
    line = ref["straight_pieces"][0]
    assert leg == line["leg"] and [list(start), list(end)] == line["points"]
    samples = path.sample(9)
    assert samples.kappa.tolist() == [s["kappa"] for s in ref["samples"]]
    # The curvature is zero at the straight piece's ends to 1e-9 of the largest.
    k = path.end_curvatures
    assert abs(k[1, 1]) <= 1e-9 * np.abs(k).max() and abs(k[2, 0]) <= 1e-9 * np.abs(k).max()


def test_warm_start_g1_and_errors():
    polygon = [(0.0, 0.0), (2.0, 0.0), (3.5, 1.0), (4.0, 3.0), (3.0, 4.5), (1.0, 5.0)]
    cold = lac.Path(polygon, 0.5)
    moved = np.array(polygon)
    moved[3, 0] += 0.05
    warm = lac.Path(moved, 0.5, warm=cold.joint_fractions)
    assert warm.max_curvature_jump <= 1e-9
    g1 = lac.Path(polygon, [0.0, 0.5, 1.0, 1.0], g2=False, fractions=[0.3, 0.5, 0.7])
    assert g1.continuity == "g1"
    assert g1.joint_fractions.tolist() == [0.3, 0.5, 0.7]
    with pytest.raises(lac.LacError, match="leg P2-P3"):
        lac.Path(S_POLYGON, 0.5)  # alpha >= 0 cannot reach zero curvature
    with pytest.raises(lac.InvalidInput):
        lac.Path([(0.0, 0.0), (1.0, 0.0)], 0.5)
    with pytest.raises(lac.InvalidInput):
        lac.Path([0.0, 1.0, 2.0], 0.5)


SPLINE_POINTS = [(0.0, 0.0), (2.0, 0.3), (3.5, 1.5), (4.0, 3.0), (3.2, 4.6)]


def test_spline_equals_the_command_line(cli):
    ref = cli("spline", "--through", arg(SPLINE_POINTS), "--alpha", "0.5", "--samples", "9")
    spline = lac.Spline(SPLINE_POINTS, 0.5)
    assert not spline.closed
    assert spline.arc_length == ref["arc_length"]
    assert spline.max_curvature_jump == ref["max_curvature_jump"] <= 1e-9
    assert spline.points.tolist() == [list(p) for p in SPLINE_POINTS]
    assert spline.angles.tolist() == ref["angles"]
    assert spline.control_triangles.shape == (4, 3, 2)
    assert spline.control_triangles.tolist() == [s["control_points"] for s in ref["pieces"]]
    assert spline.end_curvatures.tolist() == [s["curvature"] for s in ref["pieces"]]
    assert spline.spans_of_pieces.tolist() == [0, 1, 2, 3] and spline.inflections.shape == (0, 2)
    assert spline.curvature_jumps.tolist() == ref["curvature_jumps"]
    samples = spline.sample(9)
    assert samples.kappa.tolist() == [s["kappa"] for s in ref["samples"]]
    assert samples.points.tolist() == [[s["x"], s["y"]] for s in ref["samples"]]


WAVE = [(float(i), math.sin(0.9 * i + 0.3)) for i in range(8)]


def test_spline_through_an_inflection_equals_the_command_line(cli):
    ref = cli("spline", "--through", arg(WAVE), "--alpha", "-0.5", "--samples", "9")
    spline = lac.Spline(WAVE, -0.5)
    assert spline.spans_of_pieces.tolist() == [p["span"] for p in ref["pieces"]]
    assert spline.spans_of_pieces.tolist() == [0, 1, 2, 3, 3, 4, 5, 6]
    assert spline.inflections.tolist() == [f["point"] for f in ref["inflections"]]
    assert spline.inflection_spans.tolist() == [3]
    assert spline.end_curvatures.tolist() == [p["curvature"] for p in ref["pieces"]]
    assert spline.max_curvature_jump <= 1e-9
    k = spline.sample(200).kappa
    assert int(np.sum(k[:-1] * k[1:] < 0)) == 1
    # Exported as the command line does.
    text, report = lac.export(spline, "step", tolerance=1e-7)
    done = subprocess.run(
        [lac_bin(), "export", "--format", "step", "--tolerance", "1e-7", "--through", arg(WAVE),
         "--alpha", "-0.5"], capture_output=True, text=True, check=True)
    assert report == json.loads(done.stderr.strip().splitlines()[-1])
    assert report["kind"] == "spline" and report["continuity"] == "G2"
    assert report["max_deviation"] <= 1e-7 and report["monotone_proven"] is True


def test_spline_options_and_errors(cli):
    ends = lac.Spline(SPLINE_POINTS, 0.5, ends=[0.0, 2.1])
    ref = cli("spline", "--through", arg(SPLINE_POINTS), "--alpha", "0.5",
              "--start-angle", "0", "--end-angle", "2.1")
    assert ends.angles.tolist() == ref["angles"] and ends.angles[[0, -1]].tolist() == [0.0, 2.1]
    ring = [(1.0, 0.0), (0.0, 1.2), (-1.0, 0.0), (0.0, -0.8)]
    closed = lac.Spline(np.array(ring), -1.0, closed=True)
    assert closed.closed and closed.control_triangles.shape == (4, 3, 2)
    assert closed.max_curvature_jump <= 1e-9
    with pytest.raises(lac.LacError, match="span"):
        lac.Spline([(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 1.0)], 0.5)  # must inflect
    with pytest.raises(lac.InvalidInput):
        lac.Spline([(0.0, 0.0), (1.0, 0.0)], 0.5)
    with pytest.raises(lac.InvalidInput):
        lac.Spline(SPLINE_POINTS, 0.5, ends=[0.1])
    with pytest.raises(lac.InvalidInput):
        lac.Spline(ring, 0.5, closed=True, ends=[0.1, 0.2])


def test_spline_point_types_are_the_command_lines(cli):
    """Point types, straight spans and end curvatures as keyword arguments: the same spline
    as `lac spline --types --angles --lines --start-curvature`, each point's measurements in
    `point_reports`."""
    u = [(0.0, 4.0), (0.0, 1.5), (1.0, 0.0), (2.0, 1.5), (2.0, 4.0)]
    spline = lac.Spline(u, -1.0, types="s s t s s", angles={2: 0.0}, lines=[0, 3])
    ref = cli("spline", "--through", arg(u), "--alpha", "-1", "--types", "s s t s s",
              "--angles", "2:0", "--lines", "0-1,3-4")
    assert spline.angles.tolist() == ref["angles"]
    rows = spline.point_reports
    assert [r[0] for r in rows] == [p["type"] for p in ref["at_points"]]
    assert list(rows[1][2]) == [True, False] and abs(rows[1][4][1]) <= 1e-12 * abs(rows[2][4][0])
    assert spline.knots.shape == (2, 2)
    ends = lac.Spline(SPLINE_POINTS, 0.5, ends=(0.1, None), start_curvature=0.2,
                      end_curvature=0.5, types=["s"] * len(SPLINE_POINTS))
    assert abs(ends.point_reports[0][4][1] - 0.2) <= 1e-12 * 0.2
    corner = lac.Spline(u, -1.0, types="s s c s s", angles={2: (None, 0.5)})
    assert abs(corner.point_reports[2][3][1] - 0.5) <= 1e-12
    with pytest.raises(lac.LacError, match="P1.*corner"):
        lac.Spline(u, 0.5, lines=[0])
    with pytest.raises(lac.InvalidInput, match="tangent point"):
        lac.Spline(u, -1.0, types="s s t s s")
    with pytest.raises(lac.InvalidInput, match="not a point type"):
        lac.Spline(u, -1.0, types="s s x s s")


def test_spline_warm_from_an_earlier_one_is_the_cold_one():
    """`warm=` an earlier spline (a point dragged): the same spline as solved afresh; a warm
    spline of another shape (other types) is solved afresh too."""
    u = [(0.0, 4.0), (0.0, 1.5), (1.0, 0.0), (2.0, 1.5), (2.0, 4.0)]
    first = lac.Spline(u, -1.0, types="s s t s s", angles={2: 0.0}, lines=[0, 3])
    moved = list(u)
    moved[2] = (1.004, -0.003)
    warm = lac.Spline(moved, -1.0, types="s s t s s", angles={2: 0.0}, lines=[0, 3], warm=first)
    cold = lac.Spline(moved, -1.0, types="s s t s s", angles={2: 0.0}, lines=[0, 3])
    assert abs(warm.angles - cold.angles).max() <= 1e-9
    other = lac.Spline(moved, -1.0, warm=first)
    assert abs(other.angles - lac.Spline(moved, -1.0).angles).max() <= 1e-9


def test_export_equals_the_command_line(cli, tmp_path):
    seg = lac.Segment([(0.0, 0.0), (1.0, 0.0), (1.6, 0.9)], -1.0)
    for fmt in ["step", "iges", "dxf", "svg", "json"]:
        text, report = lac.export(seg, fmt, tolerance=1e-7, name="seg")
        out = tmp_path / f"seg.{fmt}"
        done = subprocess.run(
            [lac_bin(), "export", "--format", fmt, "--tolerance", "1e-7", "-o", str(out),
             "--points", "0,0 1,0 1.6,0.9", "--alpha", "-1"],
            capture_output=True, text=True, check=True)
        ref = json.loads(done.stderr.strip().splitlines()[-1])
        assert report == ref
        assert report["max_deviation"] <= 1e-7 and report["monotone_proven"] is True
        # The same curves; only the name and the time stamp may differ.
        expected = out.read_text()
        if fmt in ("json", "svg"):
            assert text == expected
        else:
            # (Not IGES's time stamps, yyyymmdd.hhmmss: the two calls may fall in
            # different seconds.)
            numbers = lambda t: [  # noqa: E731
                n for n in re.findall(r"-?\d+\.\d+(?:[eE][-+]?\d+)?", t)
                if not re.fullmatch(r"\d{8}\.\d{6}", n)]
            assert len(text) > 200 and numbers(text)[-50:] == numbers(expected)[-50:]
    # A path through an inflection exports too, its straight piece included.
    path = lac.Path(S_POLYGON, -1.0)
    text, report = lac.export(path, "step")
    assert report["kind"] == "path" and report["continuity"] == "G2"
    assert report["max_deviation"] <= report["tolerance"] and report["monotone_proven"] is True
    # A closed one through two inflections too, its last piece the straight piece on the
    # leg that closes the polygon: the same file and report as the command line's.
    eight = [(1.5, -1.0), (3.0, -1.8), (4.5, -1.0), (4.5, 1.0), (3.0, 1.8), (1.5, 1.0),
             (-1.5, -1.0), (-3.0, -1.8), (-4.5, -1.0), (-4.5, 1.0), (-3.0, 1.8), (-1.5, 1.0)]
    text, report = lac.export(lac.Path(eight, -1.0, closed=True), "json", tolerance=1e-7)
    done = subprocess.run(
        [lac_bin(), "export", "--format", "json", "--tolerance", "1e-7", "--alpha", "-1",
         "--closed", "--g2", "--polygon", " ".join(f"{x!r},{y!r}" for x, y in eight)],
        capture_output=True, text=True, check=True)
    assert report == json.loads(done.stderr.strip().splitlines()[-1]) and text == done.stdout
    assert report["continuity"] == "G2" and report["max_deviation"] <= 1e-7
    g2 = lac.Path([(0.0, 0.0), (3.0, 0.0), (4.0, 2.0), (2.0, 4.0), (-1.0, 2.0)], 1.0)
    text, report = lac.export(g2, "iges", tolerance=1e-6, relative=True, pieces=True)
    assert report["kind"] == "path" and report["single_spans"] and report["continuity"] == "G2"
    assert report["max_deviation"] <= report["tolerance"] == pytest.approx(1e-6 * g2.arc_length)
    space = lac.SpaceSegment([(0, 0, 0), (1, 0, 0), (2, 1, 0.5), (2, 2, 1.5)], 0.0, 0.0)
    text, report = lac.export(space, "json")
    assert json.loads(text)["curves"][0]["dimension"] == 3 and report["continuity"] == "C1"
    with pytest.raises(lac.InvalidInput, match="format"):
        lac.export(seg, "obj")
    with pytest.raises(lac.InvalidInput, match="Segment, CompoundCurve, Path, Spline"):
        lac.export([(0, 0), (1, 0), (1, 1)], "step")
    with pytest.raises(lac.LacError, match="tolerance"):
        lac.export(seg, "step", tolerance=1e-20)


def test_paths_splines_and_space_segments_say_what_they_are():
    path = lac.Path(S_POLYGON, -1.0)
    assert re.fullmatch(r"<Path continuity=g2 closed=False segments=4 arc_length=[0-9.e+-]+>",
                        repr(path)), repr(path)
    spline = lac.Spline([(0.0, 0.0), (2.0, 0.3), (3.5, 1.5), (4.0, 3.0)], 0.5)
    assert re.fullmatch(r"<Spline closed=False points=4 pieces=3 arc_length=[0-9.e+-]+>",
                        repr(spline)), repr(spline)
    space = lac.SpaceSegment([(0, 0, 0), (3, 0, 0), (3, 3, 1.5), (0, 3, 3)], 0.5, 0.0, 0.3)
    assert repr(space).startswith("<SpaceSegment alpha=0.5 beta=0 omega=0.3 type=1 arc_length=")
