//! Schemes as values: a step of a pipeline is a [`Scheme`] with its parameter inside.
//!
//! The text form is what the CLI, the files and the app's pipeline editor read and write:
//! `doo-sabin`, `angle-bisector:l=0.1`, `cut-width:d=0.1`, `vector-sum:alpha=0.2`
//! (`vector-sum:alpha=0.2:reflex=inward` for the paper's reflex-corner option),
//! `cylindrical:r=0.2`, `minimum:r=0.2`, `combination:r=0.2`, and the primal schemes
//! `catmull-clark` and `loop`; a pipeline is a comma-separated list of steps (e.g.
//! `cut-width:d=0.1,catmull-clark,catmull-clark`). Parsing and printing round-trip. The
//! names, keys and ranges come from [`CATALOGUE`]; no other file spells them.

mod catalogue;

pub use catalogue::{CATALOGUE, Entry, Family, ParamSpec, Scale, SchemeKind, known_names, table};

use crate::primal::PrimalScheme;
use crate::rules::{CornerRule, ParamError, ReflexMode};
use std::fmt;
use thiserror::Error;

/// One step of a pipeline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scheme {
    /// PRISM's biquadratic step (Doo–Sabin and the chamfer and cylindrical rules).
    Biquadratic(CornerRule),
    /// Catmull–Clark or Loop, with the mesh's creases, corners and holes.
    Primal(PrimalScheme),
}

#[derive(Debug, Clone, PartialEq, Error)]
pub enum SchemeError {
    #[error("unknown scheme '{0}' (known: {known})", known = known_names())]
    Unknown(String),
    #[error("scheme '{scheme}' needs the parameter {param} (e.g. '{scheme}:{param}=0.1')")]
    Missing { scheme: String, param: &'static str },
    #[error("scheme '{scheme}' has no parameter '{param}'")]
    UnexpectedParam { scheme: String, param: String },
    #[error("scheme '{scheme}' is given '{param}' twice")]
    Repeated { scheme: String, param: String },
    #[error("'{0}' is not a number")]
    BadNumber(String),
    #[error("'{0}' is not of the form key=value")]
    BadOption(String),
    #[error("the pipeline is empty")]
    Empty,
    #[error(transparent)]
    Param(#[from] ParamError),
}

impl SchemeKind {
    /// The scheme of this kind with parameter `param` (required when the catalogue gives
    /// the kind one, refused otherwise) and the reflex option, checked.
    pub fn scheme(self, param: Option<f64>, reflex: ReflexMode) -> Result<Scheme, SchemeError> {
        let e = self.entry();
        let x = match (&e.param, param) {
            (Some(_), Some(x)) => x,
            (Some(p), None) => {
                return Err(SchemeError::Missing {
                    scheme: e.name.into(),
                    param: p.key,
                });
            }
            (None, Some(_)) => {
                return Err(SchemeError::UnexpectedParam {
                    scheme: e.name.into(),
                    param: "a value".into(),
                });
            }
            (None, None) => 0.0,
        };
        let s = match self {
            SchemeKind::DooSabin => Scheme::Biquadratic(CornerRule::DooSabin),
            SchemeKind::AngleBisector => Scheme::Biquadratic(CornerRule::AngleBisector { l: x }),
            SchemeKind::CutWidth => Scheme::Biquadratic(CornerRule::CutWidth { d: x }),
            SchemeKind::VectorSum => {
                Scheme::Biquadratic(CornerRule::VectorSum { alpha: x, reflex })
            }
            SchemeKind::Cylindrical => Scheme::Biquadratic(CornerRule::Cylindrical { r: x }),
            SchemeKind::Minimum => Scheme::Biquadratic(CornerRule::Minimum { r: x }),
            SchemeKind::Combination => Scheme::Biquadratic(CornerRule::Combination { r: x }),
            SchemeKind::CatmullClark => Scheme::Primal(PrimalScheme::CatmullClark),
            SchemeKind::Loop => Scheme::Primal(PrimalScheme::Loop),
            SchemeKind::CatmullClarkCircle => Scheme::Primal(PrimalScheme::CatmullClarkCircle),
        };
        s.validate()?;
        Ok(s)
    }

    /// The scheme of this kind with its default parameter.
    pub fn default_scheme(self) -> Scheme {
        let p = self.entry().param.map(|p| p.default);
        self.scheme(p, ReflexMode::AsPrinted)
            .expect("catalogue defaults are admissible")
    }
}

impl Scheme {
    /// Which scheme of the catalogue this is.
    pub fn kind(&self) -> SchemeKind {
        match self {
            Scheme::Biquadratic(r) => match r {
                CornerRule::DooSabin => SchemeKind::DooSabin,
                CornerRule::AngleBisector { .. } => SchemeKind::AngleBisector,
                CornerRule::CutWidth { .. } => SchemeKind::CutWidth,
                CornerRule::VectorSum { .. } => SchemeKind::VectorSum,
                CornerRule::Cylindrical { .. } => SchemeKind::Cylindrical,
                CornerRule::Minimum { .. } => SchemeKind::Minimum,
                CornerRule::Combination { .. } => SchemeKind::Combination,
            },
            Scheme::Primal(p) => p.kind(),
        }
    }

    /// The scheme's name in the text form.
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// The value of its parameter, if the catalogue gives it one.
    pub fn param(&self) -> Option<f64> {
        let Scheme::Biquadratic(r) = *self else {
            return None;
        };
        match r {
            CornerRule::DooSabin => None,
            CornerRule::AngleBisector { l } => Some(l),
            CornerRule::CutWidth { d } => Some(d),
            CornerRule::VectorSum { alpha, .. } => Some(alpha),
            CornerRule::Cylindrical { r }
            | CornerRule::Minimum { r }
            | CornerRule::Combination { r } => Some(r),
        }
    }

    /// The same scheme with parameter `x` (options such as `reflex` kept; unchecked).
    pub fn with_param(&self, x: f64) -> Scheme {
        let Scheme::Biquadratic(r) = *self else {
            return *self;
        };
        Scheme::Biquadratic(match r {
            CornerRule::DooSabin => CornerRule::DooSabin,
            CornerRule::AngleBisector { .. } => CornerRule::AngleBisector { l: x },
            CornerRule::CutWidth { .. } => CornerRule::CutWidth { d: x },
            CornerRule::VectorSum { reflex, .. } => CornerRule::VectorSum { alpha: x, reflex },
            CornerRule::Cylindrical { .. } => CornerRule::Cylindrical { r: x },
            CornerRule::Minimum { .. } => CornerRule::Minimum { r: x },
            CornerRule::Combination { .. } => CornerRule::Combination { r: x },
        })
    }

    /// Why this scheme's parameter is unsafe to repeat, when it is above the catalogue's
    /// repeatable bound (vector sum with ¼ < α < ½).
    pub fn repeat_warning(&self) -> Option<String> {
        let p = self.kind().entry().param?;
        let (bound, why) = p.repeatable?;
        let x = self.param()?;
        (x > bound).then(|| format!("{} {} = {x} is above {bound}: {why}", self.name(), p.symbol))
    }

    /// Whether this scheme rounds edges (the cylindrical family: cylindrical, minimum,
    /// combination), so a run of it has fillets to measure.
    pub fn rounds_edges(&self) -> bool {
        matches!(self, Scheme::Biquadratic(r) if r.is_cylindrical_family())
    }

    /// Whether repeating this scheme needs its parameter shrunk: the absolute chamfers,
    /// whose new faces are about l or d wide and are cut from both sides by the same value
    /// again (seed 000 §3.1, docs/algorithms/chamfers.md: about 4× per step).
    pub fn shrinks_when_repeated(&self) -> bool {
        matches!(
            self,
            Scheme::Biquadratic(CornerRule::AngleBisector { .. } | CornerRule::CutWidth { .. })
        )
    }

    /// `n` steps of this scheme, the parameter divided by `shrink` at each step after the
    /// first when it [shrinks when repeated](Scheme::shrinks_when_repeated) (the same scheme
    /// `n` times otherwise).
    pub fn schedule(&self, n: usize, shrink: f64) -> Vec<Scheme> {
        let mut out = Vec::with_capacity(n);
        let mut s = *self;
        for _ in 0..n {
            out.push(s);
            s = s.shrunk(shrink);
        }
        out
    }

    /// The next step of a shrinking schedule: the parameter divided by `shrink` for the
    /// absolute chamfers, unchanged otherwise.
    pub fn shrunk(&self, shrink: f64) -> Scheme {
        match self.param() {
            Some(x) if self.shrinks_when_repeated() => self.with_param(x / shrink),
            _ => *self,
        }
    }

    /// Checks the parameter against the catalogue's range.
    pub fn validate(&self) -> Result<(), ParamError> {
        match (self.kind().entry().param, self.param()) {
            (Some(p), Some(x)) if !p.admits(x) => Err(ParamError {
                name: p.key,
                value: x,
                expected: p.expected,
            }),
            _ => Ok(()),
        }
    }
}

impl fmt::Display for Scheme {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = self.kind().entry();
        write!(f, "{}", e.name)?;
        if let (Some(p), Some(x)) = (&e.param, self.param()) {
            write!(f, ":{}={x}", p.key)?;
        }
        if let Scheme::Biquadratic(CornerRule::VectorSum {
            reflex: ReflexMode::Inward,
            ..
        }) = self
        {
            write!(f, ":{REFLEX_KEY}=inward")?;
        }
        Ok(())
    }
}

/// The key of seed 000's reflex-corner option in the text form.
const REFLEX_KEY: &str = "reflex";

impl std::str::FromStr for Scheme {
    type Err = SchemeError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mut parts = s.trim().split(':');
        let name = parts.next().unwrap_or("").trim();
        let kind =
            SchemeKind::from_name(name).ok_or_else(|| SchemeError::Unknown(name.to_string()))?;
        let e = kind.entry();
        let (mut value, mut reflex) = (None, None);
        for opt in parts {
            let (k, v) = opt
                .split_once('=')
                .ok_or_else(|| SchemeError::BadOption(opt.to_string()))?;
            let (k, v) = (k.trim(), v.trim());
            let unexpected = || SchemeError::UnexpectedParam {
                scheme: name.into(),
                param: k.into(),
            };
            let repeated = || SchemeError::Repeated {
                scheme: name.into(),
                param: k.into(),
            };
            if k == REFLEX_KEY {
                if !e.reflex_option {
                    return Err(unexpected());
                }
                let mode = match v {
                    "inward" => ReflexMode::Inward,
                    "as-printed" => ReflexMode::AsPrinted,
                    _ => return Err(SchemeError::BadOption(opt.to_string())),
                };
                if reflex.replace(mode).is_some() {
                    return Err(repeated());
                }
                continue;
            }
            let p = e
                .param
                .filter(|p| p.key == k || p.aliases.contains(&k))
                .ok_or_else(unexpected)?;
            let x: f64 = v
                .parse()
                .map_err(|_| SchemeError::BadNumber(v.to_string()))?;
            if value.replace(x).is_some() {
                return Err(SchemeError::Repeated {
                    scheme: name.into(),
                    param: p.key.into(),
                });
            }
        }
        kind.scheme(value, reflex.unwrap_or_default())
    }
}

/// Parses a comma-separated pipeline such as `vector-sum:alpha=0.2,doo-sabin,doo-sabin`.
pub fn parse_pipeline(s: &str) -> Result<Vec<Scheme>, SchemeError> {
    let steps: Vec<Scheme> = s
        .split(',')
        .filter(|p| !p.trim().is_empty())
        .map(str::parse)
        .collect::<Result<_, _>>()?;
    if steps.is_empty() {
        return Err(SchemeError::Empty);
    }
    Ok(steps)
}

/// Prints a pipeline in the form [`parse_pipeline`] reads.
pub fn format_pipeline(steps: &[Scheme]) -> String {
    steps
        .iter()
        .map(|s| s.to_string())
        .collect::<Vec<_>>()
        .join(",")
}

impl PrimalScheme {
    /// Its kind in the scheme catalogue.
    pub fn kind(self) -> SchemeKind {
        match self {
            PrimalScheme::CatmullClark => SchemeKind::CatmullClark,
            PrimalScheme::Loop => SchemeKind::Loop,
            PrimalScheme::CatmullClarkCircle => SchemeKind::CatmullClarkCircle,
        }
    }

    pub fn name(self) -> &'static str {
        self.kind().name()
    }
}

impl CornerRule {
    /// Checks the parameter against the scheme catalogue's range (lengths finite and > 0,
    /// 0 < α < ½: α = ½ collapses a square).
    pub fn validate(&self) -> Result<(), ParamError> {
        Scheme::Biquadratic(*self).validate()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_form_round_trips() {
        let text = "vector-sum:alpha=0.2,doo-sabin,cut-width:d=0.025,angle-bisector:l=0.1,cylindrical:r=0.45,minimum:r=0.3,combination:r=0.2,vector-sum:alpha=0.1:reflex=inward,catmull-clark,loop";
        let p = parse_pipeline(text).unwrap();
        assert_eq!(p.len(), 10);
        assert_eq!(format_pipeline(&p), text);
    }

    #[test]
    fn bad_text_is_refused_with_a_reason() {
        use SchemeError as E;
        let refused = |text: &str| text.parse::<Scheme>().unwrap_err();
        assert!(matches!(refused("foo"), E::Unknown(_)));
        assert!(matches!(refused("combination"), E::Missing { .. }));
        assert!(matches!(refused("vector-sum:alpha=0.5"), E::Param(_)));
        assert!(matches!(refused("cut-width:d=-1"), E::Param(_)));
        assert!(matches!(refused("cut-width:d=nan"), E::Param(_)));
        assert!(matches!(
            refused("doo-sabin:r=1"),
            E::UnexpectedParam { .. }
        ));
        assert!(matches!(refused("cut-width:d=x"), E::BadNumber(_)));
        assert!(matches!(parse_pipeline(" , "), Err(E::Empty)));
        assert!(matches!(refused("loop:r=1"), E::UnexpectedParam { .. }));
        assert!(matches!(
            refused("combination:r=0.1:r=0.2"),
            E::Repeated { .. }
        ));
        assert!(matches!(
            refused("combination:r=0.1:radius=0.2"),
            E::Repeated { .. }
        ));
        assert!(matches!(
            refused("cut-width:reflex=inward"),
            E::UnexpectedParam { .. }
        ));
        // The unknown-scheme message lists every scheme of the catalogue.
        let msg = "spline".parse::<Scheme>().unwrap_err().to_string();
        assert!(CATALOGUE.iter().all(|e| msg.contains(e.name)), "{msg}");
    }

    #[test]
    fn every_kind_round_trips_through_its_default() {
        for k in SchemeKind::all() {
            let s = k.default_scheme();
            assert_eq!(s.kind(), k);
            assert_eq!(s.to_string().parse::<Scheme>().unwrap(), s);
            if let Some(x) = s.param() {
                assert_eq!(s.with_param(2.0 * x).param(), Some(2.0 * x));
            }
        }
    }
}
