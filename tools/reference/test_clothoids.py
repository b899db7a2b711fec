"""alpha = -1 is the clothoid: our segments must agree with Bertolazzi's Clothoids library.

    .venv/bin/python -m pytest tools/reference/test_clothoids.py -q      (from the repo root)

The command line is `lac` from $LAC_BIN (default target/release/lac); its test is skipped,
with a message, only when that binary does not exist.
"""

import json
import math
import os
import subprocess
import tempfile

import pytest
import pyclothoids

from clothoid_cases import configurations, end_curvatures, g1_clothoid

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FIXTURES = os.path.join(ROOT, "crates", "lac", "tests", "fixtures", "segments.json")
TOL = 1e-10
MIN_COMPARED = 200


def lac_bin():
    return os.path.join(ROOT, os.environ.get("LAC_BIN", os.path.join("target", "release", "lac")))


def inflection_free(k0, k1):
    return k0 * k1 > 0


def compare(label, ours, curve):
    """Length relative to the length; curvatures relative to max(|k0|, |k1|)."""
    length = curve.length()
    k0, k1 = end_curvatures(curve)
    kmax = max(abs(k0), abs(k1))
    assert abs(ours["arc_length"] - length) <= TOL * length, (label, ours["arc_length"], length)
    assert abs(ours["curvature_start"] - k0) <= TOL * kmax, (label, ours["curvature_start"], k0)
    assert abs(ours["curvature_end"] - k1) <= TOL * kmax, (label, ours["curvature_end"], k1)
    for s in ours.get("samples", []):
        x, y = curve.eval(s["s"])
        assert math.hypot(s["x"] - x, s["y"] - y) <= TOL * length, (label, s)
        assert abs(s["kappa"] - curve.kappa(s["s"])) <= TOL * kmax, (label, s)


def test_clothoids_g1_interpolates_the_hermite_data():
    """Clothoids' build_G1 (and pyclothoids' G1Hermite, the same C++ code) reproduce the end
    points and end tangents of every configuration, so they are fit to judge ours."""
    for pa, pb, pc in configurations():
        curve = g1_clothoid(pa, pb, pc)
        length = curve.length()
        x1, y1 = curve.eval(length)
        assert math.hypot(x1 - pc[0], y1 - pc[1]) <= 1e-12 * length
        x0, y0 = curve.eval(0.0)
        assert math.hypot(x0 - pa[0], y0 - pa[1]) <= 1e-12 * length
        th1 = math.atan2(pc[1] - pb[1], pc[0] - pb[0])
        assert abs(math.remainder(curve.theta(length) - th1, 2 * math.pi)) <= 1e-12
        other = pyclothoids.Clothoid.G1Hermite(
            pa[0], pa[1], curve.theta(0.0), pc[0], pc[1], curve.theta(length), 1e-14)
        assert abs(other.length - length) <= 1e-12 * length


def test_reference_fixtures_agree_with_clothoids():
    """The 40-digit Python reference (segments.json) agrees with Clothoids at alpha = -1."""
    with open(FIXTURES) as f:
        cases = [c for c in json.load(f)["cases"] if c["alpha"] == -1.0]
    drawable = [c for c in cases if c["drawable"]]
    assert len(drawable) >= 10
    for c in cases:
        curve = g1_clothoid(*c["points"])
        if c["drawable"]:
            compare(c["kind"], c, curve)
        elif "collinear" not in c["reason"] and "coincident" not in c["reason"]:
            assert not inflection_free(*end_curvatures(curve)), c


def run_cli(configs):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "in.jsonl")
        with open(path, "w") as f:
            for pts in configs:
                f.write(json.dumps({"points": [list(p) for p in pts], "alpha": -1}) + "\n")
        run = subprocess.run([lac_bin(), "segment", "--batch", path, "--samples", "2"],
                             capture_output=True, text=True, timeout=600)
    lines = run.stdout.splitlines()
    assert len(lines) == len(configs), (len(lines), len(configs), run.stderr)
    out = [json.loads(line) for line in lines]
    # A batch exits 0 when every line was solved, else with the first failed line's code
    # (2 invalid, 3 not drawable) and a one-line JSON summary on standard error.
    failed = [o for o in out if "error" in o]
    if failed:
        assert run.returncode in (2, 3), (run.returncode, run.stderr)
        assert json.loads(run.stderr)["error"]["kind"] == failed[0]["error"]["kind"], run.stderr
    else:
        assert run.returncode == 0, run.stderr
    return out


def test_cli_agrees_with_clothoids():
    """Every segment `lac segment --batch` draws at alpha = -1 is Clothoids' G1 clothoid to
    1e-10; every one it refuses needs an inflection (end curvatures of opposite signs)."""
    if not os.path.exists(lac_bin()):
        pytest.skip(f"no lac binary at {lac_bin()}: build it with "
                    "`cargo build --release -p lac-cli` or set LAC_BIN")
    configs = configurations()
    compared, refused = 0, 0
    for i, (pts, out) in enumerate(zip(configs, run_cli(configs))):
        curve = g1_clothoid(*pts)
        k0, k1 = end_curvatures(curve)
        if "error" in out:
            refused += 1
            # not drawable: Clothoids needs an inflection (a zero end curvature allowed)
            assert k0 * k1 <= 1e-9 * max(k0 * k0, k1 * k1), (i, pts, out, k0, k1)
        else:
            compare(i, out, curve)
            compared += 1
    print(f"compared {compared}, refused (inflection needed) {refused}")
    assert compared >= MIN_COMPARED
    assert compared + refused == len(configs)
