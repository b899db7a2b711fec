//! Seeded random and adversarial inputs for every public entry point of `lac`, and the
//! invariants every answer must satisfy.
//!
//! Each [`EntryPoint`] draws its inputs from a deterministic generator that mixes ordinary
//! values, extreme magnitudes (1e-300 … 1e300), special floats (NaN, ±∞, ±0, subnormals) and
//! near-degenerate configurations (almost collinear or coincident points, isosceles
//! triangles, curves far from the origin), calls the library under `catch_unwind`, and
//! checks the answer:
//!
//! * no panic;
//! * an `Err` is a typed error (any kind is acceptable for bad input);
//! * an `Ok` has no NaN or infinity anywhere and meets the constraints it was asked to
//!   meet, re-verified independently of the solver (ends, end tangents, the tangent of every
//!   sampled chord, curvature monotone and of one sign, joints continuous, tolerances met,
//!   monotonicity verdicts not contradicted by sampling), to the bounds stated in
//!   [`bounds`];
//! * every call returns (iteration caps, not clocks); the slowest call is reported.
//!
//! Inputs that ever failed are kept in `regressions/` and replayed by the tests.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

use lac_export::Format;
use serde::{Deserialize, Serialize};

mod checks;
mod generate;

pub use checks::bounds;
pub use generate::Rng;

/// An input of one entry point, as JSON-friendly data (so failures can be kept).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "entry", rename_all = "snake_case")]
pub enum Input {
    /// `Segment::from_control_points`, then evaluation and sampling of the result.
    Segment {
        /// P0, P1, P2.
        points: [[f64; 2]; 3],
        /// α.
        alpha: f64,
        /// Samples asked of the result.
        samples: usize,
        /// Accuracy asked of adaptive sampling (absolute).
        accuracy: f64,
    },
    /// `CompoundCurve::from_three_points`.
    Compound3 {
        /// a0, a1, a2.
        points: [[f64; 2]; 3],
        /// α0, α1.
        alpha: [f64; 2],
        /// r_θ.
        ratio: f64,
        /// Samples asked of the result.
        samples: usize,
    },
    /// `CompoundCurve::from_four_points`.
    Compound4 {
        /// P0..P3.
        points: [[f64; 2]; 4],
        /// α0, α1.
        alpha: [f64; 2],
        /// Samples asked of the result.
        samples: usize,
    },
    /// `RationalCubic::curvature_monotonicity`.
    Monotone {
        /// b0..b3.
        points: [[f64; 2]; 4],
        /// w0..w3.
        weights: [f64; 4],
    },
    /// `curvature_plot` and `log_curvature_graph` of a chain of rational cubics.
    Analysis {
        /// Each piece's control points and weights.
        pieces: Vec<([[f64; 2]; 4], [f64; 4])>,
        /// Points per piece.
        per_piece: usize,
    },
    /// The quasi-aesthetic fits of a segment: the seed's single rational cubic, and
    /// rational and plain chains within a relative tolerance.
    Quasi {
        /// P0, P1, P2.
        points: [[f64; 2]; 3],
        /// α.
        alpha: f64,
        /// Relative tolerance (None: the seed's single piece).
        tolerance: Option<f64>,
        /// Plain cubics.
        cubic: bool,
    },
    /// `Path::g1` / `Path::g2` from a control polygon.
    Path {
        /// The polygon's vertices.
        points: Vec<[f64; 2]>,
        /// One α for every segment, or one per segment.
        alpha: Vec<f64>,
        /// A closed polygon.
        closed: bool,
        /// Curvature continuous at the joints (else joints at the leg midpoints).
        g2: bool,
    },
    /// `Spline::from_points_with` through points, with point types.
    Spline {
        /// The points it passes through.
        points: Vec<[f64; 2]>,
        /// α.
        alpha: f64,
        /// A closed spline.
        closed: bool,
        /// An open spline's end tangent directions (None: the circles').
        ends: Option<[f64; 2]>,
        /// Each point's type, `s`, `t` or `c` (empty: every point smooth).
        #[serde(default)]
        types: Vec<String>,
        /// Each point's given directions (a tangent point's first; a corner's in and out).
        #[serde(default)]
        angles: Vec<[Option<f64>; 2]>,
        /// The straight spans.
        #[serde(default)]
        lines: Vec<usize>,
        /// An open spline's end curvatures.
        #[serde(default)]
        curvatures: [Option<f64>; 2],
    },
    /// `SpaceSegment::from_control_points`.
    Space {
        /// P0..P3.
        points: [[f64; 3]; 4],
        /// α, β, Ω.
        alpha: f64,
        /// β.
        beta: f64,
        /// Ω.
        omega: f64,
        /// 1 or 2.
        torsion: u8,
    },
    /// `Fit::from_points`: a log-aesthetic path fitted to points.
    Fit {
        /// The points, in order.
        points: Vec<[f64; 2]>,
        /// The largest distance allowed (None: `max_segments` segments by least squares).
        tolerance: Option<f64>,
        /// The number of segments, or the most with a tolerance.
        max_segments: usize,
        /// Every segment's α, fixed (None: fitted in the default range).
        alpha: Option<f64>,
        /// A closed fit.
        closed: bool,
        /// Tangent continuity only.
        g1: bool,
        /// The ends held on the first and last points.
        pin_ends: bool,
        /// Huber's δ (None: least squares).
        huber: Option<f64>,
        /// A weight per point.
        weights: Option<Vec<f64>>,
    },
    /// `lac_export::export` of a solved curve: a segment, compound curve, path or space
    /// segment, in one of the file formats.
    Export {
        /// The curve, as the input that solves it (its sampling fields are not used).
        curve: Box<Input>,
        /// The file format.
        format: Format,
        /// The tolerance asked.
        tolerance: f64,
        /// The tolerance is relative to the arc length (else model units).
        relative: bool,
        /// One curve per piece.
        single_spans: bool,
    },
}

/// A fit is drawn this many times less often than the other entry points
/// ([`EntryPoint::count`]).
pub const FIT_SHARE: u64 = 100;

/// The entry points the harness drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EntryPoint {
    /// Segments from three points, with evaluation and sampling.
    Segment,
    /// Compound curves from three points and a ratio.
    Compound3,
    /// Compound curves from four points.
    Compound4,
    /// The monotonicity test.
    Monotone,
    /// Curvature plots and logarithmic curvature graphs of Bézier chains.
    Analysis,
    /// Quasi-aesthetic fits.
    Quasi,
    /// Space segments.
    Space,
    /// Paths from a control polygon.
    Path,
    /// CAD export of solved curves.
    Export,
    /// G2 splines through points.
    Spline,
    /// Paths fitted to points.
    Fit,
}

impl EntryPoint {
    /// Every entry point.
    pub const ALL: [EntryPoint; 11] = [
        EntryPoint::Segment,
        EntryPoint::Compound3,
        EntryPoint::Compound4,
        EntryPoint::Monotone,
        EntryPoint::Analysis,
        EntryPoint::Quasi,
        EntryPoint::Space,
        EntryPoint::Path,
        EntryPoint::Export,
        EntryPoint::Spline,
        EntryPoint::Fit,
    ];

    /// Its name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            EntryPoint::Segment => "segment",
            EntryPoint::Compound3 => "compound3",
            EntryPoint::Compound4 => "compound4",
            EntryPoint::Monotone => "monotone",
            EntryPoint::Analysis => "analysis",
            EntryPoint::Quasi => "quasi",
            EntryPoint::Space => "space",
            EntryPoint::Path => "path",
            EntryPoint::Export => "export",
            EntryPoint::Spline => "spline",
            EntryPoint::Fit => "fit",
        }
    }

    /// How many inputs a run of `count` per entry point draws for this one: all of them,
    /// but for a fit (which costs about a hundred times a segment, and more with thousands
    /// of points) one in [`FIT_SHARE`], at least ten.
    pub fn count(self, count: u64) -> u64 {
        match self {
            EntryPoint::Fit => count.div_ceil(FIT_SHARE).max(count.min(10)),
            _ => count,
        }
    }

    /// The entry point called `name`.
    pub fn from_name(name: &str) -> Option<EntryPoint> {
        EntryPoint::ALL.into_iter().find(|e| e.name() == name)
    }

    /// The `index`-th input of the stream for `seed`.
    pub fn input(self, seed: u64, index: u64) -> Input {
        let mut rng = Rng::new(
            seed ^ (self as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15),
            index,
        );
        self.generate(&mut rng)
    }

    /// The input a coverage-guided fuzzer's byte string stands for: its first byte picks
    /// the entry point, the rest steer that entry point's generator (see
    /// [`Rng::from_bytes`]).
    pub fn input_from_bytes(bytes: &[u8]) -> Input {
        let (first, rest) = bytes.split_first().unwrap_or((&0, &[]));
        let entry = EntryPoint::ALL[usize::from(*first) % EntryPoint::ALL.len()];
        entry.generate(&mut Rng::from_bytes(rest))
    }

    /// An input of this entry point, drawn from `rng`.
    pub fn generate(self, rng: &mut Rng) -> Input {
        match self {
            EntryPoint::Segment => generate::segment(rng),
            EntryPoint::Compound3 => generate::compound3(rng),
            EntryPoint::Compound4 => generate::compound4(rng),
            EntryPoint::Monotone => generate::monotone(rng),
            EntryPoint::Analysis => generate::analysis(rng),
            EntryPoint::Quasi => generate::quasi(rng),
            EntryPoint::Space => generate::space(rng),
            EntryPoint::Path => generate::path(rng),
            EntryPoint::Export => generate::export(rng),
            EntryPoint::Spline => generate::spline(rng),
            EntryPoint::Fit => generate::fit(rng),
        }
    }
}

/// What one call gave.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// An answer that met every invariant.
    Ok,
    /// A typed error.
    Refused,
    /// An answer that broke an invariant: what was wrong.
    Violation(String),
    /// The call panicked: its message.
    Panic(String),
}

/// Run one input and check its answer.
pub fn run(input: &Input) -> (Outcome, Duration) {
    let start = Instant::now();
    let outcome = catch_unwind(AssertUnwindSafe(|| checks::check(input)));
    let elapsed = start.elapsed();
    let outcome = match outcome {
        Ok(Ok(true)) => Outcome::Ok,
        Ok(Ok(false)) => Outcome::Refused,
        Ok(Err(why)) => Outcome::Violation(why),
        Err(payload) => Outcome::Panic(
            payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "a panic without a message".to_string()),
        ),
    };
    (outcome, elapsed)
}

/// The figures of a run over one entry point.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Inputs tried.
    pub tried: u64,
    /// Answers that met every invariant.
    pub ok: u64,
    /// Typed errors.
    pub refused: u64,
    /// Invariant violations, with their inputs (the first few kept).
    pub violations: Vec<(Input, String)>,
    /// How many violations in all.
    pub violation_count: u64,
    /// Panics, with their inputs (the first few kept).
    pub panics: Vec<(Input, String)>,
    /// How many panics in all.
    pub panic_count: u64,
    /// The slowest call and its input.
    pub slowest: Option<(Duration, Input)>,
    /// Calls over one second.
    pub over_one_second: u64,
}

impl Stats {
    fn add(&mut self, input: Input, outcome: Outcome, elapsed: Duration) {
        const KEEP: usize = 20;
        self.tried += 1;
        match outcome {
            Outcome::Ok => self.ok += 1,
            Outcome::Refused => self.refused += 1,
            Outcome::Violation(why) => {
                self.violation_count += 1;
                if self.violations.len() < KEEP {
                    self.violations.push((input.clone(), why));
                }
            }
            Outcome::Panic(why) => {
                self.panic_count += 1;
                if self.panics.len() < KEEP {
                    self.panics.push((input.clone(), why));
                }
            }
        }
        if elapsed > Duration::from_secs(1) {
            self.over_one_second += 1;
        }
        if self.slowest.as_ref().is_none_or(|(d, _)| elapsed > *d) {
            self.slowest = Some((elapsed, input));
        }
    }

    fn merge(mut self, other: Stats) -> Stats {
        self.tried += other.tried;
        self.ok += other.ok;
        self.refused += other.refused;
        self.violation_count += other.violation_count;
        self.panic_count += other.panic_count;
        self.over_one_second += other.over_one_second;
        self.violations.extend(other.violations);
        self.violations.truncate(20);
        self.panics.extend(other.panics);
        self.panics.truncate(20);
        if let Some((d, i)) = other.slowest {
            if self.slowest.as_ref().is_none_or(|(e, _)| d > *e) {
                self.slowest = Some((d, i));
            }
        }
        self
    }

    /// Did every input pass (no panic, no violation, nothing over a second)?
    pub fn clean(&self) -> bool {
        self.panic_count == 0 && self.violation_count == 0 && self.over_one_second == 0
    }

    /// One line of figures.
    pub fn summary(&self, entry: EntryPoint) -> String {
        format!(
            "{:<10} tried {:>9}  ok {:>9}  refused {:>9}  violations {:>6}  panics {:>4}  \
             over 1 s {:>3}  slowest {:>9.3} ms",
            entry.name(),
            self.tried,
            self.ok,
            self.refused,
            self.violation_count,
            self.panic_count,
            self.over_one_second,
            self.slowest
                .as_ref()
                .map_or(0.0, |(d, _)| d.as_secs_f64() * 1e3),
        )
    }
}

/// Run `entry.count(count)` inputs of `entry` from `seed` (`count`, or a share of it for the
/// dearer entry points: [`EntryPoint::count`]), in parallel, calling `progress` with the
/// number done now and then.
pub fn campaign(
    entry: EntryPoint,
    seed: u64,
    count: u64,
    progress: &(dyn Fn(u64) + Sync),
) -> Stats {
    use rayon::prelude::*;
    let count = entry.count(count);
    const CHUNK: u64 = 1000;
    let chunks = count.div_ceil(CHUNK);
    let done = std::sync::atomic::AtomicU64::new(0);
    (0..chunks)
        .into_par_iter()
        .map(|c| {
            let mut stats = Stats::default();
            for i in c * CHUNK..((c + 1) * CHUNK).min(count) {
                let input = entry.input(seed, i);
                let (outcome, elapsed) = run(&input);
                stats.add(input, outcome, elapsed);
            }
            let n = done.fetch_add(stats.tried, std::sync::atomic::Ordering::Relaxed);
            progress(n + stats.tried);
            stats
        })
        .reduce(Stats::default, Stats::merge)
}

/// Replay kept inputs (one JSON [`Input`] per line; `#` comments and blank lines skipped).
pub fn replay(lines: &str) -> Vec<(Input, Outcome)> {
    lines
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .map(|l| {
            let input: Input = serde_json::from_str(l)
                .unwrap_or_else(|e| panic!("a regression line does not parse ({e}): {l}"));
            let (outcome, _) = run(&input);
            (input, outcome)
        })
        .collect()
}
