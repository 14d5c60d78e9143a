//! How neighbouring sections of a skin are paired, and what is refused or named
//! (docs/algorithms/skin.md, "Correspondence", "Crossings"): a section that turns steadily
//! keeps its natural pairing at any turn up to a quarter turn a section (the paper's least
//! twist pairs corners with sides past 180°/n and the skin crumples), sections that are not
//! star-shaped are refused whatever their counts, a skin through itself is found and named by
//! its cells, and a skin that turns back is refused.

use glam::DVec3;
use prism_geom::freeform::skin::Cell;
use prism_geom::freeform::{
    Pairing, SectionInput, Skin, SkinError, SkinOptions, skin, skin_options,
};
use proptest::prelude::*;

fn built(input: &[SectionInput], pairing: Pairing) -> Skin {
    let options = SkinOptions {
        pairing,
        ..SkinOptions::default()
    };
    skin_options(input, options).unwrap()
}

/// The closed outline through `corners` with `per_side` points a side (corners included).
fn outline(corners: &[(f64, f64)], per_side: usize) -> Vec<(f64, f64)> {
    let n = corners.len();
    (0..n)
        .flat_map(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % n]);
            (0..per_side).map(move |j| {
                let t = j as f64 / per_side as f64;
                (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
            })
        })
        .collect()
}

/// `m` sections of `shape` one apart along z, section k turned by k·`turn` degrees; every
/// point a corner when `polygon`.
fn turning_polygon(shape: &[(f64, f64)], turn: f64, m: usize, polygon: bool) -> Vec<SectionInput> {
    (0..m)
        .map(|k| {
            let a = (turn * k as f64).to_radians();
            let points = shape
                .iter()
                .map(|&(x, y)| {
                    DVec3::new(
                        x * a.cos() - y * a.sin(),
                        x * a.sin() + y * a.cos(),
                        k as f64,
                    )
                })
                .collect();
            SectionInput {
                points,
                polygon,
                ..SectionInput::default()
            }
        })
        .collect()
}

/// [`turning_polygon`] with smooth section curves.
fn turning(shape: &[(f64, f64)], turn: f64, m: usize) -> Vec<SectionInput> {
    turning_polygon(shape, turn, m, false)
}

/// The largest distance of the mesh (K = 8) from the twisted bar — section 0's curve turned
/// continuously by `turn` degrees a unit of height — as a share of the section's size: a skin
/// that follows the turn stays within a few hundredths, a crumpled one swings a tenth and more
/// off it.
fn off_the_bar(s: &Skin, turn: f64) -> f64 {
    let m = s.tessellate(8, false).unwrap();
    let sec = &s.sections[0];
    let curve: Vec<DVec3> = sec
        .curve
        .iter()
        .flat_map(|c| (0..64).map(move |j| prism_geom::freeform::spline::eval(c, j as f64 / 64.0)))
        .collect();
    let size = sec.points.iter().map(|p| p.length()).fold(0.0, f64::max);
    let worst = m
        .positions
        .iter()
        .map(|p| {
            let a = -(turn * p.z).to_radians();
            let q = DVec3::new(
                p.x * a.cos() - p.y * a.sin(),
                p.x * a.sin() + p.y * a.cos(),
                0.0,
            );
            curve
                .iter()
                .map(|c| (*c - q).length())
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    worst / size
}

/// The case: a 2 × 1 rectangle of 8 points turned 25° a section. The paper's least
/// twist pairs corners with side midpoints (shift 7, 160° against 200°) and the skin swings
/// far off the twisted bar; the shape pairing keeps shift 0 and follows it.
#[test]
fn the_papers_pairing_crumples_a_turning_rectangle_and_the_shape_pairing_does_not() {
    let rect = outline(&[(1.0, -0.5), (1.0, 0.5), (-1.0, 0.5), (-1.0, -0.5)], 2);
    let input = turning(&rect, 25.0, 5);
    let paper = built(&input, Pairing::Paper);
    assert_eq!(paper.shifts, vec![7; 4]);
    let off = off_the_bar(&paper, 25.0);
    assert!(off > 0.1, "{off}");
    let shape = built(&input, Pairing::Shape);
    assert_eq!(shape.shifts, vec![0; 4]);
    for t in &shape.twists {
        assert!((t.to_degrees() - 200.0).abs() < 1e-6, "{t}");
    }
    let off = off_the_bar(&shape, 25.0);
    assert!(off < 0.02, "{off}");
}

/// The shapes of the generated turning skins: a rectangle of aspect 1.5–3 (4–16 points), a
/// scalene triangle (6–15 points), an L polygon (6–12 points, arms 1.5–2 long and 1 wide, so
/// that it is star-shaped about its centroid) — none with a symmetry a turn of up to 60° could
/// be mistaken for.
fn shape(kind: u8, aspect: f64, per_side: usize) -> Vec<(f64, f64)> {
    match kind {
        0 => {
            let (w, h) = (aspect, 1.0);
            outline(
                &[(w, -h), (w, h), (-w, h), (-w, -h)].map(|(x, y)| (x / 2.0, y / 2.0)),
                per_side.clamp(1, 4),
            )
        }
        1 => outline(
            &[(1.2, -0.5), (-0.3, 1.0 + 0.2 * aspect), (-0.9, -0.5)],
            (per_side + 1).clamp(2, 5),
        ),
        _ => {
            let a = 1.5 + (aspect - 1.5) / 3.0;
            outline(
                &[
                    (0.0, 0.0),
                    (a, 0.0),
                    (a, 1.0),
                    (1.0, 1.0),
                    (1.0, 2.0),
                    (0.0, 2.0),
                ],
                per_side.clamp(1, 2),
            )
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// Rectangles, triangles and L-shapes of 4–16 points turned by 0–60° a section, 3–8
    /// sections: the shape pairing keeps the natural pairing (shift 0, each pair's twist the
    /// section's turn times its points) and the skin stays on the twisted bar.
    #[test]
    fn a_steadily_turning_section_follows_its_turn(
        kind in 0u8..3,
        aspect in 1.5f64..3.0,
        per_side in 1usize..5,
        turn in 0.0f64..60.0,
        m in 3usize..9,
    ) {
        let outline = shape(kind, aspect, per_side);
        let polygon = kind == 2;
        // Centred on the area centroid, so that the turn is about the section's centre.
        let s = built(&turning_polygon(&outline, 0.0, 1 + 1, polygon), Pairing::Shape);
        let c = s.sections[0].centre;
        let shifted: Vec<(f64, f64)> = outline.iter().map(|&(x, y)| (x - c.x, y - c.y)).collect();
        let s = built(&turning_polygon(&shifted, turn, m, polygon), Pairing::Shape);
        prop_assert_eq!(&s.shifts, &vec![0; m - 1]);
        let off = off_the_bar(&s, turn);
        prop_assert!(off < 0.1, "{} points turned {turn:.1}°: {off:.3} off the bar", outline.len());
    }
}

/// Seed 003 fig. 3: four square sections whose lists start at different corners pair alike by
/// shape and by the paper's least twist — the chain from vertex 1 of the first section runs
/// through V₁₁, V₂₄, V₃₁, V₄₂ (1-based) either way.
#[test]
fn figure_3_pairs_alike_by_shape_and_by_least_twist() {
    let start = [0usize, 3, 0, 1];
    let input: Vec<SectionInput> = start
        .iter()
        .enumerate()
        .map(|(k, &c)| SectionInput {
            points: (0..4)
                .map(|i| {
                    let j = (i + 4 - c) % 4;
                    let a = std::f64::consts::FRAC_PI_4 + j as f64 * std::f64::consts::FRAC_PI_2;
                    DVec3::new(a.cos(), a.sin(), k as f64)
                })
                .collect(),
            ..SectionInput::default()
        })
        .collect();
    for pairing in [Pairing::Shape, Pairing::Paper] {
        let s = built(&input, pairing);
        let chain0: Vec<usize> = (0..4)
            .map(|k| s.sections[k].original[s.offset[k]] + 1)
            .collect();
        assert_eq!(chain0, vec![1, 4, 1, 2], "{pairing:?}");
    }
}

/// A C-shaped section among sections of the same count, and of other counts: refused by name
/// either way (its rays from the centre meet its curve more than once; at equal counts it gave
/// a skin through itself).
#[test]
fn sections_not_star_shaped_are_refused_whatever_the_counts() {
    let square = |z: f64| SectionInput {
        points: outline(&[(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)], 2)
            .into_iter()
            .map(|(x, y)| DVec3::new(x, y, z))
            .collect(),
        ..SectionInput::default()
    };
    let c = SectionInput {
        points: [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 0.5],
            [0.5, 0.5],
            [0.5, 1.5],
            [2.0, 1.5],
            [2.0, 2.0],
            [0.0, 2.0],
        ]
        .iter()
        .map(|p| DVec3::new(p[0] - 1.0, p[1] - 1.0, 1.0))
        .collect(),
        ..SectionInput::default()
    };
    let input = vec![square(0.0), c, square(2.0)];
    assert_eq!(input[0].points.len(), input[1].points.len());
    let e = skin(&input).unwrap_err();
    assert!(
        matches!(e, SkinError::NotStarShaped { section: 1, .. }),
        "{e}"
    );
    assert!(
        e.to_string().contains("section 1 is not star-shaped"),
        "{e}"
    );
}

/// A circle of 12 points, in the plane through `c` with normal `n`.
fn circle(c: DVec3, n: DVec3, r: f64) -> SectionInput {
    let q = glam::DQuat::from_rotation_arc(DVec3::Z, n.normalize());
    SectionInput {
        points: (0..12)
            .map(|i| {
                let t = i as f64 / 12.0 * std::f64::consts::TAU;
                c + q * DVec3::new(r * t.cos(), r * t.sin(), 0.0)
            })
            .collect(),
        ..SectionInput::default()
    }
}

/// A tube of 12 circles around a ring of radius 2 through 440°: each pair of neighbours is
/// fine, but the last part runs through the first — found and named by the cells (patches
/// between sections on chains, caps) and the sections they touch; a plain tube passes through
/// nothing.
#[test]
fn a_skin_through_itself_is_found_and_named_by_its_cells() {
    let ring: Vec<SectionInput> = (0..12)
        .map(|k| {
            let a = (40.0 * k as f64).to_radians();
            let c = DVec3::new(2.0 * a.cos(), 2.0 * a.sin(), 0.1 * k as f64);
            circle(c, DVec3::new(-a.sin(), a.cos(), 0.0), 0.6)
        })
        .collect();
    let s = skin(&ring).unwrap();
    let mesh = s.tessellate(8, true).unwrap();
    let c = s.crossings(&mesh, 8);
    assert!(c.faces > 0);
    assert_eq!(c.points.len(), c.faces);
    let sections = c.sections();
    assert!(
        sections.contains(&0) && sections.contains(&10),
        "{sections:?}"
    );
    let w = c.warning().unwrap();
    assert!(
        w.contains("passes through itself") && w.contains("near sections 0, 1"),
        "{w}"
    );
    // Every face maps to its cell: the first quad to patch (0, 0), the caps last.
    assert_eq!(
        s.cell_of(0, 8),
        Cell::Patch {
            section: 0,
            chain: 0
        }
    );
    assert_eq!(s.cell_of(mesh.num_faces() - 2, 8), Cell::Cap { section: 0 });
    assert_eq!(
        s.cell_of(mesh.num_faces() - 1, 8),
        Cell::Cap { section: 11 }
    );
    let tube = vec![
        circle(DVec3::ZERO, DVec3::Z, 1.0),
        circle(DVec3::Z, DVec3::Z, 0.8),
        circle(DVec3::new(0.3, 0.0, 2.0), DVec3::new(0.2, 0.0, 1.0), 1.0),
    ];
    let s = skin(&tube).unwrap();
    let mesh = s.tessellate(8, true).unwrap();
    assert_eq!(s.crossings(&mesh, 8).warning(), None);
}

/// Sections A, B, A (the last repeating the first, as when closing a loop): the chains stop at
/// B and turn back, which left the patches beside it without a normal (NaN points); refused,
/// naming the section where the skin turns back. A section tilted past its neighbours is
/// refused alike.
#[test]
fn a_skin_that_turns_back_is_refused_naming_the_section() {
    let a = circle(DVec3::ZERO, DVec3::Z, 1.0);
    let b = circle(DVec3::Z, DVec3::Z, 0.8);
    let e = skin(&[a.clone(), b, a.clone()]).unwrap_err();
    assert!(matches!(e, SkinError::TurnsBack { section: 1, .. }), "{e}");
    assert!(e.to_string().contains("turns back at section 1"), "{e}");
    let tilted = circle(DVec3::new(0.0, 0.0, 0.4), DVec3::new(1.0, 0.0, 0.3), 1.0);
    let e = skin(&[a, tilted]).unwrap_err();
    assert!(matches!(e, SkinError::TurnsBack { .. }), "{e}");
}

/// The bundled spout, wing and pitched wing pair alike by shape and by the paper's least twist
/// (sections of different shapes are the paper's own case): the same shifts and twists.
#[test]
fn the_bundled_skins_pair_alike_under_both_criteria() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    for name in ["spout", "wing", "wing-pitched"] {
        let text = std::fs::read_to_string(dir.join(format!("{name}.skin.json"))).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let input: Vec<SectionInput> = serde_json::from_value(v["sections"].clone()).unwrap();
        let (shape, paper) = (built(&input, Pairing::Shape), built(&input, Pairing::Paper));
        assert_eq!(shape.shifts, paper.shifts, "{name}");
        assert_eq!(shape.twists, paper.twists, "{name}");
    }
}
