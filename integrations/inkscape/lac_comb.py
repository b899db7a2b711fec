#!/usr/bin/env python3
"""Inkscape extension: draw the curvature comb of each selected path as a group beside it
(just above it, with its transform): a tooth at every sample, of length scale × |κ| away
from the centre of curvature, and the line through the teeth's tips. The curvature is
lac's (`lac.curvature_plot` of the path's cubic Bézier pieces, exact dκ/ds).

    PYTHONPATH=/usr/share/inkscape/extensions python3 lac_comb.py --id=ID in.svg > out.svg
"""

from __future__ import annotations

import math

import inkex

import lac_inkscape as li

def tangent(c: li.Cubic, t: float) -> li.Point:
    """The unit tangent of a piece at t."""
    u = 1 - t
    w = (3 * u * u, 6 * u * t, 3 * t * t)
    dx = sum(wi * (c[i + 1][0] - c[i][0]) for i, wi in enumerate(w))
    dy = sum(wi * (c[i + 1][1] - c[i][1]) for i, wi in enumerate(w))
    n = math.hypot(dx, dy)
    return (dx / n, dy / n)


class LacComb(inkex.EffectExtension):
    def add_arguments(self, pars: inkex.utils.argparse.ArgumentParser) -> None:
        pars.add_argument("--per_piece", type=int, default=16, help="Teeth per Bézier piece")
        pars.add_argument(
            "--scale", type=float, default=0.0,
            help="Tooth length per unit curvature (0: the longest tooth a fifth of the path's length)",
        )
        pars.add_argument("--color", default="#f57900", help="Colour of the comb")

    def effect(self) -> None:
        for element in li.selected_paths(self):
            width = li.local_tolerance(self, element, self.svg.to_dimensional(0.5, self.svg.document_unit))
            group = inkex.Group(id=self.svg.get_unique_id(f"lac-comb-{element.get_id()}"))
            group.set("transform", str(element.transform))
            group.style = {"fill": "none", "stroke": self.options.color, "stroke-width": width}
            with li.lac_errors(element):
                for pieces in li.cubics(element):
                    group.add(self.comb(pieces))
            element.addnext(group)

    def comb(self, pieces: list[li.Cubic]) -> inkex.PathElement:
        """The teeth and the tips' line of one subpath, as one path."""
        per = max(self.options.per_piece, 2)
        plot = li.lac.curvature_plot([li.lac.RationalCubic(c) for c in pieces], per)
        ts = [(k, i / (per - 1)) for k in range(len(pieces)) for i in range(per) if k == 0 or i > 0]
        kmax = max(abs(plot.kappa))
        scale = self.options.scale or (0.2 * plot.s[-1] / kmax if kmax > 0 else 0.0)
        tips = []
        d = []
        for (k, t), (x, y), kappa in zip(ts, plot.points, plot.kappa):
            tx, ty = tangent(pieces[k], t)
            # Left normal (-ty, tx); the centre of curvature is on it for kappa > 0.
            tip = (x + scale * kappa * ty, y - scale * kappa * tx)
            tips.append(tip)
            d.append(f"M {x:.9g},{y:.9g} L {tip[0]:.9g},{tip[1]:.9g}")
        d.append("M " + " L ".join(f"{x:.9g},{y:.9g}" for x, y in tips))
        return inkex.PathElement(d=" ".join(d))


if __name__ == "__main__":
    LacComb().run()
