//! `lac region`: the drawable region as a JSON grid and as a PNG.

use crate::common;

use common::{assert_failure, json, lac};

#[test]
fn json_is_a_size_by_size_grid_mostly_drawable_for_alpha_between_0_and_1() {
    let run = lac(&[
        "region", "--alpha", "0.5", "--size", "16", "--format", "json",
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let v = json(&run);
    assert_eq!(v["size"], 16);
    assert_eq!(v["extent"], serde_json::json!([-1.0, 1.0, -1.0, 1.0]));
    assert_eq!(v["first"], serde_json::json!([-1.0, 0.0]));
    assert_eq!(v["last"], serde_json::json!([1.0, 0.0]));
    let rows = v["drawable"].as_array().unwrap();
    assert_eq!(rows.len(), 16);
    assert!(rows.iter().all(|r| r.as_array().unwrap().len() == 16));
    let fraction = v["drawable_fraction"].as_f64().unwrap();
    assert!(fraction > 0.9, "{fraction}");
}

#[test]
fn the_clothoid_region_excludes_the_sides_and_the_axis() {
    let v = json(&lac(&[
        "region", "--alpha", "-1", "--size", "15", "--format", "json",
    ]));
    let rows = v["drawable"].as_array().unwrap();
    let at = |r: usize, c: usize| rows[r][c].as_bool().unwrap();
    assert!(at(3, 7), "above the middle of the chord");
    assert!(!at(3, 0) && !at(3, 14), "far to the sides");
    assert!(
        (0..15).all(|c| !at(7, c)),
        "the middle row is y = 0: collinear"
    );
    let fraction = v["drawable_fraction"].as_f64().unwrap();
    assert!(fraction > 0.2 && fraction < 0.8, "{fraction}");
}

#[test]
fn png_is_valid_grayscale_and_matches_the_json_grid() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("region.png");
    let run = lac(&[
        "region",
        "--alpha",
        "-1",
        "--size",
        "24",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    assert_eq!((info.width, info.height), (24, 24));
    assert_eq!(info.color_type, png::ColorType::Grayscale);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);

    let v = json(&lac(&[
        "region", "--alpha", "-1", "--size", "24", "--format", "json",
    ]));
    let grid: Vec<u8> = v["drawable"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|d| if d.as_bool().unwrap() { 255 } else { 0 })
        })
        .collect();
    assert_eq!(pixels[..24 * 24], grid[..]);
}

#[test]
fn png_goes_to_standard_output_when_it_is_a_pipe() {
    let run = lac(&["region", "--alpha", "0.5", "--size", "4"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(&run.stdout_bytes[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn size_and_alpha_are_checked() {
    assert_failure(
        &lac(&["region", "--alpha", "0.5", "--size", "0"]),
        2,
        "usage",
    );
    // The work limit: 2048 pixels a side (about 10 s), 8192 with --allow-large.
    let message = assert_failure(
        &lac(&["region", "--alpha", "0.5", "--size", "2049"]),
        2,
        "limit",
    );
    assert!(
        message.contains("2,048") && message.contains("--allow-large"),
        "{message}"
    );
    assert_failure(
        &lac(&[
            "region",
            "--alpha",
            "0.5",
            "--size",
            "8193",
            "--allow-large",
        ]),
        2,
        "limit",
    );
    assert_failure(
        &lac(&["region", "--alpha", "nan", "--format", "json"]),
        2,
        "non_finite",
    );
    assert_failure(&lac(&["region"]), 2, "usage");
    // A slope no curve takes is said so, not drawn as an empty map.
    for args in [
        &["region", "--alpha", "1e308", "--size", "4"][..],
        &[
            "region", "--alpha0", "1", "--alpha1", "-2e6", "--ratio", "0.5", "--size", "4",
        ],
    ] {
        assert_failure(&lac(args), 2, "out_of_range");
    }
}

#[test]
fn compound_regions_are_16_by_16_and_a_mountain_mirrors_the_valley() {
    let grid = |alpha0: &str, alpha1: &str, ratio: &str| {
        let run = lac(&[
            "region", "--alpha0", alpha0, "--alpha1", alpha1, "--ratio", ratio, "--size", "16",
            "--format", "json",
        ]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        json(&run)
    };
    let valley = grid("-1", "2", "0.25");
    assert_eq!(valley["alpha"], -1.0);
    assert_eq!(valley["alpha1"], 2.0);
    assert_eq!(valley["ratio"], 0.25);
    assert_eq!(valley["size"], 16);
    let rows: Vec<Vec<bool>> = serde_json::from_value(valley["drawable"].clone()).unwrap();
    assert_eq!(rows.len(), 16);
    assert!(rows.iter().all(|r| r.len() == 16));
    let fraction = valley["drawable_fraction"].as_f64().unwrap();
    assert!(fraction > 0.2 && fraction < 0.95, "{fraction}");
    // Not the segment map of either slope.
    for alpha in ["-1", "2"] {
        let segment = json(&lac(&[
            "region", "--alpha", alpha, "--size", "16", "--format", "json",
        ]));
        assert_ne!(segment["drawable"], valley["drawable"], "alpha {alpha}");
    }
    // Swapping the ends swaps α0 ↔ α1 and r ↔ 1 − r: the map is mirrored left to right.
    let mountain = grid("2", "-1", "0.75");
    let mirrored: Vec<Vec<bool>> =
        serde_json::from_value::<Vec<Vec<bool>>>(mountain["drawable"].clone())
            .unwrap()
            .into_iter()
            .map(|r| r.into_iter().rev().collect())
            .collect();
    assert_eq!(mirrored, rows);
}

#[test]
fn compound_region_flags_come_together_and_are_checked() {
    let base = ["region", "--size", "4", "--format", "json"];
    let with = |extra: &[&str]| lac(&[&base[..], extra].concat());
    assert_failure(&with(&["--alpha0", "-1", "--alpha1", "2"]), 2, "usage");
    assert_failure(&with(&["--alpha0", "-1", "--ratio", "0.5"]), 2, "usage");
    assert_failure(&with(&["--alpha", "-1", "--ratio", "0.5"]), 2, "usage");
    for ratio in ["0", "1", "1.5"] {
        assert_failure(
            &with(&["--alpha0", "-1", "--alpha1", "2", "--ratio", ratio]),
            2,
            "out_of_range",
        );
    }
    assert_failure(
        &with(&["--alpha0", "-1", "--alpha1", "nan", "--ratio", "0.5"]),
        2,
        "non_finite",
    );
    let v = json(&with(&["--alpha", "-1"]));
    assert!(v.get("alpha1").is_none() && v.get("ratio").is_none());
}

#[test]
fn the_old_spelling_of_compound_slopes_is_a_usage_error_that_names_the_new_one() {
    // `lac region` once took --alpha A --alpha1 B; every subcommand now says --alpha0.
    let run = lac(&[
        "region", "--alpha", "-1", "--alpha1", "2", "--ratio", "0.5", "--size", "4", "--format",
        "json",
    ]);
    let message = assert_failure(&run, 2, "usage");
    assert!(
        message.contains("--alpha0 A --alpha1 B --ratio R"),
        "{message}"
    );
    let help = lac(&["region", "--help"]).stdout;
    for flag in [
        "--alpha ",
        "--alpha0",
        "--alpha1",
        "--ratio",
        "-o, --output",
    ] {
        assert!(help.contains(flag), "{flag} in region --help");
    }
}
