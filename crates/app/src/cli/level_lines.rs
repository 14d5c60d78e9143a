//! What `prism subdivide` and `prism render` say of every level: the step's notes and
//! warnings in the words the app's status bar uses too ([`StepReport::notes`]), then the
//! volume's.

use prism_geom::StepReport;

/// A level whose volume differs from the level before's by more than this factor is
/// named (a subdivision step changes the volume by a few per cent).
const VOLUME_JUMP: f64 = 10.0;

/// What `subdivide` and `render` say of every level: its warnings in words (a step that
/// turns the solid inside out fails in the pipeline itself, `StepError::InsideOut`).
pub struct LevelWarnings {
    /// The signed volume of the level before.
    volume: f64,
}

impl LevelWarnings {
    pub fn new(input: &prism_geom::PolyMesh) -> LevelWarnings {
        LevelWarnings {
            volume: prism_geom::geometry::signed_volume(input),
        }
    }

    /// Prints the warnings of level `k`, whose step reported `r`.
    pub fn level(&mut self, k: usize, r: &StepReport) {
        let before = std::mem::replace(&mut self.volume, r.volume);
        warn_level(k, r, before);
    }
}

/// Prints one level's warnings ([`level_lines`]).
fn warn_level(k: usize, r: &StepReport, before: f64) {
    for line in level_lines(k, r, before) {
        eprintln!("{line}");
    }
}

/// One level's notes and warnings as the CLI prints them: the step's own
/// ([`StepReport::notes`], the words the app's status bar shows too), then the volume's;
/// `before` is the signed volume of the level before.
pub fn level_lines(k: usize, r: &StepReport, before: f64) -> Vec<String> {
    let mut out: Vec<String> = r
        .notes()
        .into_iter()
        .map(|n| {
            let kind = if n.warning { "warning" } else { "note" };
            format!("{kind}: level {k}: {}", n.text)
        })
        .collect();
    if before > 0.0
        && r.volume > 0.0
        && (r.volume / before > VOLUME_JUMP || before / r.volume > VOLUME_JUMP)
    {
        out.push(format!(
            "warning: level {k}: the volume jumped from {before:.4e} to {:.4e} (the surface folds through itself)",
            r.volume
        ));
    }
    if r.volume < 0.0 && before <= 0.0 {
        out.push(format!(
            "warning: level {k}: the solid is inside out (signed volume {:.4e})",
            r.volume
        ));
    }
    out
}
