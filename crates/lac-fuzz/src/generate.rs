//! The generators: ordinary values, extreme magnitudes, special floats and near-degenerate
//! configurations, mixed.

use crate::Input;

/// A small deterministic generator (SplitMix64): input `index` of stream `seed` is the
/// same on every machine, so any failure can be reproduced from its two numbers.
///
/// [`Rng::from_bytes`] makes the same generators read their choices from a byte string
/// instead, so that a coverage-guided fuzzer (AFL, through `crates/lac-fuzz/afl`) steers
/// them: every byte string is an input, and small changes to it make small changes to it.
#[derive(Clone, Debug)]
pub struct Rng {
    state: u64,
    /// The fuzzer's bytes and the next one to read; SplitMix64 continues once they run out.
    tape: Option<(Vec<u8>, usize)>,
}

impl Rng {
    /// The generator for input `index` of stream `seed`.
    pub fn new(seed: u64, index: u64) -> Rng {
        let mut r = Rng {
            state: seed ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03),
            tape: None,
        };
        r.next_u64();
        r
    }

    /// A generator that reads its 64-bit draws from `bytes`, eight at a time (little
    /// endian, the last draw padded with zeros), then continues pseudo-randomly from a
    /// state that depends on every byte.
    pub fn from_bytes(bytes: &[u8]) -> Rng {
        let state = bytes.iter().fold(0xCBF2_9CE4_8422_2325u64, |h, &b| {
            (h ^ u64::from(b)).wrapping_mul(0x100_0000_01B3)
        });
        Rng {
            state,
            tape: Some((bytes.to_vec(), 0)),
        }
    }

    /// 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        if let Some((bytes, at)) = &mut self.tape {
            if *at < bytes.len() {
                let mut word = [0u8; 8];
                let end = (*at + 8).min(bytes.len());
                word[..end - *at].copy_from_slice(&bytes[*at..end]);
                *at = end;
                return u64::from_le_bytes(word);
            }
        }
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [a, b).
    pub fn uniform(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }

    /// Uniform in 0..n.
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }

    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// One of `items`.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    /// ±10^e with e uniform in [lo, hi].
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let m = 10f64.powf(self.uniform(lo, hi));
        if self.chance(0.5) {
            m
        } else {
            -m
        }
    }

    /// A special float.
    pub fn special(&mut self) -> f64 {
        self.pick(&[
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            1.0 + f64::EPSILON,
            1.0 - f64::EPSILON / 2.0,
        ])
    }

    /// A coordinate-like number: mostly ordinary, sometimes extreme or special.
    pub fn number(&mut self) -> f64 {
        match self.below(100) {
            0..=59 => self.uniform(-10.0, 10.0),
            60..=79 => self.pick(&[-2.0, -1.0, -0.5, 0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0]),
            80..=94 => self.log_uniform(-300.0, 300.0),
            _ => self.special(),
        }
    }
}

/// A slope α: the named members, ordinary values, values next to 0 and 1, extremes.
fn alpha(rng: &mut Rng) -> f64 {
    match rng.below(100) {
        0..=29 => rng.pick(&[-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0]),
        30..=69 => rng.uniform(-3.0, 4.0),
        70..=79 => rng.pick(&[0.0, 1.0]) + rng.log_uniform(-17.0, -3.0),
        80..=89 => rng.log_uniform(-3.0, 7.0),
        90..=96 => rng.log_uniform(-300.0, 308.0),
        _ => rng.special(),
    }
}

/// A plane point from three: a random triangle, possibly near-degenerate, scaled and moved.
fn triangle(rng: &mut Rng) -> [[f64; 2]; 3] {
    let mut p = match rng.below(100) {
        // Ordinary triangles.
        0..=49 => [
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
        ],
        // The canonical region's frame: P0 = (−1, 0), P2 = (1, 0).
        50..=64 => [
            [-1.0, 0.0],
            [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)],
            [1.0, 0.0],
        ],
        // Nearly collinear: P1 just off the line, on it, or beyond an end.
        65..=72 => {
            let t = rng.uniform(-0.5, 1.5);
            let off = rng.log_uniform(-16.0, -2.0);
            [[0.0, 0.0], [t, off], [1.0, 0.0]]
        }
        // Nearly isosceles (a circular arc) and exactly isosceles.
        73..=80 => {
            let h = rng.uniform(0.05, 3.0);
            let skew = if rng.chance(0.3) {
                0.0
            } else {
                rng.log_uniform(-15.0, -3.0)
            };
            [[-1.0, 0.0], [skew, h], [1.0, 0.0]]
        }
        // Nearly coincident points.
        81..=86 => {
            let eps = rng.log_uniform(-16.0, -6.0);
            let which = rng.below(3);
            let mut p = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]];
            p[(which + 1) % 3] = [p[which][0] + eps, p[which][1] + eps.abs()];
            p
        }
        // Any numbers at all.
        _ => [
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
        ],
    };
    transform(rng, &mut p);
    p
}

/// A factor that takes a shape of size about 1 to within a few binades of the largest
/// double: its coordinates and their differences near `f64::MAX`.
fn near_max(rng: &mut Rng) -> f64 {
    f64::MAX / 2f64.powf(rng.uniform(2.0, 10.0))
}

/// Scale, rotate and move points, sometimes to extreme magnitudes or far from the origin.
fn transform<const N: usize>(rng: &mut Rng, p: &mut [[f64; 2]; N]) {
    if rng.chance(0.3) {
        let scale = match rng.below(5) {
            0 => 10f64.powf(rng.uniform(-160.0, 160.0)),
            1 => near_max(rng),
            _ => 10f64.powf(rng.uniform(-6.0, 6.0)),
        };
        let (s, c) = rng.uniform(0.0, std::f64::consts::TAU).sin_cos();
        let (dx, dy) = if rng.chance(0.3) {
            (rng.log_uniform(-3.0, 8.0), rng.log_uniform(-3.0, 8.0))
        } else {
            (0.0, 0.0)
        };
        for q in p.iter_mut() {
            let (x, y) = (q[0] * scale, q[1] * scale);
            *q = [c * x - s * y + dx, s * x + c * y + dy];
        }
    }
    if rng.chance(0.1) {
        for q in p.iter_mut() {
            q[1] = -q[1];
        }
    }
}

fn samples(rng: &mut Rng) -> usize {
    match rng.below(10) {
        0 => rng.pick(&[0, 1, 2, 3]),
        1 => rng.below(5000),
        _ => rng.pick(&[2, 9, 33, 65, 129]),
    }
}

pub(crate) fn segment(rng: &mut Rng) -> Input {
    Input::Segment {
        points: triangle(rng),
        alpha: alpha(rng),
        samples: samples(rng),
        // Adaptive sampling's cost grows as accuracy^(-1/2): the tight accuracies (1e-12 to
        // 1e-7, up to the 50,000-sample limit for these sizes) are a tenth of the draws,
        // not most of the time.
        accuracy: match rng.below(10) {
            0 => rng.number(),
            1 => 10f64.powf(rng.uniform(-12.0, -7.0)),
            _ => 10f64.powf(rng.uniform(-7.0, -1.0)),
        },
    }
}

pub(crate) fn compound3(rng: &mut Rng) -> Input {
    Input::Compound3 {
        points: triangle(rng),
        alpha: [alpha(rng), alpha(rng)],
        ratio: match rng.below(10) {
            0 => rng.number(),
            1 => rng.pick(&[1e-12, 1e-6, 0.999999, 1.0 - 1e-12]),
            _ => rng.uniform(0.02, 0.98),
        },
        samples: samples(rng),
    }
}

pub(crate) fn compound4(rng: &mut Rng) -> Input {
    let mut p = match rng.below(10) {
        0..=6 => {
            // A polygon turning one way, with random legs: the common case.
            let mut theta = rng.uniform(-3.0, 3.0);
            let sign = if rng.chance(0.5) { 1.0 } else { -1.0 };
            let mut p = [[0.0; 2]; 4];
            for i in 1..4 {
                let leg = rng.uniform(0.2, 3.0);
                p[i] = [
                    p[i - 1][0] + leg * theta.cos(),
                    p[i - 1][1] + leg * theta.sin(),
                ];
                theta += sign * rng.uniform(0.05, 2.2);
            }
            p
        }
        7 => {
            // The kind of near-degenerate four-point input.
            [
                [0.0, 0.0],
                [rng.uniform(5.0, 8.0), 0.0],
                [rng.uniform(5.0, 7.0), rng.uniform(-2.0, 0.0)],
                [rng.uniform(5.0, 7.0), rng.uniform(-0.5, 0.5)],
            ]
        }
        _ => [
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
        ],
    };
    transform(rng, &mut p);
    Input::Compound4 {
        points: p,
        alpha: [alpha(rng), alpha(rng)],
        samples: samples(rng),
    }
}

fn bezier(rng: &mut Rng) -> ([[f64; 2]; 4], [f64; 4]) {
    let mut p = if rng.chance(0.85) {
        [
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
            [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
        ]
    } else {
        [
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
            [rng.number(), rng.number()],
        ]
    };
    if rng.chance(0.1) {
        // A repeated control point (a cusp or a degenerate end).
        let i = rng.below(3);
        p[i + 1] = p[i];
    }
    transform(rng, &mut p);
    let w = match rng.below(10) {
        0..=3 => [1.0; 4],
        4..=7 => [
            rng.uniform(0.1, 3.0),
            rng.uniform(0.1, 3.0),
            rng.uniform(0.1, 3.0),
            rng.uniform(0.1, 3.0),
        ],
        8 => [
            rng.log_uniform(-100.0, 100.0).abs(),
            rng.log_uniform(-100.0, 100.0).abs(),
            rng.log_uniform(-100.0, 100.0).abs(),
            rng.log_uniform(-100.0, 100.0).abs(),
        ],
        _ => [rng.number(), rng.number(), rng.number(), rng.number()],
    };
    (p, w)
}

pub(crate) fn monotone(rng: &mut Rng) -> Input {
    let (points, weights) = bezier(rng);
    Input::Monotone { points, weights }
}

pub(crate) fn analysis(rng: &mut Rng) -> Input {
    let n = 1 + rng.below(4);
    Input::Analysis {
        pieces: (0..n).map(|_| bezier(rng)).collect(),
        per_piece: match rng.below(10) {
            0 => rng.below(3),
            _ => rng.pick(&[2, 8, 33, 64]),
        },
    }
}

pub(crate) fn quasi(rng: &mut Rng) -> Input {
    Input::Quasi {
        points: triangle(rng),
        alpha: alpha(rng),
        // As for sampling, the tight tolerances (the checks sample the segment to a tenth
        // of them) are a tenth of the draws.
        tolerance: match rng.below(10) {
            0..=2 => None,
            3 => Some(rng.number()),
            4 => Some(10f64.powf(rng.uniform(-11.0, -7.0))),
            _ => Some(10f64.powf(rng.uniform(-7.0, -1.0))),
        },
        cubic: rng.chance(0.3),
    }
}

pub(crate) fn space(rng: &mut Rng) -> Input {
    let mut p = if rng.chance(0.85) {
        // A helix-like polygon: legs turning and climbing.
        let mut p = [[0.0; 3]; 4];
        let (mut theta, mut z) = (0.0f64, 0.0f64);
        for i in 1..4 {
            let leg = rng.uniform(0.3, 3.0);
            theta += rng.uniform(0.1, 1.8);
            z += rng.uniform(-1.5, 1.5);
            p[i] = [
                p[i - 1][0] + leg * theta.cos(),
                p[i - 1][1] + leg * theta.sin(),
                z,
            ];
        }
        if rng.chance(0.1) {
            // Coplanar.
            for q in p.iter_mut() {
                q[2] = 0.0;
            }
        }
        p
    } else {
        [
            [rng.number(), rng.number(), rng.number()],
            [rng.number(), rng.number(), rng.number()],
            [rng.number(), rng.number(), rng.number()],
            [rng.number(), rng.number(), rng.number()],
        ]
    };
    if rng.chance(0.2) {
        let scale = if rng.chance(0.2) {
            near_max(rng)
        } else {
            10f64.powf(rng.uniform(-100.0, 100.0))
        };
        for q in p.iter_mut() {
            for c in q.iter_mut() {
                *c *= scale;
            }
        }
    }
    Input::Space {
        points: p,
        alpha: alpha(rng),
        beta: alpha(rng),
        omega: match rng.below(10) {
            0 => rng.number(),
            1 => rng.log_uniform(-3.0, 8.0).abs(),
            _ => rng.uniform(0.0, 0.6),
        },
        torsion: rng.pick(&[1, 2, 1, 2, 0, 3]),
    }
}

pub(crate) fn path(rng: &mut Rng) -> Input {
    let mut n = 2 + rng.below(11);
    let mut closed = rng.chance(0.3);
    let mut points: Vec<[f64; 2]> = match rng.below(10) {
        // Around a circle (turning one way, as a G2 path wants), radii and steps jittered.
        0..=5 => {
            let mut angle = rng.uniform(0.0, 6.3);
            let span = if closed { 6.2 } else { rng.uniform(0.5, 6.0) };
            (0..n)
                .map(|_| {
                    angle += span / n as f64 * rng.uniform(0.5, 1.5);
                    let r = rng.uniform(0.7, 1.3);
                    [r * angle.cos(), r * angle.sin()]
                })
                .collect()
        }
        // A zigzag: the turning changes direction at every vertex.
        6 => (0..n)
            .map(|i| {
                [
                    i as f64,
                    if i % 2 == 0 {
                        0.0
                    } else {
                        rng.uniform(0.2, 2.0)
                    },
                ]
            })
            .collect(),
        // A figure eight, closed, every vertex moved and started anywhere: two loops
        // turning opposite ways, so a G2 path (α < 0) passes through two inflections, with
        // a straight piece on each crossing leg, the seam on or next to one of them.
        7 => {
            const EIGHT: [[f64; 2]; 12] = [
                [1.5, -1.0],
                [3.0, -1.8],
                [4.5, -1.0],
                [4.5, 1.0],
                [3.0, 1.8],
                [1.5, 1.0],
                [-1.5, -1.0],
                [-3.0, -1.8],
                [-4.5, -1.0],
                [-4.5, 1.0],
                [-3.0, 1.8],
                [-1.5, 1.0],
            ];
            (n, closed) = (EIGHT.len(), true);
            let first = rng.below(n);
            (0..n)
                .map(|i| {
                    let [x, y] = EIGHT[(first + i) % n];
                    [x + rng.uniform(-0.3, 0.3), y + rng.uniform(-0.3, 0.3)]
                })
                .collect()
        }
        // Anything.
        _ => (0..n).map(|_| [rng.number(), rng.number()]).collect(),
    };
    if rng.chance(0.1) && n > 2 {
        // Two vertices coincide, or three are collinear.
        let i = rng.below(n - 1);
        points[i + 1] = if rng.chance(0.5) {
            points[i]
        } else {
            let (a, b) = (points[i], points[(i + 2) % n]);
            [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
        };
    }
    if rng.chance(0.15) {
        // Far from the origin, or very large or very small.
        let scale = if rng.chance(0.2) {
            near_max(rng) / 10.0
        } else {
            rng.log_uniform(-150.0, 150.0).abs()
        };
        let shift = rng.log_uniform(-3.0, 8.0);
        for p in points.iter_mut() {
            *p = [p[0] * scale + shift, p[1] * scale];
        }
    }
    let segments = if closed { n } else { n.saturating_sub(2) };
    let alpha = if rng.chance(0.8) || segments == 0 {
        vec![alpha(rng)]
    } else {
        (0..segments).map(|_| alpha(rng)).collect()
    };
    Input::Path {
        points,
        alpha,
        closed,
        g2: rng.chance(0.6),
    }
}

pub(crate) fn export(rng: &mut Rng) -> Input {
    use lac_export::Format;
    let curve = match rng.below(10) {
        0..=2 => segment(rng),
        3 => compound3(rng),
        4 => compound4(rng),
        5..=7 => path(rng),
        _ => space(rng),
    };
    Input::Export {
        curve: Box::new(curve),
        format: rng.pick(&[
            Format::Json,
            Format::Json,
            Format::Dxf,
            Format::Step,
            Format::Iges,
            Format::Svg,
        ]),
        // Fits get dearer as the tolerance tightens: the tightest (to 1e-11, past what can
        // be certified) are a tenth of the draws.
        tolerance: match rng.below(10) {
            0 => rng.number(),
            1 => 10f64.powf(rng.uniform(-11.0, -8.0)),
            _ => 10f64.powf(rng.uniform(-8.0, -2.0)),
        },
        relative: rng.chance(0.7),
        single_spans: rng.chance(0.2),
    }
}

pub(crate) fn spline(rng: &mut Rng) -> Input {
    // The points of a path's polygon (around a circle, a zigzag, anything; degenerate and
    // far-away variants), or a wave whose turning changes direction (S spans for α < 0).
    let Input::Path {
        mut points,
        mut closed,
        ..
    } = path(rng)
    else {
        unreachable!("path() draws paths")
    };
    if rng.chance(0.3) {
        let (n, step, phase) = (
            3 + rng.below(10),
            rng.uniform(0.3, 1.5),
            rng.uniform(0.0, 6.3),
        );
        let amplitude = rng.uniform(0.1, 2.0);
        points = (0..n)
            .map(|i| {
                let x = i as f64 * rng.uniform(0.7, 1.3);
                [x, amplitude * (step * i as f64 + phase).sin()]
            })
            .collect();
        closed = false;
    }
    let ends =
        (!closed && rng.chance(0.2)).then(|| [rng.uniform(-3.2, 3.2), rng.uniform(-3.2, 3.2)]);
    // Point types on half the inputs: corners, tangent points (their directions near the
    // polygon's, or anything), straight spans, end curvatures (0 now and then).
    let (mut types, mut angles, mut lines, mut curvatures) =
        (Vec::new(), Vec::new(), Vec::new(), [None, None]);
    if rng.chance(0.5) && !points.is_empty() {
        let n = points.len();
        for i in 0..n {
            let [x0, y0] = points[i];
            let [x1, y1] = points[(i + 1) % n];
            let along = (y1 - y0).atan2(x1 - x0);
            let (kind, given) = match rng.below(8) {
                0 => ("c", [rng.chance(0.5).then(|| rng.uniform(-3.2, 3.2)), None]),
                1 => ("t", [Some(along + rng.uniform(-0.3, 0.3)), None]),
                2 if rng.chance(0.2) => ("t", [Some(rng.uniform(-10.0, 10.0)), None]),
                _ => ("s", [None, None]),
            };
            types.push(kind.to_string());
            angles.push(given);
            if rng.chance(0.12) {
                lines.push(if rng.chance(0.05) {
                    rng.below(2 * n)
                } else {
                    i
                });
            }
        }
        if !closed {
            for c in curvatures.iter_mut() {
                if rng.chance(0.2) {
                    *c = Some(if rng.chance(0.2) {
                        0.0
                    } else {
                        rng.uniform(-3.0, 3.0)
                    });
                }
            }
        }
    }
    Input::Spline {
        points,
        alpha: alpha(rng),
        closed,
        ends,
        types,
        angles,
        lines,
        curvatures,
    }
}

/// Points to fit: along a curve with noise, random, collinear, repeated, clustered, a
/// million apart in scale, with a special float among them, one or two points, and now and
/// then a few thousand; and the fit's options, ordinary or not.
pub(crate) fn fit(rng: &mut Rng) -> Input {
    let mut n = match rng.below(20) {
        0 => rng.pick(&[0, 1, 2, 3, 4]),
        1 => 500 + rng.below(2500),
        _ => 5 + rng.below(120),
    };
    let noise = match rng.below(4) {
        0 => 0.0,
        _ => rng.log_uniform(-8.0, -1.0).abs(),
    };
    let mut points: Vec<[f64; 2]> = match rng.below(10) {
        // Along an arc or a spiral (curvature growing or shrinking), with noise.
        0..=3 => {
            let (k0, k1) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0));
            let length = rng.uniform(0.5, 6.0);
            let (mut x, mut y, mut theta) = (0.0, 0.0, 0.0);
            let ds = length / n.max(1) as f64;
            (0..n)
                .map(|i| {
                    let t = i as f64 / n.max(1) as f64;
                    theta += (k0 + (k1 - k0) * t) * ds;
                    x += theta.cos() * ds;
                    y += theta.sin() * ds;
                    [
                        x + noise * rng.uniform(-1.0, 1.0),
                        y + noise * rng.uniform(-1.0, 1.0),
                    ]
                })
                .collect()
        }
        // A wave: the curvature changes sign (S pieces for α < 0).
        4 => {
            let (a, w) = (rng.uniform(0.05, 1.5), rng.uniform(0.5, 6.0));
            (0..n)
                .map(|i| {
                    let x = i as f64 / n.max(1) as f64 * 4.0;
                    [x, a * (w * x).sin() + noise * rng.uniform(-1.0, 1.0)]
                })
                .collect()
        }
        // Random points.
        5 => (0..n)
            .map(|_| [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)])
            .collect(),
        // Collinear, exactly or within rounding.
        6 => {
            let (dx, dy) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            let off = if rng.chance(0.5) {
                0.0
            } else {
                rng.log_uniform(-17.0, -10.0)
            };
            (0..n)
                .map(|i| {
                    let t = i as f64 * rng.uniform(0.5, 1.5);
                    [t * dx, t * dy + if i % 3 == 1 { off } else { 0.0 }]
                })
                .collect()
        }
        // Repeated points: a few distinct ones, each many times.
        7 => {
            let distinct: Vec<[f64; 2]> = (0..1 + rng.below(4))
                .map(|_| [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)])
                .collect();
            (0..n)
                .map(|i| distinct[i * distinct.len() / n.max(1)])
                .collect()
        }
        // Clusters: tight groups far apart, or a tiny curve beside one far point (a million
        // apart in scale).
        8 => {
            let spread = rng.log_uniform(-9.0, -3.0).abs();
            let centres: Vec<[f64; 2]> = (0..2 + rng.below(3))
                .map(|_| [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)])
                .collect();
            let mut p: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let c = centres[i * centres.len() / n.max(1)];
                    [
                        c[0] + spread * rng.uniform(-1.0, 1.0),
                        c[1] + spread * rng.uniform(-1.0, 1.0),
                    ]
                })
                .collect();
            if rng.chance(0.5) && !p.is_empty() {
                let last = p.len() - 1;
                p[last] = [1e6, -1e6];
            }
            p
        }
        // Any numbers at all.
        _ => (0..n).map(|_| [rng.number(), rng.number()]).collect(),
    };
    // Scaled and moved, sometimes to extreme magnitudes; reversed; a special float.
    if rng.chance(0.3) {
        let scale = match rng.below(4) {
            0 => 10f64.powf(rng.uniform(-150.0, 150.0)),
            _ => 10f64.powf(rng.uniform(-6.0, 6.0)),
        };
        let (dx, dy) = if rng.chance(0.3) {
            (rng.log_uniform(-3.0, 8.0), rng.log_uniform(-3.0, 8.0))
        } else {
            (0.0, 0.0)
        };
        for q in &mut points {
            *q = [q[0] * scale + dx, q[1] * scale + dy];
        }
    }
    if rng.chance(0.05) && !points.is_empty() {
        let k = rng.below(points.len());
        points[k][rng.below(2)] = rng.special();
    }
    n = points.len();
    let size = points
        .iter()
        .map(|p| p[0].abs().max(p[1].abs()))
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let tolerance = match rng.below(10) {
        0..=4 => None,
        5 => Some(rng.number()),
        _ => Some(size * 10f64.powf(rng.uniform(-6.0, -1.0)) + noise),
    };
    Input::Fit {
        points,
        tolerance,
        max_segments: match rng.below(10) {
            0 => rng.pick(&[0, 65, 1000]),
            1..=3 => 1,
            _ => 1 + rng.below(4),
        },
        alpha: rng.chance(0.3).then(|| alpha(rng)),
        closed: rng.chance(0.15),
        g1: rng.chance(0.15),
        pin_ends: rng.chance(0.15),
        huber: rng.chance(0.15).then(|| match rng.below(5) {
            0 => rng.number(),
            _ => size * 10f64.powf(rng.uniform(-6.0, -1.0)),
        }),
        weights: rng.chance(0.1).then(|| {
            (0..n + usize::from(rng.chance(0.1)))
                .map(|_| match rng.below(10) {
                    0 => rng.number(),
                    1 => 0.0,
                    _ => rng.uniform(0.1, 2.0),
                })
                .collect()
        }),
    }
}
