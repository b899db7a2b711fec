"""`lac.fit` answers what `lac fit` answers (the same Rust code): a segment found again from
its points, a path within a tolerance with continuous joints, the fit's figures as NumPy
arrays, CAD export of a fit, and the library's errors."""

import numpy as np
import pytest

import lac


def segment_points(n=200):
    return lac.Segment([(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)], 0.5).sample(n).points


def path_points(n=300):
    polygon = [(0.0, 0.0), (2.0, 0.0), (3.5, 1.0), (4.0, 3.0), (3.0, 4.5), (1.0, 5.0)]
    return lac.Path(polygon, 0.5).sample(n).points


def test_a_fit_equals_the_command_lines_bit_for_bit(cli, tmp_path):
    points = segment_points()
    points[50, 1] += 1e-3
    file = tmp_path / "points.txt"
    file.write_text("".join(f"{float(x)!r} {float(y)!r}\n" for x, y in points))
    ref = cli("fit", str(file), "--samples", "9")
    fit = lac.fit(points)
    assert isinstance(fit, lac.Curve)
    assert fit.fitted_segments == ref["fitted_segments"] == 1
    assert fit.rms == ref["rms"] and fit.max_distance == ref["max_distance"]
    assert fit.worst_point == ref["worst_point"] == 50
    assert fit.farthest_points(10).tolist() == [r["index"] for r in ref["farthest"]]
    assert fit.alphas.tolist() == [p["alpha"] for p in ref["pieces"]]
    assert fit.piece_curvatures.tolist() == [p["curvature"] for p in ref["pieces"]]
    assert fit.arc_length == ref["arc_length"]
    samples = fit.sample(9)
    assert samples.kappa.tolist() == [s["kappa"] for s in ref["samples"]]
    assert samples.points[:, 0].tolist() == [s["x"] for s in ref["samples"]]
    assert fit.distances.shape == (200,) and fit.feet.shape == (200,)
    assert fit.distances.max() == fit.max_distance
    assert abs(fit.alphas[0] - 0.5) < 1e-2


def test_a_path_within_a_tolerance_has_continuous_joints_and_exports():
    fit = lac.fit(path_points(), tolerance=1e-4)
    assert fit.max_distance <= 1e-4
    k = fit.fitted_segments
    assert k >= 2 and fit.alphas.shape == (k,) and fit.piece_curvatures.shape == (k, 2)
    assert fit.joint_points.shape == (k - 1, 2) and fit.joint_s.shape == (k - 1,)
    assert (fit.curvature_jumps <= 1e-9).all()
    assert (fit.joint_gaps <= 1e-9).all()
    assert np.allclose(fit.piece_starts[1:], fit.joint_s)
    assert fit.continuity == "g2" and not fit.closed
    text, report = lac.export(fit, "json", tolerance=1e-7)
    assert report["kind"] == "fit" and report["max_deviation"] <= 1e-7
    assert '"knots"' in text


def test_options_are_the_command_lines():
    points = segment_points()
    assert lac.fit(points, alpha=1.0).alphas.tolist() == [1.0]
    two = lac.fit(points, max_segments=2, alpha_range=(-1, 2), shared_alpha=True)
    assert two.fitted_segments <= 2 and len(set(two.alphas.tolist())) == 1
    assert lac.fit(points, g1=True, max_segments=2).continuity == "g1"
    pinned = lac.fit(points, pin_ends=True)
    assert np.allclose(pinned.start_point, points[0], atol=1e-9)
    moved = points.copy()
    moved[120, 1] += 0.3
    robust = lac.fit(moved, huber=1e-3)
    assert robust.worst_point == 120 and robust.distances[np.arange(200) != 120].max() < 1e-3
    weights = np.ones(200)
    weights[120] = 0.0
    assert lac.fit(moved, weights=weights).farthest_points(2)[0] == 120


def test_errors_are_the_librarys():
    points = segment_points()
    with pytest.raises(lac.InvalidInput) as err:
        lac.fit(points[:2])
    assert err.value.kind == "too_few_points"
    with pytest.raises(lac.NotDrawable) as err:
        lac.fit(path_points(), tolerance=1e-9, max_segments=1)
    assert err.value.kind == "fit_tolerance_not_met"
    bad = points.copy()
    bad[3, 0] = np.nan
    with pytest.raises(lac.InvalidInput):
        lac.fit(bad)
    with pytest.raises(lac.InvalidInput):
        lac.fit(points.ravel())
    with pytest.raises(lac.InvalidInput):
        lac.fit(points, alpha_range=(1.0,))
    with pytest.raises(lac.InvalidInput):
        lac.fit(points, max_segments=-1)
    with pytest.raises(lac.InvalidInput):
        lac.fit(points, alpha=1.0, alpha_range=(0, 2))
