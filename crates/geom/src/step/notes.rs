//! A step's report in words ([`StepReport::notes`]): what the preparation and the mending
//! changed and what the check found, one sentence each, the same in the CLI's lines and the
//! app's status bar.

use super::StepReport;

/// What a note is about (the app shows some of them as widgets of their own).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Topic {
    /// Radii lowered to fit their faces ([`StepReport::clamped`]).
    ClampedRadii,
    /// Clamped radii lowered further so that the combination rule reaches them
    /// ([`StepReport::reached`]).
    Reach,
    /// A chamfer's parameter lowered on faces too small for it.
    ClampedFaces,
    /// Doo–Sabin's width offset on concave faces.
    OffsetFaces,
    /// Cut widths the combination rule lowered.
    CappedEdges,
    /// New faces facing against their parent element.
    Flipped,
    /// New faces of (almost) no area.
    Degenerate,
    /// Flat edges merged away before the step.
    Dissolved,
    /// Corners on zero-length edges.
    CollapsedCorners,
    /// Straight corners whose shift was capped.
    GuardedCorners,
    /// What the mending stage changed ([`crate::rules::MendReport`]).
    Mend,
}

/// One sentence of a step's report.
#[derive(Debug, Clone, PartialEq)]
pub struct StepNote {
    /// A warning (something is wrong with the result) rather than a note (something was
    /// changed to keep it sound).
    pub warning: bool,
    pub topic: Topic,
    pub text: String,
}

/// Up to five of `faces`, comma-separated.
fn first(faces: &[u32]) -> String {
    let s: Vec<String> = faces.iter().take(5).map(|f| f.to_string()).collect();
    s.join(", ")
}

impl StepReport {
    /// Every note and warning of the step, in the order the CLI prints them.
    pub fn notes(&self) -> Vec<StepNote> {
        let mut out = Vec::new();
        let mut say = |warning: bool, topic: Topic, text: String| {
            out.push(StepNote {
                warning,
                topic,
                text,
            })
        };
        if !self.clamped.is_empty() {
            say(
                false,
                Topic::ClampedRadii,
                crate::rules::overlap::note(&self.clamped),
            );
        }
        match self.reached {
            Some(crate::rules::Reached {
                cap: Some(cap),
                capped,
                steps,
            }) => say(
                false,
                Topic::Reach,
                format!(
                    "{capped} of them lowered further, to {cap}, the largest radius the combination rule reaches beside the others ({steps} trials, each measured a few levels on)"
                ),
            ),
            Some(crate::rules::Reached { cap: None, .. }) => say(
                true,
                Topic::Reach,
                "the combination rule misses some clamped radii even at the smallest of them (measured a few levels on): the fillets there come out smaller or larger than said".to_string(),
            ),
            None => {}
        }
        if self.clamped_faces > 0 {
            say(
                false,
                Topic::ClampedFaces,
                format!(
                    "l, d or α lowered on {} face(s) too small for it (clamp)",
                    self.clamped_faces
                ),
            );
        }
        if self.offset_faces > 0 {
            say(
                false,
                Topic::OffsetFaces,
                format!(
                    "Doo–Sabin's width offset on {} concave face(s) whose eq. (1) points would turn a strip over (clamp)",
                    self.offset_faces
                ),
            );
        }
        if self.capped_edges > 0 {
            say(
                false,
                Topic::CappedEdges,
                format!(
                    "{} edge(s) cut narrower so that the cut faces keep their edges",
                    self.capped_edges
                ),
            );
        }
        if !self.flipped.is_empty() {
            say(
                true,
                Topic::Flipped,
                format!(
                    "{} face(s) flipped (normal against their parent's), e.g. face(s) {}",
                    self.flipped.len(),
                    first(&self.flipped)
                ),
            );
        }
        if !self.degenerate.is_empty() {
            say(
                true,
                Topic::Degenerate,
                format!(
                    "{} face(s) of (almost) no area, e.g. face(s) {}",
                    self.degenerate.len(),
                    first(&self.degenerate)
                ),
            );
        }
        if self.dissolved_edges > 0 {
            say(
                false,
                Topic::Dissolved,
                format!(
                    "{} flat edge(s) dissolved first (coplanar faces merged)",
                    self.dissolved_edges
                ),
            );
        }
        if self.collapsed_corners > 0 {
            say(
                true,
                Topic::CollapsedCorners,
                format!(
                    "{} corner(s) on collapsed edges kept at their vertex",
                    self.collapsed_corners
                ),
            );
        }
        for text in self.mend.notes() {
            say(false, Topic::Mend, text);
        }
        if self.guarded_corners > 0 {
            say(
                false,
                Topic::GuardedCorners,
                format!(
                    "{} straight corner(s) with unequal cut widths capped",
                    self.guarded_corners
                ),
            );
        }
        out
    }
}
