//! Sampling a segment: equally in arc length, equally in tangent angle, adaptively to a
//! chordal tolerance; and its evolute.
//!
//! Positions between consecutive samples come from the two-point Hermite (Obreshkov)
//! quadrature of f(s) = e^{iθ(s)}, whose derivatives at a sample are algebraic in κ, κ′, κ″:
//! `∫₀ʰ f = h/2 (f₀+f₁) + 3h²/28 (f₀′−f₁′) + h³/84 (f₀″+f₁″) + h⁴/1680 (f₀‴−f₁‴)`,
//! exact for degree 7. The same rule with one derivative fewer estimates the error; where
//! the two differ by more than 3e-11·h (strong curvature variation between samples) the
//! interval is halved (and integrated by the general quadrature after 12 halvings). So a sample costs one
//! evaluation of θ and κ, which the output needs anyway, and no extra quadrature nodes.

use kurbo::{Point, Vec2};

use crate::error::{Error, Result};
use crate::integrate::integrate;
use crate::numeric::{expm1_ratio, ln1p_ratio, Complex};
use crate::segment::Segment;
use crate::standard_form::{StandardForm, Station};

/// One sample of a segment, in the caller's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Arc length from the first control point.
    pub s: f64,
    /// Position.
    pub point: Point,
    /// Tangent direction, radians, continuous from the first control point.
    pub theta: f64,
    /// Signed curvature (positive for a left turn).
    pub kappa: f64,
}

impl Sample {
    /// The unit tangent (cos θ, sin θ).
    pub fn tangent(&self) -> Vec2 {
        Vec2::from_angle(self.theta)
    }
}

/// Largest number of samples any sampling call returns.
const MAX_SAMPLES: usize = 10_000_000;

impl Segment {
    /// `n ≥ 2` samples equally spaced in arc length, the first at the first control point
    /// and the last at the last.
    pub fn sample_by_arc_length(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        // Standard-form arc length between samples; each sample is placed from the nearer
        // end, where ρ is known exactly (see `Segment::station_at_s`).
        let step = (self.last.s - self.first.s) / (n - 1) as f64;
        let (head, tail) = (
            Anchor::new(&self.form, self.first),
            Anchor::new(&self.form, self.last),
        );
        let half = (n - 1) / 2;
        let nodes: Vec<Node> = (0..n)
            .map(|i| {
                let node = if i <= half {
                    head.advance_s(&self.form, i as f64 * step)
                } else {
                    tail.advance_s(&self.form, -((n - 1 - i) as f64) * step)
                };
                node.ok_or(Error::OutOfRange {
                    name: "samples",
                    value: n as f64,
                    expected: "a sample count whose stations stay inside the curve",
                })
            })
            .collect::<Result<_>>()?;
        Ok(self.samples_at_nodes(&nodes))
    }

    /// `n ≥ 2` samples equally spaced in tangent angle, ends included.
    pub fn sample_by_tangent_angle(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        let sign = if self.left { 1.0 } else { -1.0 };
        let step = sign * self.turning / (n - 1) as f64;
        let stations: Vec<Station> = (0..n)
            .map(|i| {
                if i == n - 1 {
                    Ok(self.last)
                } else {
                    self.station_at_theta(self.theta_first + i as f64 * step)
                }
            })
            .collect::<Result<_>>()?;
        Ok(self.samples_at(&stations))
    }

    /// Samples such that the polyline through them stays within `tolerance` (caller's
    /// units) of the curve. Each span is split at its point of largest deviation, where the
    /// tangent is parallel to the chord, until that deviation is within tolerance.
    pub fn sample_adaptive(&self, tolerance: f64) -> Result<Vec<Sample>> {
        let len = self.arc_length();
        if !(tolerance.is_finite() && tolerance >= 1e-14 * len) {
            return Err(Error::OutOfRange {
                name: "tolerance",
                value: tolerance,
                expected: "a finite tolerance of at least 1e-14 times the arc length",
            });
        }
        let scaled = tolerance / self.scale();
        let mut out = vec![(self.first, Complex::ZERO)];
        let mut stack = vec![(self.last, self.chord)];
        let mut current = (self.first, Complex::ZERO);
        // Depth-first: the stack holds the right ends still to reach.
        while let Some(&(end, end_z)) = stack.last() {
            let (start, start_z) = current;
            let chord = end_z - start_z;
            let split = self.deviation_point(&start, &end, chord);
            match split {
                Some((st, z, dev)) if dev > scaled && out.len() + stack.len() < MAX_SAMPLES => {
                    stack.push((st, start_z + z));
                }
                _ => {
                    stack.pop();
                    out.push((end, end_z));
                    current = (end, end_z);
                }
            }
        }
        Ok(out
            .iter()
            .map(|(st, z)| self.sample_from_station(st, *z))
            .collect())
    }

    /// `n ≥ 2` points of the evolute (the locus of centres of curvature), at the arc-length
    /// samples: `P + N/κ` with N the left normal.
    pub fn evolute(&self, n: usize) -> Result<Vec<Point>> {
        Ok(self
            .sample_by_arc_length(n)?
            .iter()
            .map(|s| s.point + s.tangent().turn_90() * (1.0 / s.kappa))
            .collect())
    }

    /// The point between two stations where the tangent is parallel to the chord, its
    /// offset from `a`, and its distance from the chord (standard-form units).
    fn deviation_point(
        &self,
        a: &Station,
        b: &Station,
        chord: Complex,
    ) -> Option<(Station, Complex, f64)> {
        let chord_dir = chord.arg();
        // Standard-form tangent angle at which the tangent is parallel to the chord.
        let base = if self.dir() > 0.0 {
            0.0
        } else {
            std::f64::consts::PI
        };
        let mut target = chord_dir + base;
        // Bring it into the span [a.theta, b.theta].
        let (lo, hi) = (a.theta.min(b.theta), a.theta.max(b.theta));
        let tau = std::f64::consts::TAU;
        while target > hi + 1e-9 {
            target -= tau;
        }
        while target < lo - 1e-9 {
            target += tau;
        }
        let target = target.clamp(lo, hi);
        let st = self.form.advance_theta(a, target - a.theta)?;
        let z = span(self, a, &st);
        let dev = (chord.conj() * z).im.abs() / chord.norm();
        (hi - lo > 0.0).then_some((st, z, dev))
    }

    /// Samples at `stations`, positions accumulated from the first one.
    pub(crate) fn samples_at(&self, stations: &[Station]) -> Vec<Sample> {
        let nodes: Vec<Node> = stations
            .iter()
            .map(|st| Node::new(&self.form, *st))
            .collect();
        self.samples_at_nodes(&nodes)
    }

    fn samples_at_nodes(&self, nodes: &[Node]) -> Vec<Sample> {
        let mut z = self.offset_of(&nodes[0].st);
        let mut out = Vec::with_capacity(nodes.len());
        let mut prev = &nodes[0];
        let mut prev_jet = self.jet_of(prev);
        out.push(self.sample_from(prev, z));
        for node in &nodes[1..] {
            let jet = self.jet_of(node);
            z += self.hermite(prev, node, &prev_jet, &jet, 0);
            out.push(self.sample_from(node, z));
            prev = node;
            prev_jet = jet;
        }
        out
    }

    fn sample_from(&self, node: &Node, z: Complex) -> Sample {
        let k = node.kappa / self.scale();
        Sample {
            s: self.s_of(&node.st),
            point: self.caller_point(z),
            theta: self.theta_of(&node.st),
            kappa: if self.left { k } else { -k },
        }
    }

    fn sample_from_station(&self, st: &Station, z: Complex) -> Sample {
        self.sample_from(&Node::new(&self.form, *st), z)
    }

    /// f = e^{iθ} and its first three derivatives in standard-form arc length.
    pub(crate) fn jet(&self, st: &Station) -> [Complex; 4] {
        self.jet_of(&Node::new(&self.form, *st))
    }

    fn jet_of(&self, node: &Node) -> [Complex; 4] {
        let (alpha, lambda) = (self.form.alpha, self.form.lambda);
        let f = Complex::cis(node.st.theta);
        let (k, q) = (node.kappa, node.q);
        let k1 = -lambda * k * q;
        let k2 = lambda * lambda * (1.0 + alpha) * k * q * q;
        [
            f,
            f * Complex::new(0.0, k),
            f * Complex::new(-k * k, k1),
            f * Complex::new(-3.0 * k * k1, k2 - k * k * k),
        ]
    }

    /// ∫ e^{iθ} ds from `a` to `b` by the Hermite rule, halving the interval where the
    /// error estimate is too large, and by the general quadrature after 12 halvings.
    fn hermite(
        &self,
        a: &Node,
        b: &Node,
        ja: &[Complex; 4],
        jb: &[Complex; 4],
        depth: u32,
    ) -> Complex {
        let h = b.st.s - a.st.s;
        let (h2, h3, h4) = (h * h, h * h * h, h * h * h * h);
        let sum0 = (ja[0] + jb[0]).scale(0.5 * h);
        let d1 = ja[1] - jb[1];
        let s2 = ja[2] + jb[2];
        let d3 = ja[3] - jb[3];
        let order7 = sum0 + d1.scale(3.0 * h2 / 28.0) + s2.scale(h3 / 84.0) + d3.scale(h4 / 1680.0);
        let order5 = sum0 + d1.scale(h2 / 10.0) + s2.scale(h3 / 120.0);
        // The order-5 rule's error is |order7 − order5|; order 7's is smaller by about
        // (hκ)²/250 ≤ 1e-4 whenever that difference is below 3e-11·h (hκ ≤ 0.16).
        if (order7 - order5).norm_sqr() <= 9e-22 * h * h {
            return order7;
        }
        let mid = match self.form.advance_s(&a.st, 0.5 * h) {
            Some(st) if depth < 12 => Node::new(&self.form, st),
            _ => return span(self, &a.st, &b.st),
        };
        let jm = self.jet_of(&mid);
        self.hermite(a, &mid, ja, &jm, depth + 1) + self.hermite(&mid, b, &jm, jb, depth + 1)
    }
}

/// P(b) − P(a) in the standard form by the general quadrature.
fn span(seg: &Segment, a: &Station, b: &Station) -> Complex {
    if a.theta <= b.theta {
        integrate(&seg.form, a, b, false).value
    } else {
        -integrate(&seg.form, b, a, false).value
    }
}

fn check_count(n: usize) -> Result<()> {
    if (2..=MAX_SAMPLES).contains(&n) {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            name: "samples",
            value: n as f64,
            expected: "between 2 and 10000000 samples",
        })
    }
}

/// A station with its curvature κ = 1/ρ and q = ρ^(−α), the quantities of the jet.
struct Node {
    st: Station,
    kappa: f64,
    q: f64,
}

impl Node {
    fn new(form: &StandardForm, st: Station) -> Self {
        Node {
            st,
            kappa: st.kappa(),
            q: (-form.alpha * st.ln_rho).exp(),
        }
    }
}

/// A segment end from which samples are placed by arc length: `StandardForm::advance_s`
/// with ρ^α and κ at the anchor computed once, and q of the new point obtained
/// algebraically (ρ^α is linear in s).
struct Anchor {
    st: Station,
    v: f64,
    kappa: f64,
}

impl Anchor {
    fn new(form: &StandardForm, st: Station) -> Self {
        Anchor {
            st,
            v: (form.alpha * st.ln_rho).exp(),
            kappa: st.kappa(),
        }
    }

    fn advance_s(&self, form: &StandardForm, d_s: f64) -> Option<Node> {
        let (a, l) = (form.alpha, form.lambda);
        let t = l * d_s / self.v;
        let x = a * t;
        if x <= -1.0 || x.is_nan() {
            return None;
        }
        let lr = ln1p_ratio(x);
        let d_ln_rho = t * lr;
        let ln_rho = self.st.ln_rho + d_ln_rho;
        let kappa = (-ln_rho).exp();
        // e^{(α−1)Δu} = (1 + x)·κ/κ_anchor; its expm1 from that product is accurate
        // (within 4 ulp) once |(α−1)Δu| > 1/4, which saves a transcendental per sample.
        let y = (a - 1.0) * d_ln_rho;
        let ratio = if y.abs() > 0.25 {
            ((1.0 + x) * kappa / self.kappa - 1.0) / y
        } else {
            expm1_ratio(y)
        };
        let d_theta = self.kappa * d_s * lr * ratio;
        Some(Node {
            st: Station {
                theta: self.st.theta + d_theta,
                s: self.st.s + d_s,
                ln_rho,
            },
            kappa,
            q: 1.0 / (self.v + l * a * d_s),
        })
    }
}
