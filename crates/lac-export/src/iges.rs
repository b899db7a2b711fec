//! IGES 5.3: each curve a rational B-spline curve, entity 126 (form 0), in millimetres.
//!
//! Fixed 80-column records: Start (S), Global (G), Directory Entry (D, two records of ten
//! 8-column fields per entity), Parameter Data (P, data in columns 1–64, the entity's
//! directory pointer in 66–72) and Terminate (T); columns 73–80 hold the section letter and
//! the record's number. Entity 126's parameters: K (last control point index), M = 3,
//! PROP1 planar, PROP2 closed = 0, PROP3 polynomial, PROP4 periodic = 0, the K + M + 2
//! knots, the K + 1 weights, the control points, the parameter range V0, V1, and the unit
//! normal of the plane (planar curves; 0, 0, 1).

use super::number::real;
use super::nurbs::Nurbs;
use super::Meta;

/// A Hollerith string `nH…` of ASCII text (non-ASCII dropped).
fn hollerith(text: &str) -> String {
    let kept: String = text
        .chars()
        .filter(|c| c.is_ascii_graphic() || *c == ' ')
        .collect();
    format!("{}H{}", kept.len(), kept)
}

/// Tokens (each followed by its delimiter) packed into records of at most `width` columns.
fn pack(tokens: &[String], width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for token in tokens {
        if !line.is_empty() && line.len() + token.len() > width {
            lines.push(std::mem::take(&mut line));
        }
        // A token longer than a record (a long Hollerith string) is split across records.
        let mut rest = token.as_str();
        while rest.len() > width {
            let (head, tail) = rest.split_at(width - line.len());
            line.push_str(head);
            lines.push(std::mem::take(&mut line));
            rest = tail;
        }
        line.push_str(rest);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// Tokens with delimiters: `,` between, `;` after the last.
fn delimited(values: Vec<String>) -> Vec<String> {
    let n = values.len();
    values
        .into_iter()
        .enumerate()
        .map(|(i, v)| v + if i + 1 == n { ";" } else { "," })
        .collect()
}

/// The parameters of entity 126 for `curve`.
fn parameters(curve: &Nurbs) -> Vec<String> {
    let k = curve.control_points.len() - 1;
    let mut v = vec![
        "126".to_string(),
        k.to_string(),
        "3".to_string(),
        u8::from(curve.planar).to_string(),
        "0".to_string(),
        u8::from(curve.is_polynomial()).to_string(),
        "0".to_string(),
    ];
    v.extend(curve.knots.iter().map(|x| real(*x)));
    v.extend(curve.weights.iter().map(|x| real(*x)));
    v.extend(curve.control_points.iter().flatten().map(|x| real(*x)));
    v.push(real(curve.knots[0]));
    v.push(real(curve.knots[curve.knots.len() - 1]));
    v.extend(["0.0", "0.0", "1.0"].map(String::from));
    delimited(v)
}

/// The IGES document of `curves`; `resolution` is the minimum intended resolution (mm).
pub fn write(curves: &[Nurbs], meta: &Meta, resolution: f64) -> String {
    let mut out = String::new();
    let mut record = |data: &str, letter: char, number: usize| {
        out.push_str(&format!("{data:<72}{letter}{number:>7}\n"));
    };
    let start = ["a log-aesthetic curve as rational B-splines (entity 126), lac export"];
    for (i, line) in start.iter().enumerate() {
        record(line, 'S', i + 1);
    }
    let max_coordinate = curves
        .iter()
        .map(Nurbs::max_coordinate)
        .fold(0.0f64, f64::max);
    let stamp = iges_time(&meta.timestamp);
    let system = format!("lac {}", meta.version);
    let global = delimited(vec![
        "1H,".into(),
        "1H;".into(),
        hollerith(&meta.name),
        hollerith(&meta.name),
        hollerith(&system),
        hollerith(&system),
        "32".into(),
        "38".into(),
        "6".into(),
        "308".into(),
        "15".into(),
        hollerith(&meta.name),
        "1.0".into(),
        "2".into(),
        "2HMM".into(),
        "1".into(),
        "1.0".into(),
        hollerith(&stamp),
        real(resolution),
        real(max_coordinate),
        hollerith(""),
        hollerith(""),
        "11".into(),
        "0".into(),
        hollerith(&stamp),
    ]);
    let global_lines = pack(&global, 72);
    for (i, line) in global_lines.iter().enumerate() {
        record(line, 'G', i + 1);
    }
    // Parameter data first (the directory points into it), then both sections in order.
    let mut directory = Vec::new();
    let mut parameter_lines = Vec::new();
    for (i, curve) in curves.iter().enumerate() {
        let de = 2 * i + 1;
        let lines = pack(&parameters(curve), 64);
        let first = parameter_lines.len() + 1;
        let count = lines.len();
        for line in lines {
            parameter_lines.push(format!("{line:<64} {de:>7}"));
        }
        let fields1 = [126, first, 0, 1, 0, 0, 0, 0];
        let fields2 = [126, 0, 0, count, 0];
        let mut d1: String = fields1.iter().map(|f| format!("{f:>8}")).collect();
        d1.push_str("00000000");
        let mut d2: String = fields2.iter().map(|f| format!("{f:>8}")).collect();
        d2.push_str(&format!("{:>8}{:>8}{:>8}{:>8}", "", "", "LACCURVE", i + 1));
        directory.push(d1);
        directory.push(d2);
    }
    for (i, line) in directory.iter().enumerate() {
        record(line, 'D', i + 1);
    }
    for (i, line) in parameter_lines.iter().enumerate() {
        record(line, 'P', i + 1);
    }
    let terminate = format!(
        "S{:>7}G{:>7}D{:>7}P{:>7}",
        start.len(),
        global_lines.len(),
        directory.len(),
        parameter_lines.len()
    );
    record(&terminate, 'T', 1);
    out
}

/// `YYYYMMDD.HHNNSS` from an ISO 8601 `YYYY-MM-DDTHH:MM:SS…` time stamp (digits only kept).
fn iges_time(timestamp: &str) -> String {
    let digits: String = timestamp
        .chars()
        .filter(char::is_ascii_digit)
        .chain(std::iter::repeat('0'))
        .take(14)
        .collect();
    format!("{}.{}", &digits[..8], &digits[8..])
}
