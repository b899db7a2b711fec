"""`lac path --g2` and `lac spline` checked independently: every reported segment is solved
again from its control triangle and alpha by the 30-digit mpmath reference
(segment_mpmath.py, docs/math.md §3), and at every joint the reference's curvatures on the two sides
must agree to 1e-9 (relative), as must the command's own report.

    .venv/bin/python -m pytest tools/reference/test_path.py -q      (from the repo root)
"""

import json
import math
import subprocess

import pytest

from mpmath import atan2, cos, mp, mpc, mpf, quad, sin

from lac_cli import lac_bin, require
from segment_mpmath import solve_segment

# Open and closed polygons with a G2 path for these slopes (turning one way).
CASES = [
    ("0,0 2,0 3.5,1 4,3 3,4.5 1,5", False, [-0.5, 0.0, 0.5, 1.0, 2.0]),
    ("0,0 3,-0.5 4.5,2 2,4 -0.5,2.5", True, [-1.0, 0.0, 1.0]),
    ("0,0 1,0 2,0.3 2.8,1 3.2,2 3.1,3", False, [0.0, 0.5]),
]
JUMP = mpf("1e-9")


def triangle_rounding(tri):
    """The relative error that the rounding of a reported control triangle's coordinates
    (to doubles) puts into its turning angle, and so into any curvature solved again from
    it: each leg's direction is known to about two ulps of the largest coordinate over the
    leg's length. Negligible for most pieces (below 1e-13); not for a half S that turns by
    1e-4 rad next to a point, whose apex lies 1e-7 off its chord: there the triangle, not
    the curve, limits the reference."""
    (x0, y0), (x1, y1), (x2, y2) = tri
    big = max(abs(c) for p in tri for c in p)
    (ux, uy), (vx, vy) = (x1 - x0, y1 - y0), (x2 - x1, y2 - y1)
    leg = min(math.hypot(ux, uy), math.hypot(vx, vy))
    turning = abs(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy))
    return 2 * math.ulp(big) / (leg * turning)


@pytest.fixture(autouse=True)
def _keep_precision():
    """These tests work at 30 digits; the modules run after them expect their own 40."""
    dps = mp.dps
    yield
    mp.dps = dps


def run_path(polygon, closed, alpha):
    args = [lac_bin(), "path", "--polygon", polygon, "--alpha", str(alpha), "--g2",
            "--samples", "2"]
    if closed:
        args.append("--closed")
    run = subprocess.run(args, capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_g2_path_joints_are_continuous_in_the_mpmath_reference():
    require("path")
    mp.dps = 30
    checked, worst, worst_self = 0, mpf(0), mpf(0)
    for polygon, closed, alphas in CASES:
        for alpha in alphas:
            report = run_path(polygon, closed, alpha)
            assert report["continuity"] == "g2"
            ends = []
            for seg in report["segments"]:
                pa, pb, pc = (mpc(*map(mpf, p)) for p in seg["control_points"])
                ref = solve_segment(pa, pb, pc, seg["alpha"], [0, 1])
                ends.append((ref["curvature_start"], ref["curvature_end"]))
                # The command's segment is the reference's.
                for got, want in zip(seg["curvature"], (ref["curvature_start"],
                                                         ref["curvature_end"])):
                    err = abs(mpf(got) - want) / abs(want)
                    worst_self = max(worst_self, err)
                    assert err <= mpf("1e-12"), (got, want)
            pairs = len(ends) if closed else len(ends) - 1
            for k in range(pairs):
                before, after = ends[k][1], ends[(k + 1) % len(ends)][0]
                jump = abs(before - after) / max(abs(before), abs(after))
                assert jump <= JUMP, (polygon, alpha, k, jump)
                worst = max(worst, jump)
                checked += 1
    print(f"{checked} joints: largest curvature jump in the reference {float(worst):.2e}, "
          f"largest end-curvature error of lac {float(worst_self):.2e}")
    assert checked >= 30


# Polygons whose turning changes direction (G2 through inflections: the segments next to an
# inflection leg reach zero curvature at the ends of a straight piece on it).
INFLECTION_CASES = [
    ("0,0 1,0 2,0.5 5,2.5 6,3 7,3", False, [-1.0, -0.75, -0.5, -0.25]),
    ("-1.5,1 1.5,-1 3,-1.8 4.5,-1 4.5,1 3,1.8 1.5,1 -1.5,-1 -3,-1.8 -4.5,-1 -4.5,1 -3,1.8",
     True, [-1.0, -0.5]),
]


def inflection_segment(tri, alpha, at_start):
    """The reference for a segment with one end at (or a hair before) its inflection: from
    the inflection point a log-aesthetic curve of slope alpha < 0 has κ ∝ d^(1/|α|) (d the
    arc length from it), so up to similarity θ(d) = d^p with p = 1 + 1/|α| (docs/math.md §2,
    ρ^α linear in s and zero at the inflection). The piece [d0, D] turning by the triangle's
    angle whose tangent triangle has the reported leg ratio is found by bisection in
    w = −log10(d0 / D); returns (κ at the inflection end, κ at the other end), signed, in
    the caller's units."""
    p = 1 + 1 / abs(mpf(alpha))
    q0, pv, q1 = (mpc(*map(mpf, pt)) for pt in tri)
    infl_leg, other_leg = (abs(pv - q0), abs(q1 - pv)) if at_start else (abs(q1 - pv), abs(pv - q0))
    want = infl_leg / other_leg
    v1, v2 = pv - q0, q1 - pv
    turn = v1.real * v2.imag - v1.imag * v2.real
    theta_d = abs(atan2(turn, (v1.conjugate() * v2).real))
    sign = 1 if turn > 0 else -1
    # (κ's sign: left turn positive; the inflection end's sign is the other end's.)

    def piece(d0):
        big_d = (d0 ** p + theta_d) ** (1 / p)
        x = quad(lambda t: cos(t ** p), [d0, big_d])
        y = quad(lambda t: sin(t ** p), [d0, big_d])
        e0, e1 = mpc(cos(d0 ** p), sin(d0 ** p)), mpc(cos(big_d ** p), sin(big_d ** p))
        cr = lambda a, b: a.real * b.imag - a.imag * b.real
        chord = mpc(x, y)
        u = cr(chord, e1) / cr(e0, e1)  # the leg at d0 (inflection side)
        v = cr(e0, chord) / cr(e0, e1)
        return big_d, u / v, abs(chord)

    big_d, ratio_at_zero, _ = piece(mpf(0))
    assert ratio_at_zero >= want, "the reported triangle is past its inflection"
    lo, hi = mpf(0), mpf(60)  # w: d0 = D 10^-w; large w is near the inflection
    for _ in range(50):
        mid = (lo + hi) / 2
        _, ratio, _ = piece(big_d * mpf(10) ** -mid)
        if ratio > want:
            hi = mid  # too close to the inflection
        else:
            lo = mid
    d0 = big_d * mpf(10) ** -((lo + hi) / 2)
    big_d, _, chord = piece(d0)
    scale = abs(q1 - q0) / chord
    kappa = lambda d: sign * p * d ** (p - 1) / scale
    return kappa(d0), kappa(big_d)


def test_g2_path_inflections_reach_zero_curvature_in_the_reference():
    """The segments next to a straight piece checked against the closed-form shape of a
    log-aesthetic curve from its inflection point (mpmath quadrature, 30 digits): their
    curvature there is zero to 1e-9 of their other end's, and every joint (those ends
    included) is continuous to 1e-9 in the reference; the other segments by the mpmath
    segment reference."""
    require("path")
    mp.dps = 30
    inflections, worst_zero, worst_jump = 0, mpf(0), mpf(0)
    for polygon, closed, alphas in INFLECTION_CASES:
        for alpha in alphas:
            report = run_path(polygon, closed, alpha)
            assert report["continuity"] == "g2"
            lines = report["straight_pieces"]
            assert lines
            segs = report["segments"]
            n = len(segs)
            ends_on_line = {tuple(line["points"][0]) for line in lines}
            starts_on_line = {tuple(line["points"][1]) for line in lines}
            refs = []
            for seg in segs:
                tri = seg["control_points"]
                if tuple(tri[0]) in starts_on_line:
                    k_infl, k_other = inflection_segment(tri, seg["alpha"], at_start=True)
                    refs.append((k_infl, k_other))
                elif tuple(tri[2]) in ends_on_line:
                    k_infl, k_other = inflection_segment(tri, seg["alpha"], at_start=False)
                    refs.append((k_other, k_infl))
                else:
                    pa, pb, pc = (mpc(*map(mpf, pt)) for pt in tri)
                    ref = solve_segment(pa, pb, pc, seg["alpha"], [0, 1])
                    refs.append((ref["curvature_start"], ref["curvature_end"]))
            pairs = n if closed else n - 1
            for k in range(pairs):
                before, after = refs[k][1], refs[(k + 1) % n][0]
                if tuple(segs[k]["control_points"][2]) in ends_on_line:
                    zero = max(abs(before) / abs(refs[k][0]),
                               abs(after) / abs(refs[(k + 1) % n][1]))
                    assert zero <= mpf("1e-9"), (polygon, alpha, k, zero)
                    assert before * after <= 0  # the curvature changes sign across it
                    worst_zero = max(worst_zero, zero)
                    inflections += 1
                else:
                    jump = abs(before - after) / max(abs(before), abs(after))
                    assert jump <= JUMP, (polygon, alpha, k, jump)
                    worst_jump = max(worst_jump, jump)
    print(f"{inflections} inflections: largest |κ| there in the reference "
          f"{float(worst_zero):.2e} of the segment's other end; other joints' largest "
          f"jump {float(worst_jump):.2e}")
    assert inflections == 4 + 2 * 2


# Point sets with a G2 spline through them for these slopes (turning one way, and a wave
# whose spans through an inflection are each two segments meeting at zero curvature).
WAVE = " ".join(f"{i},{math.sin(0.9 * i + 0.3):.4f}" for i in range(8))
SPLINE_CASES = [
    ("0,0 2,0.3 3.5,1.5 4,3 3.2,4.6", False, [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0]),
    ("1,0 0,1.2 -1,0 0,-0.8", True, [-1.0, 0.0, 1.0]),
    ("0,0 1,0.05 2,0.3 3,0.8 3.8,1.6 4.2,2.6", False, [-0.5, 0.5]),
    (WAVE, False, [-0.25, -0.5, -1.0]),
]


def test_g2_spline_joints_are_continuous_in_the_mpmath_reference():
    """`lac spline`: every piece's segment solved again by the mpmath reference from its
    reported control triangle; the spans pass through the given points, their tangents are
    continuous (the triangles' legs at a point are collinear) and so is the reference's
    curvature, to 1e-9 (relative). The two halves of a span through an inflection meet where
    the reference's curvature is zero (within 1e-9 of the halves' other ends), with opposite
    signs on either side."""
    require("spline")
    mp.dps = 30
    checked, worst, worst_self, worst_tangent = 0, mpf(0), mpf(0), mpf(0)
    inflections, worst_zero, flat, worst_flat = 0, mpf(0), 0, mpf(0)
    for through, closed, alphas in SPLINE_CASES:
        points = [tuple(map(float, p.split(","))) for p in through.split()]
        for alpha in alphas:
            args = [lac_bin(), "spline", "--through", through, "--alpha", str(alpha),
                    "--samples", "2"] + (["--closed"] if closed else [])
            run = subprocess.run(args, capture_output=True, text=True, timeout=60)
            assert run.returncode == 0, run.stderr
            report = json.loads(run.stdout)
            pieces = report["pieces"]
            spans = [p["span"] for p in pieces]
            assert sorted(set(spans)) == list(range(len(points) if closed else len(points) - 1))
            ends, legs = [], []
            for k, piece in enumerate(pieces):
                tri = piece["control_points"]
                span = piece["span"]
                if k == 0 or spans[k - 1] != span:
                    assert tuple(tri[0]) == points[span]
                if k + 1 == len(pieces) or spans[k + 1] != span:
                    assert tuple(tri[2]) == points[(span + 1) % len(points)]
                pa, pb, pc = (mpc(*map(mpf, p)) for p in tri)
                if k + 1 < len(pieces) and spans[k + 1] == span:
                    # The first half of an S: its inflection at its end.
                    k_infl, k_other = inflection_segment(tri, alpha, at_start=False)
                    ends.append((k_other, k_infl))
                elif k > 0 and spans[k - 1] == span:
                    ends.append(inflection_segment(tri, alpha, at_start=True))
                else:
                    ref = solve_segment(pa, pb, pc, alpha, [0, 1])
                    ends.append((ref["curvature_start"], ref["curvature_end"]))
                legs.append((pb - pa, pc - pb, pa, pc))
                scale = max(abs(e) for e in ends[-1])
                # The reference can be no better than the triangle it starts from (ten times
                # its rounding, where that exceeds 1e-13).
                rounding = triangle_rounding(tri)
                allowed = max(mpf("1e-12"), 10 * mpf(rounding))
                for got, want in zip(piece["curvature"], ends[-1]):
                    if abs(want) < mpf("1e-9") * scale:
                        continue  # a half's end at the inflection: checked below
                    err = abs(mpf(got) - want) / abs(want)
                    if rounding <= 1e-13:
                        worst_self = max(worst_self, err)
                    else:
                        flat += 1
                        worst_flat = max(worst_flat, err / mpf(rounding))
                    assert err <= allowed, (through, alpha, k, got, want, rounding)
            pairs = len(pieces) if closed else len(pieces) - 1
            for k in range(pairs):
                nxt = (k + 1) % len(pieces)
                before, after = ends[k][1], ends[nxt][0]
                u, v = legs[k][1], legs[nxt][0]
                tangent = abs(atan2(u.real * v.imag - u.imag * v.real, (u.conjugate() * v).real))
                assert tangent <= mpf("1e-12"), (through, alpha, k, tangent)
                worst_tangent = max(worst_tangent, tangent)
                if spans[k] == spans[nxt]:
                    # The inflection: zero curvature on both sides, the halves' ends within
                    # rounding of each other.
                    scale = max(abs(ends[k][0]), abs(ends[nxt][1]))
                    zero = max(abs(before), abs(after)) / scale
                    assert zero <= mpf("1e-9") and before * after <= 0, (through, alpha, k)
                    assert ends[k][0] * ends[nxt][1] < 0
                    assert abs(legs[k][3] - legs[nxt][2]) <= mpf("1e-11")
                    worst_zero = max(worst_zero, zero)
                    inflections += 1
                    continue
                jump = abs(before - after) / max(abs(before), abs(after))
                assert jump <= JUMP, (through, alpha, k, jump)
                worst = max(worst, jump)
                checked += 1
    print(f"{checked} spline joints: largest curvature jump in the reference "
          f"{float(worst):.2e}, tangent mismatch {float(worst_tangent):.2e}; largest "
          f"end-curvature error of lac {float(worst_self):.2e} ({flat} ends of pieces whose "
          f"triangles' rounding exceeds 1e-13: at most {float(worst_flat):.2f} times it); "
          f"{inflections} inflections, |κ| there at most {float(worst_zero):.2e} of the "
          f"halves' other ends")
    assert checked == 6 * 3 + 3 * 4 + 2 * 4 + 3 * 6
    assert inflections == 3


# Splines with point types (docs/math.md, splines with point types): a U whose straight sides
# the curve meets with zero curvature and whose bottom is horizontal; tangent points; G2
# Hermite ends; a closed outline with a stem, a corner and horizontal extrema.
TYPED_CASES = [
    (["--through", "0,4 0,1.5 1,0 2,1.5 2,4", "--types", "s s t s s", "--angles", "2:0",
      "--lines", "0-1,3-4"], [-1.0, -0.5]),
    (["--through", "0,0 1,0.6 2,0.8 3,0.55 4,0", "--types", "s s t s s", "--angles", "2:0"],
     [-1.0, -0.5, 0.0, 0.5, 1.0]),
    (["--through", "0,0 1,0.6 2,0.8 3,0.6 4,0", "--start-angle", "0.7", "--start-curvature",
      "-0.3", "--end-curvature", "-0.2"], [-1.0, 0.0, 0.5, 2.0]),
    (["--through", "0,0 0,4 2,3.6 3,2 2,0.4", "--closed", "--types", "c c s t s",
      "--angles", "3:-1.5707963267948966", "--lines", "0-1"], [-1.0]),
]


def test_splines_with_point_types_meet_their_conditions_in_the_mpmath_reference():
    """`lac spline` with point types: every piece's segment solved again by the mpmath
    reference from its reported control triangle (a piece that meets a straight span or an
    inflection by the reference of a segment ending at its inflection); at every point and
    knot the tangent is continuous (the triangles' legs collinear, except at corners) to
    1e-12 rad and the reference's curvature to 1e-9 (relative, except at corners); a given
    direction is the leg's to 1e-12 rad; where a curve meets a straight span the reference's
    curvature is within 1e-12 of the largest, its leg along the span; a given end curvature
    is the reference's to 1e-12 (relative)."""
    require("spline")
    mp.dps = 30
    worst = {"g2": mpf(0), "tangent": mpf(0), "flat": mpf(0), "end": mpf(0), "given": mpf(0)}
    joints = 0
    for args, alphas in TYPED_CASES:
        through = args[args.index("--through") + 1]
        points = [tuple(map(float, p.split(","))) for p in through.split()]
        n = len(points)
        closed = "--closed" in args
        for alpha in alphas:
            run = subprocess.run([lac_bin(), "spline", "--alpha", str(alpha), "--samples", "2"]
                                 + args, capture_output=True, text=True, timeout=120)
            assert run.returncode == 0, (args, alpha, run.stderr)
            report = json.loads(run.stdout)
            pieces, at, lines = report["pieces"], report["at_points"], report["lines"]
            spans = [p["span"] for p in pieces]
            tris = [[tuple(p) for p in piece["control_points"]] for piece in pieces]
            ends = []
            for k, tri in enumerate(tris):
                span = spans[k]
                first = k == 0 or spans[k - 1] != span
                last = k + 1 == len(tris) or spans[k + 1] != span
                flat_start = tri[0] != (points[span] if first else tris[k - 1][2])
                flat_end = tri[2] != (points[(span + 1) % n] if last else tris[k + 1][0])
                if flat_end:
                    k_flat, k_other = inflection_segment(tri, alpha, at_start=False)
                    ends.append((k_other, k_flat))
                elif flat_start:
                    ends.append(inflection_segment(tri, alpha, at_start=True))
                else:
                    pa, pb, pc = (mpc(*map(mpf, p)) for p in tri)
                    ref = solve_segment(pa, pb, pc, alpha, [0, 1])
                    ends.append((ref["curvature_start"], ref["curvature_end"]))
            scale = max(abs(e) for pair in ends for e in pair)

            def leg(tri, at_start):
                a, b = (tri[0], tri[1]) if at_start else (tri[1], tri[2])
                return atan2(mpf(b[1]) - mpf(a[1]), mpf(b[0]) - mpf(a[0]))

            def wrap(a):
                return abs(a - 2 * mp.pi * mp.nint(a / (2 * mp.pi)))

            # Joints inside a span: knots (exact) and inflections (checked above by the
            # reference's zero).
            for k in range(len(tris) - 1):
                if spans[k] == spans[k + 1] and tris[k][2] == tris[k + 1][0]:
                    t = wrap(leg(tris[k], False) - leg(tris[k + 1], True))
                    jump = abs(ends[k][1] - ends[k + 1][0]) / max(abs(ends[k][1]),
                                                                 abs(ends[k + 1][0]))
                    assert t <= mpf("1e-12") and jump <= JUMP, (args, alpha, k, t, jump)
                    worst["g2"], worst["tangent"] = max(worst["g2"], jump), max(worst["tangent"], t)
                    joints += 1
            # The points.
            for i in range(n):
                before_span, after_span = (i - 1) % n, i
                has_before, has_after = closed or i > 0, closed or i + 1 < n
                b = a = None
                if has_before and before_span not in lines:
                    kb = max(k for k in range(len(spans)) if spans[k] == before_span)
                    b = (leg(tris[kb], False), ends[kb][1])
                if has_after and after_span not in lines:
                    ka = min(k for k in range(len(spans)) if spans[k] == after_span)
                    a = (leg(tris[ka], True), ends[ka][0])
                kind, given = at[i]["type"], at[i]["given"]
                for side, g in ((b, given[0]), (a, given[1])):
                    if side is not None and g is not None:
                        worst["given"] = max(worst["given"], wrap(side[0] - mpf(g)))
                        assert wrap(side[0] - mpf(g)) <= mpf("1e-12"), (args, alpha, i)
                for side, on_line in ((b, has_after and after_span in lines),
                                      (a, has_before and before_span in lines)):
                    if side is not None and on_line and kind != "corner":
                        span = after_span if side is b else before_span
                        d = (mpf(points[(span + 1) % n][0]) - mpf(points[span][0]),
                             mpf(points[(span + 1) % n][1]) - mpf(points[span][1]))
                        t = wrap(side[0] - atan2(d[1], d[0]))
                        flat = abs(side[1]) / scale
                        assert t <= mpf("1e-12") and flat <= mpf("1e-12"), (args, alpha, i, t, flat)
                        worst["flat"], worst["tangent"] = max(worst["flat"], flat), max(worst["tangent"], t)
                if b is not None and a is not None and kind != "corner":
                    t = wrap(b[0] - a[0])
                    jump = abs(b[1] - a[1]) / max(abs(b[1]), abs(a[1]))
                    assert t <= mpf("1e-12") and jump <= JUMP, (args, alpha, i, t, jump)
                    worst["g2"], worst["tangent"] = max(worst["g2"], jump), max(worst["tangent"], t)
                    joints += 1
            for name, side, flag in (("start", ends[0][0], "--start-curvature"),
                                     ("end", ends[-1][1], "--end-curvature")):
                if flag in args:
                    want = mpf(args[args.index(flag) + 1])
                    err = abs(side - want) / abs(want)
                    worst["end"] = max(worst["end"], err)
                    assert err <= mpf("1e-12"), (args, alpha, name, err)
    print(f"{joints} joints with point types; worst in the reference: " +
          ", ".join(f"{k} {float(v):.1e}" for k, v in worst.items()))
    assert joints >= 40
