//! Claim: the drawable-region maps, solved on the part that does not repeat and mirrored
//! (`lac::region::row`, `top_rows`, `mirror_rows`), equal a solve at every pixel, for
//! segments at every slope class and for compound curves (mirrored in y only), at even and
//! odd sizes.

use lac::region::{
    compound_row, is_drawable, is_drawable_compound, mirror_rows, pixel_center, row, top_rows,
};

/// Pixels where the mirrored map and the pixel-by-pixel solve disagree.
fn disagreements(size: usize, map: &[Vec<bool>], solve: impl Fn(usize, usize) -> bool) -> usize {
    assert_eq!(map.len(), size);
    let mut count = 0;
    for (r, cells) in map.iter().enumerate() {
        assert_eq!(cells.len(), size);
        for (c, &cell) in cells.iter().enumerate() {
            if cell != solve(r, c) {
                count += 1;
            }
        }
    }
    count
}

#[test]
fn segment_maps_equal_a_solve_at_every_pixel() {
    for alpha in [-3.0, -1.0, -0.5, 0.0, 0.3, 1.0, 1.5, 2.0, 4.0] {
        for size in [64, 65] {
            let top = (0..top_rows(size)).map(|r| row(alpha, size, r)).collect();
            let map = mirror_rows(size, top);
            // (For 0 ≤ α ≤ 1 every pixel centre is drawable.)
            let drawable = map.iter().flatten().filter(|&&d| d).count();
            assert!(drawable > 0, "alpha {alpha}");
            assert!(
                (0.0..=1.0).contains(&alpha) || drawable < size * size,
                "alpha {alpha}"
            );
            let off = disagreements(size, &map, |r, c| {
                is_drawable(alpha, pixel_center(size, r, c))
            });
            assert_eq!(off, 0, "alpha {alpha}, size {size}");
        }
    }
}

#[test]
fn compound_maps_equal_a_solve_at_every_pixel() {
    for (alpha0, alpha1, ratio) in [(-1.0, 2.0, 0.5), (0.5, -0.5, 0.3), (1.5, 0.0, 0.8)] {
        for size in [48, 49] {
            let top = (0..top_rows(size))
                .map(|r| compound_row(alpha0, alpha1, ratio, size, r))
                .collect();
            let map = mirror_rows(size, top);
            let off = disagreements(size, &map, |r, c| {
                is_drawable_compound(alpha0, alpha1, ratio, pixel_center(size, r, c))
            });
            assert_eq!(
                off, 0,
                "alphas {alpha0} {alpha1}, ratio {ratio}, size {size}"
            );
        }
    }
}
