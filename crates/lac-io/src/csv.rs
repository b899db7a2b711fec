//! The CSV forms of the reports: a header line, then one row per sample (per Bézier piece
//! for [`QuasiReport`], per graph point for the graphs).
//!
//! Numbers are written as the shortest decimal that reads back to the same `f64` (Rust's
//! `{:?}`, with an exponent for very small or large magnitudes), as in the JSON; a value that
//! does not exist (a graph point where κ = 0, the sign change of a monotone piece) is an
//! empty cell. A report's `note` (why a graph has no line, or no points) comes first, as one
//! comment line starting with `# `, which CSV readers skip when told that `#` starts a comment
//! (pandas' `comment="#"`, numpy's default).

use std::fmt::Write as _;

use crate::json::{
    CompoundReport, FitReport, LcgReport, PathReport, QuasiReport, SampleRow, SegmentReport,
    SpaceLcgReport, SpaceReport, SplineReport,
};

/// Samples as CSV with the header `s,x,y,theta,kappa` (shortest round-trip numbers).
pub fn samples_csv(samples: &[SampleRow]) -> String {
    let mut out = String::from("s,x,y,theta,kappa\n");
    for r in samples {
        let [s, x, y, theta, kappa] = r.values();
        out.push_str(&format!("{s:?},{x:?},{y:?},{theta:?},{kappa:?}\n"));
    }
    out
}

/// `{x:?}`, or an empty cell for `None`.
fn cell(x: Option<f64>) -> String {
    x.map(|x| format!("{x:?}")).unwrap_or_default()
}

/// The `# note` line, if there is a note.
fn note_line(out: &mut String, note: Option<&str>) {
    if let Some(note) = note {
        let _ = writeln!(out, "# {}", note.replace(['\n', '\r'], " "));
    }
}

impl SegmentReport {
    /// The samples: `s,x,y,theta,kappa`.
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

impl CompoundReport {
    /// The samples: `s,x,y,theta,kappa`.
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

impl PathReport {
    /// The samples: `s,x,y,theta,kappa`.
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

impl FitReport {
    /// The samples: `s,x,y,theta,kappa`.
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

impl SplineReport {
    /// The samples: `s,x,y,theta,kappa`.
    pub fn to_csv(&self) -> String {
        samples_csv(&self.samples)
    }
}

impl QuasiReport {
    /// One row per piece: `piece,x0,y0,x1,y1,x2,y2,x3,y3,w0,w1,w2,w3,monotone,proven,t,
    /// turning0,turning1,max_deviation` (piece from 0; `t` empty unless not monotone).
    pub fn to_csv(&self) -> String {
        let mut out = String::from(
            "piece,x0,y0,x1,y1,x2,y2,x3,y3,w0,w1,w2,w3,monotone,proven,t,turning0,turning1,\
             max_deviation\n",
        );
        for (i, p) in self.pieces.iter().enumerate() {
            let _ = write!(out, "{i}");
            for v in p.points.iter().flatten().chain(&p.weights) {
                let _ = write!(out, ",{v:?}");
            }
            let _ = writeln!(
                out,
                ",{},{},{},{:?},{:?},{:?}",
                p.monotone,
                p.proven,
                cell(p.t),
                p.turning[0],
                p.turning[1],
                p.max_deviation
            );
        }
        out
    }
}

impl LcgReport {
    /// One row per plot point: `s,kappa,dkappa_ds,log_rho,log_lcg`, the last two empty where
    /// there is no graph point; after the `# note` line when the curvature is not monotone.
    pub fn to_csv(&self) -> String {
        let mut out = String::new();
        note_line(&mut out, self.note.as_deref());
        out.push_str("s,kappa,dkappa_ds,log_rho,log_lcg\n");
        for p in &self.points {
            let _ = writeln!(
                out,
                "{:?},{:?},{:?},{},{}",
                p.s,
                p.kappa,
                p.dkappa_ds,
                cell(p.log_rho),
                cell(p.log_lcg)
            );
        }
        out
    }
}

impl SpaceReport {
    /// One row per sample: `s,x,y,z,kappa,tau`, and with frames
    /// `tx,ty,tz,nx,ny,nz,bx,by,bz` (unit tangent, normal, binormal).
    pub fn to_csv(&self) -> String {
        let frames = self.samples.first().is_some_and(|r| r.t.is_some());
        let mut out = String::from("s,x,y,z,kappa,tau");
        if frames {
            out.push_str(",tx,ty,tz,nx,ny,nz,bx,by,bz");
        }
        out.push('\n');
        for r in &self.samples {
            let _ = write!(
                out,
                "{:?},{:?},{:?},{:?},{:?},{:?}",
                r.s, r.x, r.y, r.z, r.kappa, r.tau
            );
            for v in [r.t, r.n, r.b].iter().flatten().flatten() {
                let _ = write!(out, ",{v:?}");
            }
            out.push('\n');
        }
        out
    }
}

impl SpaceLcgReport {
    /// One row per sample: `s,log_rho,log_lcg,log_mu,log_ltg`, the curvature graph's point
    /// and the torsion graph's at the same arc length (empty cells where a graph has none),
    /// after the `# note` line when a graph is empty.
    pub fn to_csv(&self) -> String {
        let mut out = String::new();
        note_line(&mut out, self.note.as_deref());
        out.push_str("s,log_rho,log_lcg,log_mu,log_ltg\n");
        let (curvature, torsion) = (&self.curvature.points, &self.torsion.points);
        for i in 0..curvature.len().max(torsion.len()) {
            let (c, t) = (curvature.get(i), torsion.get(i));
            let s = c.or(t).map(|p| p.s);
            let _ = writeln!(
                out,
                "{},{},{},{},{}",
                cell(s),
                cell(c.map(|p| p.x)),
                cell(c.map(|p| p.y)),
                cell(t.map(|p| p.x)),
                cell(t.map(|p| p.y))
            );
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use crate::json::{QuasiInput, QuasiReport, SpaceInput, SpaceLcgReport, SpaceReport};
    use lac::Curve;

    #[test]
    fn a_quasi_csv_has_a_row_per_piece_with_its_nineteen_cells() {
        let input: QuasiInput =
            serde_json::from_str(r#"{"points":[[0,0],[3,0],[4,1.5]],"alpha":-1,"tolerance":1e-6}"#)
                .unwrap();
        let (solved, quasi) = input.solve().unwrap();
        let report = QuasiReport::new(&quasi, solved.curve().arc_length(), Some(1e-6), false);
        let csv = report.to_csv();
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), report.pieces.len() + 1);
        for (i, line) in lines.iter().enumerate() {
            assert_eq!(line.split(',').count(), 19, "{line}");
            if i > 0 {
                assert!(line.starts_with(&format!("{},", i - 1)));
                assert!(line.contains(",increasing,") || line.contains(",decreasing,"));
            }
        }
    }

    #[test]
    fn space_csvs_align_their_columns_and_say_why_a_graph_is_empty() {
        let input = SpaceInput {
            points: [
                [0.0, 0.0, 0.0],
                [3.0, 0.0, 0.0],
                [3.0, 3.0, 1.5],
                [0.0, 3.0, 3.0],
            ],
            alpha: 0.5,
            beta: 0.0,
            omega: 0.0,
            torsion_type: 1,
        };
        let segment = input.solve().unwrap();
        let samples = SpaceReport::new(&segment, 5, true).unwrap().to_csv();
        assert!(samples.starts_with("s,x,y,z,kappa,tau,tx,ty,tz,nx,ny,nz,bx,by,bz\n"));
        assert!(samples.lines().skip(1).all(|l| l.split(',').count() == 15));
        let graphs = SpaceLcgReport::new(&segment, 5).unwrap().to_csv();
        let lines: Vec<&str> = graphs.lines().collect();
        assert!(
            lines[0].starts_with("# ") && lines[0].contains("Ω = 0"),
            "{graphs}"
        );
        assert_eq!(lines[1], "s,log_rho,log_lcg,log_mu,log_ltg");
        assert_eq!(lines.len(), 7);
        assert!(lines[2..].iter().all(|l| l.ends_with(",,")));
    }
}
