//! Claim: every documented form of a point file reads to the same points, and every bad line
//! is refused as invalid input naming its line (its point, in JSON).

use lac_io::points::{read_points, Columns, PointFile};

const WANT: [[f64; 2]; 3] = [[0.0, 0.0], [1.5, -2.0], [3.0, 1e-3]];

fn points(text: &str) -> Vec<[f64; 2]> {
    read_points(text, Columns::Points)
        .unwrap_or_else(|e| panic!("{text:?}: {e}"))
        .points
}

fn refused(text: &str, columns: Columns) -> String {
    let err = read_points(text, columns).unwrap_err();
    assert_eq!(err.kind, "invalid_input", "{text:?}");
    err.message
}

#[test]
fn spaces_commas_tabs_and_semicolons_separate_the_coordinates() {
    for text in [
        "0 0\n1.5 -2\n3 1e-3\n",
        "0,0\n1.5,-2\n3,0.001",
        "0\t0\n1.5\t-2\n3\t1e-3\n",
        "0;0\r\n1.5;-2\r\n3;1e-3\r\n",
        "  0 ,  0\n\t1.5 , -2 \n 3,\t0.001  \n",
    ] {
        assert_eq!(points(text), WANT, "{text:?}");
    }
}

#[test]
fn comments_blank_lines_a_header_and_extra_columns_are_skipped() {
    let text = "\u{feff}# measured 2026-11-28\nx,y,z\n\n0 0 7 # first\n  # a whole line\n1.5 -2 8 9\n\n3 1e-3 extra words\n";
    assert_eq!(points(text), WANT);
    // A header is only the first line: a later line of words is an error.
    let message = refused("0 0\nx y\n", Columns::Points);
    assert!(message.starts_with("line 2: x \"x\""), "{message}");
}

#[test]
fn a_json_array_reads_to_the_same_points_and_ignores_extra_entries() {
    assert_eq!(points("[[0, 0], [1.5, -2], [3, 1e-3]]"), WANT);
    assert_eq!(points(" \n[[0, 0, 5], [1.5, -2, 6], [3, 0.001, 7]]"), WANT);
    assert_eq!(points("[]"), Vec::<[f64; 2]>::new());
}

#[test]
fn a_weight_column_is_read_when_asked_and_required_on_every_line() {
    let file = read_points("0 0 1\n1.5 -2 0.5\n3 1e-3 2 extra\n", Columns::Weighted).unwrap();
    assert_eq!(
        file,
        PointFile {
            points: WANT.to_vec(),
            weights: Some(vec![1.0, 0.5, 2.0]),
        }
    );
    let json = read_points("[[0,0,1],[1.5,-2,0.5],[3,1e-3,2]]", Columns::Weighted).unwrap();
    assert_eq!(json, file);
    assert_eq!(
        read_points("0 0 1\n", Columns::Points).unwrap().weights,
        None
    );
    let message = refused("0 0 1\n1 1\n", Columns::Weighted);
    assert!(
        message.starts_with("line 2: 2 fields in \"1 1\"") && message.contains("\"x y w\""),
        "{message}"
    );
    let message = refused("[[0,0,1],[1,1]]", Columns::Weighted);
    assert!(message.starts_with("point 1 (from 0): [1,1]"), "{message}");
}

#[test]
fn bad_lines_are_named_by_their_number() {
    for (text, start) in [
        ("0 0\n1\n", "line 2: 1 field in \"1\""),
        (
            "# c\n0 0\n\n1 one\n",
            "line 4: y \"one\" is not a finite number",
        ),
        (
            "0 0\n1 2\nnan 3\n",
            "line 3: x \"nan\" is not a finite number",
        ),
        ("0 0\n1 inf\n", "line 2: y \"inf\" is not a finite number"),
        (
            "0 0\n1 1e999\n",
            "line 2: y \"1e999\" is not a finite number",
        ),
        ("0 0\n1 0x10\n", "line 2: y \"0x10\" is not a finite number"),
    ] {
        let message = refused(text, Columns::Points);
        assert!(message.starts_with(start), "{text:?}: {message}");
    }
}

#[test]
fn bad_json_is_refused_naming_the_point_or_the_syntax() {
    for (text, start) in [
        ("[[0, 0], [1]]", "point 1 (from 0): [1] is not [x, y]"),
        ("[[0, 0], [1, \"2\"]]", "point 1 (from 0): [1,\"2\"]"),
        ("[[0, 0], 7]", "point 1 (from 0): 7"),
        ("[[0, 0], [1, 1e999]]", "number out of range"),
        ("[[0, 0], [1, 1]", "EOF while parsing"),
        ("[[0, 0]] trailing", "trailing characters"),
    ] {
        let message = refused(text, Columns::Points);
        assert!(message.starts_with(start), "{text:?}: {message}");
    }
}
