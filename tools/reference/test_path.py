"""`lac path --g2` checked independently: every reported segment is solved again from its
control triangle and alpha by the 30-digit mpmath reference (segment_mpmath.py, SPEC §3),
and at every joint the reference's curvatures on the two sides must agree to 1e-9
(relative), as must the command's own report.

    .venv/bin/python -m pytest tools/reference/test_path.py -q      (from the repo root)
"""

import json
import subprocess

from mpmath import mp, mpc, mpf

from lac_cli import lac_bin, require
from segment_mpmath import solve_segment

# Open and closed polygons with a G2 path for these slopes (turning one way).
CASES = [
    ("0,0 2,0 3.5,1 4,3 3,4.5 1,5", False, [-0.5, 0.0, 0.5, 1.0, 2.0]),
    ("0,0 3,-0.5 4.5,2 2,4 -0.5,2.5", True, [-1.0, 0.0, 1.0]),
    ("0,0 1,0 2,0.3 2.8,1 3.2,2 3.1,3", False, [0.0, 0.5]),
]
JUMP = mpf("1e-9")


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
