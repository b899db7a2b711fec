"""Drawable regions (seed 000 Fig. 9): where may the middle control point lie?

With the first control point at (-1, 0) and the last at (1, 0), each map shows the middle
points for which a segment of slope alpha exists (computed on all cores by
`lac.drawable_region`), and one compound curve's map (`lac.drawable_region_compound`).

    python crates/lac-py/examples/drawable_region.py [OUTPUT_DIR]   writes drawable_region.png
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import lac  # noqa: E402

ALPHAS = [-1.0, 0.0, 0.5, 1.0, 2.0]
SIZE = 160


def main(out: Path) -> Path:
    maps = [(f"alpha = {a:g}", lac.drawable_region(a, SIZE)) for a in ALPHAS]
    maps.append(("compound -1 | 2, ratio 0.5",
                 lac.drawable_region_compound(-1.0, 2.0, 0.5, SIZE)))
    fig, axes = plt.subplots(2, 3, figsize=(10, 7))
    for ax, (title, m) in zip(axes.flat, maps):
        ax.imshow(np.where(m, 1.0, 0.0), extent=(-1, 1, -1, 1), cmap="Blues", vmin=0,
                  vmax=1.3, origin="upper", interpolation="nearest")
        ax.plot([-1, 1], [0, 0], "o", color="tab:red", ms=4)
        share = float(m.mean())
        ax.set_title(f"{title}: {100 * share:.0f}% drawable", fontsize=10)
        ax.set_aspect("equal")
    fig.suptitle("Drawable regions of the middle control point (ends in red)")
    fig.tight_layout()
    path = out / "drawable_region.png"
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main(Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
