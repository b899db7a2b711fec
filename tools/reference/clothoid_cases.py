"""Random three-point configurations for the alpha = -1 (clothoid) cross-check, and the
G1 Hermite clothoid of Bertolazzi's Clothoids library (PyPI `Clothoids`) for each.

The clothoid for control points Pa, Pb, Pc starts at Pa with direction Pb - Pa and ends
at Pc with direction Pc - Pb.  As an LAC segment with alpha = -1 it exists exactly when
that clothoid has no inflection, i.e. the end curvatures have the same sign.
"""

import math
import random

import Clothoids

SEED = 20061
COUNT = 320


def configurations(count=COUNT, seed=SEED):
    """[(Pa, Pb, Pc)] as (x, y) tuples of doubles: turning angle in (0.05, 3.0), left and
    right turns, shorter-to-longer leg ratio in (0.45, 1) with either leg first, random
    scale (1e-3 .. 1e3), rotation and offset (up to 100 leg lengths)."""
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        theta_d = rng.uniform(0.05, 3.0) * rng.choice([1, -1])
        legs = [1.0, rng.uniform(0.45, 1.0)]
        rng.shuffle(legs)
        scale = 10 ** rng.uniform(-3, 3)
        phi = rng.uniform(-math.pi, math.pi)
        reach = 10 ** rng.uniform(-2, 2) * scale
        psi = rng.uniform(-math.pi, math.pi)
        pa = (reach * math.cos(psi), reach * math.sin(psi))
        pb = (pa[0] + scale * legs[0] * math.cos(phi), pa[1] + scale * legs[0] * math.sin(phi))
        pc = (pb[0] + scale * legs[1] * math.cos(phi + theta_d),
              pb[1] + scale * legs[1] * math.sin(phi + theta_d))
        out.append((pa, pb, pc))
    return out


def g1_clothoid(pa, pb, pc, tol=1e-14):
    """Clothoids.ClothoidCurve fitted by build_G1 (G1 Hermite) to the configuration."""
    th0 = math.atan2(pb[1] - pa[1], pb[0] - pa[0])
    th1 = math.atan2(pc[1] - pb[1], pc[0] - pb[0])
    curve = Clothoids.ClothoidCurve()
    curve.build_G1(pa[0], pa[1], th0, pc[0], pc[1], th1, tol)
    return curve


def end_curvatures(curve):
    return curve.kappa(0.0), curve.kappa(curve.length())
