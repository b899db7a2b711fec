//! Sampling a segment: equally in arc length, equally in tangent angle, adaptively to a
//! chordal tolerance; and its evolute.
//!
//! Positions between consecutive samples come from the two-point Hermite (Obreshkov)
//! quadrature of f(s) = e^{iθ(s)} with derivatives up to the fifth,
//! `∫₀ʰ f = Σₖ cₖ hᵏ⁺¹ (f₀⁽ᵏ⁾ + (−1)ᵏ f₁⁽ᵏ⁾)`, c = (1/2, 5/44, 1/66, 1/792, 1/15840,
//! 1/665280), exact for degree 11 (coefficients from `tools/reference/hermite_rule.py`).
//! The derivatives are algebraic: κ⁽ʲ⁾ = κ (Λρ^(−α))ʲ Πᵢ₍ᵢ<ⱼ₎ −(1 + iα), and
//! f⁽ⁿ⁺¹⁾ = i Σⱼ C(n, j) κ⁽ʲ⁾ f⁽ⁿ⁻ʲ⁾. The order-9 rule (one derivative fewer) estimates the
//! error; where the two differ by more than 1e-11·h (strong curvature variation between
//! samples, e.g. near ρ = 0 for α > 1) the interval is halved, and after 12 halvings it is
//! integrated by the general quadrature. So a sample costs one
//! evaluation of θ and κ, which the output needs anyway, and no extra quadrature nodes.

use crate::family::sample::{check_count, Sample, MAX_ADAPTIVE_SAMPLES};
use crate::family::standard_form::integrate::integrate;
use crate::family::standard_form::{StandardForm, Station};
use crate::foundation::error::{Error, Result};
use crate::foundation::numeric::{expm1_ratio, ln1p_ratio, Complex};
use crate::segment::Segment;

impl Segment {
    /// Samples at the given ascending arc lengths within the segment (caller's units,
    /// within [0, length]).
    pub(crate) fn samples_at_local(&self, at: &[f64]) -> Result<Vec<Sample>> {
        if at.is_empty() {
            return Ok(Vec::new());
        }
        // Each sample is placed from the nearer end, where ρ is known exactly (see
        // `Segment::station_at_s`), in standard-form arc length; the ends themselves are
        // the solved stations (each anchor is made when a sample first needs it).
        let (len, k) = (self.length(), self.dir() / self.scale());
        let (mut head, mut tail) = (None, None);
        let nodes: Vec<Node> = at
            .iter()
            .map(|&s| {
                let node = if s == 0.0 {
                    Some(Node::new(self.first))
                } else if s == len {
                    Some(Node::new(self.last))
                } else if s <= 0.5 * len {
                    head.get_or_insert_with(|| Anchor::new(&self.form, self.first))
                        .advance_s(&self.form, k * s)
                } else {
                    tail.get_or_insert_with(|| Anchor::new(&self.form, self.last))
                        .advance_s(&self.form, -k * (len - s))
                };
                node.ok_or(Error::NumericalFailure {
                    what: "a sample of the segment",
                })
            })
            .collect::<Result<_>>()?;
        Ok(self.samples_at_nodes(&nodes))
    }

    /// `n ≥ 2` samples equally spaced in tangent angle, ends included.
    pub fn sample_by_tangent_angle(&self, n: usize) -> Result<Vec<Sample>> {
        check_count(n)?;
        let step = self.turn.sign() * self.turning / (n - 1) as f64;
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

    /// Samples such that the polyline through them stays within `accuracy` (caller's
    /// units) of the curve. Each span is split at its point of largest deviation, where the
    /// tangent is parallel to the chord, until that deviation is within tolerance.
    pub(crate) fn adaptive_samples(&self, accuracy: f64) -> Result<Vec<Sample>> {
        let len = self.length();
        if !(accuracy.is_finite() && accuracy >= 1e-14 * len) {
            return Err(Error::OutOfRange {
                name: "accuracy",
                value: accuracy,
                expected: "a finite distance of at least 1e-14 times the arc length",
            });
        }
        let scaled = accuracy / self.scale();
        let mut out = vec![(self.first, Complex::ZERO)];
        let mut stack = vec![(self.last, self.chord)];
        let mut current = (self.first, Complex::ZERO);
        // Depth-first: the stack holds the right ends still to reach.
        while let Some(&(end, end_z)) = stack.last() {
            let (start, start_z) = current;
            let chord = end_z - start_z;
            let split = self.deviation_point(&start, &end, chord);
            match split {
                // A deviation that is not a number splits too: never taken as flat.
                Some((st, z, dev)) if dev.is_nan() || dev > scaled => {
                    if out.len() + stack.len() >= 2 * MAX_ADAPTIVE_SAMPLES {
                        // The estimate in `Curve::sample_adaptive` keeps this from happening;
                        // a polyline short of the accuracy asked is never returned.
                        return Err(Error::OutOfRange {
                            name: "accuracy",
                            value: accuracy,
                            expected: "an accuracy reachable with at most 50000 samples",
                        });
                    }
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
        let target = crate::foundation::numeric::clamp(target, lo, hi);
        let st = self.form.advance_theta(a, target - a.theta)?;
        let z = span(self, a, &st);
        // Across the unit chord: the product of two standard-form lengths would overflow
        // for curves whose standard form is ~1e216 long (a hook of radius 1e-216).
        let dev = (chord.scale(1.0 / chord.norm()).conj() * z).im.abs();
        (hi - lo > 0.0).then_some((st, z, dev))
    }

    /// Samples at `stations`, positions accumulated from the first one.
    pub(crate) fn samples_at(&self, stations: &[Station]) -> Vec<Sample> {
        let nodes: Vec<Node> = stations.iter().map(|st| Node::new(*st)).collect();
        self.samples_at_nodes(&nodes)
    }

    fn samples_at_nodes(&self, nodes: &[Node]) -> Vec<Sample> {
        let mut z = self.offset_of(&nodes[0].st);
        let mut out = Vec::with_capacity(nodes.len());
        let mut prev = &nodes[0];
        // (Not needed when the only other sample is the last point.)
        let mut prev_jet = None;
        out.push(self.sample_from(prev, z));
        for node in &nodes[1..] {
            if node.st == self.last {
                // The last point's offset is the solved chord: nothing to integrate.
                out.push(self.sample_from(node, self.chord));
                continue;
            }
            let jet = self.jet_of(node);
            let from = *prev_jet.get_or_insert_with(|| self.jet_of(prev));
            z += self.hermite(prev, node, &from, &jet, 0);
            out.push(self.sample_from(node, z));
            prev = node;
            prev_jet = Some(jet);
        }
        out
    }

    fn sample_from(&self, node: &Node, z: Complex) -> Sample {
        let k = node.kappa / self.scale();
        Sample {
            s: self.s_of(&node.st),
            point: self.caller_point(z),
            theta: self.theta_of(&node.st),
            kappa: self.turn.sign() * k,
        }
    }

    fn sample_from_station(&self, st: &Station, z: Complex) -> Sample {
        self.sample_from(&Node::new(*st), z)
    }

    /// f = e^{iθ} and its first five derivatives in standard-form arc length.
    pub(crate) fn jet(&self, st: &Station) -> Jet {
        self.jet_of(&Node::new(*st))
    }

    fn jet_of(&self, node: &Node) -> Jet {
        let alpha = self.form.alpha;
        let q = node.q.unwrap_or_else(|| (-alpha * node.st.ln_rho).exp());
        let r = self.form.lambda * q; // −κ′/κ
                                      // κ⁽ʲ⁾ = κ (−r)ʲ Πᵢ₍ᵢ<ⱼ₎ (1 + iα), j = 0..4.
        let k0 = node.kappa;
        let k1 = -k0 * r;
        let k2 = -k1 * r * (1.0 + alpha);
        let k3 = -k2 * r * (1.0 + 2.0 * alpha);
        let k4 = -k3 * r * (1.0 + 3.0 * alpha);
        let f = Complex::cis(node.st.theta);
        let g = derivative_factors([k0, k1, k2, k3, k4]);
        g.map(|gn| f * gn)
    }

    /// ∫ e^{iθ} ds from `a` to `b` by the Hermite rule, halving the interval where the
    /// error estimate is too large, and by the general quadrature after 12 halvings.
    fn hermite(&self, a: &Node, b: &Node, ja: &Jet, jb: &Jet, depth: u32) -> Complex {
        let h = b.st.s - a.st.s;
        let (mut order11, mut order9) = hermite_rules(ja, jb, h, Powers::Direct);
        let mut estimate = (order11 - order9).norm_max();
        if !estimate.is_finite() {
            // hᵏ⁺¹ overflows (or the jets underflow) although their product need not: a
            // standard form whose lengths reach 1e60 where the curvature is 1e-64 (α near
            // 1, Λ ~ 1e4). Multiplied term by term instead.
            (order11, order9) = hermite_rules(ja, jb, h, Powers::Stepwise);
            estimate = (order11 - order9).norm_max();
        }
        // The order-9 rule's error is about |order11 − order9|; order 11's is smaller by
        // about (hκ)²/600, and a difference below 1e-11·h implies hκ < 0.85.
        if estimate <= 0.7e-11 * h.abs() {
            return order11;
        }
        if !estimate.is_finite() {
            // Halving cannot mend an undefined estimate (it would only repeat it 4096 times).
            return span(self, &a.st, &b.st);
        }
        let mid = match self.form.advance_s(&a.st, 0.5 * h) {
            Some(st) if depth < 12 => Node::new(st),
            _ => return span(self, &a.st, &b.st),
        };
        let jm = self.jet_of(&mid);
        self.hermite(a, &mid, ja, &jm, depth + 1) + self.hermite(&mid, b, &jm, jb, depth + 1)
    }
}

/// How [`hermite_rules`] forms `(f₀⁽ᵏ⁾ ± f₁⁽ᵏ⁾)·hᵏ⁺¹`.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Powers {
    /// With hᵏ⁺¹ formed first: fast, and exact unless hᵏ⁺¹ leaves double range.
    Direct,
    /// Multiplying by h one factor at a time, so that the product stays in range whenever
    /// hκ does not exceed about 1.
    Stepwise,
}

/// The order-11 and order-9 Hermite rules for ∫ f over an interval of length `h`, from the
/// jets (f and its first five derivatives) at its ends.
fn hermite_rules(ja: &Jet, jb: &Jet, h: f64, powers: Powers) -> (Complex, Complex) {
    const ORDER_11: [f64; 6] = [
        1.0 / 2.0,
        5.0 / 44.0,
        1.0 / 66.0,
        1.0 / 792.0,
        1.0 / 15840.0,
        1.0 / 665280.0,
    ];
    const ORDER_9: [f64; 5] = [
        1.0 / 2.0,
        1.0 / 9.0,
        1.0 / 72.0,
        1.0 / 1008.0,
        1.0 / 30240.0,
    ];
    let (mut order11, mut order9) = (Complex::ZERO, Complex::ZERO);
    let mut hk = h;
    for k in 0..6 {
        // (f₀⁽ᵏ⁾ + (−1)ᵏ f₁⁽ᵏ⁾)·hᵏ⁺¹
        let sum = if k % 2 == 0 {
            ja[k] + jb[k]
        } else {
            ja[k] - jb[k]
        };
        let term = match powers {
            Powers::Direct => sum.scale(hk),
            Powers::Stepwise => (0..=k).fold(sum, |t, _| t.scale(h)),
        };
        order11 += term.scale(ORDER_11[k]);
        if k < 5 {
            order9 += term.scale(ORDER_9[k]);
        }
        hk *= h;
    }
    (order11, order9)
}

/// P(b) − P(a) in the standard form by the general quadrature.
fn span(seg: &Segment, a: &Station, b: &Station) -> Complex {
    if a.theta <= b.theta {
        integrate(&seg.form, a, b, false).value
    } else {
        -integrate(&seg.form, b, a, false).value
    }
}

/// g₀..g₅ with f⁽ⁿ⁾ = gₙ·e^{iθ} for f = e^{iθ(s)}, θ′ = κ, given κ⁽ʲ⁾ for j = 0..4: the
/// expansion of gₙ₊₁ = i Σⱼ C(n, j) κ⁽ʲ⁾ gₙ₋ⱼ, written out.
#[inline]
fn derivative_factors([k0, k1, k2, k3, k4]: [f64; 5]) -> [Complex; 6] {
    let k00 = k0 * k0;
    [
        Complex::new(1.0, 0.0),
        Complex::new(0.0, k0),
        Complex::new(-k00, k1),
        Complex::new(-3.0 * k0 * k1, k2 - k00 * k0),
        Complex::new(
            k00 * k00 - 4.0 * k0 * k2 - 3.0 * k1 * k1,
            k3 - 6.0 * k00 * k1,
        ),
        Complex::new(
            10.0 * k00 * k0 * k1 - 5.0 * k0 * k3 - 10.0 * k1 * k2,
            k00 * k00 * k0 - 10.0 * k00 * k2 - 15.0 * k0 * k1 * k1 + k4,
        ),
    ]
}

/// f = e^{iθ} and its derivatives of orders 0 to 5 at a station.
pub(crate) type Jet = [Complex; 6];

/// A station with its curvature κ = 1/ρ and q = ρ^(−α), the quantities of the jet (q when
/// it came for free; else it is computed when a jet needs it: an end sample needs none).
struct Node {
    st: Station,
    kappa: f64,
    q: Option<f64>,
}

impl Node {
    fn new(st: Station) -> Self {
        Node {
            st,
            kappa: st.kappa(),
            q: None,
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
            q: Some(1.0 / (self.v + l * a * d_s)),
        })
    }
}
