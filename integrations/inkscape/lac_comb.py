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
        pars.add_argument("--teeth", type=int, default=120, help="Teeth along each subpath")
        pars.add_argument(
            "--scale",
            type=float,
            default=0.0,
            help="Tooth length per unit curvature (0: the longest tooth a fifth of the path's length)",
        )
        pars.add_argument("--color", default="#f57900", help="Colour of the comb")

    def effect(self) -> None:
        for element in li.selected_paths(self):
            width = li.local_tolerance(
                self, element, self.svg.to_dimensional(0.5, self.svg.document_unit)
            )
            group = inkex.Group(id=self.svg.get_unique_id(f"lac-comb-{element.get_id()}"))
            group.set("transform", str(element.transform))
            group.style = {"fill": "none", "stroke": self.options.color, "stroke-width": width}
            with li.lac_errors(element):
                for pieces in li.cubics(element):
                    group.add(self.comb(pieces))
            element.addnext(group)

    def comb(self, pieces: list[li.Cubic]) -> inkex.PathElement:
        """The teeth and the tips' line of one subpath, as one path: each piece gets teeth
        in proportion to its length (two at least, its ends), equally spaced in its
        parameter."""
        rational = [li.lac.RationalCubic(c) for c in pieces]
        lengths = [r.arc_length for r in rational]
        total = sum(lengths)
        per_piece = [max(2, round(self.options.teeth * n / total) + 1) for n in lengths]
        feet, kappas, ts = [], [], []
        for k, (piece, count) in enumerate(zip(rational, per_piece)):
            plot = li.lac.curvature_plot([piece], count)
            first = 0 if k == 0 else 1  # a joint once
            feet += [tuple(p) for p in plot.points[first:]]
            kappas += list(plot.kappa[first:])
            ts += [(k, i / (count - 1)) for i in range(first, count)]
        kmax = max(abs(k) for k in kappas)
        scale = self.options.scale or (0.2 * total / kmax if kmax > 0 else 0.0)
        tips = []
        d = []
        for (k, t), (x, y), kappa in zip(ts, feet, kappas):
            tx, ty = tangent(pieces[k], t)
            # Left normal (-ty, tx); the centre of curvature is on it for kappa > 0.
            tip = (x + scale * kappa * ty, y - scale * kappa * tx)
            tips.append(tip)
            d.append(f"M {x:.9g},{y:.9g} L {tip[0]:.9g},{tip[1]:.9g}")
        d.append("M " + " L ".join(f"{x:.9g},{y:.9g}" for x, y in tips))
        return inkex.PathElement(d=" ".join(d))


if __name__ == "__main__":
    LacComb().run()
