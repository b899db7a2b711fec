"""lac against the Clothoids library (Bertolazzi & Frego, PyPI `Clothoids`) on the same
drawable alpha = -1 configurations, side by side in one run, repeated.

    make python                                   # the venv with Clothoids
    .venv/bin/python tools/bench_vs_clothoids.py [--count 20000] [--repeats 5]

Builds `lac` and the timing example (cargo, release profile), draws `count` configurations
of three control points (random turning, leg ratio, scale, rotation and offset, as in
tools/reference/clothoid_cases.py) whose G1 Hermite clothoid has no inflection and which
lac solves, writes them as a `lac segment --batch` input, and times in each repeat:

* solver: `Segment::from_control_points` alone, in Rust (crates/lac/examples/time_segments.rs
  reads the same file; per configuration the median of 3 rounds, then the median over the
  configurations);
* build_G1: `ClothoidCurve.build_G1(x0, y0, th0, x1, y1, th1, 1e-12)` per configuration in
  a loop of REPS calls, its median over the configurations, minus the binding's call
  overhead: a call of `ClothoidCurve.build(x0, y0, th0, k, dk, L)` (6 numbers, trivial
  work) plus one more argument's conversion (the 6-argument call minus `length()`, over 6);
* batch: `lac segment --batch FILE --samples 2 -o /dev/null` over the file repeated
  BATCH_COPIES times (JSON in and out, every core), wall time per curve, process start
  included;
* python_loop: one `build_G1` per configuration in a plain Python loop, per curve.

Wall times on a shared machine depend on its load (every runnable thread gets a share of
the cores), so the batch and the loop are also given in CPU time (the batch's summed over its
threads).

Prints one JSON object: the medians over the repeats, the ratios the issue asks about
(solver / build_G1 ≤ 1, batch / python_loop ≤ 1), every repeat's figures and the load
average before and after (the machine is shared).
"""

import argparse
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import Clothoids

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools" / "reference"))
from clothoid_cases import configurations, end_curvatures  # noqa: E402

TOL = 1e-12
REPS = 10
BATCH_COPIES = 5


def target_dir():
    return Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))


def build():
    for args in (["-p", "lac-cli", "--bin", "lac"], ["-p", "lac", "--example", "time_segments"]):
        subprocess.run(["cargo", "build", "--release", "--quiet", *args], cwd=ROOT, check=True)
    release = target_dir() / "release"
    return release / "lac", release / "examples" / "time_segments"


def hermite(pa, pb, pc):
    th0 = math.atan2(pb[1] - pa[1], pb[0] - pa[0])
    th1 = math.atan2(pc[1] - pb[1], pc[0] - pb[0])
    return (pa[0], pa[1], th0, pc[0], pc[1], th1)


def drawable_set(count, lac, workdir):
    """`count` configurations without inflection that lac solves, as (points, hermite)."""
    curve = Clothoids.ClothoidCurve()
    candidates = []
    for pa, pb, pc in configurations(count=int(count * 1.6) + 100, seed=2026):
        data = hermite(pa, pb, pc)
        curve.build_G1(*data, TOL)
        k0, k1 = end_curvatures(curve)
        if k0 * k1 > 0:
            candidates.append(((pa, pb, pc), data))
    lines = [json.dumps({"points": [list(p) for p in pts], "alpha": -1.0}) for pts, _ in candidates]
    probe = workdir / "probe.jsonl"
    probe.write_text("\n".join(lines) + "\n")
    out = subprocess.run([str(lac), "segment", "--batch", str(probe), "--samples", "2"],
                         capture_output=True, text=True).stdout.splitlines()
    kept = [(c, line) for c, line, answer in zip(candidates, lines, out) if '"error"' not in answer]
    if len(kept) < count:
        raise SystemExit(f"only {len(kept)} drawable configurations")
    return kept[:count]


def per_call_us(fn, args, reps=REPS):
    start = time.perf_counter_ns()
    for _ in range(reps):
        fn(*args)
    return (time.perf_counter_ns() - start) / reps / 1000


def time_clothoids(data):
    curve = Clothoids.ClothoidCurve()
    g1 = lambda *a: curve.build_G1(*a, TOL)  # noqa: E731
    raw = statistics.median(per_call_us(g1, d) for d in data)
    # The binding's overhead: a trivial 6-number call, a 0-number one, and so one number's
    # conversion; build_G1 passes 7.
    build_args = (0.0, 0.0, 0.1, 0.5, 0.1, 1.0)
    six = statistics.median(per_call_us(curve.build, build_args, 1000) for _ in range(50))
    zero = statistics.median(per_call_us(curve.length, (), 1000) for _ in range(50))
    overhead = six + max(six - zero, 0.0) / 6
    # The plain Python loop, one call per configuration.
    start, cpu = time.perf_counter_ns(), time.process_time_ns()
    for d in data:
        curve.build_G1(*d, TOL)
    loop = (time.perf_counter_ns() - start) / len(data) / 1000
    loop_cpu = (time.process_time_ns() - cpu) / len(data) / 1000
    return {"build_G1_raw_us": raw, "overhead_us": overhead, "build_G1_us": raw - overhead,
            "python_loop_us": loop, "python_loop_cpu_us": loop_cpu}


def time_batch(lac, big, lines):
    """Wall time and CPU time (all threads) per curve."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter_ns()
    subprocess.run([str(lac), "segment", "--batch", str(big), "--samples", "2", "-o", os.devnull],
                   check=True)
    wall = (time.perf_counter_ns() - start) / lines / 1000
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime) / lines * 1e6
    return wall, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=20000)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    lac, timer = build()
    load_before = os.getloadavg()
    with tempfile.TemporaryDirectory() as tmp:
        workdir = Path(tmp)
        kept = drawable_set(args.count, lac, workdir)
        inputs = workdir / "inputs.jsonl"
        inputs.write_text("\n".join(line for _, line in kept) + "\n")
        big = workdir / "batch.jsonl"
        big.write_text(inputs.read_text() * BATCH_COPIES)
        data = [h for (_, h), _ in kept]
        runs = []
        for _ in range(args.repeats):
            solver = json.loads(subprocess.run([str(timer), str(inputs), "3"], check=True,
                                               capture_output=True, text=True).stdout)
            batch, batch_cpu = time_batch(lac, big, len(kept) * BATCH_COPIES)
            run = {"solver_us": solver["median_us"], **time_clothoids(data),
                   "batch_us": batch, "batch_cpu_us": batch_cpu, "load": os.getloadavg()[0]}
            runs.append(run)
            print(json.dumps({k: round(v, 4) for k, v in run.items()}), file=sys.stderr)
    median = {k: round(statistics.median(r[k] for r in runs), 4) for k in runs[0]}
    ratios = {
        "solver_over_build_G1": [round(r["solver_us"] / r["build_G1_us"], 3) for r in runs],
        "batch_over_python_loop": [round(r["batch_us"] / r["python_loop_us"], 3) for r in runs],
        # CPU time (all of lac's threads) against the loop's: what a loaded machine cannot
        # blur; with every core free the batch's wall time is this divided by the cores.
        "batch_cpu_over_python_loop_cpu": [
            round(r["batch_cpu_us"] / r["python_loop_cpu_us"], 3) for r in runs],
    }
    print(json.dumps({
        "configurations": len(kept),
        "repeats": args.repeats,
        "median": median,
        "ratios_per_repeat": ratios,
        "median_ratios": {k: statistics.median(v) for k, v in ratios.items()},
        "load_average_before": [round(x, 2) for x in load_before],
        "load_average_after": [round(x, 2) for x in os.getloadavg()],
        "cpus": os.cpu_count(),
        "runs": [{k: round(v, 4) for k, v in r.items()} for r in runs],
    }, indent=1))


if __name__ == "__main__":
    sys.exit(main())
