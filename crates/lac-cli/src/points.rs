//! Parsing the `--points` argument: points "x,y" (or "x,y,z" for `lac space`) separated by
//! spaces and/or semicolons.

use lac_io::json::{ErrorBody, Xy, Xyz};

/// Parse exactly three points "x0,y0 x1,y1 x2,y2".
///
/// Spaces and semicolons separate points; spaces around a comma are allowed ("1, 2; 3, 4").
/// Numbers are read by Rust's `f64` parser, so "nan" and "inf" parse and are rejected later
/// by the library with the name of the coordinate.
pub(crate) fn parse_points(text: &str) -> Result<[Xy; 3], ErrorBody> {
    let points = parse_point_list(text, &[3])?;
    Ok([points[0], points[1], points[2]])
}

/// Parse as many points as one of `counts` (ascending) allows, as [`parse_points`] does.
pub(crate) fn parse_point_list(text: &str, counts: &[usize]) -> Result<Vec<Xy>, ErrorBody> {
    parse_coordinates::<2>(text, counts)
}

/// Parse between `min` and `max` points (a control polygon), as [`parse_points`] does.
pub(crate) fn parse_polygon(text: &str, min: usize, max: usize) -> Result<Vec<Xy>, ErrorBody> {
    let tight = tighten_commas(text);
    let count = tight
        .split(|c: char| c == ';' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .count();
    if !(min..=max).contains(&count) {
        return Err(ErrorBody::invalid_input(format!(
            "expected {min} to {max} points \"x,y\" separated by spaces or semicolons, got \
             {count}"
        )));
    }
    parse_coordinates::<2>(text, &[count])
}

/// Parse exactly four space points "x0,y0,z0 x1,y1,z1 x2,y2,z2 x3,y3,z3", as
/// [`parse_points`] does.
pub(crate) fn parse_space_points(text: &str) -> Result<[Xyz; 4], ErrorBody> {
    let points = parse_coordinates::<3>(text, &[4])?;
    Ok([points[0], points[1], points[2], points[3]])
}

/// Parse as many points of `N` coordinates as one of `counts` (ascending) allows.
fn parse_coordinates<const N: usize>(
    text: &str,
    counts: &[usize],
) -> Result<Vec<[f64; N]>, ErrorBody> {
    let tight = tighten_commas(text);
    let tokens: Vec<&str> = tight
        .split(|c: char| c == ';' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    if !counts.contains(&tokens.len()) {
        let expected = match counts {
            [n] => format!("exactly {n}"),
            _ => {
                let names: Vec<String> = counts.iter().map(usize::to_string).collect();
                names.join(" or ")
            }
        };
        return Err(ErrorBody::invalid_input(format!(
            "expected {expected} points \"{}\" separated by spaces or semicolons, got {} in \
             {text:?}",
            form(N),
            tokens.len()
        )));
    }
    tokens
        .iter()
        .enumerate()
        .map(|(i, token)| parse_point(token, i))
        .collect()
}

/// Parse the four weights "w0,w1,w2,w3" of a rational cubic, separated by commas, spaces
/// and/or semicolons. Whether they are positive and finite is the library's to say.
pub(crate) fn parse_weights(text: &str) -> Result<[f64; 4], ErrorBody> {
    let tokens: Vec<&str> = text
        .split(|c: char| c == ',' || c == ';' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .collect();
    let [w0, w1, w2, w3] = tokens[..] else {
        return Err(ErrorBody::invalid_input(format!(
            "expected 4 weights \"w0,w1,w2,w3\", got {} in {text:?}",
            tokens.len()
        )));
    };
    let parse = |i: usize, token: &str| {
        token.parse::<f64>().map_err(|_| {
            ErrorBody::invalid_input(format!(
                "weight w{i} {token:?} is not a number; write the weights as \"w0,w1,w2,w3\""
            ))
        })
    };
    Ok([parse(0, w0)?, parse(1, w1)?, parse(2, w2)?, parse(3, w3)?])
}

/// Points as kurbo points, for drawing.
pub(crate) fn kurbo_points(points: &[Xy]) -> Vec<kurbo::Point> {
    points
        .iter()
        .map(|&[x, y]| kurbo::Point::new(x, y))
        .collect()
}

/// Remove whitespace on either side of each comma, so "1 , 2" reads as one point.
fn tighten_commas(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut after_comma = false;
    for ch in text.chars() {
        if ch == ',' {
            out.truncate(out.trim_end().len());
            after_comma = true;
            out.push(ch);
        } else if !(after_comma && ch.is_whitespace()) {
            after_comma = false;
            out.push(ch);
        }
    }
    out
}

/// How a point of `n` coordinates is written: "x,y" or "x,y,z".
fn form(n: usize) -> &'static str {
    if n == 2 {
        "x,y"
    } else {
        "x,y,z"
    }
}

fn parse_point<const N: usize>(token: &str, index: usize) -> Result<[f64; N], ErrorBody> {
    let bad = |why: &str| {
        ErrorBody::invalid_input(format!(
            "control point P{index} {token:?}: {why}; write each point as \"{}\"",
            form(N)
        ))
    };
    let parts: Vec<&str> = token.split(',').collect();
    match parts.len() {
        1 => return Err(bad("no comma")),
        n if n != N => return Err(bad(&format!("{n} coordinates, not {N}"))),
        _ => {}
    }
    let mut point = [0.0; N];
    for ((slot, part), name) in point.iter_mut().zip(&parts).zip(["x", "y", "z"]) {
        *slot = part
            .parse()
            .map_err(|_| bad(&format!("{name} is not a number")))?;
    }
    Ok(point)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spaces_semicolons_and_negative_numbers_all_separate_points() {
        let want = [[-1.0, 0.0], [0.2, 0.8], [1.0, -0.5]];
        for text in [
            "-1,0 0.2,0.8 1,-0.5",
            "-1,0;0.2,0.8;1,-0.5",
            " -1 , 0 ; 0.2, 0.8 ;  1 ,-0.5 ",
            "-1e0,0\t2e-1,8e-1\n1,-.5",
        ] {
            assert_eq!(parse_points(text).unwrap(), want, "{text:?}");
        }
    }

    #[test]
    fn wrong_count_and_bad_numbers_are_invalid_input() {
        for text in [
            "",
            "0,0 1,1",
            "0,0 1,1 2,0 3,3",
            "0,0 1;1 2,0",
            "0,0 1,x 2,0",
            "0,0 1,1,1 2,0",
        ] {
            assert_eq!(
                parse_points(text).unwrap_err().kind,
                "invalid_input",
                "{text:?}"
            );
        }
    }

    #[test]
    fn a_list_takes_any_of_the_allowed_counts_and_names_them_when_wrong() {
        assert_eq!(parse_point_list("0,0 1,0 1,1", &[3, 4]).unwrap().len(), 3);
        assert_eq!(
            parse_point_list("0,0 1,0 1,1 0,1", &[3, 4]).unwrap().len(),
            4
        );
        let err = parse_point_list("0,0 1,0", &[3, 4]).unwrap_err();
        assert!(err.message.contains("expected 3 or 4 points"), "{err}");
    }

    #[test]
    fn weights_take_commas_or_spaces_and_exactly_four_numbers() {
        assert_eq!(parse_weights("1,0.5, 2 ;3").unwrap(), [1.0, 0.5, 2.0, 3.0]);
        assert_eq!(parse_weights("1 1 1 1").unwrap(), [1.0; 4]);
        for text in ["", "1,1,1", "1,1,1,1,1", "1,x,1,1"] {
            assert_eq!(
                parse_weights(text).unwrap_err().kind,
                "invalid_input",
                "{text:?}"
            );
        }
    }

    #[test]
    fn space_points_take_three_coordinates_and_exactly_four_points() {
        assert_eq!(
            parse_space_points("0,0,0 1,0,0; 2, 1, 0.5 -2,2,-1e0").unwrap(),
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [2.0, 1.0, 0.5],
                [-2.0, 2.0, -1.0]
            ]
        );
        for text in [
            "0,0,0 1,0,0 2,1,0",
            "0,0,0 1,0,0 2,1,0 2,2,1 3,3,3",
            "0,0,0 1,0 2,1,0 2,2,1",
            "0,0,0 1,0,0,0 2,1,0 2,2,1",
            "0,0,0 1,0,z 2,1,0 2,2,1",
        ] {
            let err = parse_space_points(text).unwrap_err();
            assert_eq!(err.kind, "invalid_input", "{text:?}");
            assert!(err.message.contains("\"x,y,z\""), "{err}");
        }
        assert!(parse_points("0,0 1,1,1 2,0")
            .unwrap_err()
            .message
            .contains("3 coordinates, not 2"));
    }

    #[test]
    fn nan_parses_so_the_library_can_name_the_coordinate() {
        let p = parse_points("nan,0 1,1 2,0").unwrap();
        assert!(p[0][0].is_nan());
    }
}
