//! Computing the drawable-region map, one rayon task per row.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

/// Rows 0 to `size` (from the top, y = +1) of a map, `row(r)` computing row `r`
/// (`lac::region::row` or `lac::region::compound_row`).
///
/// Shows a progress bar on standard error when it is a terminal, never in pipes or CI.
pub(crate) fn drawable_rows<F>(size: usize, row: F) -> Vec<Vec<bool>>
where
    F: Fn(usize) -> Vec<bool> + Sync,
{
    let progress = progress_bar(size);
    let rows = (0..size)
        .into_par_iter()
        .map(|r| {
            let pixels = row(r);
            progress.inc(1);
            pixels
        })
        .collect();
    progress.finish_and_clear();
    rows
}

fn progress_bar(rows: usize) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(rows as u64);
    if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {eta} left") {
        bar.set_style(style);
    }
    bar
}
