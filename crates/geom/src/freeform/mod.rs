//! The free-form family: curves and patches evaluated exactly rather than refined — rational
//! Bézier curves ([`bezier`]), C2 cubic splines ([`spline`]), bicubic Gregory patches
//! ([`gregory`]), skinning through cross-sections ([`skin`], seed 003) and envelopes of
//! primitives ([`envelope`], seed 004), whose G1 borders share [`g1`]
//! (docs/architecture.md, "Where the free-form family goes").

pub mod bezier;
pub mod envelope;
pub mod g1;
pub mod gregory;
pub mod skin;
pub mod spline;

pub use bezier::RationalBezier;
pub use gregory::Gregory;
pub use skin::{
    Basis, Pairing, SectionInput, Skin, SkinError, SkinOptions, SkinSpec, skin, skin_options,
    skin_with,
};
