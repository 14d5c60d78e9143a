//! Surveys: measurements over many generated inputs that print what they find, for the docs'
//! figures (docs/algorithms/cylindrical.md, "Random mixes"). Not tests: a test states a
//! property and fails; a survey counts.
//!
//! ```text
//! cargo run --release -p prism-geom --example survey -- mixes [--seeds 37,41,…] [--no-mend] [--check]
//! ```
//!
//! `mixes`: random pipelines on the six bundled solids — one to three steps drawn from a menu
//! of every scheme, then two or three combination steps, clamped — 300 from each seed (the
//! default seeds 1, 7, 11, 13 are the set the mending strategies were built while looking at;
//! others are held out). A combination level is unsound when it has a flipped or degenerate
//! face or a non-positive volume while every level before it was sound, and, counted apart,
//! when faces pass through each other (`analysis::crossings`). Every unsound mix is printed,
//! then the counts. `--no-mend` turns the whole-level crossing search off (the default is on);
//! `--check` exits 1 when the default seeds exceed the bounds the docs state (none flipped,
//! at most one crossing at a rounding, at most 20 unsound at any level).

use prism_geom::Pipeline;
use prism_geom::io;
use prism_geom::rules::Overlap;
use std::path::Path;

/// What one survey of random mixes found.
#[derive(Debug, Default)]
struct Mixes {
    tried: usize,
    /// Flipped, degenerate or inside out at a rounding.
    unsound: usize,
    /// The same, or crossing itself, at a rounding.
    crossing: usize,
    /// Crossing itself or unsound at a step that is not a combination step.
    before: usize,
}

/// A linear congruential draw (the same mixes on every machine).
struct Draw(u64);

impl Draw {
    fn below(&mut self, k: usize) -> usize {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 33) as usize) % k
    }
}

fn mixes(seeds: &[u64], mend: bool) -> Mixes {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    let solids: Vec<(&str, io::Document)> = [
        "tripod.obj",
        "computer-room.obj",
        "l-block.obj",
        "cube.obj",
        "holed-block.prism.json",
        "cube-rim.prism.json",
    ]
    .iter()
    .map(|f| (*f, io::load(&dir.join(f)).expect("bundled solid").0))
    .collect();
    let menu = [
        "catmull-clark",
        "doo-sabin",
        "combination:r=0.2",
        "combination:r=0.1",
        "cylindrical:r=0.2",
        "vector-sum:alpha=0.2:reflex=inward",
        "vector-sum:alpha=0.1:reflex=inward",
        "cut-width:d=0.05",
        "angle-bisector:l=0.05",
        "minimum:r=0.2",
        "combination:r=0.4",
        "loop",
    ];
    let tails = [
        "combination:r=0.2",
        "combination:r=0.1",
        "combination:r=0.3",
    ];
    let mut out = Mixes::default();
    for &seed in seeds {
        let mut draw = Draw(seed);
        for _ in 0..300 {
            let (name, doc) = &solids[draw.below(solids.len())];
            let n = 1 + draw.below(3);
            let mut text: Vec<&str> = (0..n).map(|_| menu[draw.below(menu.len())]).collect();
            let tail = tails[draw.below(tails.len())];
            for _ in 0..2 + draw.below(2) {
                text.push(tail);
            }
            let text = text.join(",");
            out.tried += 1;
            let steps = prism_geom::scheme::parse_pipeline(&text).expect("menu parses");
            let mut p = Pipeline::with_tags(
                doc.mesh.clone(),
                doc.edge_attrs.clone(),
                doc.tags.clone(),
                steps,
            );
            p.options.overlap = Overlap::Clamp;
            p.options.memory_budget = 2 << 30;
            p.options.mend.crossings = mend;
            let _ = p.compute();
            // Without and with the crossing check.
            let mut sound_so_far = [true, true];
            for (k, lv) in p.levels().iter().enumerate().skip(1) {
                let r = lv.report.as_ref().expect("a computed level has a report");
                let faces_ok = r.flipped.is_empty() && r.degenerate.is_empty() && r.volume > 0.0;
                let crossing = prism_geom::analysis::crossings(&lv.mesh).len();
                let rounding = text
                    .split(',')
                    .nth(k - 1)
                    .is_some_and(|s| s.starts_with("combination"));
                for (i, sound) in [faces_ok, faces_ok && crossing == 0]
                    .into_iter()
                    .enumerate()
                {
                    if sound_so_far[i] && !sound {
                        let what = format!(
                            "{name} {text} level {k}: {} flipped, {} degenerate, {crossing} pair(s) crossing",
                            r.flipped.len(),
                            r.degenerate.len()
                        );
                        match (rounding, i) {
                            (true, 0) => {
                                out.unsound += 1;
                                println!("unsound at a rounding: {what}");
                            }
                            (true, _) => {
                                out.crossing += 1;
                                println!("crossing at a rounding: {what}");
                            }
                            (false, 1) => {
                                out.before += 1;
                                println!("at another step: {what}");
                            }
                            _ => {}
                        }
                    }
                    sound_so_far[i] &= sound;
                }
            }
        }
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) != Some("mixes") {
        eprintln!(
            "usage: survey mixes [--seeds 37,41,…] [--no-mend] [--check]\n(see the example's doc)"
        );
        std::process::exit(2);
    }
    let mut seeds = vec![1u64, 7, 11, 13];
    let mut held_out = false;
    let (mut mend, mut check) = (true, false);
    let mut it = args[1..].iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--seeds" => {
                let list = it.next().map(String::as_str).unwrap_or_default();
                let parsed: Result<Vec<u64>, _> =
                    list.split(',').map(|x| x.trim().parse()).collect();
                match parsed {
                    Ok(s) if !s.is_empty() => {
                        seeds = s;
                        held_out = true;
                    }
                    _ => {
                        eprintln!("--seeds takes numbers separated by commas, got {list:?}");
                        std::process::exit(2);
                    }
                }
            }
            "--no-mend" => mend = false,
            "--check" => check = true,
            other => {
                eprintln!("unknown argument {other:?}");
                std::process::exit(2);
            }
        }
    }
    let m = mixes(&seeds, mend);
    println!(
        "{} mixes: {} unsound at a rounding, {} counting faces that pass through each other, {} unsound at another step (Catmull–Clark, a chamfer, the simple type …)",
        m.tried, m.unsound, m.crossing, m.before
    );
    if check && !held_out {
        let ok = m.unsound == 0
            && m.crossing <= usize::from(!mend)
            && m.crossing + m.before <= 20 + usize::from(!mend);
        if !ok {
            eprintln!("over the bounds docs/algorithms/cylindrical.md states");
            std::process::exit(1);
        }
    }
}
