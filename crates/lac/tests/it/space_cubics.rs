//! Space segments replaced by cubic pieces within a tolerance (`SpaceSegment::to_cubics`):
//! the claims checked at points the fit never looked at (random arc lengths, distances to
//! the chain found by a dense search), the joins C1, the ends on the control polygon, and a
//! tolerance that needs too many pieces refused.

use lac::SpaceCurve;
use lac::{Error, SpaceCubics, SpaceSegment, SpaceShape, Tolerance, TorsionType, Vec3};

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn segments() -> Vec<SpaceSegment> {
    let cases = [
        (
            [
                [0.0, 0.0, 0.0],
                [3.0, 0.0, 0.0],
                [3.0, 3.0, 1.5],
                [0.0, 3.0, 3.0],
            ],
            0.5,
            0.0,
            0.3,
            TorsionType::One,
        ),
        (
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [2.0, 1.0, 0.3],
                [2.0, 2.0, 1.0],
            ],
            0.0,
            0.0,
            0.3,
            TorsionType::One,
        ),
        (
            [
                [0.0, 0.0, 0.0],
                [2.0, 0.0, 0.0],
                [2.5, 1.0, -0.3],
                [2.5, 1.5, -1.0],
            ],
            0.5,
            1.0,
            0.0,
            TorsionType::Two,
        ),
        // Coplanar points: the planar fallback.
        (
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [2.0, 1.0, 0.0],
                [2.0, 2.0, 0.0],
            ],
            -1.0,
            0.0,
            0.0,
            TorsionType::One,
        ),
    ];
    cases
        .iter()
        .map(|(p, alpha, beta, omega, torsion)| {
            let shape = SpaceShape {
                alpha: *alpha,
                beta: *beta,
                omega: *omega,
                torsion: *torsion,
            };
            SpaceSegment::from_control_points(p.map(Vec3::from_array), shape).unwrap()
        })
        .collect()
}

/// Distance from `q` to the chain: the nearest of 400 points per piece, refined by golden
/// section on its neighbouring intervals.
fn distance_to_chain(chain: &SpaceCubics, q: Vec3) -> f64 {
    let mut best = f64::INFINITY;
    for piece in &chain.pieces {
        let n = 400;
        let (mut j, mut dj) = (0, f64::INFINITY);
        for i in 0..=n {
            let d = piece.eval(i as f64 / n as f64).distance(q);
            if d < dj {
                (j, dj) = (i, d);
            }
        }
        let (mut lo, mut hi) = (
            (j.max(1) - 1) as f64 / n as f64,
            ((j + 1).min(n)) as f64 / n as f64,
        );
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..60 {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if piece.eval(x1).distance(q) < piece.eval(x2).distance(q) {
                hi = x2;
            } else {
                lo = x1;
            }
        }
        best = best.min(dj).min(piece.eval(0.5 * (lo + hi)).distance(q));
    }
    best
}

#[test]
fn the_exact_curve_stays_within_the_tolerance_of_the_chain_at_random_points() {
    let mut rng = Rng(0x5EED_C0B1);
    for seg in segments() {
        for tol in [1e-3, 1e-6, 1e-9] {
            let chain = seg.to_cubics(Tolerance::Absolute(tol)).unwrap();
            assert!(chain.max_deviation <= tol);
            let len = seg.arc_length();
            let mut s: Vec<f64> = (0..300).map(|_| rng.next() * len).collect();
            s.sort_by(f64::total_cmp);
            let worst = seg
                .frames(&s)
                .unwrap()
                .iter()
                .map(|f| distance_to_chain(&chain, f.point))
                .fold(0.0, f64::max);
            assert!(worst <= tol, "{worst:e} > {tol:e}");
        }
    }
}

#[test]
fn pieces_join_with_the_curves_points_and_tangents_and_end_on_the_polygon() {
    for seg in segments() {
        let chain = seg.to_cubics(Tolerance::Relative(1e-8)).unwrap();
        let p = seg.control_points();
        let first = chain.pieces[0].points;
        let last = chain.pieces[chain.pieces.len() - 1].points;
        assert!(first[0].distance(p[0]) < 1e-12 && last[3].distance(p[3]) < 1e-9);
        // End tangents along the first and last legs.
        let t0 = (first[1] - first[0]).normalize();
        let t1 = (last[3] - last[2]).normalize();
        assert!(t0.angle_to(p[1] - p[0]) < 1e-9 && t1.angle_to(p[3] - p[2]) < 1e-9);
        for pair in chain.pieces.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            assert_eq!(a.points[3], b.points[0]);
            assert_eq!(a.s.1, b.s.0);
            // C1 with knots spaced by arc length: 3(b3 − b2)/h_a = 3(b1 − b0)/h_b.
            let da = (a.points[3] - a.points[2]) * (3.0 / (a.s.1 - a.s.0));
            let db = (b.points[1] - b.points[0]) * (3.0 / (b.s.1 - b.s.0));
            assert!((da - db).length() < 1e-12, "{da:?} {db:?}");
        }
    }
}

#[test]
fn tolerances_down_to_1e_12_of_the_length_are_met_and_smaller_ones_refused() {
    let seg = &segments()[0];
    let chain = seg.to_cubics(Tolerance::Relative(1e-12)).unwrap();
    assert!(chain.pieces.len() <= lac::MAX_PIECES);
    assert!(chain.max_deviation <= 1e-12 * seg.arc_length());
    assert!(matches!(
        seg.to_cubics(Tolerance::Absolute(f64::NAN)),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        seg.to_cubics(Tolerance::Relative(1e-13)),
        Err(Error::OutOfRange { .. })
    ));
    assert!(matches!(
        seg.to_cubics(Tolerance::Absolute(-1.0)),
        Err(Error::OutOfRange { .. })
    ));
}
