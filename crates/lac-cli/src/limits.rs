//! Work limits: how much one command may be asked to do, so that none needs more than about
//! 1 GB of memory or a few seconds unless `--allow-large` says so.
//!
//! The figures behind them (two cores): 1,000,000 samples of a segment take 1.4 s and 170 MB
//! (130 MB of JSON), of a space curve with `--frames` 3 s and 480 MB; a region map of 2048²
//! pixels takes about 10 s for segments and 30 s for compound curves, and the time grows
//! with the number of pixels. The library's own ceiling is 10,000,000 samples.

use lac_io::json::ErrorBody;

/// The limits in force: the defaults, or the large ones of `--allow-large`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    large: bool,
}

/// Most samples (or curvature points in all) by default, and with `--allow-large`.
const SAMPLES: [usize; 2] = [1_000_000, 10_000_000];
/// Most points of one fit (`lac fit`): 5,000 noisy points take 0.2 s, 100,000 about 30 s,
/// and a million did not finish in two minutes (two cores).
const POINTS: [usize; 2] = [20_000, 1_000_000];
/// Most pixels per side of a region map.
const SIZE: [usize; 2] = [2048, 8192];
/// Longest `--batch` line, bytes.
const LINE: [usize; 2] = [1 << 20, 64 << 20];
/// Longest JSON document read by `lac lcg` and `lac monotone`, bytes.
const DOCUMENT: [usize; 2] = [64 << 20, 1 << 30];

impl Limits {
    /// The limits, large with `--allow-large`.
    pub(crate) fn new(allow_large: bool) -> Limits {
        Limits { large: allow_large }
    }

    fn pick(self, limits: [usize; 2]) -> usize {
        limits[usize::from(self.large)]
    }

    /// `n` samples asked for with `flag` (e.g. "--samples"), or why that is too many.
    pub(crate) fn samples(self, n: usize, flag: &str) -> Result<usize, ErrorBody> {
        self.check(n, self.pick(SAMPLES), flag, "samples")
    }

    /// `n` points to fit, or why that is too many.
    pub(crate) fn points(self, n: usize) -> Result<usize, ErrorBody> {
        self.check(n, self.pick(POINTS), "the input", "points")
    }

    /// `n` pixels per side of a region map, or why that is too many.
    pub(crate) fn size(self, n: usize) -> Result<usize, ErrorBody> {
        self.check(n, self.pick(SIZE), "--size", "pixels per side")
    }

    /// The longest `--batch` line, bytes.
    pub(crate) fn line(self) -> usize {
        self.pick(LINE)
    }

    /// The longest input document, bytes.
    pub(crate) fn document(self) -> usize {
        self.pick(DOCUMENT)
    }

    fn check(self, n: usize, most: usize, flag: &str, what: &str) -> Result<usize, ErrorBody> {
        if n <= most {
            return Ok(n);
        }
        let raise = if self.large {
            String::from("this is the most lac does")
        } else {
            format!(
                "--allow-large raises it to {}, at the cost of several GB and minutes",
                thousands(self.with_large().pick(match what {
                    "pixels per side" => SIZE,
                    "points" => POINTS,
                    _ => SAMPLES,
                }))
            )
        };
        Err(ErrorBody::limit(format!(
            "{flag} asks for {} {what}, over the limit of {}; {raise}",
            thousands(n),
            thousands(most)
        )))
    }

    fn with_large(self) -> Limits {
        Limits { large: true }
    }
}

/// `n` with thousands separated by commas: 1,000,000.
pub(crate) fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// `bytes` as "1 MiB", "64 MiB", "1 GiB".
pub(crate) fn mebibytes(bytes: usize) -> String {
    if bytes >= 1 << 30 {
        format!("{} GiB", bytes >> 30)
    } else {
        format!("{} MiB", bytes >> 20)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_say_how_far_to_go_and_how_to_go_further() {
        let normal = Limits::new(false);
        assert_eq!(normal.samples(1_000_000, "--samples").unwrap(), 1_000_000);
        let err = normal.samples(1_000_001, "--samples").unwrap_err();
        assert_eq!(err.kind, "limit");
        assert!(err.message.contains("1,000,000") && err.message.contains("--allow-large"));
        assert!(err.message.contains("10,000,000"), "{}", err.message);
        let large = Limits::new(true);
        assert!(large.samples(10_000_000, "--samples").is_ok());
        assert!(large.size(8193).unwrap_err().message.contains("the most"));
        assert_eq!(
            (normal.line(), mebibytes(normal.line())),
            (1 << 20, "1 MiB".into())
        );
        assert_eq!(thousands(1234), "1,234");
        assert_eq!(thousands(12), "12");
    }
}
