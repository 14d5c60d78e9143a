//! What the views compute with: the clamp and the mending of crossings, and the memory
//! guard's question when a pipeline would not fit its budget (compute anyway, keep fewer
//! levels, or drop the step).

use super::*;

impl ModelTab {
    pub(super) fn budget_question(&mut self, ctx: &egui::Context) {
        let Some((view, o)) = self.question.clone() else {
            return;
        };
        egui::Modal::new(egui::Id::unique("prism-budget-question")).show(ctx, |ui| {
            ui.heading("This step needs a lot of memory");
            ui.label(format!(
                "View {}: the next level would have {} faces and need about {} MiB; the budget is {} MiB.",
                view + 1,
                o.faces,
                o.needed_mib,
                o.budget_mib
            ));
            ui.horizontal(|ui| {
                if ui.button("Compute anyway").clicked() {
                    self.push(Command::ComputeAnyway);
                }
                if ui.button("Remove the step").clicked() {
                    self.push(Command::RemoveOverBudgetStep);
                }
                if ui
                    .button("Keep only the last level")
                    .on_hover_text(
                        "free the levels between the input and the last (the level slider then \
                         shows those two) and go on within the budget",
                    )
                    .clicked()
                {
                    self.push(Command::DropKeptLevels);
                }
            });
        });
    }

    /// What the views do with radii that do not fit ([`ModelTab::clamp`]).
    pub fn overlap(&self) -> prism_geom::rules::Overlap {
        prism_geom::rules::Overlap::clamping(self.clamp)
    }

    /// Turns mending crossings on or off: every view computes its levels again.
    pub fn set_mend_crossings(&mut self, on: bool) {
        self.mend_crossings = on;
        for v in &mut self.views {
            v.mend_crossings = on;
        }
        self.synced = None;
    }

    /// Turns clamping on or off: every view computes its levels again.
    pub fn set_clamp(&mut self, on: bool) {
        self.clamp = on;
        let overlap = self.overlap();
        for v in &mut self.views {
            v.overlap = overlap;
        }
        self.synced = None;
    }

    /// The answer "compute anyway" to the budget question.
    pub fn compute_anyway(&mut self, doc: &DocState) {
        if let Some((view, o)) = self.question.take() {
            let v = &mut self.views[view];
            v.budget_override = Some((o.needed_mib + o.needed_mib / 4 + 16) << 20);
            self.compute_on(view, doc);
        }
    }

    /// After an answer to the memory question: view `view` computes its missing levels from
    /// the ones it has.
    pub(super) fn compute_on(&mut self, view: usize, doc: &DocState) {
        let v = &mut self.views[view];
        let next = v.pipeline.rebased(doc.pipelines[view].clone());
        v.submit(next, self.budget_mib << 20, false, &self.waker);
    }

    /// The answer "keep only the last level": the view keeps the input, the level each
    /// rounding run starts from and the newest ([`Keep::Needed`]), frees the others now, and
    /// computes on within the budget (asking again if even that is too much).
    pub fn drop_kept_levels(&mut self, doc: &DocState) {
        if let Some((view, _)) = self.question.take() {
            let v = &mut self.views[view];
            v.keep = prism_geom::pipeline::Keep::Needed;
            v.pipeline.keep = v.keep;
            v.pipeline.release_unneeded();
            self.compute_on(view, doc);
        }
    }

    /// The answer "remove the step": the pipeline keeps the levels that were computed.
    pub fn remove_over_budget_step(&mut self) -> Option<Edit> {
        let (view, _) = self.question.take()?;
        let len = self.views[view].pipeline.levels().len() - 1;
        Some(Edit::TruncateSteps { view, len })
    }
}
