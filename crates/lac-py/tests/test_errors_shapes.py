"""Errors map to lac.LacError / lac.InvalidInput (a ValueError) / lac.NotDrawable with the
library's kind and message; NumPy input of the wrong shape or dtype is a ValueError."""

import math

import numpy as np
import pytest

import lac

GOOD = [(-1.0, 0.0), (-0.2, 0.8), (1.0, 0.0)]


def test_hierarchy():
    assert issubclass(lac.InvalidInput, lac.LacError)
    assert issubclass(lac.InvalidInput, ValueError)
    assert issubclass(lac.NotDrawable, lac.LacError)
    assert not issubclass(lac.NotDrawable, ValueError)
    assert issubclass(lac.LacError, Exception)
    assert lac.LacError.__module__ == "lac"


@pytest.mark.parametrize("points,alpha,error,kind,words", [
    ([(0, 0), (1, 0), (2, 0)], -1.0, lac.InvalidInput, "collinear_points", "collinear"),
    ([(0, 0), (0, 0), (2, 1)], -1.0, lac.InvalidInput, "coincident_points", "coincide"),
    ([(0, 0), (math.nan, 0), (2, 1)], -1.0, lac.InvalidInput, "non_finite", "finite"),
    (GOOD, math.inf, lac.InvalidInput, "non_finite", "alpha"),
    (GOOD, 1e9, lac.InvalidInput, "out_of_range", "alpha"),
    ([(-1, 0), (0.9, 0.9), (1, 0)], -1.0, lac.NotDrawable, "not_drawable", "not drawable"),
])
def test_segment_errors(points, alpha, error, kind, words):
    with pytest.raises(error) as info:
        lac.Segment(points, alpha)
    assert info.value.kind == kind
    assert words in str(info.value)
    assert info.value.message == str(info.value)


def test_errors_say_what_the_command_line_says(cli):
    from conftest import points_arg

    bad = [(-1.0, 0.0), (0.9, 0.9), (1.0, 0.0)]
    ref = cli("segment", "--points", points_arg(bad), "--alpha", "-1")["error"]
    with pytest.raises(lac.NotDrawable) as info:
        lac.Segment(bad, -1.0)
    assert (info.value.kind, str(info.value)) == (ref["kind"], ref["message"])


def test_other_kinds():
    with pytest.raises(lac.InvalidInput) as info:  # inflected polygon
        lac.CompoundCurve([(0, 0), (1, 0), (2, 1), (3, 0)], 0.5, 0.5)
    assert info.value.kind == "inflected_polygon"
    with pytest.raises(lac.InvalidInput) as info:
        lac.CompoundCurve(GOOD, -1.0, 2.0, 1.5)
    assert info.value.kind == "out_of_range" and "ratio" in str(info.value)
    seg = lac.Segment(GOOD, 0.5)
    with pytest.raises(lac.InvalidInput) as info:
        seg.to_rational_cubics(1e-20)
    assert info.value.kind == "out_of_range" and "tolerance" in str(info.value)
    with pytest.raises(ValueError):
        seg.to_rational_cubics(math.nan)
    with pytest.raises(lac.InvalidInput) as info:
        seg.point_at_s(seg.arc_length * 2)
    assert info.value.kind == "out_of_range"
    with pytest.raises(lac.InvalidInput):
        seg.sample(1)
    with pytest.raises(lac.InvalidInput):
        seg.sample(-3)
    with pytest.raises(lac.InvalidInput):
        lac.RationalCubic([(0, 0), (1, 0), (2, 1), (3, 3)], [1, -1, 1, 1])
    with pytest.raises(lac.InvalidInput):
        lac.drawable_region(-1.0, 0)
    with pytest.raises(lac.InvalidInput):
        lac.drawable_region_compound(-1.0, 2.0, 0.0, 8)
    with pytest.raises(lac.InvalidInput):
        lac.SpaceSegment([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 1)], 0.5, 0.0,
                         torsion_type=3)
    with pytest.raises(lac.NotDrawable):
        lac.classify(-1.0, (0.9, 0.9))
    assert lac.classify(0.5, (0.0, 0.5)) is None


def test_torsion_too_large_reports_omega_max():
    points = [(0.0, 0.0, 0.0), (3.0, 0.0, 0.0), (3.0, 3.0, 1.5), (0.0, 3.0, 3.0)]
    with pytest.raises(lac.NotDrawable) as info:
        lac.SpaceSegment(points, 0.5, 0.0, omega=1e6)
    assert info.value.kind == "not_drawable"
    if info.value.omega_max is not None:
        assert 0 <= info.value.omega_max < 1e6
        assert "omega" in str(info.value)


@pytest.mark.parametrize("points,words", [
    (np.zeros((2, 2)), "(shape (3, 2)), got shape (2, 2)"),
    (np.zeros((3, 3)), "got shape (3, 3)"),
    (np.zeros(6), "got shape (6,)"),
    (np.zeros((3, 2), dtype=complex), "dtype complex128"),
    (np.zeros((3, 2), dtype=bool), "dtype bool"),
    (np.array([["a", "b"]] * 3), "dtype <U1"),
    ("abc", "real numbers"),
    ([(0, 0), (1, 0)], "got shape (2, 2)"),
    ([(0, 0), (1, 0), (1, 1, 1)], "real numbers"),
    (None, "got dtype object"),
    # A complex number in a list is refused, not cast to its real part.
    ([(0, 1j), (1, 0), (1, 1)], "dtype complex128"),
])
def test_wrong_shape_or_dtype_is_a_clear_value_error(points, words):
    with pytest.raises(ValueError) as info:
        lac.Segment(points, 0.5)
    assert isinstance(info.value, lac.InvalidInput)
    assert words in str(info.value)
    assert "points" in str(info.value)


def test_arrays_of_other_real_dtypes_and_layouts_are_accepted():
    ref = lac.Segment(GOOD, 0.5).arc_length
    assert lac.Segment(np.array(GOOD, dtype=np.float32), 0.5).arc_length == pytest.approx(
        ref, rel=1e-6)
    assert lac.Segment(np.asfortranarray(GOOD), 0.5).arc_length == ref
    assert lac.Segment(np.array(GOOD)[::-1][::-1], 0.5).arc_length == ref
    assert lac.Segment(np.array([[-2, 0], [0, 2], [2, 0]], dtype=np.int64), 0.5).arc_length > 0
    assert lac.Segment(tuple(GOOD), 0.5).arc_length == ref


def test_batch_shapes_and_error_array():
    pts = np.array([GOOD, [(0, 0), (1, 0), (2, 0)], [(-1, 0), (0.9, 0.9), (1, 0)], GOOD])
    batch = lac.solve_segments(pts, [0.5, 0.5, -1.0, math.nan], samples=5)
    assert len(batch) == 4
    assert batch.ok.dtype == np.bool_
    assert batch.ok.tolist() == [True, False, False, False]
    assert batch.error_kind == [None, "collinear_points", "not_drawable", "non_finite"]
    assert batch.error[0] is None and "collinear" in (batch.error[1] or "")
    assert np.isnan(batch.arc_length[1:]).all() and batch.arc_length[0] > 0
    assert batch.points is not None and np.isnan(batch.points[1:]).all()
    assert batch.alpha.tolist()[:3] == [0.5, 0.5, -1.0]
    assert lac.solve_segments(pts, 0.5).points is None
    empty = lac.solve_segments(np.zeros((0, 3, 2)), 0.5, samples=3)
    assert len(empty) == 0 and empty.points is not None and empty.points.shape == (0, 3, 2)
    for bad, words in [(np.zeros((4, 3)), "shape (n, 3, 2)"), (np.zeros((4, 2, 2)), "(4, 2, 2)")]:
        with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
            lac.solve_segments(bad, 0.5)
    with pytest.raises(ValueError, match="alpha must be a number or an array of shape"):
        lac.solve_segments(pts, [0.5, 1.0])
    with pytest.raises(ValueError, match="samples"):
        lac.solve_segments(pts, 0.5, samples=1)
    with pytest.raises(ValueError, match="chunks"):
        lac.solve_segments(pts, 0.5, samples=10_000_000)
    with pytest.raises(ValueError, match="dtype complex"):
        lac.solve_segments(pts.astype(complex), 0.5)
