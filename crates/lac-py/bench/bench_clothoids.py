"""lac's Python bindings against Clothoids' `build_G1`, on the same alpha = -1 inputs.

    .venv/bin/python crates/lac-py/bench/bench_clothoids.py     (make py-bench)

The inputs are the drawable configurations of the Clothoids cross-check
(tools/reference/clothoid_cases.py: 320 random three-point configurations, the ones whose
G1 clothoid has no inflection). Timed, per curve, from Python:

* `clothoids_loop`: a Python loop of `ClothoidCurve.build_G1(x0, y0, th0, x1, y1, th1, tol)`
  (SWIG binding, one C++ object reused, end angles precomputed);
* `lac_loop`: a Python loop of `lac.Segment(((x0, y0), (x1, y1), (x2, y2)), -1.0)`;
* `lac_vectorised`: one `lac.solve_segments(points, -1.0)` call over all of them, on all
  cores; `lac_vectorised_1_thread` the same with `threads=1` (on the calling thread);
* `lac_vectorised_100x`: the set repeated 100 times in one call (all cores).

Each is timed twice: wall time (`time.perf_counter`) and the process's CPU time over all
its threads (`time.process_time`). Each figure is the median of `ROUNDS` rounds; every
round runs them one after the other, so a load change on the machine affects them alike,
and the ratios are taken within each round (median of the per-round ratios). On a machine
whose cores are busy with other work, a call longer than a scheduler time slice is
descheduled and its wall time says more about the load than about lac: compare the CPU
times there. Prints one line of JSON.
"""

import json
import math
import os
import platform
import statistics
import sys
import time
from importlib.metadata import version

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "tools", "reference"))

import Clothoids  # noqa: E402
from clothoid_cases import configurations, end_curvatures, g1_clothoid  # noqa: E402

import lac  # noqa: E402

ROUNDS = 15
TOL = 1e-12  # Clothoids' Newton tolerance, as in tools/reference/bench_clothoids.py
REPEAT = 100  # the large vectorised call: the set repeated


def per_curve_us(fn, count):
    """(wall, cpu) microseconds per curve of one call of `fn`."""
    wall, cpu = time.perf_counter_ns(), time.process_time_ns()
    fn()
    return ((time.perf_counter_ns() - wall) / count / 1000,
            (time.process_time_ns() - cpu) / count / 1000)


def main():
    drawable = [c for c in configurations() if end_curvatures(g1_clothoid(*c))[0]
                * end_curvatures(g1_clothoid(*c))[1] > 0]
    hermite = []
    for pa, pb, pc in drawable:
        th0 = math.atan2(pb[1] - pa[1], pb[0] - pa[0])
        th1 = math.atan2(pc[1] - pb[1], pc[0] - pb[0])
        hermite.append((pa[0], pa[1], th0, pc[0], pc[1], th1))
    triples = [tuple(c) for c in drawable]
    points = np.array(drawable, dtype=np.float64)
    big = np.tile(points, (REPEAT, 1, 1))
    n = len(drawable)

    curve = Clothoids.ClothoidCurve()
    build = curve.build_G1
    segment = lac.Segment

    def clothoids_loop():
        for d in hermite:
            build(*d, TOL)

    def lac_loop():
        for p in triples:
            segment(p, -1.0)

    def lac_vectorised():
        lac.solve_segments(points, -1.0)

    def lac_vectorised_1_thread():
        lac.solve_segments(points, -1.0, threads=1)

    def lac_vectorised_big():
        lac.solve_segments(big, -1.0)

    # Every configuration solves, with lac as with Clothoids.
    check = lac.solve_segments(points, -1.0)
    assert bool(check.ok.all()), "a drawable configuration failed"

    runs = {
        "clothoids_loop": (clothoids_loop, n),
        "lac_loop": (lac_loop, n),
        "lac_vectorised": (lac_vectorised, n),
        "lac_vectorised_1_thread": (lac_vectorised_1_thread, n),
        "lac_vectorised_100x": (lac_vectorised_big, n * REPEAT),
    }
    rounds = []
    for _ in range(ROUNDS):
        rounds.append({k: per_curve_us(fn, count) for k, (fn, count) in runs.items()})
    out = {}
    for clock, i in (("wall", 0), ("cpu", 1)):
        out[f"median_us_per_curve_{clock}"] = {
            k: round(statistics.median(r[k][i] for r in rounds), 3) for k in runs}
        out[f"clothoids_over_lac_{clock}"] = {
            k: round(statistics.median(r["clothoids_loop"][i] / r[k][i] for r in rounds), 2)
            for k in runs if k != "clothoids_loop"}
    print(json.dumps({
        "benchmark": "alpha = -1 segments from three control points, per curve, from Python",
        "configurations": n,
        "rounds": ROUNDS,
        **out,
        "cores": os.cpu_count(),
        "load_average": os.getloadavg()[0],
        "versions": {"Clothoids": version("Clothoids"), "lac": version("lac"),
                     "numpy": np.__version__, "python": platform.python_version()},
    }))


if __name__ == "__main__":
    sys.exit(main())
