#!/usr/bin/env python3
"""Inkscape extension: replace each selected path by the G2 log-aesthetic spline through its
nodes (`lac spline`; closed subpaths closed), written as cubic Béziers within a tolerance in
document units.

    PYTHONPATH=/usr/share/inkscape/extensions python3 lac_spline.py --alpha=-1 --id=ID in.svg > out.svg
"""

from __future__ import annotations

import inkex

import lac_inkscape as li


class LacSpline(inkex.EffectExtension):
    def add_arguments(self, pars: inkex.utils.argparse.ArgumentParser) -> None:
        pars.add_argument("--alpha", type=float, default=-1.0, help="Slope of every segment")
        pars.add_argument(
            "--tolerance",
            type=float,
            default=0.01,
            help="Largest distance from the Béziers to the spline, in document units",
        )
        pars.add_argument("--keep", type=inkex.Boolean, default=False, help="Keep the original")

    def effect(self) -> None:
        for element in li.selected_paths(self):
            tolerance = li.local_tolerance(self, element, self.options.tolerance)
            with li.lac_errors(element):
                d = " ".join(
                    li.path_data(
                        li.lac.Spline(sub.nodes, self.options.alpha, closed=sub.closed), tolerance
                    )
                    for sub in li.subpaths(element)
                )
            li.replace(element, d, self.options.keep)


if __name__ == "__main__":
    LacSpline().run()
