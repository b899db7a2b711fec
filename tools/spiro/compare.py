"""lac's splines with point types side by side with libspiro (Spiro, the spline inside
FontForge and Inkscape) on the same seeded glyph-like outlines with the same point types: the
share each solves, the time per solve, and the curvature plots of one outline both ways.

    .venv/bin/python tools/spiro/compare.py [--count 1000] [--plot docs/spiro.png]

Needs Debian's libspiro-dev (`apt-get install libspiro-dev`), a C compiler, the Python
bindings (`make py`) and matplotlib for the plot. The outlines are those of
crates/lac/benches/common/glyphs.rs (the same SplitMix64 stream and construction): closed,
8–20 points around a wobbly oval, about a quarter of them corners or straight spans' ends, the
extrema horizontal. Spiro's types: smooth 'c' (G2), corner 'v', a straight span from '[' to
']', a tangent point an anchor 'a' with its handle 'h' one unit along the direction. Spiro
has no α: its curve is a polynomial spiral (curvature cubic in arc length), so the plots show
two families of fair curves through the same points, not one curve twice.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import lac

HERE = os.path.dirname(os.path.abspath(__file__))
MASK = (1 << 64) - 1


class Rng:
    """SplitMix64, as crates/lac/benches/common/mod.rs."""

    def __init__(self, seed):
        self.state = seed & MASK

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return ((z ^ (z >> 31)) >> 11) / float(1 << 53)


def glyph(rng):
    """One outline: points, types ('s', 't', 'c'), the tangent points' directions, lines."""
    tau = 2 * math.pi
    n = 8 + int(13.0 * rng.next())
    p2, p3 = tau * rng.next(), tau * rng.next()
    w2, w3 = 0.08 * rng.next(), 0.05 * rng.next()
    points = []
    for k in range(n):
        t = tau * (k + 0.35 * (rng.next() - 0.5)) / n
        r = 1.0 + w2 * math.sin(2.0 * t + p2) + w3 * math.sin(3.0 * t + p3)
        points.append((r * math.cos(t), 1.4 * r * math.sin(t)))
    types, angles, taken, lines = ["s"] * n, {}, [False] * n, []
    for k in range(n):
        r = rng.next()
        if taken[k]:
            continue
        if r < 0.1:
            types[k], taken[k] = "c", True
        elif r < 0.18 and not taken[(k + 1) % n]:
            lines.append(k)
            taken[k] = taken[(k + 1) % n] = True
    top = max(range(n), key=lambda k: points[k][1])
    bottom = min(range(n), key=lambda k: points[k][1])
    for k, angle in ((top, math.pi), (bottom, 0.0)):
        if not taken[k]:
            types[k], angles[k] = "t", angle
    return points, types, angles, lines


def spiro_line(points, types, angles, lines):
    """The outline as spiro_run reads it."""
    n = len(points)
    ty = {"s": "c", "c": "v", "t": "a"}
    cps = []
    for k, (x, y) in enumerate(points):
        t = ty[types[k]]
        if k in lines:
            t = "["
        elif (k - 1) % n in lines:
            t = "]"
        cps.append(f"{x!r} {y!r} {t}")
        if t == "a":
            a = angles[k]
            cps.append(f"{x + math.cos(a)!r} {y + math.sin(a)!r} h")
    return f"{len(cps)} 1 " + " ".join(cps)


def cubic_curvature(q, steps=40):
    """(arc length, signed curvature) along a cubic Bézier piece, s from its start."""
    (x0, y0, x1, y1, x2, y2, x3, y3) = q
    out, s, last = [], 0.0, None
    for i in range(steps + 1):
        t = i / steps
        u = 1 - t
        dx = 3 * (u * u * (x1 - x0) + 2 * u * t * (x2 - x1) + t * t * (x3 - x2))
        dy = 3 * (u * u * (y1 - y0) + 2 * u * t * (y2 - y1) + t * t * (y3 - y2))
        ddx = 6 * (u * (x2 - 2 * x1 + x0) + t * (x3 - 2 * x2 + x1))
        ddy = 6 * (u * (y2 - 2 * y1 + y0) + t * (y3 - 2 * y2 + y1))
        speed = math.hypot(dx, dy)
        if last is not None:
            s += 0.5 * (speed + last) / steps
        last = speed
        out.append((s, (dx * ddy - dy * ddx) / speed ** 3 if speed > 0 else 0.0))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--count", type=int, default=1000)
    ap.add_argument("--plot", default=None, help="PNG of one outline's curvature both ways")
    ap.add_argument("--outline", type=int, default=None, help="which outline to plot")
    args = ap.parse_args()
    rng = Rng(0x6C795048)
    outlines = [glyph(rng) for _ in range(args.count)]

    work = tempfile.mkdtemp()
    exe = os.path.join(work, "spiro_run")
    subprocess.run(["cc", "-O2", "-o", exe, os.path.join(HERE, "spiro_run.c"), "-lspiro", "-lm"],
                   check=True)
    text = "\n".join(spiro_line(*o) for o in outlines) + "\n"
    # Twice: the first run warms the library and the caches; the second is timed.
    subprocess.run([exe], input=text, capture_output=True, text=True, check=True)
    rows = subprocess.run([exe], input=text, capture_output=True, text=True, check=True)
    spiro = [tuple(map(int, line.split())) for line in rows.stdout.splitlines()]
    result = {"outlines": args.count, "spiro": {
        "solved": sum(ok for ok, _, _ in spiro),
        "median_us": statistics.median(ns for _, ns, _ in spiro) / 1e3}}

    solved_lac = {}
    for alpha in (-1.0, -0.5):
        ok, times, reasons = [], [], {}
        for points, types, angles, lines in outlines:
            t0 = time.perf_counter()
            try:
                lac.Spline(points, alpha, closed=True, types=types, angles=angles, lines=lines)
                good = True
            except lac.LacError as e:
                good = False
                key = str(e).split(" there")[0].split(",")[0]
                key = "".join(c for c in key if not c.isdigit())
                reasons[key] = reasons.get(key, 0) + 1
            times.append(time.perf_counter() - t0)
            ok.append(good)
        solved_lac[alpha] = ok
        result[f"lac alpha={alpha}"] = {"solved": sum(ok),
                                        "median_us": statistics.median(times) * 1e6,
                                        "refused": reasons}
    both = [k for k in range(args.count) if spiro[k][0] and solved_lac[-1.0][k]]
    result["both (alpha=-1)"] = len(both)
    print(json.dumps(result))

    if args.plot and both:
        k = args.outline if args.outline is not None else both[0]
        plot(exe, text, outlines[k], k, args.plot)


def plot(exe, text, outline, k, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    points, types, angles, lines = outline
    run = subprocess.run([exe, "--curves", str(k)], input=text, capture_output=True, text=True,
                         check=True)
    rows = run.stdout.splitlines()[k + 1:]
    pieces = [tuple(map(float, r.split())) for r in rows if len(r.split()) == 8]
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 4.2))
    s0, xs, ks, bx, by = 0.0, [], [], [], []
    for q in pieces:
        for s, kappa in cubic_curvature(q):
            xs.append(s0 + s)
            ks.append(kappa)
        s0 = xs[-1]
        for i in range(21):
            t = i / 20
            u = 1 - t
            bx.append(u ** 3 * q[0] + 3 * u * u * t * q[2] + 3 * u * t * t * q[4] + t ** 3 * q[6])
            by.append(u ** 3 * q[1] + 3 * u * u * t * q[3] + 3 * u * t * t * q[5] + t ** 3 * q[7])
    ax1.plot(xs, ks, color="#e69138", label="Spiro (libspiro)")
    ax0.plot(bx, by, color="#e69138", lw=1)
    for alpha, color in ((-1.0, "#1f4e9c"), (-0.5, "#6aa84f")):
        try:
            spl = lac.Spline(points, alpha, closed=True, types=types, angles=angles, lines=lines)
        except lac.LacError:
            continue
        smp = spl.sample(800)
        ax1.plot(smp.s, smp.kappa, color=color, label=f"lac, α = {alpha}")
        ax0.plot(smp.points[:, 0], smp.points[:, 1], color=color, lw=1)
    mark = {"s": "o", "t": ">", "c": "s"}
    for (x, y), t in zip(points, types):
        ax0.plot([x], [y], marker=mark[t], color="k", ms=4)
    ax0.set_aspect("equal")
    ax0.set_title(f"outline {k}: {len(points)} points ({types.count('c')} corners, "
                  f"{len(lines)} straight spans, {types.count('t')} tangent)", fontsize=9)
    ax1.set_xlabel("arc length")
    ax1.set_ylabel("signed curvature")
    ax1.legend(fontsize=8)
    ax1.set_title("curvature along the outline", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    print(f"wrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
