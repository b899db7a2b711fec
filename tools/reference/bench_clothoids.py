"""Time Clothoids' G1 Hermite fit on the drawable alpha = -1 configurations of the test.

    .venv/bin/python tools/reference/bench_clothoids.py      (by hand, for the report)

Prints one line of JSON.  Each configuration is fitted `repetitions` times in a loop; the
per-fit time of a configuration is the loop time divided by the repetitions, and the
median over configurations is reported.  The times are measured from Python, so they
include the Python-to-C++ call overhead; `call_overhead_us` is the time of a trivial
call through the same binding (ClothoidCurve.length()) for scale.
"""

import json
import math
import platform
import statistics
import sys
import time
from importlib.metadata import version

import Clothoids
import pyclothoids

from clothoid_cases import configurations, end_curvatures, g1_clothoid

REPETITIONS = 200
TOL = 1e-12  # Newton tolerance passed to both


def hermite_data(pa, pb, pc):
    th0 = math.atan2(pb[1] - pa[1], pb[0] - pa[0])
    th1 = math.atan2(pc[1] - pb[1], pc[0] - pb[0])
    return (pa[0], pa[1], th0, pc[0], pc[1], th1)


def inflection_free(curve):
    k0, k1 = end_curvatures(curve)
    return k0 * k1 > 0


def per_call_us(fn, args):
    start = time.perf_counter_ns()
    for _ in range(REPETITIONS):
        fn(*args)
    return (time.perf_counter_ns() - start) / REPETITIONS / 1000


def main():
    drawable = [c for c in configurations() if inflection_free(g1_clothoid(*c))]
    data = [hermite_data(*c) for c in drawable]
    curve = Clothoids.ClothoidCurve()
    build = lambda *a: curve.build_G1(*a, TOL)  # reuses one C++ object (SWIG binding)
    g1 = lambda *a: pyclothoids.Clothoid.G1Hermite(*a, tol=TOL)  # new object per fit
    swig = [per_call_us(build, d) for d in data]
    pyc = [per_call_us(g1, d) for d in data]
    overhead = statistics.median(per_call_us(curve.length, ()) for _ in range(50))
    print(json.dumps({
        "benchmark": "G1 Hermite clothoid fit, drawable alpha = -1 configurations",
        "configurations": len(data),
        "repetitions": REPETITIONS,
        "clothoids_build_G1_median_us": round(statistics.median(swig), 3),
        "pyclothoids_G1Hermite_median_us": round(statistics.median(pyc), 3),
        "tolerance": TOL,
        "includes_python_call_overhead": True,
        "call_overhead_us": round(overhead, 3),
        "versions": {"Clothoids": version("Clothoids"), "pyclothoids": version("pyclothoids"),
                     "python": platform.python_version()},
        "machine": platform.processor() or platform.machine(),
    }))


if __name__ == "__main__":
    sys.exit(main())
