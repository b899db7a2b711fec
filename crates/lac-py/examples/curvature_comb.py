"""A log-aesthetic segment with its curvature comb, evolute and curvature plot.

The comb draws, at each sample, a tooth along the normal of length proportional to the
curvature (pointing away from the centre of curvature); the evolute is the locus of the
centres of curvature. Beside it: the curvature plot and the logarithmic curvature graph,
whose fitted slope is the segment's alpha.

    python crates/lac-py/examples/curvature_comb.py [OUTPUT_DIR]    writes curvature_comb.png
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import lac  # noqa: E402

POINTS = [(0.0, 0.0), (3.0, 0.0), (4.2, 1.9)]
ALPHA = 0.5


def main(out: Path) -> Path:
    seg = lac.Segment(POINTS, ALPHA)
    fine = seg.sample(400)
    teeth = seg.sample(60)
    # Left normals (-sin, cos); kappa < 0 for a right turn, so -kappa * N points outward
    # for either turn when scaled by the turn's sign.
    normal = np.stack([-np.sin(teeth.theta), np.cos(teeth.theta)], axis=1)
    scale = 0.6 / float(np.max(np.abs(teeth.kappa)))
    tips = teeth.points - normal * (teeth.kappa * scale)[:, None]
    evolute = seg.evolute(200)
    plot = seg.curvature_plot(200)
    graph = plot.log_curvature_graph()

    fig, (ax, ax_k, ax_g) = plt.subplots(1, 3, figsize=(14, 4.5),
                                         gridspec_kw={"width_ratios": [1.6, 1, 1]})
    for p, q in zip(teeth.points, tips):
        ax.plot([p[0], q[0]], [p[1], q[1]], color="tab:orange", lw=0.8)
    ax.plot(tips[:, 0], tips[:, 1], color="tab:orange", lw=0.8)
    ax.plot(fine.points[:, 0], fine.points[:, 1], color="tab:blue", lw=2, label="segment")
    ax.plot(evolute[:, 0], evolute[:, 1], color="tab:green", lw=1, ls="--", label="evolute")
    cp = seg.control_points
    ax.plot(cp[:, 0], cp[:, 1], "o-", color="grey", lw=0.6, ms=4, label="control points")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(f"alpha = {ALPHA}, arc length {seg.arc_length:.4f}", fontsize=10)

    ax_k.plot(plot.s, plot.kappa, color="tab:blue")
    ax_k.set_xlabel("s")
    ax_k.set_ylabel("signed curvature")
    ax_k.set_title("curvature plot", fontsize=10)

    ax_g.plot(graph.points[:, 0], graph.points[:, 1], ".", ms=3, color="tab:blue")
    fit = graph.fit
    if fit is not None:
        x = np.array(fit.log_rho)
        ax_g.plot(x, fit.alpha * x + fit.intercept, color="tab:red", lw=0.8,
                  label=f"fit: alpha = {fit.alpha:.6f}")
        ax_g.legend(fontsize=8)
    ax_g.set_xlabel("log rho")
    ax_g.set_ylabel("log(rho ds/drho)")
    ax_g.set_title("logarithmic curvature graph", fontsize=10)
    fig.tight_layout()
    path = out / "curvature_comb.png"
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main(Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
