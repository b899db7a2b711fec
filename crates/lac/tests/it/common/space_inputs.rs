//! Inputs of `SpaceSegment::from_control_points` built from known log-aesthetic space curves
//! (so that a segment exists), shared by the constructed-input test and the space benchmark.
//!
//! A case takes a standard form with α, β ∈ {−1, −0.5, 0, 0.5, 1, 2} (cycled, with both
//! torsion types, so every pair and type is equally represented), Λ uniform in [0.05, 0.6],
//! Ω in [0, 0.4] (every fourth case Ω = 0), ν in [0.8, 4]; an end `s_end` where the chord
//! makes angles of at most 1.4 rad with both end tangents and the tangent and binormal turn by
//! at most 2π (seed 003's guard); and the four control points of that piece (legs 0.3–0.8 of
//! the chord), in random order (either end first), mirrored with chance 0.3, under a random
//! rotation, a scale 0.1–10 (log-uniform) and a shift. One case in four is put near the
//! cone's edge: `s_end` where |θ2| is within 0.05 rad of π/2, where the end's crossing of the
//! cone about the start tangent changes from outward (first) to inward (second).
//! [`generate_with`] takes other cells and ranges of the end ([`Recipe`]).

#![allow(dead_code)] // the benchmark uses the generator only

use lac::{SpaceForm, SpaceFormParams, SpaceShape, TorsionType, Vec3};

/// The slopes of the curvature and torsion graphs the cases cycle through.
pub(crate) const SLOPES: [f64; 6] = [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0];

/// SplitMix64.
pub(crate) struct Rng(pub u64);

impl Rng {
    /// A uniform number in [0, 1).
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// One constructed input and the curve it was built from.
#[derive(Clone, Debug)]
pub(crate) struct Case {
    /// The control points handed to the solver.
    pub(crate) points: [Vec3; 4],
    /// α, β, Ω and type handed to the solver.
    pub(crate) shape: SpaceShape,
    /// The standard form the points were taken from (its Λ and ν are one solution).
    pub(crate) form: SpaceForm,
    /// The end of the piece on that form.
    pub(crate) s_end: f64,
    /// Built near the cone's edge (|θ2| close to π/2).
    pub(crate) edge: bool,
    /// Which crossing of the cone about the start tangent the end is (1 = the first).
    pub(crate) crossing: u32,
    /// The chord makes the larger angle with the tangent at the form's end (θ0 < θ1 on the
    /// piece), where a planar spiral has it at its start.
    pub(crate) larger_angle_at_end: bool,
}

/// `(θ0, θ1, θ2)` of the standard-form piece from 0 to `s`: the angles of the chord with the
/// two end tangents and the dihedral about it (docs/math.md §6), written out here.
pub(crate) fn angles(form: &SpaceForm, s: f64) -> Option<(f64, f64, f64)> {
    let f = form.frame_at_s(s).ok()?;
    let c = f.point.normalize();
    let u0 = Vec3::X - c * c.x;
    let m = -f.tangent;
    let u1 = m - c * m.dot(c);
    let theta2 = c.dot(u0.cross(u1)).atan2(u0.dot(u1));
    Some((Vec3::X.angle_to(c), f.tangent.angle_to(c), theta2))
}

/// The number of times the piece from 0 to `s_end` crosses the cone of half-angle θ0 about
/// its start tangent, counting the end (sampled finely).
fn crossing_number(form: &SpaceForm, s_end: f64, theta0: f64) -> u32 {
    let n = 400;
    let s: Vec<f64> = (1..n).map(|i| s_end * i as f64 / n as f64).collect();
    let frames = form.frames(&s).unwrap();
    let mut outside = false;
    let mut count = 0;
    for f in frames {
        let g = f.point.length() * theta0.cos() - f.point.x;
        if (g > 0.0) != outside {
            outside = !outside;
            count += 1;
        }
    }
    count + 1
}

/// A random proper rotation (a uniform unit quaternion) applied to `v`.
fn rotation(rng: &mut Rng) -> impl Fn(Vec3) -> Vec3 {
    let (u1, u2, u3) = (rng.next(), rng.next(), rng.next());
    let tau = std::f64::consts::TAU;
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    let q = [
        a * (tau * u2).sin(),
        a * (tau * u2).cos(),
        b * (tau * u3).sin(),
        b * (tau * u3).cos(),
    ];
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    let m = [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - z * w),
            2.0 * (x * z + y * w),
        ],
        [
            2.0 * (x * y + z * w),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - x * w),
        ],
        [
            2.0 * (x * z - y * w),
            2.0 * (y * z + x * w),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ];
    move |v: Vec3| {
        Vec3::new(
            m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
        )
    }
}

/// Whether the piece from 0 to `s` is acceptable: inside the valid range, chord angles in
/// (0.02, 1.4], not coplanar, turning within seed 003's 2π guard.
fn acceptable(form: &SpaceForm, s: f64) -> Option<(f64, f64, f64)> {
    if !(s > 0.0 && s < 0.98 * form.s_range().1) {
        return None;
    }
    let tau = std::f64::consts::TAU;
    if form.theta(s).ok()? > tau || form.phi(s).ok()? > tau {
        return None;
    }
    let (t0, t1, t2) = angles(form, s)?;
    let ok = (0.02..=1.4).contains(&t0)
        && (0.02..=1.4).contains(&t1)
        && t2.abs().min(std::f64::consts::PI - t2.abs()) > 1e-3;
    ok.then_some((t0, t1, t2))
}

/// Near the cone's edge: an `s` where |θ2(s)| − π/2 changes sign (on a grid of 200 over
/// (0, `s_hi`], then bisection), moved so that |θ2| is off π/2 by up to 0.05 either way.
fn edge_end(form: &SpaceForm, s_hi: f64, rng: &mut Rng) -> Option<f64> {
    let d = |s: f64| angles(form, s).map(|(_, _, t2)| t2.abs() - std::f64::consts::FRAC_PI_2);
    let n = 200;
    let mut roots = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for i in 1..=n {
        let s = s_hi * i as f64 / n as f64;
        let Some(v) = d(s) else {
            prev = None;
            continue;
        };
        if let Some((sp, vp)) = prev {
            if (vp > 0.0) != (v > 0.0) {
                roots.push((sp, s));
            }
        }
        prev = Some((s, v));
    }
    if roots.is_empty() {
        return None;
    }
    let (mut lo, mut hi) = roots[(rng.next() * roots.len() as f64) as usize % roots.len()];
    let target = (2.0 * rng.next() - 1.0) * 0.05;
    let f = |s: f64| d(s).map(|v| v - target);
    let (flo, fhi) = (f(lo)?, f(hi)?);
    if (flo > 0.0) == (fhi > 0.0) {
        return Some(0.5 * (lo + hi));
    }
    for _ in 0..50 {
        let mid = 0.5 * (lo + hi);
        if (f(mid)? > 0.0) == (flo > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// What [`generate_with`] draws: which (α, β, type) cells, cycled so that each is equally
/// represented, and the ranges of the piece's end.
#[derive(Clone, Debug)]
pub(crate) struct Recipe {
    /// The cells (α, β, torsion type), taken in turn.
    pub(crate) cells: Vec<(f64, f64, TorsionType)>,
    /// The end `s_end` is drawn uniformly in this range of the standard form's arc length
    /// (cut to 98% of its valid range; rejected when the piece is not acceptable there), and
    /// a near-edge end searched up to its upper bound.
    pub(crate) s_end: (f64, f64),
    /// Ends shorter than this are rejected (the default set keeps short near-edge ends).
    pub(crate) min_s_end: f64,
    /// The least |θ2| and π − |θ2| (radians): how clearly the points are not coplanar.
    pub(crate) min_dihedral: f64,
}

impl Recipe {
    /// The default set: α, β ∈ [`SLOPES`] (α fastest), type 1 for the first 36 cells,
    /// type 2 for the next; ends at 0.1–6.
    pub(crate) fn all_slopes() -> Recipe {
        let mut cells = Vec::new();
        for torsion in [TorsionType::One, TorsionType::Two] {
            for beta in SLOPES {
                for alpha in SLOPES {
                    cells.push((alpha, beta, torsion));
                }
            }
        }
        Recipe {
            cells,
            s_end: (0.1, 6.0),
            min_s_end: 0.0,
            min_dihedral: 1e-3,
        }
    }
}

/// `n` cases from `seed` by [`Recipe::all_slopes`], deterministic.
pub(crate) fn generate(seed: u64, n: usize) -> Vec<Case> {
    generate_with(seed, n, &Recipe::all_slopes())
}

/// `n` cases from `seed` by `recipe`, deterministic.
pub(crate) fn generate_with(seed: u64, n: usize, recipe: &Recipe) -> Vec<Case> {
    let mut rng = Rng(seed);
    let mut cases = Vec::with_capacity(n);
    let mut k = 0usize;
    while cases.len() < n {
        let (alpha, beta, torsion) = recipe.cells[cases.len() % recipe.cells.len()];
        k += 1;
        let lambda = 0.05 + 0.55 * rng.next();
        let omega = if k % 4 == 0 { 0.0 } else { 0.4 * rng.next() };
        let nu = 0.8 + 3.2 * rng.next();
        let Ok(form) = SpaceForm::new(SpaceFormParams {
            alpha,
            beta,
            lambda,
            omega,
            nu,
            torsion,
        }) else {
            continue;
        };
        let (s_lo, s_hi) = recipe.s_end;
        let s_hi = s_hi.min(0.98 * form.s_range().1);
        let edge = rng.next() < 0.25;
        let s_end = if edge {
            match edge_end(&form, s_hi, &mut rng) {
                Some(s) => s,
                None => continue,
            }
        } else {
            s_lo + (s_hi - s_lo) * rng.next()
        };
        if s_end < recipe.min_s_end {
            continue;
        }
        let Some((theta0, theta1, theta2)) = acceptable(&form, s_end) else {
            continue;
        };
        if theta2.abs().min(std::f64::consts::PI - theta2.abs()) <= recipe.min_dihedral {
            continue;
        }
        let end = form.frame_at_s(s_end).unwrap();
        let chord = end.point.length();
        let (a, b) = (
            chord * (0.3 + 0.5 * rng.next()),
            chord * (0.3 + 0.5 * rng.next()),
        );
        let mut p = [
            Vec3::ZERO,
            Vec3::new(a, 0.0, 0.0),
            end.point - b * end.tangent,
            end.point,
        ];
        if rng.next() < 0.5 {
            p.reverse();
        }
        let mirror = rng.next() < 0.3;
        let rotate = rotation(&mut rng);
        let scale = 10f64.powf(2.0 * rng.next() - 1.0);
        let shift = Vec3::new(
            10.0 * rng.next() - 5.0,
            10.0 * rng.next() - 5.0,
            10.0 * rng.next() - 5.0,
        );
        let points = p.map(|q| {
            let q = if mirror { Vec3::new(q.x, q.y, -q.z) } else { q };
            shift + scale * rotate(q)
        });
        cases.push(Case {
            points,
            shape: SpaceShape {
                alpha,
                beta,
                omega,
                torsion,
            },
            form,
            s_end,
            edge,
            crossing: crossing_number(&form, s_end, theta0),
            larger_angle_at_end: theta0 < theta1,
        });
    }
    cases
}

// The check of a solution, independent of the solver and of the library's integrator.

use lac::SpaceSegment;

/// κ(s) and τ(s) of the standard form straight from docs/math.md §6 (ρ and μ, then reciprocals).
pub(crate) fn kappa_tau(f: &SpaceForm, s: f64) -> (f64, f64) {
    let (alpha, beta, lambda, omega, nu) = (f.alpha(), f.beta(), f.lambda(), f.omega(), f.nu());
    let rho = if alpha == 0.0 {
        (lambda * s).exp()
    } else {
        (lambda * alpha * s + 1.0).powf(1.0 / alpha)
    };
    let sg = match f.torsion_type() {
        TorsionType::One => 1.0,
        TorsionType::Two => -1.0,
    };
    let mu = if beta == 0.0 {
        nu * (sg * omega * s).exp()
    } else {
        (sg * omega * beta * s + nu.powf(beta)).powf(1.0 / beta)
    };
    (1.0 / rho, 1.0 / mu)
}

/// Classical RK4 on (x, t, n, b) from 0 to `s_end`, with step doubling: each step is taken
/// whole and as two halves, accepted when they agree to 1e-14 and Richardson-combined, and
/// the step adapts (κ and τ may vary on very different scales along one segment).
pub(crate) fn independent_end(f: &SpaceForm, s_end: f64) -> (Vec3, Vec3) {
    let deriv = |s: f64, y: &[f64; 12]| -> [f64; 12] {
        let (k, t) = kappa_tau(f, s);
        let mut d = [0.0; 12];
        for i in 0..3 {
            d[i] = y[3 + i];
            d[3 + i] = k * y[6 + i];
            d[6 + i] = -k * y[3 + i] + t * y[9 + i];
            d[9 + i] = -t * y[6 + i];
        }
        d
    };
    let add = |y: &[f64; 12], d: &[f64; 12], c: f64| {
        let mut z = *y;
        for i in 0..12 {
            z[i] += c * d[i];
        }
        z
    };
    let rk4 = |s: f64, y: &[f64; 12], h: f64| {
        let k1 = deriv(s, y);
        let k2 = deriv(s + 0.5 * h, &add(y, &k1, 0.5 * h));
        let k3 = deriv(s + 0.5 * h, &add(y, &k2, 0.5 * h));
        let k4 = deriv(s + h, &add(y, &k3, h));
        let mut z = *y;
        for j in 0..12 {
            z[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
        z
    };
    let mut y = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let (mut s, mut h) = (0.0, 1e-3 * s_end);
    while s < s_end {
        h = h.min(s_end - s);
        let whole = rk4(s, &y, h);
        let half = rk4(s, &y, 0.5 * h);
        let halves = rk4(s + 0.5 * h, &half, 0.5 * h);
        // Positions are measured against the piece's length (rounding alone reaches 1e-14
        // of it on long pieces), the unit frame vectors as they are.
        let size = |j: usize| if j < 3 { s_end.max(1.0) } else { 1.0 };
        let err = (0..12).fold(0.0f64, |m, j| m.max((whole[j] - halves[j]).abs() / size(j)));
        if err > 1e-14 && h > 1e-9 * s_end {
            h *= 0.5;
            continue;
        }
        for j in 0..12 {
            y[j] = halves[j] + (halves[j] - whole[j]) / 15.0;
        }
        s += h;
        if err < 1e-16 {
            h *= 2.0;
        }
    }
    (Vec3::new(y[0], y[1], y[2]), Vec3::new(y[3], y[4], y[5]))
}

/// Check the ends and end tangents of `seg` against `points`, by the independent
/// integration; returns (position error / chord, tangent error in radians).
pub(crate) fn check_ends(seg: &SpaceSegment, p: [Vec3; 4]) -> (f64, f64) {
    let form = seg.standard_form().unwrap();
    let tr = seg.transform().unwrap();
    let s_end = seg.s_end().unwrap();
    let (x_end, t_end) = independent_end(form, s_end);
    let start = tr.apply(Vec3::ZERO);
    let end = tr.apply(x_end);
    let t_start = tr.apply_vector(Vec3::X);
    let t_end = tr.apply_vector(t_end);
    let (first, last, t_first, t_last) = if tr.reversed {
        (end, start, -t_end, -t_start)
    } else {
        (start, end, t_start, t_end)
    };
    let chord = p[3].distance(p[0]);
    let pos = first.distance(p[0]).max(last.distance(p[3])) / chord;
    let tan = t_first
        .angle_to(p[1] - p[0])
        .max(t_last.angle_to(p[3] - p[2]));
    (pos, tan)
}
