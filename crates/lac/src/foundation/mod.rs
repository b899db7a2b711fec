//! Layer 0, the foundations: what every other layer uses and which uses nothing of the
//! crate above it. The error type (every error of the crate, [`error`]), safeguarded numerics
//! and root finding ([`numeric`]), Gauss–Legendre rules ([`gauss`]), the Fresnel integrals of
//! the clothoid ([`fresnel`]), the 3-D vector ([`vec3`]), the turning direction ([`turn`]) and
//! tolerances ([`tolerance`]).

pub(crate) mod error;
pub(crate) mod fresnel;
pub(crate) mod gauss;
pub(crate) mod numeric;
pub(crate) mod tolerance;
pub(crate) mod turn;
pub(crate) mod vec3;
