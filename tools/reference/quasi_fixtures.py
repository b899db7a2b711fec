#!/usr/bin/env python3
"""Write the quasi-aesthetic-curve fixtures (docs/math.md §5; mathematics in quasi_mpmath.py).

    .venv/bin/python tools/reference/quasi_fixtures.py [--only monotone|quasi] [-j JOBS]

crates/lac/tests/fixtures/monotone.json -- exact curvature-monotonicity verdicts of
rational cubic Beziers given by float control points and weights (converted exactly):
    verdict        increasing | decreasing | constant | not_monotone (for dkappa/ds on [0, 1])
    sign_changes   the parameters in (0, 1) where dkappa/ds changes sign (to 1e-16)
    samples        t = 0, 1/8, ..., 1 with signed kappa and dkappa/ds (40 digits, rounded)
    kind           how the case was made (below); near-circle cases also carry
                   max_dkappa_ds_over_kappa_sq = max |dkappa/ds| / kappa^2 over 1001 t values
                   (= max |drho/ds|, scale-free: tiny means nearly constant curvature).
Kinds: random (points in [-1, 1]^2, weights log-uniform in [0.1, 10]), polynomial (all
weights 1), spiral (a perturbed Class A polygon, legs turning by a fixed angle and growing
by a fixed ratio, weights in [0.8, 1.25] or all 1: often monotone), scaled (random and
spiral curves scaled by 1e6 or 1e-6 and/or offset by up to 1e6), collinear (constant),
circle (exact rational cubic circles with integer data: constant), near-circle
(degree-elevated circular arcs, optionally reparametrised w_i -> w_i lam^i, with the
weights rounded to doubles: dkappa/ds ~ 1e-15 kappa^2, any verdict), and four kinds from
one-parameter families s -> (points, weights) interpolated between a monotone curve and a
non-monotone one, bisected in s to the double where the number of sign changes first
changes:
    near-not-monotone   monotone side of a place where two sign changes are born
                        (dkappa/ds has a near-double root)
    narrow              the other side: dkappa/ds has the minority sign only on an interval
                        narrower than 1e-4 (down to 3e-9) that sampling at t = k/1000 and
                        t = k/999 misses
    near-end            one sign change within 1e-6 of t = 0 or t = 1 (down to 1e-13)
    near-end-monotone   monotone with dkappa/ds nearly 0 at an end (root just outside)
Curves whose speed vanishes somewhere on [0, 1] are left out.

crates/lac/tests/fixtures/quasi.json -- the seed-001 one-piece fit (docs/math.md §5) at its
reference optimum (u, v) of F(u, v) = int_0^Theta d(phi)^2 dphi (tangent-angle
correspondence), with the LAC segment's arc length and signed end curvatures (caller's
order), the rational cubic (bezier, weights with w1 = w2 = (2 cos(Theta/2) + 1)/3),
rms and max of d / arc_length for that cubic as written (doubles), Theta ("turning") and
the exact verdict of the written cubic.  An isosceles triangle gives the circle
u = v = 2c/(1 + 2c), c = cos(Theta/2), w0 = w3 = 1 by rule: F = 0 along a whole curve of
(u, v) there; its written cubic's exact verdict is that of rounded doubles (not "constant").
Checks done here for every fit: the Newton step and a finer quadrature rule (36 nodes)
move (u, v) by less than 1e-12; rms and max agree between the two rules; the written
cubic's end curvatures are the LAC's (1e-12 relative).

Random choices use fixed seeds; the output does not depend on the number of jobs.
"""

import argparse
import json
import math
import os
import random
import sys
import time
from multiprocessing import Pool

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpmath import mp, mpf, mpc, cos, fabs  # noqa: E402

import quasi_mpmath as qm  # noqa: E402
from segment_mpmath import NotDrawable  # noqa: E402

mp.dps = 40
OUT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                    "crates", "lac", "tests", "fixtures"))
SAMPLE_TS = [k / 8 for k in range(9)]


def write(name, description, cases):
    path = os.path.join(OUT, name)
    lines = [json.dumps(c, separators=(",", ":")) for c in cases]
    with open(path, "w") as f:
        f.write("{" + '"description": %s,\n"cases": [\n' % json.dumps(description))
        f.write(",\n".join(lines))
        f.write("\n]}\n")
    print(f"{path}: {len(cases)} cases, {os.path.getsize(path)} bytes")


# ---- monotone.json ---------------------------------------------------------------------

def record(kind, points, weights):
    """The fixture row for one curve, or None if its speed vanishes on [0, 1]."""
    points = [[float(x), float(y)] for x, y in points]
    weights = [float(w) for w in weights]
    cubic = qm.ExactCubic(points, weights)
    if cubic.speed_vanishes():
        return None
    verdict, changes = cubic.verdict()
    rc = qm.RationalCubic(points, weights)
    samples, values = [], []
    for t in SAMPLE_TS:
        k, dk = qm.homogeneous_kappa(cubic, t)       # exact polynomials (0 stays 0)
        k2, dk2 = rc.kappa(mpf(t)), rc.dkappa_ds(mpf(t))  # seed 001 eq. 5.1
        values.append((k, dk, k2, dk2))
        samples.append({"t": t, "kappa": float(k), "dkappa_ds": float(dk)})
    size = max(math.hypot(p[0] - q[0], p[1] - q[1]) for p in points for q in points)
    kscale = max(fabs(v[0]) for v in values) + 1 / mpf(size)
    dscale = max(fabs(v[1]) for v in values) + kscale ** 2
    for k, dk, k2, dk2 in values:
        assert fabs(k - k2) <= mpf("1e-25") * kscale and fabs(dk - dk2) <= mpf("1e-25") * dscale
        if verdict == "increasing":
            assert dk >= 0
        if verdict == "decreasing":
            assert dk <= 0
        if verdict == "constant":
            assert dk == 0
    row = {"name": None, "kind": kind, "points": points, "weights": weights,
           "verdict": verdict, "sign_changes": changes, "samples": samples}
    if kind in ("near-circle", "circle"):
        worst = mpf(0)
        with mp.workdps(30):
            for j in range(1001):
                t = mpf(j) / 1000
                worst = max(worst, fabs(rc.dkappa_ds(t)) / rc.kappa(t) ** 2)
        row["max_dkappa_ds_over_kappa_sq"] = float(worst)
    return row


def random_curve(rng, polynomial=False):
    pts = [(rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(4)]
    ws = [1.0] * 4 if polynomial else [10 ** rng.uniform(-1, 1) for _ in range(4)]
    return pts, ws


def spiral_curve(rng, polynomial=False):
    """Legs b_(i+1) - b_i = (q e^(i phi))^i (b1 - b0): a Class A polygon (Farin 2006) that
    gives monotone curvature for many (q, phi), slightly perturbed; weights log-uniform in
    [0.8, 1.25] or all 1; either order."""
    q = rng.uniform(1.2, 3.0)
    phi = rng.choice([-1, 1]) * rng.uniform(0.05, 0.7)
    start = rng.uniform(-math.pi, math.pi)
    z, leg = 0j, complex(math.cos(start), math.sin(start))
    pts = [(0.0, 0.0)]
    for _ in range(3):
        z += leg * complex(rng.uniform(0.95, 1.05), rng.uniform(-0.05, 0.05))
        pts.append((z.real, z.imag))
        leg *= q * complex(math.cos(phi), math.sin(phi))
    if rng.random() < 0.5:
        pts = pts[::-1]
    ws = [1.0] * 4 if polynomial else [1.25 ** rng.uniform(-1, 1) for _ in range(4)]
    return pts, ws


def collinear_curves(rng):
    """Points in order along exactly representable lines; kappa = 0 identically."""
    out = []
    for line in range(10):
        xs = sorted(rng.choice(range(-64, 65)) / 32 for _ in range(4))
        if len(set(xs)) < 2:
            xs = [-1.0, -0.25, 0.5, 1.0]
        if line % 5 == 0:
            pts = [(x, 0.0) for x in xs]
        elif line % 5 == 1:
            pts = [(x, x) for x in xs]
        elif line % 5 == 2:
            pts = [(x, 2 * x + 0.5) for x in xs]
        elif line % 5 == 3:
            pts = [(3.0, x) for x in xs]
        else:
            pts = [(1e6 + x, -x / 4) for x in xs]
        ws = [1.0] * 4 if line < 3 else [10 ** rng.uniform(-1, 1) for _ in range(4)]
        out.append((pts, ws))
    return out


def exact_circles():
    """Half-turning angle with cos 4/5, sin 3/5: ba = (0, 0), bb = (325, 0),
    bc = (416, 312), u = v = 2c/(1 + 2c) = 8/13, weights (15, 13, 13, 15), all exact."""
    base = [(0, 0), (200, 0), (360, 120), (416, 312)]
    out = []
    for rot, off, ws in [(0, (0, 0), [15.0, 13.0, 13.0, 15.0]),
                         (1, (-1000, 7), [7.5, 6.5, 6.5, 7.5]),
                         (2, (0.5, 0.25), [15.0, 13.0, 13.0, 15.0]),
                         (3, (0, 0), [30.0, 26.0, 26.0, 30.0])]:
        pts = []
        for x, y in base:
            for _ in range(rot):  # rotate by 90 degrees: exact
                x, y = -y, x
            pts.append((x + off[0], y + off[1]))
        out.append((pts, ws))
    out.append(([p for p in reversed(out[0][0])], list(reversed(out[0][1]))))
    return out


def near_circles(rng, n):
    """Degree-elevated circular arcs (weights 1, (2c + 1)/3, (2c + 1)/3, 1), sometimes
    reparametrised (w_i -> w_i lam^i), under a random similarity, rounded to doubles."""
    out = []
    for i in range(n):
        theta = mpf(rng.uniform(0.1, 3.0))
        c = cos(theta / 2)
        ba, bb, bc = mpc(0), mpc(1), 1 + mp.expj(theta)
        u = 2 * c / (1 + 2 * c)
        b = [ba, ba + u * (bb - ba), bc + u * (bb - bc), bc]
        w = [mpf(1), (2 * c + 1) / 3, (2 * c + 1) / 3, mpf(1)]
        if i % 2:
            lam = mpf(10 ** rng.uniform(-0.5, 0.5))
            w = [wi * lam ** j for j, wi in enumerate(w)]
        scale = 10 ** rng.uniform(-3, 3)
        rot = mp.expj(rng.uniform(-math.pi, math.pi)) * scale
        off = mpc(rng.uniform(-1, 1), rng.uniform(-1, 1)) * scale * (10 if i % 3 == 0 else 0)
        pts = [(float((off + rot * z).real), float((off + rot * z).imag)) for z in b]
        if i % 4 == 3:
            pts, w = pts[::-1], w[::-1]
        out.append((pts, [float(x) for x in w]))
    return out


def scaled_curves(rng, n):
    out = []
    for i in range(n):
        pts, ws = (spiral_curve if i % 2 else random_curve)(rng, polynomial=(i % 4 == 0))
        size = [1e6, 1e-6, 1.0][i % 3]
        off = [(0.0, 0.0), (size * rng.uniform(-10, 10), size * rng.uniform(-10, 10)),
               (1e6 * rng.uniform(-1, 1), 1e6 * rng.uniform(-1, 1))][(i // 3) % 3]
        if size == 1.0 and off[0] == 0.0:
            off = (1e6, -3e5)
        out.append(([(size * x + off[0], size * y + off[1]) for x, y in pts], ws))
    return out


# ---- one-parameter families and their transitions -------------------------------------------

def family(a, b):
    """s -> curve: points linear, log-weights linear, rounded to doubles."""
    (pa, wa), (pb, wb) = a, b

    def at(s):
        pts = [((1 - s) * x0 + s * x1, (1 - s) * y0 + s * y1) for (x0, y0), (x1, y1) in zip(pa, pb)]
        ws = [math.exp((1 - s) * math.log(w0) + s * math.log(w1)) for w0, w1 in zip(wa, wb)]
        return pts, ws
    return at


def state(curve):
    c = qm.ExactCubic(*curve)
    if c.speed_vanishes():
        return None
    return c.count_sign_changes(), c.end_signs()


def transition(at, grid=16):
    """First s where the state (count of sign changes, end signs) leaves that of s = 0,
    bisected to adjacent doubles: (s_lo, s_hi, state_lo, state_hi), or None."""
    s0 = state(at(0.0))
    if s0 is None or s0[0] != 0:
        return None
    lo = 0.0
    for j in range(1, grid + 1):
        hi = j / grid
        st = state(at(hi))
        if st is None:
            return None
        if st != s0:
            break
        lo = hi
    else:
        return None
    st_hi = st
    while True:
        mid = (lo + hi) / 2
        if mid <= lo or mid >= hi:
            break
        st = state(at(mid))
        if st is None:
            return None
        if st == s0:
            lo = mid
        else:
            hi, st_hi = mid, st
    return lo, hi, s0, st_hi


def sampling_misses(curve):
    """True if dkappa/ds has one sign (or 0) at all of t = k/1000 and t = k/999."""
    c = qm.ExactCubic(*curve)
    ip = qm.integer_poly(c.N)
    from fractions import Fraction
    signs = set()
    for den in (1000, 999):
        for k in range(den + 1):
            v = qm.peval(ip, Fraction(k, den))
            if v:
                signs.add(v > 0)
    return len(signs) <= 1


def transition_cases(at, lo, hi, st_lo, st_hi):
    """Cases on both sides of one transition (monotone at s <= lo)."""
    out = []
    end = st_lo[1] != st_hi[1]
    if end:
        # inside: the root enters at an end; keep the farthest, the middle and the nearest
        # of those within 1e-6 of that end
        found = []
        for delta in [0.0] + [10.0 ** e for e in range(-15, -4)]:
            curve = at(hi + delta)
            c = qm.ExactCubic(*curve)
            if c.speed_vanishes():
                continue
            verdict, changes = c.verdict()
            if verdict == "not_monotone" and len(changes) == 1:
                dist = min(changes[0], 1 - changes[0])
                if 1e-13 <= dist < 1e-6:
                    found.append((dist, curve))
        found.sort(key=lambda f: f[0])
        picks = {0, len(found) // 2, len(found) - 1} if found else set()
        out += [("near-end", found[i][1]) for i in sorted(picks)]
        for delta in [0.0, 1e-9]:
            out.append(("near-end-monotone", at(lo - delta)))
    else:
        for delta in [0.0, 1e-13, 1e-11, 1e-9]:
            curve = at(hi + delta)
            c = qm.ExactCubic(*curve)
            if c.speed_vanishes():
                continue
            verdict, changes = c.verdict()
            if verdict == "not_monotone" and len(changes) == 2 and changes[1] - changes[0] < 1e-4 \
                    and sampling_misses(curve):
                out.append(("narrow", curve))
        for delta in [0.0, 1e-12, 1e-9, 1e-6]:
            out.append(("near-not-monotone", at(lo - delta)))
    return out


def family_job(seed):
    """One random family: a monotone curve and a non-monotone one; its transition cases."""
    rng = random.Random(1000 + seed)
    polynomial = seed % 3 == 0
    for _ in range(200):
        a = random_curve(rng, polynomial)
        st = state(a)
        if st is not None and st[0] == 0 and qm.ExactCubic(*a).N:
            break
    for _ in range(200):
        b = random_curve(rng, polynomial)
        st = state(b)
        if st is not None and st[0] >= 1:
            break
    at = family(a, b)
    tr = transition(at)
    if tr is None:
        return []
    rows = []
    for kind, curve in transition_cases(at, *tr):
        row = record(kind, *curve)
        if row is None:
            continue
        ok = {"near-end": row["verdict"] == "not_monotone",
              "narrow": row["verdict"] == "not_monotone",
              "near-end-monotone": row["verdict"] in ("increasing", "decreasing"),
              "near-not-monotone": row["verdict"] in ("increasing", "decreasing")}[kind]
        if ok:
            rows.append(row)
    return rows


def simple_job(spec):
    kind, curve = spec
    return record(kind, *curve)


def monotone(jobs):
    start = time.time()
    rng = random.Random(7)
    specs = [("random", random_curve(rng)) for _ in range(60)]
    specs += [("polynomial", random_curve(rng, polynomial=True)) for _ in range(30)]
    specs += [("spiral", spiral_curve(rng, polynomial=(i % 3 == 0))) for i in range(50)]
    specs += [("scaled", c) for c in scaled_curves(rng, 30)]
    specs += [("collinear", c) for c in collinear_curves(rng)]
    specs += [("circle", c) for c in exact_circles()]
    specs += [("near-circle", c) for c in near_circles(rng, 20)]
    with Pool(jobs) as pool:
        rows = [r for r in pool.map(simple_job, specs, chunksize=4) if r is not None]
        print(f"  {len(rows)} plain cases ({len(specs) - len(rows)} with vanishing speed "
              f"left out), {time.time() - start:.0f} s", flush=True)
        fam = []
        quota = {"narrow": 20, "near-end": 20, "near-not-monotone": 30, "near-end-monotone": 14}
        have = dict.fromkeys(quota, 0)
        seed = 0
        while any(have[k] < quota[k] for k in quota) and seed < 400:
            batch = pool.map(family_job, range(seed, seed + 2 * jobs))
            seed += 2 * jobs
            for rs in batch:
                for r in rs:
                    if have[r["kind"]] < quota[r["kind"]]:
                        have[r["kind"]] += 1
                        fam.append(r)
            print(f"  families {seed}: {have}, {time.time() - start:.0f} s", flush=True)
    rows += fam
    for i, r in enumerate(rows):
        r["name"] = f"{r['kind']}-{i:03d}"
    description = __doc__.split("crates/lac/tests/fixtures/quasi.json")[0].split(
        "crates/lac/tests/fixtures/monotone.json -- ")[1].strip()
    write("monotone.json", "Generated by tools/reference/quasi_fixtures.py. " + description, rows)
    summary(rows)
    print(f"monotone: {time.time() - start:.0f} s")


def summary(rows):
    kinds = sorted({r["kind"] for r in rows})
    print(f"{'kind':20s}" + "".join(f"{v:>14s}" for v in qm.VERDICTS))
    for k in kinds:
        counts = [sum(1 for r in rows if r["kind"] == k and r["verdict"] == v) for v in qm.VERDICTS]
        print(f"{k:20s}" + "".join(f"{c:14d}" for c in counts))
    counts = [sum(1 for r in rows if r["verdict"] == v) for v in qm.VERDICTS]
    print(f"{'total':20s}" + "".join(f"{c:14d}" for c in counts))
    nc = [r["max_dkappa_ds_over_kappa_sq"] for r in rows if r["kind"] == "near-circle"]
    if nc:
        print(f"near-circle max |dkappa/ds|/kappa^2: {min(nc):.2e} .. {max(nc):.2e}")
    ends = [min(t, 1 - t) for r in rows if r["kind"] == "near-end" for t in r["sign_changes"]]
    if ends:
        print(f"near-end: distance of the sign change to the end "
              f"{min(ends):.1e} .. {max(ends):.1e}")
    widths = [r["sign_changes"][1] - r["sign_changes"][0] for r in rows if r["kind"] == "narrow"]
    if widths:
        print(f"narrow: interval widths {min(widths):.1e} .. {max(widths):.1e}")


# ---- quasi.json ------------------------------------------------------------------------

def quasi_specs():
    specs = []
    for r in [1.0, 0.8, 0.6, 0.4]:
        for alpha in [-1.0, 0.0, 1.0, 2.0]:
            specs.append((f"turn90-r{r}-alpha{alpha:g}", [(0.0, 0.0), (1.0, 0.0), (1.0, r)], alpha))
    for r, alpha in [(0.8, 0.5), (0.6, 0.5), (0.6, 1.5)]:
        specs.append((f"turn90-r{r}-alpha{alpha:g}", [(0.0, 0.0), (1.0, 0.0), (1.0, r)], alpha))
    for deg, r, alphas in [(30, 0.6, [0.0, 1.0]), (60, 0.6, [0.0, 1.0]), (120, 0.6, [0.0, 1.0])]:
        th = math.radians(deg)
        for alpha in alphas:
            pc = (1.0 + r * math.cos(th), r * math.sin(th))
            specs.append((f"turn{deg}-r{r}-alpha{alpha:g}", [(0.0, 0.0), (1.0, 0.0), pc], alpha))
    # exactly isosceles in doubles (symmetric about the y axis), turning 2 atan(h) ~ 60 degrees;
    # (1, 0) -> (1 + cos 60, sin 60) would be isosceles only up to rounding, and near an
    # isosceles triangle F is nearly 0 along a whole curve of (u, v): ill-conditioned
    h = math.tan(math.radians(30))
    specs.append(("turn60-isosceles-alpha0.5", [(-1.0, 0.0), (0.0, h), (1.0, 0.0)], 0.5))
    for alpha in [-1.0, 0.0]:
        specs.append((f"right-turn90-r0.6-alpha{alpha:g}",
                      [(0.0, 0.0), (1.0, 0.0), (1.0, -0.6)], alpha))
    for alpha in [0.0, 2.0]:
        specs.append((f"reversed-turn90-r0.6-alpha{alpha:g}",
                      [(1.0, 0.6), (1.0, 0.0), (0.0, 0.0)], alpha))
    rot, scale, off = math.radians(37), 3.7, (5.0, -2.0)
    sim = lambda p: (off[0] + scale * (math.cos(rot) * p[0] - math.sin(rot) * p[1]),
                     off[1] + scale * (math.sin(rot) * p[0] + math.cos(rot) * p[1]))
    for alpha in [0.5, 1.0]:
        specs.append((f"similar-turn90-r0.6-alpha{alpha:g}",
                      [sim(p) for p in [(0.0, 0.0), (1.0, 0.0), (1.0, 0.6)]], alpha))
    return specs


def quasi_job(spec):
    name, points, alpha = spec
    t0 = time.time()
    try:
        lac, u, v, pts, ws, info = qm.seed_fit(*points, alpha)
    except NotDrawable as e:
        return {"skip": f"{name}: not drawable ({e})"}
    bezier = [[float(p.real), float(p.imag)] for p in pts]
    weights = [float(w) for w in ws]
    written = qm.RationalCubic(bezier, weights)
    rms, mx = qm.correspondence_errors(lac, [written])
    # checks: a finer rule moves neither the optimum nor the errors
    notes = []
    if info["hessian"] is not None:
        step = max(fabs(s) for s in info["step"])
        fine = qm.FitObjective(lac, 36)
        h = mpf("1e-10")
        grad = ((fine(u + h, v) - fine(u - h, v)) / (2 * h),
                (fine(u, v + h) - fine(u, v - h)) / (2 * h))
        du, dv = qm.newton_step(grad, info["hessian"])
        shift = max(fabs(du), fabs(dv), step)
        assert shift < 1e-12, (name, shift)
        huu, huv, hvv = info["hessian"]
        tr, det = huu + hvv, huu * hvv - huv ** 2
        disc = mp.sqrt(tr ** 2 / 4 - det)
        cond = (tr / 2 + disc) / (tr / 2 - disc)
        notes.append(f"(u,v) moved {mp.nstr(shift, 2)} by 36 nodes, "
                     f"Hessian cond {mp.nstr(cond, 3)}")
    rms36, mx36 = qm.correspondence_errors(lac, [written], n=36)
    assert fabs(rms36 - rms) <= mpf("1e-8") * rms + mpf("1e-30"), (name, rms, rms36)
    assert fabs(mx36 - mx) <= mpf("1e-8") * mx + mpf("1e-30"), (name, mx, mx36)
    for t, kappa in [(0, lac.kappa_start), (1, lac.kappa_end)]:
        assert fabs(written.kappa(mpf(t)) - kappa) <= mpf("1e-12") * fabs(kappa), (name, t)
    verdict, changes = qm.monotone_verdict(bezier, weights)
    row = {"name": name, "points": [list(p) for p in points], "alpha": alpha,
           "u": float(u), "v": float(v), "weights": weights, "bezier": bezier,
           "rms": float(rms), "max": float(mx), "arc_length": float(lac.arc_length),
           "kappa_start": float(lac.kappa_start), "kappa_end": float(lac.kappa_end),
           "turning": float(lac.theta), "verdict": verdict}
    print(f"  {name}: u {float(u):.12f} v {float(v):.12f} rms {float(rms):.3e} max {float(mx):.3e} "
          f"{verdict} ({time.time() - t0:.0f} s) {'; '.join(notes)}", flush=True)
    return row


def quasi(jobs):
    start = time.time()
    with Pool(jobs) as pool:
        rows = pool.map(quasi_job, quasi_specs(), chunksize=1)
    for r in rows:
        if "skip" in r:
            print("  skipped:", r["skip"])
    rows = [r for r in rows if "skip" not in r]
    description = "Generated by tools/reference/quasi_fixtures.py. " + __doc__.split(
        "crates/lac/tests/fixtures/quasi.json -- ")[1].split("Random choices")[0].strip()
    write("quasi.json", description, rows)
    print("rms / max (relative to the arc length), turning 90 degrees, "
          "Pa = (0,0), Pb = (1,0), Pc = (1,r):")
    print(f"{'r':>5s}" + "".join(f"{'alpha ' + format(a, 'g'):>24s}" for a in [-1, 0, 1, 2]))
    for r in [1.0, 0.8, 0.6, 0.4]:
        cells = []
        for a in [-1.0, 0.0, 1.0, 2.0]:
            c = [x for x in rows if x["name"] == f"turn90-r{r}-alpha{a:g}"]
            cells.append(f"{c[0]['rms']:.2e} / {c[0]['max']:.2e}" if c else "not drawable")
        print(f"{r:5.1f}" + "".join(f"{x:>24s}" for x in cells))
    print(f"quasi: {time.time() - start:.0f} s")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", choices=["monotone", "quasi"])
    ap.add_argument("-j", "--jobs", type=int, default=min(2, os.cpu_count() or 1))
    args = ap.parse_args()
    if args.only in (None, "quasi"):
        quasi(args.jobs)
    if args.only in (None, "monotone"):
        monotone(args.jobs)


if __name__ == "__main__":
    main()
