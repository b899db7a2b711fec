//! What one request may ask for: every number a client sends that sizes the work or the
//! answer is checked against these before anything is allocated.

use std::time::Duration;

use lac_io::json::ErrorBody;

/// Bounds on requests. [`Limits::default`] suits one designer on a laptop: every answer
/// within the limits takes milliseconds, the largest maps a fraction of a second.
#[derive(Clone, Debug)]
pub struct Limits {
    /// Largest request body, bytes (larger: 413).
    pub body_bytes: usize,
    /// Samples of a curve when the request gives none.
    pub default_samples: usize,
    /// Most samples (and curvature-plot points) of one curve.
    pub max_samples: usize,
    /// Most curvature-plot points and Bézier samples over all the pieces of a chain.
    pub max_piece_points: usize,
    /// Most points of one fit (`/api/fit`).
    pub max_fit_points: usize,
    /// Pixels per side of a region map when the request gives none.
    pub default_region_size: usize,
    /// Most pixels per side of the canonical region map (`/api/region`).
    pub max_region_size: usize,
    /// Most pixels per side of one point's region (`/api/region/point`).
    pub max_point_region_size: usize,
    /// Requests solved at once (each on a thread of the blocking pool); others wait.
    pub compute_slots: usize,
    /// Requests accepted at once, waiting or working; others wait for a place.
    pub in_flight: usize,
    /// A request still waiting or working after this long is answered 503.
    pub timeout: Duration,
    /// Canonical region maps kept (they depend only on α, or α0, α1 and the ratio).
    pub cached_regions: usize,
    /// The smallest export tolerance, relative to the arc length (`/api/export`): tighter
    /// ones take many pieces (space curves: error ∝ h⁴) and seconds of work.
    pub min_export_relative_tolerance: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            body_bytes: 64 * 1024,
            default_samples: 201,
            max_samples: 10_000,
            max_piece_points: 20_000,
            max_fit_points: 20_000,
            default_region_size: 128,
            max_region_size: 256,
            max_point_region_size: 128,
            compute_slots: std::thread::available_parallelism().map_or(2, |n| n.get()),
            in_flight: 256,
            timeout: Duration::from_secs(10),
            cached_regions: 32,
            min_export_relative_tolerance: 1e-10,
        }
    }
}

impl Limits {
    /// The sample count asked for (or the default), if within 2..=`max_samples`.
    pub(crate) fn samples(&self, asked: Option<usize>) -> Result<usize, ErrorBody> {
        within(
            "samples",
            asked.unwrap_or(self.default_samples),
            2,
            self.max_samples,
        )
    }

    /// The pixels per side of a canonical region map.
    pub(crate) fn region_size(&self, asked: Option<usize>) -> Result<usize, ErrorBody> {
        let size = asked.unwrap_or(self.default_region_size);
        within("size", size, 1, self.max_region_size)
    }

    /// The pixels per side of one point's region map.
    pub(crate) fn point_region_size(&self, asked: Option<usize>) -> Result<usize, ErrorBody> {
        let size = asked.unwrap_or(self.default_region_size.min(self.max_point_region_size));
        within("size", size, 1, self.max_point_region_size)
    }
}

fn within(name: &str, value: usize, min: usize, max: usize) -> Result<usize, ErrorBody> {
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(ErrorBody::limit(format!(
            "{name} = {value} is outside what this server computes: give {min} to {max}"
        )))
    }
}
