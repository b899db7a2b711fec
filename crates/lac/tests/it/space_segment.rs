//! Space segments from four points (seed 003 §4): every solved segment reproduces its ends
//! and end tangents within 1e-9, checked by an integration independent of the solver (a
//! classical Runge–Kutta with step doubling on the closed-form κ(s), τ(s) written out
//! below, not the library's Taylor integrator).

use lac::SpaceCurve;
use lac::{Error, NotDrawable, SpaceForm, SpaceFormParams, SpaceSegment, SpaceShape};
use lac::{TorsionType, Vec3};

// The independent Runge–Kutta integration shared with the constructed-input test.
use crate::common::space_inputs;
use space_inputs::check_ends;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The shape α, β, Ω, type.
fn shape(alpha: f64, beta: f64, omega: f64, torsion: TorsionType) -> SpaceShape {
    SpaceShape {
        alpha,
        beta,
        omega,
        torsion,
    }
}

/// Four points from their coordinates.
fn points(p: [[f64; 3]; 4]) -> [Vec3; 4] {
    p.map(Vec3::from_array)
}

/// The control points most tests use: a right-handed, non-planar polygon.
fn twisted() -> [Vec3; 4] {
    points([
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [2.0, 1.0, 0.5],
        [2.0, 2.0, 1.5],
    ])
}

/// Four control points from a standard-form piece, moved by a rotation, scale, translation
/// and (optionally) a mirror: solvable by construction.
fn constructed(rng: &mut Rng, form: &SpaceForm, s_end: f64) -> [Vec3; 4] {
    let f0 = form.frame_at_s(0.0).unwrap();
    let f1 = form.frame_at_s(s_end).unwrap();
    let (a, b) = (0.3 + 0.5 * rng.next(), 0.3 + 0.5 * rng.next());
    let mut p = [
        f0.point,
        Vec3::new(a, 0.0, 0.0),
        f1.point - b * f1.tangent,
        f1.point,
    ];
    // Half the time the caller gives the points the other way round (θ0 < θ1): the
    // solver swaps the ends.
    if rng.next() < 0.5 {
        p.reverse();
    }
    let mirror = rng.next() < 0.3;
    let (yaw, pitch, roll) = (6.0 * rng.next(), 3.0 * rng.next(), 6.0 * rng.next());
    let k = 0.1 + 10.0 * rng.next();
    let shift = Vec3::new(rng.next() * 5.0, -rng.next() * 5.0, rng.next());
    for q in &mut p {
        if mirror {
            q.z = -q.z;
        }
        let (c, s) = (yaw.cos(), yaw.sin());
        *q = Vec3::new(c * q.x - s * q.y, s * q.x + c * q.y, q.z);
        let (c, s) = (pitch.cos(), pitch.sin());
        *q = Vec3::new(c * q.x + s * q.z, q.y, -s * q.x + c * q.z);
        let (c, s) = (roll.cos(), roll.sin());
        *q = Vec3::new(q.x, c * q.y - s * q.z, s * q.y + c * q.z);
        *q = k * *q + shift;
    }
    p
}

#[test]
fn solved_segments_reproduce_ends_and_tangents_within_1e_9() {
    let mut rng = Rng(0x005e_ed3d);
    let (mut solved, mut total, mut reversed, mut mirrored) = (0, 0, 0, 0);
    let mut worst = (0.0f64, 0.0f64);
    for alpha in [-1.0, 0.0, 1.0] {
        for beta in [-1.0, 0.0, 1.0] {
            let mut made = 0;
            while made < 12 {
                let lambda = 1.5 * rng.next();
                let nu = (2.0 * rng.next() - 0.7).exp();
                let omega = if made % 2 == 0 { 0.0 } else { 0.4 * rng.next() };
                let kind = if made % 4 < 2 {
                    TorsionType::One
                } else {
                    TorsionType::Two
                };
                let form = SpaceForm::new(SpaceFormParams {
                    alpha,
                    beta,
                    lambda,
                    omega,
                    nu,
                    torsion: kind,
                })
                .unwrap();
                let s_end = 0.3 + 3.0 * rng.next();
                if s_end >= 0.999 * form.s_range().1
                    || form.theta(s_end).unwrap() > 5.5
                    || form.phi(s_end).unwrap() > 5.5
                {
                    continue;
                }
                made += 1;
                total += 1;
                let p = constructed(&mut rng, &form, s_end);
                let Ok(seg) = SpaceSegment::from_control_points(p, shape(alpha, beta, omega, kind))
                else {
                    continue;
                };
                solved += 1;
                let tr = seg.transform().unwrap();
                reversed += usize::from(tr.reversed);
                mirrored += usize::from(tr.mirror_z);
                let f = seg.standard_form().unwrap();
                assert!(f.lambda() >= 0.0 && f.nu() > 0.0);
                // The seed's guard: neither tangent nor binormal turns by more than 2π.
                let s_end = seg.s_end().unwrap();
                assert!(f.theta(s_end).unwrap() <= std::f64::consts::TAU);
                assert!(f.phi(s_end).unwrap() <= std::f64::consts::TAU);
                let (pos, tan) = check_ends(&seg, p);
                assert!(
                    pos < 1e-9 && tan < 1e-9,
                    "alpha {alpha} beta {beta} omega {omega} {kind:?}: position {pos:e}, \
                     tangent {tan:e}"
                );
                worst = (worst.0.max(pos), worst.1.max(tan));
            }
        }
    }
    eprintln!(
        "solved {solved}/{total} (reversed {reversed}, mirrored {mirrored}); worst position \
         {:e}, tangent {:e}",
        worst.0, worst.1
    );
    assert!(
        solved as f64 >= 0.95 * total as f64,
        "solved {solved}/{total}"
    );
    assert!(reversed > 0 && mirrored > 0 && reversed < solved);
}

#[test]
fn frames_are_orthonormal_right_handed_and_match_the_ends() {
    let p = twisted();
    let seg = SpaceSegment::from_control_points(p, shape(0.0, 0.0, 0.2, TorsionType::One)).unwrap();
    let frames = seg.sample_by_arc_length(33).unwrap();
    assert_eq!(frames.len(), 33);
    assert!(frames[0].point.distance(p[0]) < 1e-12);
    assert!(frames[32].point.distance(p[3]) < 1e-9 * 3.0);
    for (i, f) in frames.iter().enumerate() {
        assert!((f.s - seg.arc_length() * i as f64 / 32.0).abs() < 1e-12);
        for v in [f.tangent, f.normal, f.binormal] {
            assert!((v.length() - 1.0).abs() < 1e-14);
        }
        assert!(f.tangent.dot(f.normal).abs() < 1e-14);
        assert!(f.tangent.cross(f.normal).distance(f.binormal) < 1e-14);
        assert!(f.curvature > 0.0 && f.torsion != 0.0);
    }
    // The tangent is the derivative of the position (central differences).
    for w in frames.windows(3) {
        let h = w[2].s - w[0].s;
        let d = (w[2].point - w[0].point) / h;
        assert!(d.distance(w[1].tangent) < 1e-3);
    }
}

#[test]
fn curvature_and_torsion_graphs_are_lines_of_slopes_alpha_and_beta() {
    let p = twisted();
    for (alpha, beta) in [(-1.0, 0.5), (0.0, 0.0), (1.0, -1.0)] {
        let seg = SpaceSegment::from_control_points(p, shape(alpha, beta, 0.1, TorsionType::Two))
            .unwrap();
        for (graph, slope) in [
            (seg.log_curvature_graph(9).unwrap(), alpha),
            (seg.log_torsion_graph(9).unwrap(), beta),
        ] {
            assert_eq!(graph.len(), 9);
            for w in graph.windows(2) {
                let measured = (w[1].y - w[0].y) / (w[1].x - w[0].x);
                assert!((measured - slope).abs() < 1e-6, "{measured} vs {slope}");
            }
        }
        // Finite differences of the sampled radii give the same ordinate.
        let frames = seg.sample_by_arc_length(2001).unwrap();
        let lcg = seg.log_curvature_graph(2001).unwrap();
        let i = 1000;
        let (r0, r1) = (1.0 / frames[i - 1].curvature, 1.0 / frames[i + 1].curvature);
        let rho = 1.0 / frames[i].curvature;
        let ds_drho = (frames[i + 1].s - frames[i - 1].s) / (r1 - r0);
        assert!(((rho * ds_drho.abs()).ln() - lcg[i].y).abs() < 1e-5);
    }
}

#[test]
fn coplanar_points_give_the_planar_segment() {
    let p = points([
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [2.0, 0.5, 1.0],
        [2.5, 1.5, 1.0],
    ]);
    let seg = SpaceSegment::from_control_points(p, shape(0.5, 0.0, 0.0, TorsionType::One)).unwrap();
    assert!(seg.is_planar() && seg.standard_form().is_none() && seg.transform().is_none());
    let planar = seg.planar().unwrap();
    assert_eq!(planar.alpha(), 0.5);
    let frames = seg.sample_by_arc_length(17).unwrap();
    assert!(frames[0].point.distance(p[0]) < 1e-12);
    assert!(frames[16].point.distance(p[3]) < 1e-12);
    assert!(frames[16].tangent.angle_to(p[3] - p[2]) < 1e-12);
    assert!(frames
        .iter()
        .all(|f| f.torsion == 0.0 && (f.point.z - 1.0).abs() < 1e-12));
    // A coplanar S has an inflection: no log-aesthetic segment.
    let s = points([
        [0.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [2.0, -1.0, 0.0],
        [3.0, 0.0, 0.0],
    ]);
    assert!(matches!(
        SpaceSegment::from_control_points(s, shape(0.5, 0.0, 0.0, TorsionType::One)),
        Err(Error::InflectedPolygon { .. })
    ));
}

#[test]
fn bad_input_gives_typed_errors() {
    let p = twisted();
    let solve = |p, a, b, w| SpaceSegment::from_control_points(p, shape(a, b, w, TorsionType::One));
    let mut nan = p;
    nan[2].y = f64::NAN;
    assert!(matches!(
        solve(nan, 0.0, 0.0, 0.0),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        solve(p, f64::INFINITY, 0.0, 0.0),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        solve(p, 0.0, 0.0, -1.0),
        Err(Error::OutOfRange { .. })
    ));
    let mut same = p;
    same[1] = same[0];
    assert!(matches!(
        solve(same, 0.0, 0.0, 0.0),
        Err(Error::CoincidentPoints {
            first: 0,
            second: 1
        })
    ));
    // Start tangent along the chord.
    let along = points([
        [0.0, 0.0, 0.0],
        [1.0, 1.0, 1.0],
        [2.0, 1.0, 0.5],
        [2.0, 2.0, 2.0],
    ]);
    assert!(matches!(
        solve(along, 0.0, 0.0, 0.0),
        Err(Error::CollinearPoints)
    ));
    assert!(TorsionType::from_number(3).is_err());
}

#[test]
fn out_of_reach_omega_reports_where_the_branch_ends() {
    let p = twisted();
    let solve =
        |omega| SpaceSegment::from_control_points(p, shape(0.0, 1.0, omega, TorsionType::One));
    let err = solve(50.0).unwrap_err();
    // The message says what the search found, one line, not that Ω is too large.
    let message = err.to_string();
    assert!(
        message.contains("no space segment found for omega = 50;")
            && message.contains("found by continuing from omega = 0 ends near omega = ")
            && !message.contains("too large")
            && !message.contains('\n'),
        "{message}"
    );
    let Error::NotDrawable(NotDrawable::TorsionTooLarge { omega, omega_max }) = err else {
        panic!("expected TorsionTooLarge, got {err:?}");
    };
    assert_eq!(omega, 50.0);
    assert!(omega_max > 0.0 && omega_max < 50.0);
    let seg = solve(omega_max).unwrap();
    let (pos, tan) = check_ends(&seg, p);
    let f = seg.standard_form().unwrap();
    assert!(
        pos < 1e-9 && tan < 1e-9,
        "{pos:e} {tan:e} {f:?} {:?}",
        seg.s_end()
    );
    // Some way beyond Ω_max it still fails.
    assert!(solve(omega_max * 1.05 + 1e-3).is_err());
}

/// Pieces of known space curves that the search used to miss, each solved now and its ends
/// reproduced: three of type 1 with β = −1 whose chord makes the larger angle with the
/// tangent at the form's end (found only with the ends in the other order; they were refused
/// as "omega too large"), and two of type 2 ending where the curve grazes the cone about the
/// start tangent (found only from the scans' touches).
#[test]
fn pieces_the_search_used_to_miss_are_solved() {
    let cases = [
        (
            0.5,
            -1.0,
            0.09778619517379782,
            TorsionType::One,
            [
                [1.3895617668398228, -2.564261834393954, -2.8091210890292633],
                [1.1460167392628535, -3.2632023123888185, -3.098789027032256],
                [0.5346775160893406, -2.4133878912986755, -3.0220331052082083],
                [
                    0.48382525680320576,
                    -2.6179171878701157,
                    -3.3423874802826727,
                ],
            ],
        ),
        (
            1.0,
            -1.0,
            0.1868153369512504,
            TorsionType::One,
            [
                [-1.0882533107743493, 4.599549536895837, 3.0746321932132656],
                [-1.1616445867579073, 4.56219858798149, 3.2800439365380027],
                [-0.8805933869418084, 4.890487707885293, 3.325435628220098],
                [-0.7520476588954708, 4.69794229976112, 3.38523841342203],
            ],
        ),
        (
            2.0,
            -1.0,
            0.1822517018656115,
            TorsionType::One,
            [
                [-4.123385313620144, -1.1674479167420673, 4.213382981103715],
                [-5.2270002653653655, -5.784428151126061, 6.680455829314085],
                [4.759444933340005, -6.858727940513, 1.2800879271324561],
                [-1.7956472215109107, -11.48515876117612, -0.7745569467139344],
            ],
        ),
        (
            2.0,
            -1.0,
            0.2194752495109898,
            TorsionType::Two,
            [
                [9.81098301201163, 3.863257491614762, 2.277454579902903],
                [5.777221247355678, 3.345945979981524, 2.308931533509147],
                [
                    4.6744912721333565,
                    -0.012784908053850685,
                    0.34048691912400936,
                ],
                [2.1815947506101487, 3.203158143919289, 0.5852808729800429],
            ],
        ),
        (
            2.0,
            -1.0,
            0.3691045607601698,
            TorsionType::Two,
            [
                [-2.9568651402718804, -0.7661126900318627, 1.805196657879087],
                [-2.9812246717368764, 0.19799453522525762, 1.6926895188027338],
                [-2.7047454280456225, 0.10237752147335943, 1.1195224494584233],
                [-2.966855331297399, 0.4838917533161249, 1.3750837763429038],
            ],
        ),
    ];
    for (alpha, beta, omega, torsion, p) in cases {
        let p = points(p);
        let seg = SpaceSegment::from_control_points(p, shape(alpha, beta, omega, torsion))
            .unwrap_or_else(|e| panic!("alpha {alpha} beta {beta} omega {omega}: {e}"));
        let (pos, tan) = check_ends(&seg, p);
        assert!(
            pos < 1e-9 && tan < 1e-9,
            "alpha {alpha} beta {beta} omega {omega}: {pos:e} {tan:e}"
        );
    }
}

mod never_panics {
    use lac::{SpaceCurve, SpaceSegment, SpaceShape, TorsionType, Vec3};
    use proptest::prelude::*;

    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            8 => -10.0..10.0f64,
            1 => Just(0.0),
            1 => prop::num::f64::ANY,
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]
        /// Any input gives a segment or a typed error, never a panic; a segment samples.
        #[test]
        fn any_input_gives_a_segment_or_an_error(
            c in prop::collection::vec(coord(), 12),
            alpha in -3.0..3.0f64,
            beta in -3.0..3.0f64,
            omega in prop_oneof![Just(0.0), 0.0..2.0f64, Just(-1.0), Just(f64::NAN)],
            two in any::<bool>(),
        ) {
            let p = [
                Vec3::new(c[0], c[1], c[2]),
                Vec3::new(c[3], c[4], c[5]),
                Vec3::new(c[6], c[7], c[8]),
                Vec3::new(c[9], c[10], c[11]),
            ];
            let torsion = if two { TorsionType::Two } else { TorsionType::One };
            let shape = SpaceShape { alpha, beta, omega, torsion };
            if let Ok(seg) = SpaceSegment::from_control_points(p, shape) {
                let frames = seg.sample_by_arc_length(5).unwrap();
                prop_assert!(frames.iter().all(|f| f.point.is_finite()));
            }
        }
    }
}
