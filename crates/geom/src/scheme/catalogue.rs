//! The one list of Prism's subdivision schemes: for each its kind, its name in the text form,
//! its family (which split it uses), the paper and equation it implements, the page of
//! `docs/algorithms/` that states the formula, and its parameter — key, symbol, admissible
//! range, default, and how a slider should move it.
//!
//! Everything that names or describes a scheme reads this table: parsing and printing of
//! [`super::Scheme`], the error texts, `prism schemes` and the CLI's help, the app's scheme
//! editor and the renderer's colour per scheme. Adding a scheme is one [`Entry`] here, one
//! [`SchemeKind`] variant, and its rule (docs/architecture.md, "Adding a scheme").

/// Which split a scheme uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// PRISM's biquadratic step (the dual split, CGAL's DQQ) with a corner rule.
    Biquadratic,
    /// A primal split (quads for Catmull–Clark, triangles for Loop) with vertex, edge and
    /// face masks.
    Primal,
}

/// How a parameter's slider moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    Linear,
    /// For lengths in model units: a logarithmic slider, and typed values may leave its range.
    Logarithmic,
}

/// A scheme's one numeric parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// The key of the text form (`cut-width:d=0.1`).
    pub key: &'static str,
    /// Other keys the text form accepts for it.
    pub aliases: &'static [&'static str],
    /// The CLI flag that gives it with `--scheme` (`--width 0.1`).
    pub flag: &'static str,
    /// The paper's symbol, shown beside sliders.
    pub symbol: &'static str,
    /// What it means, in a few words.
    pub meaning: &'static str,
    /// Admissible values are finite and strictly between these.
    pub above: f64,
    pub below: f64,
    /// The message for a value outside them.
    pub expected: &'static str,
    pub default: f64,
    /// The range a slider offers.
    pub slider: (f64, f64),
    pub scale: Scale,
    /// The largest value that can be repeated any number of times, when it is below
    /// `below`, and why (a value above it is admitted with a warning).
    pub repeatable: Option<(f64, &'static str)>,
}

impl ParamSpec {
    /// Whether `x` is admissible.
    pub fn admits(&self, x: f64) -> bool {
        x.is_finite() && x > self.above && x < self.below
    }
}

/// One scheme of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    pub kind: SchemeKind,
    /// Its name in the text form, the CLI and the files.
    pub name: &'static str,
    /// Its name for people (the app's picker, tables).
    pub title: &'static str,
    pub family: Family,
    /// The paper (seed) and section it comes from.
    pub paper: &'static str,
    /// The equation it implements.
    pub equation: &'static str,
    /// The page of docs/algorithms/ that states the formula Prism uses.
    pub page: &'static str,
    pub param: Option<ParamSpec>,
    /// Whether it takes the `reflex=inward` option (seed 000's reflex-corner remark).
    pub reflex_option: bool,
}

/// The schemes, in the order the catalogue lists them (the order of [`CATALOGUE`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SchemeKind {
    DooSabin,
    AngleBisector,
    CutWidth,
    VectorSum,
    Cylindrical,
    Minimum,
    Combination,
    CatmullClark,
    Loop,
    CatmullClarkCircle,
}

/// A length in model units, greater than zero.
const fn length(
    key: &'static str,
    aliases: &'static [&'static str],
    flag: &'static str,
    meaning: &'static str,
    default: f64,
) -> ParamSpec {
    ParamSpec {
        key,
        aliases,
        flag,
        symbol: key,
        meaning,
        above: 0.0,
        below: f64::INFINITY,
        expected: "a finite length > 0",
        default,
        slider: (0.001, 10.0),
        scale: Scale::Logarithmic,
        repeatable: None,
    }
}

const RADIUS: ParamSpec = length("r", &["radius"], "radius", "fillet radius", 0.2);

/// Every scheme, indexed by [`SchemeKind`] (`CATALOGUE[k as usize].kind == k`).
pub const CATALOGUE: [Entry; 10] = [
    Entry {
        kind: SchemeKind::DooSabin,
        name: "doo-sabin",
        title: "Doo–Sabin",
        family: Family::Biquadratic,
        paper: "seed 000 §2.1",
        equation: "eq. (1)",
        page: "docs/algorithms/biquadratic.md",
        param: None,
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::AngleBisector,
        name: "angle-bisector",
        title: "chamfer, angle bisector (l)",
        family: Family::Biquadratic,
        paper: "seed 000 §3.1(1)",
        equation: "fig. 3",
        page: "docs/algorithms/chamfers.md",
        param: Some(length(
            "l",
            &["distance"],
            "distance",
            "distance along the bisector",
            0.1,
        )),
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::CutWidth,
        name: "cut-width",
        title: "chamfer, cut width (d)",
        family: Family::Biquadratic,
        paper: "seed 000 §3.1(2)",
        equation: "fig. 4",
        page: "docs/algorithms/chamfers.md",
        param: Some(length("d", &["width"], "width", "cut width", 0.1)),
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::VectorSum,
        name: "vector-sum",
        title: "chamfer, vector sum (α)",
        family: Family::Biquadratic,
        paper: "seed 000 §3.1(3)",
        equation: "eq. (2)",
        page: "docs/algorithms/chamfers.md",
        param: Some(ParamSpec {
            key: "alpha",
            aliases: &["a"],
            flag: "alpha",
            symbol: "α",
            meaning: "fraction of each edge cut off",
            above: 0.0,
            below: 0.5,
            expected: "0 < alpha < 0.5 (0.25 or less recommended)",
            default: 0.2,
            // The slider ends at the repeatable bound; a typed value may go past it.
            slider: (0.001, 0.25),
            scale: Scale::Linear,
            repeatable: Some((
                0.25,
                "seed 000's \"any number of times\" needs α ≤ ¼: above it some eigenvalue 1 − 4α sin²(πk/n) of a face is negative, and repeated steps fold its new faces into zig-zags",
            )),
        }),
        reflex_option: true,
    },
    Entry {
        kind: SchemeKind::Cylindrical,
        name: "cylindrical",
        title: "rounding, simple cylindrical (r)",
        family: Family::Biquadratic,
        paper: "seed 000 §3.2(1)",
        equation: "eq. (3), (4)",
        page: "docs/algorithms/cylindrical.md",
        param: Some(RADIUS),
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::Minimum,
        name: "minimum",
        title: "rounding, minimum type (r)",
        family: Family::Biquadratic,
        paper: "seed 000 §3.2(2)",
        equation: "eq. (5)",
        page: "docs/algorithms/cylindrical.md",
        param: Some(RADIUS),
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::Combination,
        name: "combination",
        title: "rounding, combination type (r)",
        family: Family::Biquadratic,
        paper: "seed 000 §3.2(3)",
        equation: "eq. (3), (4) + eq. (1)",
        page: "docs/algorithms/cylindrical.md",
        param: Some(RADIUS),
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::CatmullClark,
        name: "catmull-clark",
        title: "Catmull–Clark",
        family: Family::Primal,
        paper: "Catmull & Clark 1978; DeRose et al. 1998 (creases)",
        equation: "OpenSubdiv's Sdc masks",
        page: "docs/algorithms/primal.md",
        param: None,
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::Loop,
        name: "loop",
        title: "Loop (triangles)",
        family: Family::Primal,
        paper: "seed 001 §2",
        equation: "eq. (1)–(4)",
        page: "docs/algorithms/primal.md",
        param: None,
        reflex_option: false,
    },
    Entry {
        kind: SchemeKind::CatmullClarkCircle,
        name: "catmull-clark-circle",
        title: "Catmull–Clark, circle-preserving creases",
        family: Family::Primal,
        paper: "seed 002 §3.1 on crease curves",
        equation: "eq. (3.1)",
        page: "docs/algorithms/curves.md",
        param: None,
        reflex_option: false,
    },
];

impl SchemeKind {
    /// Its catalogue entry.
    pub fn entry(self) -> &'static Entry {
        &CATALOGUE[self as usize]
    }

    /// Its place in the catalogue (the renderer colours schemes by it).
    pub fn index(self) -> usize {
        self as usize
    }

    pub fn name(self) -> &'static str {
        self.entry().name
    }

    /// The kind with this text name.
    pub fn from_name(name: &str) -> Option<SchemeKind> {
        CATALOGUE.iter().find(|e| e.name == name).map(|e| e.kind)
    }

    /// Every kind, in catalogue order.
    pub fn all() -> impl Iterator<Item = SchemeKind> {
        CATALOGUE.iter().map(|e| e.kind)
    }
}

/// The names of every scheme, comma-separated (for error texts and help).
pub fn known_names() -> String {
    CATALOGUE
        .iter()
        .map(|e| e.name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The catalogue as a table: name, family, parameter, paper, equation, formula page
/// (`prism schemes` prints it).
pub fn table() -> String {
    let mut out = String::from("scheme | family | parameter | paper | equation | formula\n");
    for e in &CATALOGUE {
        let param = match &e.param {
            Some(p) => format!(
                "{}={} ({}; {}, default {})",
                p.key, p.symbol, p.meaning, p.expected, p.default
            ),
            None => "—".into(),
        };
        let family = match e.family {
            Family::Biquadratic => "biquadratic",
            Family::Primal => "primal",
        };
        let reflex = if e.reflex_option {
            "; option reflex=inward"
        } else {
            ""
        };
        out += &format!(
            "{} | {family} | {param}{reflex} | {} | {} | {}\n",
            e.name, e.paper, e.equation, e.page
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_is_indexed_by_kind_and_names_are_unique() {
        for (i, e) in CATALOGUE.iter().enumerate() {
            assert_eq!(e.kind.index(), i, "{}", e.name);
            assert_eq!(SchemeKind::from_name(e.name), Some(e.kind));
            assert!(
                std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join("../..")
                    .join(e.page)
                    .exists(),
                "{} cites {}, which is missing",
                e.name,
                e.page
            );
            if let Some(p) = &e.param {
                assert!(p.admits(p.default), "{}", e.name);
                assert!(p.admits(p.slider.0) && p.admits(p.slider.1), "{}", e.name);
            }
        }
        let mut names: Vec<_> = CATALOGUE.iter().map(|e| e.name).collect();
        names.dedup();
        assert_eq!(names.len(), CATALOGUE.len());
    }
}
