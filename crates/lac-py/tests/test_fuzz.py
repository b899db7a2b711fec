"""Claim: whatever Python hands the bindings (wrong shapes, dtypes, types, special floats,
huge integers, deep nesting), every call either returns finite results or raises one of
lac.LacError, ValueError or TypeError: never a Rust panic (pyo3's PanicException is a
BaseException), never a crash, never NaN in a result.

The arguments are drawn by a seeded generator (LAC_PY_FUZZ_COUNT calls per entry point).
"""

import math
import os
import random

import numpy as np
import pytest

import lac

COUNT = int(os.environ.get("LAC_PY_FUZZ_COUNT", "1500"))
GOOD3 = [(-1.0, 0.0), (-0.2, 0.8), (1.0, 0.0)]
GOOD4 = [(0.0, 0.0), (2.0, 0.0), (2.5, 2.0), (0.0, 1.5)]
GOOD_SPACE = [(0, 0, 0), (1, 0, 0), (1.5, 0.8, 0.2), (1.6, 1.6, 0.6)]
SPECIAL = [0.0, -0.0, math.nan, math.inf, -math.inf, 5e-324, 1e308, -1e308, 1e-300]


def number(rng):
    r = rng.random()
    if r < 0.5:
        return rng.uniform(-3, 3)
    if r < 0.7:
        return rng.choice(SPECIAL)
    if r < 0.8:
        return rng.choice([0, 1, -1, 2**64, -(2**70), True])
    if r < 0.9:
        return 10 ** rng.uniform(-300, 300) * rng.choice([-1, 1])
    return rng.choice([None, "1", "nan", [], {}, (1,), object(), 1j])


def points(rng, good):
    """Points near a good set, or of the wrong shape, dtype or type."""
    r = rng.random()
    if r < 0.4:
        return [tuple(c + rng.gauss(0, 0.3) for c in p) for p in good]
    if r < 0.55:
        return [tuple(number(rng) for _ in p) for p in good]
    if r < 0.7:
        dtype = rng.choice([np.float64, np.float32, np.int64, np.int8, np.bool_, np.complex128,
                            np.uint64, object, np.float16])
        shape = rng.choice([(len(good), len(good[0])), (len(good), 1), (1, len(good[0])),
                            (len(good) + 1, len(good[0])), (0, 2), (len(good),), (2, 2, 2), ()])
        try:
            return np.ones(shape, dtype=dtype) * np.array(rng.uniform(-2, 2)).astype(dtype)
        except (TypeError, ValueError):
            return np.zeros(shape)
    if r < 0.8:
        a = np.asarray(good, dtype=np.float64)
        return rng.choice([a.T, a[::-1], np.asfortranarray(a), a[:, ::-1], a.reshape(-1)])
    if r < 0.9:
        nested = good
        for _ in range(rng.randrange(1, 50)):
            nested = [nested]
        return nested
    return rng.choice([None, "0,0 1,1 2,0", 3.0, [[1, 2], [3]], [(1, 2, 3)] * 3, {}, b"\x00"])


def finite(value):
    """Every number reachable from a result is finite (arrays, floats, tuples, objects)."""
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, np.ndarray):
        return value.dtype.kind != "f" or bool(np.isfinite(value).all())
    if isinstance(value, (tuple, list)):
        return all(finite(v) for v in value)
    return True


def call(fn, *args, **kwargs):
    """Run one call; return its result, or None when it raised an allowed error."""
    try:
        return fn(*args, **kwargs)
    except (lac.LacError, ValueError, TypeError, OverflowError):
        return None
    # A pyo3 PanicException (a BaseException) or anything else fails the test by escaping.


def exercise(curve, rng):
    """Methods of a solved curve with random arguments: results finite or an allowed error."""
    n = rng.choice([0, 1, 2, 3, 17, -1, 2**40, 1.5, None, math.nan])
    s = number(rng)
    for fn, args in [
        (curve.sample, (n,)),
        (curve.point_at_s, (s,)),
        (curve.curvature_at_s, (s,)),
        (curve.evolute, (n,)),
        (curve.curvature_plot, (n,)),
        (curve.sample_adaptive, (number(rng),)),
        (curve.sample_at, (rng.choice([[0.0, 0.1], np.array([[0.0]]), [math.nan], "x"]),)),
        (curve.to_rational_cubics, (number(rng),)),
    ]:
        out = call(fn, *args)
        if out is None:
            continue
        for attr in ("points", "s", "kappa", "theta"):
            if hasattr(out, attr):
                assert finite(getattr(out, attr)), (fn, args, attr)
        assert finite(out), (fn, args)


ENTRY_POINTS = {
    "segment": lambda rng: lac.Segment(points(rng, GOOD3), number(rng)),
    "compound3": lambda rng: lac.CompoundCurve.from_three_points(
        points(rng, GOOD3), number(rng), number(rng), number(rng)),
    "compound4": lambda rng: lac.CompoundCurve.from_four_points(
        points(rng, GOOD4), number(rng), number(rng)),
    "rational_cubic": lambda rng: lac.RationalCubic(
        points(rng, GOOD4), rng.choice([None, [1, 2, 1, 1], [number(rng) for _ in range(4)],
                                        np.ones(3), "w"])),
    "space": lambda rng: lac.SpaceSegment(
        points(rng, GOOD_SPACE), number(rng), number(rng),
        **rng.choice([{}, {"omega": number(rng)}, {"torsion_type": rng.choice([1, 2, 3, 0])}])),
    "solve_segments": lambda rng: lac.solve_segments(
        rng.choice([np.tile(np.asarray(GOOD3), (rng.randrange(0, 5), 1, 1)),
                    np.asarray(points(rng, GOOD3), dtype=object)
                    if rng.random() < 0.1 else np.random.default_rng(rng.randrange(99)).normal(
                        size=(rng.randrange(0, 6), 3, 2))]),
        rng.choice([number(rng), np.array([0.5, -1.0]), np.ones((2, 2))])),
}


@pytest.mark.parametrize("entry", sorted(ENTRY_POINTS))
def test_random_arguments_give_finite_results_or_a_python_error(entry):
    rng = random.Random(20261123)
    made = 0
    for _ in range(COUNT):
        result = call(ENTRY_POINTS[entry], rng)
        if result is None:
            continue
        made += 1
        if isinstance(result, lac.Curve):
            exercise(result, rng)
        elif isinstance(result, lac.RationalCubic):
            for fn, args in [(result.eval, ([0.0, 0.5, 1.0],)),
                             (result.signed_curvature, (number(rng),)),
                             (result.curvature_monotonicity, ())]:
                call(fn, *args)
        elif isinstance(result, lac.SpaceSegment):
            out = call(result.sample, rng.choice([2, 5, 0, -3]))
            if out is not None:
                assert finite(out.points) and finite(out.curvature)
    assert made > 0, f"no {entry} call succeeded: the generator is off"
