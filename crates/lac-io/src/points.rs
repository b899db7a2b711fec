//! Point files: the measured points that `lac fit` reads (and the server and the Python
//! bindings may read), one point a line or a JSON array.
//!
//! **Lines**: "x y", "x,y", "x;y" or "x<TAB>y" (any mix of commas, semicolons, spaces and
//! tabs between the numbers), columns after the first two ignored (or, asked for, the third
//! read as the point's weight). `#` starts a comment that runs to the end of its line; blank
//! lines are skipped, and so is a first line whose first two fields are not numbers (a CSV
//! header such as `x,y`). **JSON**: a document starting with `[`, an array of `[x, y]` (or
//! `[x, y, w]` with weights).
//!
//! Numbers are read by Rust's `f64` parser (correctly rounded); a number that does not parse
//! or is not finite (`nan`, `inf`, `1e999`) is an error that names its line (or, in JSON,
//! its point), so that a file of a million points says where it is wrong.

use serde_json::Value;

use crate::json::{ErrorBody, Xy};

/// Points read from a file, with a weight each when they were asked for.
#[derive(Clone, Debug, PartialEq)]
pub struct PointFile {
    /// The points, in the file's order.
    pub points: Vec<Xy>,
    /// Each point's weight (the third column), when [`Columns::Weighted`] was asked.
    pub weights: Option<Vec<f64>>,
}

/// Which columns a point file is read for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Columns {
    /// x and y; further columns are ignored.
    Points,
    /// x, y and a weight, which every point must have; further columns are ignored.
    Weighted,
}

impl Columns {
    fn count(self) -> usize {
        match self {
            Columns::Points => 2,
            Columns::Weighted => 3,
        }
    }

    fn form(self) -> &'static str {
        match self {
            Columns::Points => "x y",
            Columns::Weighted => "x y w",
        }
    }
}

/// The points of `text`, a point file in either form (see the module documentation).
///
/// ```
/// use lac_io::points::{read_points, Columns};
/// let file = read_points("# x y\n0 0\n1,0.5\n2\t2 extra\n", Columns::Points)?;
/// assert_eq!(file.points, vec![[0.0, 0.0], [1.0, 0.5], [2.0, 2.0]]);
/// let json = read_points("[[0, 0], [1, 0.5], [2, 2]]", Columns::Points)?;
/// assert_eq!(json.points, file.points);
/// # Ok::<(), lac_io::json::ErrorBody>(())
/// ```
pub fn read_points(text: &str, columns: Columns) -> Result<PointFile, ErrorBody> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim_start().starts_with('[') {
        json_points(text, columns)
    } else {
        line_points(text, columns)
    }
}

/// Points one a line.
fn line_points(text: &str, columns: Columns) -> Result<PointFile, ErrorBody> {
    let want = columns.count();
    let mut points = Vec::new();
    let mut weights = Vec::new();
    let mut first = true;
    for (index, line) in text.lines().enumerate() {
        let number = index + 1;
        let data = line.split('#').next().unwrap_or("");
        let fields: Vec<&str> = data
            .split(|c: char| c == ',' || c == ';' || c.is_whitespace())
            .filter(|f| !f.is_empty())
            .collect();
        if fields.is_empty() {
            continue;
        }
        let header = first && fields.iter().take(2).all(|f| f.parse::<f64>().is_err());
        first = false;
        if header {
            continue;
        }
        if fields.len() < want {
            return Err(ErrorBody::invalid_input(format!(
                "line {number}: {} field{} in {:?}; write each point as \"{}\"",
                fields.len(),
                if fields.len() == 1 { "" } else { "s" },
                line.trim(),
                columns.form()
            )));
        }
        let value = |k: usize| -> Result<f64, ErrorBody> {
            let name = ["x", "y", "the weight"][k];
            finite(fields[k]).ok_or_else(|| {
                ErrorBody::invalid_input(format!(
                    "line {number}: {name} {:?} is not a finite number",
                    fields[k]
                ))
            })
        };
        points.push([value(0)?, value(1)?]);
        if columns == Columns::Weighted {
            weights.push(value(2)?);
        }
    }
    Ok(PointFile {
        points,
        weights: (columns == Columns::Weighted).then_some(weights),
    })
}

/// A JSON array of points.
fn json_points(text: &str, columns: Columns) -> Result<PointFile, ErrorBody> {
    let want = columns.count();
    let shape = match columns {
        Columns::Points => "a JSON array of points [[x, y], …]",
        Columns::Weighted => "a JSON array of weighted points [[x, y, w], …]",
    };
    let rows: Vec<Value> = serde_json::from_str(text)
        .map_err(|e| ErrorBody::invalid_input(format!("{e}; expected {shape}")))?;
    let mut points = Vec::with_capacity(rows.len());
    let mut weights = Vec::new();
    for (index, row) in rows.iter().enumerate() {
        let numbers: Option<Vec<f64>> = row
            .as_array()
            .filter(|r| r.len() >= want)
            .map(|r| r.iter().take(want).filter_map(Value::as_f64).collect())
            .filter(|n: &Vec<f64>| n.len() == want && n.iter().all(|v| v.is_finite()));
        let Some(numbers) = numbers else {
            return Err(ErrorBody::invalid_input(format!(
                "point {index} (from 0): {row} is not [{}] of finite numbers; expected {shape}",
                columns.form().replace(' ', ", ")
            )));
        };
        points.push([numbers[0], numbers[1]]);
        if columns == Columns::Weighted {
            weights.push(numbers[2]);
        }
    }
    Ok(PointFile {
        points,
        weights: (columns == Columns::Weighted).then_some(weights),
    })
}

/// `text` as a finite number.
fn finite(text: &str) -> Option<f64> {
    text.parse::<f64>().ok().filter(|v| v.is_finite())
}
