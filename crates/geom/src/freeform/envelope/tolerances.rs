//! Every tolerance and tuned constant of the envelope's construction, in one documented struct
//! (docs/algorithms/envelope.md, "Tolerances"). The modules read their values from
//! [`TOLERANCES`]; lengths are shares of a primitive's sphere radius r or of the scene's local
//! frame (`local.rs`), angles radians unless said.

/// The envelope's tolerances, by stage.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    // --- The primitives and the hull (`primitive.rs`, `hull.rs`) ---
    /// Share of r for "on the sphere", "planar face", "convex" and "centre inside".
    pub primitive: f64,
    /// A primitive whose centre lies within this share of its radius of the hull of the others'
    /// centres is swallowed: its part would be a sliver.
    pub swallow: f64,

    // --- Clipping by the silhouette planes (`clip.rs`) ---
    /// Share of r for "on a cut plane".
    pub on_plane: f64,
    /// Unit directions closer than this are one network vertex.
    pub same_direction: f64,
    /// The cell of the directions' lookup (much larger than `same_direction`, so that a lookup
    /// meets one or two cells a side).
    pub direction_cell: f64,
    /// Corners inside one face closer than about this share of r across it are drawn to one
    /// distance from the centre (envelope.md, "Corners inside a face").
    pub near_inside: f64,
    /// A silhouette piece whose leg at either end is shorter than this share of its chord is
    /// treated as hooked and rebuilt as a cubic a third of its chord long (envelope.md, "Nearly
    /// hooked pieces"). An arc normal to two radii of equal length has legs of at least a
    /// third of its chord, so t = 1 never meets it.
    pub near_hook: f64,
    /// The same for a kept piece of a primitive's edge between a corner and a silhouette point.
    pub near_hook_edge: f64,

    // --- Fusion and the network (`fusion.rs`, `network.rs`) ---
    /// Section angles closer than this are one.
    pub same_angle: f64,
    /// How far a chain's end may lie from its ray (rounding only: both are where the same two
    /// cuts cross).
    pub end_angle: f64,
    /// The paper's patches only: section points of the two sides closer in angle than this,
    /// each the other's nearest, pair up instead of each inserting a T-point (a fusion quad this
    /// thin between them). The charts pair equal angles only, so that every fusion edge lies in
    /// a half-plane through the axis.
    pub near_angle: f64,
    /// The paper's patches only: legs closer to antiparallel than this continue each other
    /// (rule (a) of §8.2).
    pub straight_legs: f64,
    /// The paper's patches only: rule (a) where the crossing curves leave a curve at a sine of
    /// at least this; a grazing crossing would turn the cross derivative along the curve.
    pub grazing: f64,
    /// The paper's patches only: λ₀ of §11.7 step 5, the least leg an insertion curve leaves
    /// the inserted point with, in units of b_k.
    pub lambda_min: f64,

    /// Resolution of the envelope of the others about which a primitive inside a larger one's
    /// sphere is tested (`nested.rs`) …
    pub nested_resolution: usize,
    /// … and of the candidate, whose vertices are tested.
    pub candidate_resolution: usize,

    // --- The charts (`chart/`) ---
    /// Chart directions of consecutive sides closer than this (sine) are one straight side (a
    /// T-point, or a curve split where another region's corner lies on it).
    pub straight_sides: f64,

    // --- Enclosure: the strips' lifts and the regions' raises (`chart/lift.rs`) ---
    /// A lifted or raised point clears the primitive's point by this share of its distance from
    /// the axis (the chart's value).
    pub margin: f64,
    /// A point less than this share under the surface gets its term too, and is cleared by
    /// `margin` (the mesh's chords would otherwise leave it just outside); one further under is
    /// left as it lies.
    pub trigger: f64,
    /// The half-width of a lift's term about the axis.
    pub width: f64,
    /// A lift or raise reaches a point at most this share of the surface's value above it;
    /// further out it is taken to lie beyond another part of the surface.
    pub raise_reach: f64,
    /// A point over a lid is held by a strip's lift only this share of the strip's length or
    /// more from its ends (nearer, where the strips about a lid's corner meet, the lid's raise).
    pub lid_corner: f64,
    /// A lift is whole up to this multiple of the largest radius it lifts a point to …
    pub lift_inner: f64,
    /// … and fades out by this multiple of that.
    pub lift_reach: f64,
    /// The terms of a lift or raise are joined by their p-norm, `(Σ tᵢᵖ)^(1/p)`: at least the
    /// largest term and at most `n^(1/p)` times it, where a sum would pile up into wrinkles.
    pub smooth_max: i32,
    /// Points along each edge of a primitive that the lifts and raises hold, besides its ends.
    pub edge_points: usize,

    // --- The mesh (`chart/mesh.rs`) ---
    /// The refinement's least triangle angle, degrees (Ruppert's algorithm terminates for
    /// limits up to about 20.7°; border segments that meet at a smaller angle keep what they
    /// force).
    pub angle_limit: f64,
    /// How fast the spacing along a curve may grow away from a short piece: each border segment
    /// at most this many times the one before.
    pub growth: f64,
    /// Curve parameters closer than this are one sample (both meshes).
    pub same_parameter: f64,
}

/// The tolerances the envelope is built with.
pub const TOLERANCES: Tolerances = Tolerances {
    primitive: 1e-6,
    swallow: 0.1,
    on_plane: 1e-9,
    same_direction: 1e-9,
    direction_cell: 1e-6,
    near_inside: 0.03,
    near_hook: 0.15,
    near_hook_edge: 0.05,
    same_angle: 1e-9,
    end_angle: 1e-7,
    near_angle: 0.02,
    straight_legs: 1e-9,
    grazing: 0.5,
    lambda_min: 0.25,
    nested_resolution: 4,
    candidate_resolution: 2,
    straight_sides: 1e-7,
    margin: 0.05,
    trigger: 0.05,
    width: 0.5,
    raise_reach: 0.5,
    lid_corner: 0.3,
    lift_inner: 1.25,
    lift_reach: 2.5,
    smooth_max: 6,
    edge_points: 3,
    angle_limit: 20.0,
    growth: 1.5,
    same_parameter: 1e-12,
};

impl Default for Tolerances {
    fn default() -> Self {
        TOLERANCES
    }
}
