"""Seed 000 Fig. 5: the overall shape of log-aesthetic curves in standard form I.

Standard form I is the curve with rho = 1 and theta = 0 at s = 0 and Lambda = 1; its
shape depends on alpha alone. For each alpha the curve is drawn over its range of tangent
angles, cut at +-4 pi where it spirals forever and at a distance of 12 from the point
s = 0 (marked) where it runs off to infinity.

    python crates/lac-py/examples/fig5_family.py [OUTPUT_DIR]      writes fig5_family.png
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import numpy.typing as npt  # noqa: E402

import lac  # noqa: E402

ALPHAS = [-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 5.0]
NAMES = {-1.0: "clothoid", 0.0: "Nielsen spiral", 1.0: "logarithmic spiral",
         2.0: "circle involute"}
LIMIT = 4 * math.pi
REACH = 12.0
SAMPLES = 4000


def curve_points(alpha: float) -> npt.NDArray[np.float64]:
    """Points of standard form I over its tangent-angle range, cut at +-LIMIT and at
    distance REACH from the origin (the curve is connected: the points kept are those of
    the piece through s = 0)."""
    form = lac.StandardForm(alpha, 1.0)
    lo, hi = form.theta_bounds
    lo, hi = max(lo, -LIMIT), min(hi, LIMIT)
    # Stay a hair inside a finite bound: the end point there is a limit (rho = 0 or inf).
    margin = 1e-9 * (hi - lo)
    points = []
    for theta in np.linspace(lo + margin, hi - margin, SAMPLES):
        try:
            p = form.point_at_theta(float(theta))
        except lac.LacError:
            continue  # beyond double range near a limit point
        if math.hypot(p[0], p[1]) <= REACH:
            points.append(p)
        elif theta > 0:
            break  # ran off past REACH: the rest is farther still
    return np.array(points)


def main(out: Path) -> Path:
    fig, axes = plt.subplots(3, 3, figsize=(10, 10))
    for ax, alpha in zip(axes.flat, ALPHAS):
        p = curve_points(alpha)
        ax.plot(p[:, 0], p[:, 1], color="tab:blue", lw=1.2)
        ax.plot([0.0], [0.0], "o", color="tab:red", ms=4)
        name = NAMES.get(alpha, "")
        ax.set_title(f"alpha = {alpha:g}" + (f" ({name})" if name else ""), fontsize=10)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, lw=0.3)
    fig.suptitle("Log-aesthetic curves in standard form I (seed 000 Fig. 5); red: s = 0")
    fig.tight_layout()
    path = out / "fig5_family.png"
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main(Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
