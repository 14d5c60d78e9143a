//! New solids for a teacher who has no file: a box, a right prism or pyramid over a regular
//! n-gon, a tripod of given arm length and width, and the extrusion of a closed outline (the
//! Curves tab's polygon: concave allowed, with an optional hole that is the outline scaled
//! about its centroid). Each is checked before it is built, and a bad one is named: a
//! parameter out of range, an outline that crosses itself (the two segments), a hole that
//! does not fit inside.

use crate::geometry::{outline_meets_itself, segments_meet};
use crate::mesh::PolyMesh;
use crate::primitives;
use glam::{DVec2, DVec3};
use thiserror::Error;

/// The most sides of a prism or pyramid (a circle is better made by subdivision).
pub const MAX_SIDES: u32 = 512;

/// The kinds of solid, as `prism new` and File ▸ New solid… name them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolidKind {
    Box,
    Prism,
    Pyramid,
    Tripod,
    Extrusion,
}

/// The numbers of every kind of solid (each kind reads its own), with the defaults that
/// `prism new` and File ▸ New solid… start from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolidParams {
    /// Box: width, depth, height.
    pub size: DVec3,
    /// Prism, pyramid: sides of the regular base polygon.
    pub sides: u32,
    /// Prism, pyramid: circumradius of the base.
    pub radius: f64,
    /// Prism, pyramid, extrusion: height.
    pub height: f64,
    /// Tripod: arm length.
    pub arm: f64,
    /// Tripod: arm width.
    pub width: f64,
}

impl Default for SolidParams {
    fn default() -> Self {
        SolidParams {
            size: DVec3::new(3.0, 2.0, 1.0),
            sides: 6,
            radius: 1.5,
            height: 2.0,
            arm: 3.0,
            width: 1.0,
        }
    }
}

impl SolidParams {
    /// The solid of `kind` with these numbers; `extrusion` gives an extrusion's outline and
    /// hole scale (only that kind calls it), or why there is none.
    pub fn solid<E>(
        &self,
        kind: SolidKind,
        extrusion: impl FnOnce() -> Result<(Vec<DVec2>, Option<f64>), E>,
    ) -> Result<Solid, E> {
        let (sides, radius, height) = (self.sides, self.radius, self.height);
        Ok(match kind {
            SolidKind::Box => Solid::Box { size: self.size },
            SolidKind::Prism => Solid::Prism {
                sides,
                radius,
                height,
            },
            SolidKind::Pyramid => Solid::Pyramid {
                sides,
                radius,
                height,
            },
            SolidKind::Tripod => Solid::Tripod {
                arm: self.arm,
                width: self.width,
            },
            SolidKind::Extrusion => {
                let (outline, hole) = extrusion()?;
                Solid::Extrusion {
                    outline,
                    height,
                    hole,
                }
            }
        })
    }
}

/// A solid to make, with its parameters.
#[derive(Debug, Clone, PartialEq)]
pub enum Solid {
    /// An axis-aligned box from the origin, `size` its three edge lengths.
    Box { size: DVec3 },
    /// A right prism over the regular `sides`-gon of circumradius `radius`, height `height`.
    Prism {
        sides: u32,
        radius: f64,
        height: f64,
    },
    /// A right pyramid over the regular `sides`-gon of circumradius `radius`.
    Pyramid {
        sides: u32,
        radius: f64,
        height: f64,
    },
    /// Three orthogonal square arms of side `width` and length `arm` joined at a corner
    /// (the bundled tripod is `arm = 3, width = 1`).
    Tripod { arm: f64, width: f64 },
    /// `outline` (closed, either orientation) extruded by `height` along z; with `hole`, a
    /// copy of the outline scaled by it about the outline's centroid is cut through.
    Extrusion {
        outline: Vec<DVec2>,
        height: f64,
        hole: Option<f64>,
    },
}

/// Why a solid could not be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolidError {
    #[error("{name} = {value} is out of range: {expected}")]
    Parameter {
        name: &'static str,
        value: f64,
        expected: &'static str,
    },
    #[error("the outline has {points} point(s): a solid needs a closed outline of at least 3")]
    TooFewPoints { points: usize },
    #[error("the outline encloses no area")]
    NoArea,
    #[error(
        "the outline crosses itself: segment {a} (points {a}-{a1}) meets segment {b} (points {b}-{b1})"
    )]
    SelfIntersecting {
        a: usize,
        a1: usize,
        b: usize,
        b1: usize,
    },
    #[error("the hole (the outline scaled by {scale}) does not fit inside the outline: {why}")]
    HoleOutside { scale: f64, why: &'static str },
}

fn positive(name: &'static str, value: f64) -> Result<f64, SolidError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(SolidError::Parameter {
            name,
            value,
            expected: "a finite length > 0",
        })
    }
}

fn sides(n: u32) -> Result<u32, SolidError> {
    if (3..=MAX_SIDES).contains(&n) {
        Ok(n)
    } else {
        Err(SolidError::Parameter {
            name: "sides",
            value: n as f64,
            expected: "3 to 512",
        })
    }
}

impl Solid {
    /// Builds the solid (closed, outward-facing) or says why it cannot be built.
    pub fn build(&self) -> Result<PolyMesh, SolidError> {
        match self {
            Solid::Box { size } => {
                let s = DVec3::new(
                    positive("width", size.x)?,
                    positive("depth", size.y)?,
                    positive("height", size.z)?,
                );
                Ok(primitives::cuboid(DVec3::ZERO, s))
            }
            Solid::Prism {
                sides: n,
                radius,
                height,
            }
            | Solid::Pyramid {
                sides: n,
                radius,
                height,
            } => {
                let make = match self {
                    Solid::Prism { .. } => primitives::ngon_prism,
                    _ => primitives::pyramid,
                };
                Ok(make(
                    sides(*n)?,
                    positive("radius", *radius)?,
                    positive("height", *height)?,
                ))
            }
            Solid::Tripod { arm, width } => {
                let (arm, width) = (positive("arm", *arm)?, positive("width", *width)?);
                if arm <= width {
                    return Err(SolidError::Parameter {
                        name: "arm",
                        value: arm,
                        expected: "longer than the width",
                    });
                }
                // The unit tripod's coordinates are 0, 1 (the width) and 3 (the arm).
                let mut m = primitives::tripod();
                for p in &mut m.positions {
                    *p = DVec3::from_array(p.to_array().map(|c| {
                        if c == 1.0 {
                            width
                        } else if c == 3.0 {
                            arm
                        } else {
                            c
                        }
                    }));
                }
                Ok(m)
            }
            Solid::Extrusion {
                outline,
                height,
                hole,
            } => extrusion(outline, positive("height", *height)?, *hole),
        }
    }
}

/// Twice the signed area of a closed polygon (positive: counter-clockwise).
fn area2(p: &[DVec2]) -> f64 {
    (0..p.len())
        .map(|i| p[i].perp_dot(p[(i + 1) % p.len()]))
        .sum()
}

/// Whether `q` is inside the closed polygon `p` (even-odd rule).
fn inside(p: &[DVec2], q: DVec2) -> bool {
    let mut c = false;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            c = !c;
        }
    }
    c
}

fn extrusion(outline: &[DVec2], height: f64, hole: Option<f64>) -> Result<PolyMesh, SolidError> {
    // A closing point repeated at the end is the same corner.
    let mut p: Vec<DVec2> = outline.to_vec();
    p.dedup();
    if p.len() > 1 && p.first() == p.last() {
        p.pop();
    }
    if p.len() < 3 {
        return Err(SolidError::TooFewPoints { points: p.len() });
    }
    if let Some(bad) = p.iter().position(|q| !q.is_finite()) {
        return Err(SolidError::Parameter {
            name: "outline point",
            value: bad as f64,
            expected: "finite coordinates",
        });
    }
    if let Some((a, b)) = outline_meets_itself(&p, 0.0) {
        return Err(SolidError::SelfIntersecting {
            a,
            a1: (a + 1) % p.len(),
            b,
            b1: (b + 1) % p.len(),
        });
    }
    let a2 = area2(&p);
    let extent = p.iter().fold(0.0f64, |m, q| m.max(q.length()));
    if a2.abs() <= 1e-12 * extent * extent {
        return Err(SolidError::NoArea);
    }
    if a2 < 0.0 {
        p.reverse();
    }
    let holes = match hole {
        None => Vec::new(),
        Some(s) => {
            if !(s.is_finite() && s > 0.0 && s < 1.0) {
                return Err(SolidError::Parameter {
                    name: "hole scale",
                    value: s,
                    expected: "between 0 and 1",
                });
            }
            // The area centroid: inside every convex outline and most others (`p` now runs
            // counter-clockwise, twice its area is |a2|).
            let c = (0..p.len())
                .map(|i| {
                    let (a, b) = (p[i], p[(i + 1) % p.len()]);
                    (a + b) * a.perp_dot(b)
                })
                .sum::<DVec2>()
                / (3.0 * a2.abs());
            let h: Vec<DVec2> = p.iter().rev().map(|&q| c + s * (q - c)).collect();
            if !inside(&p, c) {
                return Err(SolidError::HoleOutside {
                    scale: s,
                    why: "the outline's centroid is outside it",
                });
            }
            let crosses = (0..h.len()).any(|i| {
                (0..p.len()).any(|j| {
                    segments_meet(h[i], h[(i + 1) % h.len()], p[j], p[(j + 1) % p.len()], 0.0)
                })
            });
            if crosses || !h.iter().all(|&q| inside(&p, q)) {
                return Err(SolidError::HoleOutside {
                    scale: s,
                    why: "it crosses the outline",
                });
            }
            vec![h]
        }
    };
    Ok(primitives::extrude(&p, &holes, 0.0, height))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::signed_volume;
    use crate::topology::Topology;

    fn closed_volume(m: &PolyMesh) -> f64 {
        Topology::build(m).unwrap().require_closed(m).unwrap();
        signed_volume(m)
    }

    #[test]
    fn every_solid_is_closed_with_its_volume() {
        let b = Solid::Box {
            size: DVec3::new(3.0, 2.0, 1.0),
        };
        assert!((closed_volume(&b.build().unwrap()) - 6.0).abs() < 1e-12);
        let t = Solid::Tripod {
            arm: 3.0,
            width: 1.0,
        };
        assert!(t.build().unwrap() == primitives::tripod());
        // Three arms of 2 × 0.5 × 0.5 sharing the corner cube: 3·(0.5·0.5·2) − 2·0.125.
        let t = Solid::Tripod {
            arm: 2.0,
            width: 0.5,
        };
        assert!((closed_volume(&t.build().unwrap()) - 1.25).abs() < 1e-12);
        let py = Solid::Pyramid {
            sides: 4,
            radius: 2f64.sqrt(),
            height: 3.0,
        };
        assert!((closed_volume(&py.build().unwrap()) - 4.0).abs() < 1e-12);
        // A clockwise L outline with a hole of half its size: ¾ of its area, times h.
        let l: Vec<DVec2> = [(0., 0.), (0., 2.), (1., 2.), (1., 1.), (2., 1.), (2., 0.)]
            .map(DVec2::from)
            .to_vec();
        let e = Solid::Extrusion {
            outline: l.clone(),
            height: 0.5,
            hole: Some(0.5),
        };
        let v = closed_volume(&e.build().unwrap());
        assert!((v - 3.0 * 0.75 * 0.5).abs() < 1e-12, "{v}");
    }

    #[test]
    fn bad_solids_are_named() {
        let e = |outline: &[(f64, f64)], hole| {
            Solid::Extrusion {
                outline: outline.iter().map(|&p| DVec2::from(p)).collect(),
                height: 1.0,
                hole,
            }
            .build()
            .unwrap_err()
        };
        assert_eq!(
            e(&[(0., 0.), (1., 0.)], None),
            SolidError::TooFewPoints { points: 2 }
        );
        assert_eq!(e(&[(0., 0.), (1., 0.), (2., 0.)], None), SolidError::NoArea);
        // A bow tie: segment 0 (0-1) crosses segment 2 (2-3).
        let bow = [(0., 0.), (1., 1.), (1., 0.), (0., 1.)];
        assert!(matches!(
            e(&bow, None),
            SolidError::SelfIntersecting { a: 0, b: 2, .. }
        ));
        // A C shape whose centroid lies in its mouth has no room for a scaled hole.
        let c = [
            (0., 0.),
            (3., 0.),
            (3., 0.5),
            (0.5, 0.5),
            (0.5, 2.5),
            (3., 2.5),
            (3., 3.),
            (0., 3.),
        ];
        assert!(matches!(e(&c, Some(0.5)), SolidError::HoleOutside { .. }));
        assert!(matches!(
            e(&[(0., 0.), (1., 0.), (0., 1.)], Some(1.5)),
            SolidError::Parameter { .. }
        ));
        for s in [
            Solid::Prism {
                sides: 2,
                radius: 1.0,
                height: 1.0,
            },
            Solid::Box {
                size: DVec3::new(1.0, f64::NAN, 1.0),
            },
            Solid::Tripod {
                arm: 1.0,
                width: 1.0,
            },
        ] {
            assert!(
                matches!(s.build(), Err(SolidError::Parameter { .. })),
                "{s:?}"
            );
        }
    }
}
