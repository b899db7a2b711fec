#!/usr/bin/env python3
"""Inkscape extension: fair each selected path, replacing it by the log-aesthetic path that
`lac fit` fits to points along it (the fewest G2 log-aesthetic segments within a tolerance
in document units; closed subpaths closed), written as cubic Béziers.

    PYTHONPATH=/usr/share/inkscape/extensions python3 lac_fair.py --tolerance=0.5 --id=ID in.svg > out.svg
"""

from __future__ import annotations

import inkex
import numpy as np

import lac_inkscape as li

#: The Béziers follow the fitted path within this share of the fit's tolerance.
EXPORT_SHARE = 0.01


def points_along(pieces: list[li.Cubic], count: int) -> np.ndarray:
    """`count` points equally spaced in arc length along the pieces (measured by lac's
    curvature plot, 32 points a piece)."""
    rational = [li.lac.RationalCubic(c) for c in pieces]
    plot = li.lac.curvature_plot(rational, 32)
    s = np.linspace(0.0, plot.s[-1], count)
    return np.column_stack([np.interp(s, plot.s, plot.points[:, i]) for i in (0, 1)])


class LacFair(inkex.EffectExtension):
    def add_arguments(self, pars: inkex.utils.argparse.ArgumentParser) -> None:
        pars.add_argument(
            "--tolerance",
            type=float,
            default=0.5,
            help="Largest distance from the path to the faired path, in document units",
        )
        pars.add_argument(
            "--max_segments", type=int, default=0, help="At most this many (0: lac's default)"
        )
        pars.add_argument(
            "--samples", type=int, default=200, help="Points taken along each subpath"
        )
        pars.add_argument("--keep", type=inkex.Boolean, default=False, help="Keep the original")

    def effect(self) -> None:
        for element in li.selected_paths(self):
            tolerance = li.local_tolerance(self, element, self.options.tolerance)
            closed = [sub.closed for sub in li.subpaths(element)]
            with li.lac_errors(element):
                d = " ".join(
                    self.fair(pieces, is_closed, tolerance)
                    for pieces, is_closed in zip(li.cubics(element), closed)
                )
            li.replace(element, d, self.options.keep)

    def fair(self, pieces: list[li.Cubic], closed: bool, tolerance: float) -> str:
        points = points_along(pieces, max(self.options.samples, 3) + closed)
        if closed:
            points = points[:-1]  # the first point again
        fit = li.lac.fit(
            points,
            tolerance=tolerance,
            max_segments=self.options.max_segments or None,
            closed=closed,
        )
        return li.path_data(fit, EXPORT_SHARE * tolerance)


if __name__ == "__main__":
    LacFair().run()
