//! `lac space --format obj|ply`: the sampled curve as a polyline for 3-D programs.
//!
//! Numbers are written in Rust's `{:?}` form, the shortest decimal that reads back to the
//! same `f64` (with an exponent for very small or large magnitudes), which C's `strtod` and
//! every OBJ/PLY reader accept.

use std::fmt::Write as _;

use lac::{Frame, Vec3};

/// Wavefront OBJ: `header` as `#` comments, a vertex `v x y z` per frame and one polyline
/// `l 1 2 … n` through them (OBJ indices start at 1).
pub(crate) fn obj(frames: &[Frame], header: &[String]) -> String {
    let mut out = String::new();
    for line in header {
        let _ = writeln!(out, "# {}", one_line(line));
    }
    out.push_str("o lac_space_segment\n");
    for f in frames {
        let Vec3 { x, y, z } = f.point;
        let _ = writeln!(out, "v {x:?} {y:?} {z:?}");
    }
    out.push('l');
    for i in 1..=frames.len() {
        let _ = write!(out, " {i}");
    }
    out.push('\n');
    out
}

/// ASCII PLY 1.0: `header` as `comment` lines, an element `vertex` (x, y, z, kappa, tau as
/// doubles) per frame and an element `edge` (vertex1, vertex2, 0-based) between consecutive
/// frames.
pub(crate) fn ply(frames: &[Frame], header: &[String]) -> String {
    let mut out = String::from("ply\nformat ascii 1.0\n");
    for line in header {
        let _ = writeln!(out, "comment {}", one_line(line));
    }
    let _ = writeln!(out, "element vertex {}", frames.len());
    for name in ["x", "y", "z", "kappa", "tau"] {
        let _ = writeln!(out, "property double {name}");
    }
    let _ = writeln!(out, "element edge {}", frames.len().saturating_sub(1));
    out.push_str("property int vertex1\nproperty int vertex2\nend_header\n");
    for f in frames {
        let Vec3 { x, y, z } = f.point;
        let _ = writeln!(out, "{x:?} {y:?} {z:?} {:?} {:?}", f.curvature, f.torsion);
    }
    for i in 1..frames.len() {
        let _ = writeln!(out, "{} {i}", i - 1);
    }
    out
}

/// A comment's text with line breaks replaced by spaces, so it stays one header line.
fn one_line(text: &str) -> String {
    text.replace(['\n', '\r'], " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frames(n: usize) -> Vec<Frame> {
        (0..n)
            .map(|i| Frame {
                s: i as f64,
                point: Vec3::new(i as f64, 0.5, -1e-20),
                tangent: Vec3::X,
                normal: Vec3::Y,
                binormal: Vec3::Z,
                curvature: 2.0,
                torsion: -0.25,
            })
            .collect()
    }

    #[test]
    fn obj_has_a_vertex_per_frame_and_one_polyline() {
        let text = obj(&frames(3), &["a\nb".to_string()]);
        assert_eq!(
            text,
            "# a b\no lac_space_segment\nv 0.0 0.5 -1e-20\nv 1.0 0.5 -1e-20\nv 2.0 0.5 -1e-20\n\
             l 1 2 3\n"
        );
    }

    #[test]
    fn ply_declares_its_elements_and_links_consecutive_vertices() {
        let text = ply(&frames(3), &["hello".to_string()]);
        let (head, body) = text.split_once("end_header\n").unwrap();
        assert!(head.starts_with("ply\nformat ascii 1.0\ncomment hello\nelement vertex 3\n"));
        assert!(head.contains("property double tau\nelement edge 2\n"));
        assert_eq!(
            body,
            "0.0 0.5 -1e-20 2.0 -0.25\n1.0 0.5 -1e-20 2.0 -0.25\n2.0 0.5 -1e-20 2.0 -0.25\n\
             0 1\n1 2\n"
        );
    }
}
