//! Curvature plots and logarithmic curvature graphs of planar curves and Bézier pieces:
//! [`LcgReport`], what `lac lcg` prints (the editor's server answers it too), and
//! [`LcgInput`], what `lac lcg` reads (a space curve's graphs are in `space.rs`). Whether a
//! plot's curvature is monotone is decided in `verdict.rs`.

use lac::SegmentChain;
use lac::{CurvaturePoint, Curve, LcgFit, NotMonotone, RationalCubic};
use serde::{Deserialize, Serialize};

use super::{all_finite, parse, CurveInput, ErrorBody, PiecesInput, Report, SpaceInput};

/// One point of a curvature plot and, where it has one, of the logarithmic curvature graph.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlotRow {
    /// Arc length from the start.
    pub s: f64,
    /// Signed curvature, + for a left turn.
    pub kappa: f64,
    /// dκ/ds.
    pub dkappa_ds: f64,
    /// ln ρ; `null` where κ = 0.
    pub log_rho: Option<f64>,
    /// ln(ρ |ds/dρ|); `null` where κ = 0 or dκ/ds = 0.
    pub log_lcg: Option<f64>,
}

impl From<&CurvaturePoint> for PlotRow {
    fn from(p: &CurvaturePoint) -> Self {
        let graph = p.lcg();
        PlotRow {
            s: p.s,
            kappa: p.kappa,
            dkappa_ds: p.dkappa_ds,
            log_rho: graph.map(|g| g.0),
            log_lcg: graph.map(|g| g.1),
        }
    }
}

/// The line y = alpha x + intercept fitted to a logarithmic curvature graph, over
/// x ∈ log_rho (natural logarithms).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FitRow {
    /// The slope: the α of the log-aesthetic curve that matches best.
    pub alpha: f64,
    /// The value at ln ρ = 0.
    pub intercept: f64,
    /// Root mean square residual, weighted along ln ρ.
    pub rms_residual: f64,
    /// Largest residual.
    pub max_residual: f64,
    /// The range of ln ρ covered.
    pub log_rho: [f64; 2],
}

impl From<&LcgFit> for FitRow {
    fn from(f: &LcgFit) -> Self {
        FitRow {
            alpha: f.alpha,
            intercept: f.intercept,
            rms_residual: f.rms_residual,
            max_residual: f.max_residual,
            log_rho: [f.log_rho.0, f.log_rho.1],
        }
    }
}

/// A curvature plot and logarithmic curvature graph with its fitted line: `lac lcg`'s JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LcgReport {
    /// The plot, equally spaced in arc length (or per Bézier piece).
    pub points: Vec<PlotRow>,
    /// The line fitted to the whole graph; `null` for a circle (no graph) or when the
    /// curvature is not monotone (then `note` says so).
    pub fit: Option<FitRow>,
    /// A curve of several log-aesthetic pieces (a compound curve): each piece's graph with
    /// its own fitted line, in order; absent for one piece and for Bézier pieces.
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub pieces: Vec<PieceFitRow>,
    /// `false` when the curvature is not monotone (its graph is not one line, so `fit` is
    /// `null` and `note` says where); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub monotone: Option<bool>,
    /// Why there is no fitted line although the graph has points.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub note: Option<String>,
}

impl LcgReport {
    /// The plot of `plot` (a log-aesthetic curve's [`Curve::curvature_plot`] or a Bézier
    /// chain's [`lac::curvature_plot`]) with the line fitted to its logarithmic curvature
    /// graph ([`lac::log_curvature_graph`]); no line when the plot shows that the curvature
    /// is not monotone ([`LcgReport::of_pieces`] decides that for Bézier pieces with a
    /// proof).
    pub fn new(plot: &[CurvaturePoint]) -> Self {
        let report = LcgReport::fitted(plot);
        match NotMonotone::of_plot(plot) {
            Some(why) => report.not_monotone(why),
            None => report,
        }
    }
}

impl Report for LcgReport {
    fn is_finite(&self) -> bool {
        self.points.iter().all(|p| {
            all_finite([p.s, p.kappa, p.dkappa_ds])
                && p.log_rho.is_none_or(f64::is_finite)
                && p.log_lcg.is_none_or(f64::is_finite)
        }) && self
            .fit
            .iter()
            .chain(self.pieces.iter().filter_map(|p| p.fit.as_ref()))
            .all(|f| {
                all_finite([f.alpha, f.intercept, f.rms_residual, f.max_residual])
                    && all_finite(f.log_rho)
            })
            && self.pieces.iter().all(|p| all_finite(p.s))
    }
}

/// One log-aesthetic piece's logarithmic curvature graph with its own fitted line, for a
/// curve of several pieces (`lac lcg` of a compound curve).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PieceFitRow {
    /// The piece's arc lengths, [from, to], along the whole curve.
    pub s: [f64; 2],
    /// The line fitted to the piece's graph (its α); `null` for a circular arc.
    pub fit: Option<FitRow>,
}

impl LcgReport {
    /// The plot of a planar log-aesthetic curve at `n` points equally spaced in arc length,
    /// with the line fitted to the whole graph and, for a curve of several pieces, each
    /// piece's line (fitted to `n` points of its own, so that a short piece is measured as
    /// well as a long one).
    pub fn of_curve(curve: &dyn SegmentChain, n: usize) -> Result<Self, ErrorBody> {
        let mut report = LcgReport::new(&curve.curvature_plot(n)?);
        let pieces = curve.pieces();
        if pieces.len() > 1 {
            let ends: Vec<f64> = curve
                .joint_arc_lengths()
                .into_iter()
                .chain([curve.arc_length()])
                .collect();
            let mut start = 0.0;
            for (piece, &end) in pieces.iter().zip(&ends) {
                let graph = lac::log_curvature_graph(&piece.curvature_plot(n)?);
                report.pieces.push(PieceFitRow {
                    s: [start, end],
                    fit: graph.fit.as_ref().map(FitRow::from),
                });
                start = end;
            }
        }
        report.checked()
    }

    /// The plot of a chain of (rational) cubic Bézier pieces, `per_piece` points a piece
    /// equally spaced in t, with the line fitted to its graph; no line when the curvature
    /// is not monotone, which is decided with each piece's proven verdict
    /// ([`RationalCubic::curvature_monotonicity`]), the directions of consecutive pieces and
    /// the jumps at their joints, and the sign of the curvature (an inflection).
    pub fn of_pieces(pieces: &[RationalCubic], per_piece: usize) -> Result<Self, ErrorBody> {
        let plot = lac::curvature_plot(pieces, per_piece)?;
        let verdicts = pieces
            .iter()
            .map(RationalCubic::curvature_monotonicity)
            .collect::<lac::Result<Vec<_>>>()?;
        let report = LcgReport::fitted(&plot);
        let why = NotMonotone::of_chain(pieces, &verdicts)
            .or_else(|| NotMonotone::inflection_of_plot(&plot));
        match why {
            Some(why) => report.not_monotone(why),
            None => report,
        }
        .checked()
    }

    /// The plot and the line fitted to its graph, unchecked.
    fn fitted(plot: &[CurvaturePoint]) -> Self {
        LcgReport {
            points: plot.iter().map(PlotRow::from).collect(),
            fit: lac::log_curvature_graph(plot)
                .fit
                .as_ref()
                .map(FitRow::from),
            pieces: Vec::new(),
            monotone: None,
            note: None,
        }
    }

    /// The report without its line, saying `why` the curvature is not monotone.
    fn not_monotone(self, why: NotMonotone) -> Self {
        LcgReport {
            fit: None,
            monotone: Some(false),
            note: Some(format!(
                "the curvature is not monotone ({why}), so its logarithmic curvature graph \
                 is not one line and no slope alpha is fitted"
            )),
            ..self
        }
    }
}

/// What `lac lcg` reads: Bézier pieces (`lac quasi` output, [`PiecesInput`]), a planar
/// curve (`lac segment` or `lac compound` output, [`CurveInput`]) or a space curve (`lac
/// space` output, [`SpaceInput`]), told apart by their keys: `"pieces"`, `"beta"`,
/// `"alpha0"`/`"alpha1"`, `"alpha"`.
#[derive(Clone, Debug, PartialEq)]
pub enum LcgInput {
    /// A chain of (rational) cubic Bézier pieces.
    Pieces(PiecesInput),
    /// A planar log-aesthetic curve, solved again from its points and slopes.
    Curve(CurveInput),
    /// A space curve, solved again from its points and parameters.
    Space(SpaceInput),
}

impl LcgInput {
    /// The shapes, for error messages.
    pub const SHAPE: &'static str = r#"{"pieces":[{"points":[[x,y],[x,y],[x,y],[x,y]],"weights":[w0,w1,w2,w3]},…]} (weights optional; lac quasi output), a lac segment result {"points":[[x,y]×3],"alpha":A,…}, a lac compound result {"points":[…3 or 4…],"alpha0":A,"alpha1":B,"ratio":R,…} or a lac space result {"points":[[x,y,z]×4],"alpha":A,"beta":B,"omega":W,"type":1,…}"#;

    /// Read one document.
    pub fn parse(text: &str) -> Result<LcgInput, ErrorBody> {
        let value: serde_json::Value = parse(text, Self::SHAPE)?;
        let has = |key: &str| value.get(key).is_some();
        let read = |what: &str, e: serde_json::Error| {
            ErrorBody::invalid_input(format!("{what}: {e}; expected {}", Self::SHAPE))
        };
        if has("pieces") {
            let input = serde_json::from_value(value).map_err(|e| read("Bézier pieces", e))?;
            Ok(LcgInput::Pieces(input))
        } else if has("beta") {
            let input = serde_json::from_value(value).map_err(|e| read("a space curve", e))?;
            Ok(LcgInput::Space(input))
        } else if has("alpha0") || has("alpha1") {
            let input = serde_json::from_value(value).map_err(|e| read("a compound curve", e))?;
            Ok(LcgInput::Curve(CurveInput::Compound(input)))
        } else if has("alpha") {
            let input = serde_json::from_value(value).map_err(|e| read("a segment", e))?;
            Ok(LcgInput::Curve(CurveInput::Segment(input)))
        } else {
            Err(ErrorBody::invalid_input(format!(
                "no \"pieces\", \"alpha\", \"alpha0\" or \"beta\" in the input; expected {}",
                Self::SHAPE
            )))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::{to_line, CompoundInput, PieceInput, SegmentInput};

    #[test]
    fn the_plot_of_a_segment_fits_its_own_alpha() {
        let input = SegmentInput {
            points: [[0.0, 0.0], [1.0, 0.0], [1.6, 0.9]],
            alpha: 0.5,
        };
        let report = LcgReport::new(&input.solve().unwrap().curvature_plot(65).unwrap());
        assert_eq!(report.points.len(), 65);
        let fit = report.fit.as_ref().unwrap();
        assert!((fit.alpha - 0.5).abs() < 1e-9, "{}", fit.alpha);
        assert!(report.is_finite());
    }

    #[test]
    fn lcg_reports_fit_each_piece_and_refuse_a_line_when_the_curvature_is_not_monotone() {
        let compound = CompoundInput {
            points: vec![[0.0, 0.0], [2.0, 0.0], [2.5, 2.0], [0.0, 1.5]],
            alpha0: -1.0,
            alpha1: 2.0,
            ratio: None,
        };
        let curve = compound.solve().unwrap();
        let report = LcgReport::of_curve(&curve, 65).unwrap();
        let slopes: Vec<f64> = report
            .pieces
            .iter()
            .map(|p| p.fit.as_ref().unwrap().alpha)
            .collect();
        assert!((slopes[0] + 1.0).abs() < 1e-9 && (slopes[1] - 2.0).abs() < 1e-9);
        assert_eq!(report.pieces[1].s[1], curve.arc_length());
        assert!(report.fit.is_some() && report.monotone.is_none());
        // An S-shaped cubic: dκ/ds changes sign, so there is no line.
        let s_curve = PieceInput {
            points: [[0.0, 0.0], [1.0, 1.0], [2.0, -1.0], [3.0, 0.0]],
            weights: None,
        };
        let cubic = s_curve.to_rational_cubic().unwrap();
        let report = LcgReport::of_pieces(&[cubic], 64).unwrap();
        assert_eq!((report.fit.is_none(), report.monotone), (true, Some(false)));
        assert!(report.note.unwrap().contains("piece 1 of 1"));
        assert!(
            to_line(&LcgReport::of_pieces(&[cubic], 8).unwrap()).contains(r#""monotone":false"#)
        );
    }

    #[test]
    fn lcg_inputs_are_told_apart_by_their_keys() {
        let kinds: Vec<&str> = [
            r#"{"pieces":[{"points":[[0,0],[1,0],[2,1],[3,3]]}]}"#,
            r#"{"points":[[0,0],[1,0],[2,1]],"alpha":0.5}"#,
            r#"{"points":[[0,0],[1,0],[2,1]],"alpha0":0.5,"alpha1":1,"ratio":0.5}"#,
            r#"{"points":[[0,0,0],[1,0,0],[2,1,0],[2,2,1]],"alpha":0.5,"beta":0}"#,
        ]
        .iter()
        .map(|text| match LcgInput::parse(text).unwrap() {
            LcgInput::Pieces(_) => "pieces",
            LcgInput::Curve(CurveInput::Segment(_)) => "segment",
            LcgInput::Curve(CurveInput::Compound(_)) => "compound",
            LcgInput::Space(_) => "space",
        })
        .collect();
        assert_eq!(kinds, ["pieces", "segment", "compound", "space"]);
        let err = LcgInput::parse(r#"{"curve":1}"#).unwrap_err();
        assert_eq!(err.kind, "invalid_input");
    }
}
