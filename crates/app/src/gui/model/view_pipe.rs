//! One view's pipeline: the last computed result on screen, the job computing the next one,
//! the scene of the level shown and the overlay drawn over it (cages, marked and selected
//! edges, points, normals), and caches that depend on the level (edge lists, edge origins,
//! limit points). Every cache is keyed on what it was made from — the result's generation,
//! the level, the display options — so nothing has to remember to mark it stale.

use super::crossing_check::{CrossingCheck, Crossings};
use super::worker::{Finished, Job, over_budget};
use crate::gui::waker::Waker;
use prism_geom::ancestry::edge_origins;
use prism_geom::error::OverBudget;
use prism_geom::rules::Overlap;
use prism_geom::{EdgeKey, Level, LimitPoints, Pipeline, Scheme};
use prism_viewport::scene::{FLIPPED_COLOR, scheme_color};
use prism_viewport::{ColorBy, Scene, SceneOptions};
use std::collections::HashMap;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, TryRecvError};

/// Levels with more corners than this get their scene prepared on a thread; smaller ones
/// right away (100 000 triangles: about 30 ms flat, 50 ms smooth, scaled from the
/// 1M-triangle benchmark in docs/performance.md).
const ASYNC_SCENE_CORNERS: usize = 200_000;

/// The step that made level `k` of `p` (none for the input).
fn made_by(p: &Pipeline, k: usize) -> Option<Scheme> {
    k.checked_sub(1).and_then(|s| p.steps().get(s)).copied()
}

/// The scene of a level: its faces (holes left out), coloured by kind, curvature or, for a
/// solid colour, by the scheme of the step that made it (`made_by`); flipped faces red.
pub fn level_scene(lv: &Level, made_by: Option<Scheme>, opts: &SceneOptions) -> Scene {
    let mut opts = opts.clone();
    if let ColorBy::Solid(_) = opts.color_by {
        opts.color_by = ColorBy::Solid(scheme_color(made_by.as_ref()));
    }
    let mut scene = Scene::of_level(lv, &opts);
    // Faces a step turned against their parent are always shown, in red over any colouring
    // (a section paints those it keeps itself).
    if let Some(r) = &lv.report
        && opts.section.is_none()
    {
        scene.paint_faces(&lv.mesh, &r.flipped, FLIPPED_COLOR);
    }
    scene
}

/// What a scene was made from: (generation, level, display options).
type SceneKey = (u64, usize, SceneOptions);

/// What a fillet measure was made from: (generation, level shown, selected edge).
pub type FilletKey = (u64, usize, Option<EdgeKey>);

/// A level of a given result: (generation, level).
type LevelKey = (u64, usize);
/// The control edge of every edge of a level, or why there is none.
pub type Origins = Result<HashMap<EdgeKey, EdgeKey>, String>;
/// Limit points and normals of a level, or why there are none.
pub type Limits = Result<LimitPoints, String>;

/// Clamped edges whose fillet misses: the edge, its clamped radius, the radius measured.
pub type Missed = Vec<(EdgeKey, f64, Option<f64>)>;

enum LimitSlot {
    Computing(Receiver<Limits>),
    Ready(Arc<Limits>),
}

/// What a finished job left to say.
pub enum Outcome {
    Nothing,
    Updated,
    /// A step stopped at the memory budget: the app asks the user.
    AskBudget(OverBudget),
}

pub struct ViewPipe {
    /// The last result: complete, or cut short by an error.
    pub pipeline: Pipeline,
    /// Bumped whenever `pipeline` is replaced (caches compare it).
    pub generation: u64,
    /// The level the user wants to see; the one shown is the nearest computed.
    pub level: usize,
    pub job: Option<Job>,
    /// The pipeline to compute once the running job has finished.
    wanted: Option<Pipeline>,
    pub error: Option<String>,
    /// Which levels the view keeps: all (the level slider shows any), or after the memory
    /// question's "keep only the last level", the input and the newest.
    pub keep: prism_geom::pipeline::Keep,
    /// Budget for the next job when the user allowed more than the default.
    pub budget_override: Option<u64>,
    /// What the cylindrical-family steps do with radii that do not fit their faces: the
    /// app clamps by default (as Blender's bevel does), the checkbox in the step panel
    /// turns it off.
    pub overlap: Overlap,
    /// Whether the rounding steps search their whole level for faces that pass through each
    /// other and mend them with small chamfers (the step panel's checkbox; on by default, as
    /// clamping is, so that every level is sound).
    pub mend_crossings: bool,
    pub scene: Arc<Scene>,
    /// What the scene on screen was made from.
    scene_key: Option<SceneKey>,
    pub overlay: Arc<Scene>,
    /// What the overlay on screen was made from (a hash of its inputs).
    pub overlay_key: Option<u64>,
    /// Bumped whenever the scene or overlay changes (the GPU upload compares it).
    pub version: u64,
    /// Bumped whenever a scene is installed (overlays depend on its origin and size).
    scene_serial: u64,
    /// The display options scenes are built with (the worker prepares the next one).
    pub scene_opts: SceneOptions,
    /// A scene being prepared on a thread, and the (generation, level, options) it is for.
    scene_job: Option<(SceneKey, Receiver<Scene>)>,
    edges: Option<(LevelKey, Arc<Vec<EdgeKey>>)>,
    origins: Option<(LevelKey, Arc<Origins>)>,
    /// Limit points of a level: computed on a thread, then kept.
    limits: Option<(LevelKey, LimitSlot)>,
    /// Whether the level shown passes through itself: checked on a thread.
    pub crossing: CrossingCheck,
    /// The framing sphere of the installed scene ([`ViewPipe::frame_sphere`]).
    sphere: std::sync::OnceLock<(glam::Vec3, f32, usize)>,
    /// Cached fillet measure and what it was made from.
    pub fillet: Option<(FilletKey, String)>,
    /// The clamped edges whose fillet misses their radius on the shown level
    /// ([`prism_geom::Pipeline::missed_radii`]), for the generation and level it was measured
    /// on.
    pub missed: Option<((u64, usize), Arc<Missed>)>,
    /// When the edit not yet on screen was submitted.
    edit_started: Option<std::time::Instant>,
    /// How long the last edit took from its submission to its scene being ready to draw
    /// (every level recomputed, the vertex buffers built): the status bar shows it.
    pub last_edit: Option<std::time::Duration>,
}

impl ViewPipe {
    pub fn new(pipeline: Pipeline) -> ViewPipe {
        let level = pipeline.steps().len();
        ViewPipe {
            pipeline,
            generation: 0,
            level,
            job: None,
            wanted: None,
            error: None,
            keep: prism_geom::pipeline::Keep::All,
            budget_override: None,
            overlap: Overlap::Clamp,
            mend_crossings: prism_geom::rules::MendOptions::default().crossings,
            scene: Arc::new(Scene::default()),
            scene_key: None,
            overlay: Arc::new(Scene::default()),
            overlay_key: None,
            version: 0,
            scene_serial: 0,
            scene_opts: SceneOptions::default(),
            scene_job: None,
            edges: None,
            origins: None,
            limits: None,
            crossing: CrossingCheck::default(),
            sphere: std::sync::OnceLock::new(),
            fillet: None,
            missed: None,
            edit_started: None,
            last_edit: None,
        }
    }

    /// The level shown: the wanted one, or the last computed if it is not there yet or was
    /// freed ([`prism_geom::pipeline::Keep::Needed`]).
    pub fn shown(&self) -> usize {
        let last = self.pipeline.levels().len() - 1;
        let k = self.level.min(last);
        if self.pipeline.released(k) { last } else { k }
    }

    pub fn steps(&self) -> &[Scheme] {
        self.pipeline.steps()
    }

    pub fn busy(&self) -> bool {
        self.job.is_some() || self.wanted.is_some()
    }

    /// Computes `next` (which carries the levels it shares with the current pipeline).
    /// `live` changes (a vertex drag) let a running job finish and queue behind it; others
    /// cancel it. A pipeline with nothing to compute replaces the current one at once.
    pub fn submit(&mut self, mut next: Pipeline, budget: u64, live: bool, wake: &Waker) {
        next.options.memory_budget = self.budget_override.unwrap_or(budget);
        next.keep = self.keep;
        next.options.overlap = self.overlap;
        next.options.mend.crossings = self.mend_crossings;
        self.edit_started
            .get_or_insert_with(std::time::Instant::now);
        if next.is_complete() && self.job.is_none() {
            self.edit_started = None;
            self.replace(next);
            self.error = None;
            return;
        }
        if let Some(job) = &self.job {
            if !live {
                job.cancel();
            }
            self.wanted = Some(next);
        } else {
            self.spawn(next, wake);
        }
    }

    fn spawn(&mut self, p: Pipeline, wake: &Waker) {
        let w = wake.clone();
        let (want, opts) = (self.level, self.scene_opts.clone());
        let prepare = move |p: &Pipeline| {
            let k = want.min(p.levels().len() - 1);
            let scene = level_scene(&p.levels()[k], made_by(p, k), &opts);
            Some((k, opts, scene))
        };
        self.job = Some(Job::spawn(p, prepare, move || w()));
    }

    /// Takes a finished job's result.
    pub fn poll(&mut self, wake: &Waker, input: &prism_geom::io::Numbering) -> Outcome {
        let Some(job) = &mut self.job else {
            return Outcome::Nothing;
        };
        let Some(Finished {
            pipeline,
            error,
            cancelled,
            prepared,
        }) = job.poll()
        else {
            return Outcome::Nothing;
        };
        self.job = None;
        let mut out = Outcome::Updated;
        let superseded = cancelled && self.wanted.is_some();
        if pipeline.is_none() {
            self.error =
                Some("the computation stopped unexpectedly; the last result is kept".into());
        }
        if let Some(pipeline) = pipeline
            && !superseded
        {
            self.error = error.as_ref().map(|e| e.describe(input));
            if let Some(o) = error.as_ref().and_then(over_budget) {
                out = Outcome::AskBudget(o.clone());
            }
            if cancelled && error.is_none() {
                self.error =
                    Some("cancelled: the levels after the last one shown were not computed".into());
            }
            self.replace(pipeline);
            if let Some(p) = prepared
                && p.0 == self.shown()
                && p.1 == self.scene_opts
            {
                let (k, opts, scene) = *p;
                self.install_scene(scene, (self.generation, k, opts));
                if self.wanted.is_none()
                    && let Some(t) = self.edit_started.take()
                {
                    self.last_edit = Some(t.elapsed());
                }
            }
            if self.wanted.is_none() {
                self.edit_started = None;
            }
        }
        if let Some(next) = self.wanted.take() {
            self.spawn(next, wake);
        }
        out
    }

    /// Brings the scene up to date with the shown level and the display options `opts`:
    /// small levels at once, big ones on a thread (the old scene stays on screen meanwhile).
    /// Returns whether the scene changed.
    pub fn refresh_scene(&mut self, opts: &SceneOptions, wake: &Waker) -> bool {
        self.scene_opts = opts.clone();
        let key: SceneKey = (self.generation, self.shown(), opts.clone());
        let mut changed = false;
        if let Some((k, rx)) = &self.scene_job {
            match rx.try_recv() {
                Ok(scene) => {
                    let k = k.clone();
                    self.scene_job = None;
                    self.install_scene(scene, k);
                    changed = true;
                }
                Err(TryRecvError::Empty) => {}
                Err(TryRecvError::Disconnected) => self.scene_job = None,
            }
        }
        if self.scene_key.as_ref() == Some(&key)
            || self.scene_job.as_ref().is_some_and(|(k, _)| *k == key)
        {
            return changed;
        }
        let lv = &self.pipeline.levels()[key.1];
        let by = made_by(&self.pipeline, key.1);
        if lv.mesh.num_corners() < ASYNC_SCENE_CORNERS {
            let scene = level_scene(lv, by, &key.2);
            self.install_scene(scene, key);
            return true;
        }
        let (tx, rx) = std::sync::mpsc::channel();
        let (lv, opts, w) = (lv.clone(), key.2.clone(), wake.clone());
        std::thread::spawn(move || {
            let _ = tx.send(level_scene(&lv, by, &opts));
            w();
        });
        self.scene_job = Some((key, rx));
        changed
    }

    /// Whether a scene is being prepared.
    pub fn preparing(&self) -> bool {
        self.scene_job.is_some()
    }

    fn install_scene(&mut self, scene: Scene, key: SceneKey) {
        self.scene = Arc::new(scene);
        self.scene_key = Some(key);
        self.scene_serial += 1;
        self.sphere = std::sync::OnceLock::new();
        self.version += 1;
    }

    /// Draws nothing until the next scene comes (a new document: the old picture goes at
    /// once, and the view frames the new model when its first level arrives).
    pub fn clear_scene(&mut self) {
        self.scene = Arc::new(Scene::default());
        self.overlay = Arc::new(Scene::default());
        self.scene_key = None;
        self.overlay_key = None;
        self.scene_serial += 1;
        self.sphere = std::sync::OnceLock::new();
        self.version += 1;
    }

    /// Shows `scene` in place of the shown level's (tests: a level that threw vertices far
    /// out without a scheme that does).
    #[cfg(test)]
    pub fn show_scene(&mut self, scene: Scene) {
        let key = self.scene_key.clone().expect("a scene was built");
        self.install_scene(scene, key);
    }

    /// The number of scenes installed so far, for overlay keys (the overlay uses the
    /// scene's origin and size).
    pub fn scene_serial(&self) -> u64 {
        self.scene_serial
    }

    /// The sphere to frame the scene on screen with (the bounding sphere, or most of the
    /// model when a few corners lie far outside it) and how many corners lie far outside;
    /// computed once per scene.
    pub fn frame_sphere(&self) -> (glam::Vec3, f32, usize) {
        *self.sphere.get_or_init(|| {
            let (c, r, far) = self.scene.robust_sphere();
            if far == 0 {
                (glam::Vec3::ZERO, self.scene.radius(), 0)
            } else {
                (c, r, far)
            }
        })
    }

    /// Cancels the running job and forgets the queued one.
    pub fn cancel(&mut self) {
        self.wanted = None;
        if let Some(j) = &self.job {
            j.cancel();
        }
    }

    fn replace(&mut self, p: Pipeline) {
        self.pipeline = p;
        self.generation += 1;
        self.budget_override = None;
    }

    /// The edges of the shown level.
    pub fn edges(&mut self) -> Arc<Vec<EdgeKey>> {
        let key = (self.generation, self.shown());
        if let Some((k, e)) = &self.edges
            && *k == key
        {
            return e.clone();
        }
        let e = Arc::new(super::pick::mesh_edges(&self.pipeline.levels()[key.1].mesh));
        self.edges = Some((key, e.clone()));
        e
    }

    /// The control edge each edge of the shown level descends from.
    pub fn origins(&mut self) -> Arc<Origins> {
        let key = (self.generation, self.shown());
        if let Some((k, o)) = &self.origins
            && *k == key
        {
            return o.clone();
        }
        let o = Arc::new(edge_origins(self.pipeline.levels(), key.1).map_err(|e| e.to_string()));
        self.origins = Some((key, o.clone()));
        o
    }

    /// Limit points and normals of the shown level under `scheme`, computed on a thread
    /// the first time they are asked for (None until they are there; `wake` repaints then).
    pub fn limit_points(
        &mut self,
        scheme: prism_geom::PrimalScheme,
        wake: &Waker,
    ) -> Option<Arc<Limits>> {
        let key = (self.generation, self.shown());
        if let Some((k, slot)) = &mut self.limits
            && *k == key
        {
            match slot {
                LimitSlot::Ready(l) => return Some(l.clone()),
                LimitSlot::Computing(rx) => match rx.try_recv() {
                    Ok(l) => {
                        let l = Arc::new(l);
                        *slot = LimitSlot::Ready(l.clone());
                        return Some(l);
                    }
                    Err(TryRecvError::Empty) => return None,
                    Err(TryRecvError::Disconnected) => {
                        let l = Arc::new(Err("the limit computation stopped".to_string()));
                        *slot = LimitSlot::Ready(l.clone());
                        return Some(l);
                    }
                },
            }
        }
        let lv = self.pipeline.levels()[key.1].clone();
        let (tx, rx) = std::sync::mpsc::channel();
        let w = wake.clone();
        std::thread::spawn(move || {
            let l = prism_geom::limit_points(&lv.mesh, &lv.edge_attrs, &lv.tags, scheme)
                .map_err(|e| e.to_string());
            let _ = tx.send(l);
            w();
        });
        self.limits = Some((key, LimitSlot::Computing(rx)));
        None
    }

    /// Whether the shown level passes through itself ([`CrossingCheck::poll`]); once the
    /// answer is in, its faces are painted red over the scene on screen (again on every new
    /// scene of that level).
    pub fn check_crossings(&mut self, wake: &Waker) -> Crossings {
        let key = (self.generation, self.shown());
        let idle = !self.busy();
        let out = self
            .crossing
            .poll(key, &self.pipeline.levels()[key.1], idle, wake);
        if let Crossings::Done(pairs) = &out
            && !pairs.is_empty()
            && self.scene_key.as_ref().is_some_and(|k| (k.0, k.1) == key)
            && self.crossing.painted != Some(self.scene_serial)
        {
            let mesh = &self.pipeline.levels()[key.1].mesh;
            Arc::make_mut(&mut self.scene).paint_faces(
                mesh,
                &prism_geom::analysis::crossing_faces(pairs),
                FLIPPED_COLOR,
            );
            self.crossing.painted = Some(self.scene_serial);
            self.version += 1;
        }
        out
    }

    /// [`ViewPipe::check_crossings`]'s answer as it stands.
    pub fn crossings(&self) -> Crossings {
        let k = self.shown();
        let faces = self.pipeline.levels()[k].mesh.num_faces();
        self.crossing.state((self.generation, k), faces)
    }

    /// Whether the shown level is being checked for crossings.
    pub fn checking(&self) -> bool {
        self.crossings() == Crossings::Checking
    }

    /// Checks the shown level even though it is big.
    pub fn ask_crossings(&mut self) {
        self.crossing.ask((self.generation, self.shown()));
    }
}
