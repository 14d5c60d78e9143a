//! Schemes as values: a step of a pipeline is a [`Scheme`] with its parameter inside.
//!
//! The text form is what the CLI, the files and the app's pipeline editor read and write:
//! `doo-sabin`, `angle-bisector:l=0.1`, `cut-width:d=0.1`, `vector-sum:alpha=0.2`
//! (`vector-sum:alpha=0.2:reflex=inward` for the paper's reflex-corner option),
//! `cylindrical:r=0.2`, `minimum:r=0.2`, `combination:r=0.2`, and the primal schemes
//! `catmull-clark` and `loop`; a pipeline is a comma-separated list of steps (e.g.
//! `cut-width:d=0.1,catmull-clark,catmull-clark`). Parsing and printing round-trip.

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

/// The names of the primal schemes.
pub const PRIMAL_NAMES: [&str; 3] = ["catmull-clark", "loop", "catmull-clark-circle"];

/// The names of the biquadratic schemes, in the order the paper presents them.
pub const BIQUADRATIC_NAMES: [&str; 7] = [
    "doo-sabin",
    "angle-bisector",
    "cut-width",
    "vector-sum",
    "cylindrical",
    "minimum",
    "combination",
];

#[derive(Debug, Clone, PartialEq, Error)]
pub enum SchemeError {
    #[error(
        "unknown scheme '{0}' (known: doo-sabin, angle-bisector, cut-width, vector-sum, cylindrical, minimum, combination, catmull-clark, loop)"
    )]
    Unknown(String),
    #[error("scheme '{scheme}' needs the parameter {param} (e.g. '{scheme}:{param}=0.1')")]
    Missing { scheme: String, param: &'static str },
    #[error("scheme '{scheme}' has no parameter '{param}'")]
    UnexpectedParam { scheme: String, param: String },
    #[error("'{0}' is not a number")]
    BadNumber(String),
    #[error("'{0}' is not of the form key=value")]
    BadOption(String),
    #[error("the pipeline is empty")]
    Empty,
    #[error(transparent)]
    Param(#[from] ParamError),
}

impl Scheme {
    /// Builds a scheme from its name and optional parameters (as the CLI flags give them).
    pub fn from_name(
        name: &str,
        alpha: Option<f64>,
        radius: Option<f64>,
        distance: Option<f64>,
        width: Option<f64>,
        reflex: ReflexMode,
    ) -> Result<Scheme, SchemeError> {
        let need = |v: Option<f64>, param: &'static str| {
            v.ok_or(SchemeError::Missing {
                scheme: name.to_string(),
                param,
            })
        };
        let rule = match name {
            "doo-sabin" => CornerRule::DooSabin,
            "angle-bisector" => CornerRule::AngleBisector {
                l: need(distance, "l")?,
            },
            "cut-width" => CornerRule::CutWidth {
                d: need(width, "d")?,
            },
            "vector-sum" => CornerRule::VectorSum {
                alpha: need(alpha, "alpha")?,
                reflex,
            },
            "cylindrical" => CornerRule::Cylindrical {
                r: need(radius, "r")?,
            },
            "minimum" => CornerRule::Minimum {
                r: need(radius, "r")?,
            },
            "combination" => CornerRule::Combination {
                r: need(radius, "r")?,
            },
            "catmull-clark" => return Ok(Scheme::Primal(PrimalScheme::CatmullClark)),
            "loop" => return Ok(Scheme::Primal(PrimalScheme::Loop)),
            "catmull-clark-circle" => {
                return Ok(Scheme::Primal(PrimalScheme::CatmullClarkCircle));
            }
            other => return Err(SchemeError::Unknown(other.to_string())),
        };
        rule.validate()?;
        Ok(Scheme::Biquadratic(rule))
    }

    /// The scheme's name in the text form.
    pub fn name(&self) -> &'static str {
        match self {
            Scheme::Biquadratic(r) => match r {
                CornerRule::DooSabin => "doo-sabin",
                CornerRule::AngleBisector { .. } => "angle-bisector",
                CornerRule::CutWidth { .. } => "cut-width",
                CornerRule::VectorSum { .. } => "vector-sum",
                CornerRule::Cylindrical { .. } => "cylindrical",
                CornerRule::Minimum { .. } => "minimum",
                CornerRule::Combination { .. } => "combination",
            },
            Scheme::Primal(p) => p.name(),
        }
    }

    /// Checks the parameter.
    pub fn validate(&self) -> Result<(), ParamError> {
        match self {
            Scheme::Biquadratic(r) => r.validate(),
            Scheme::Primal(_) => Ok(()),
        }
    }
}

impl fmt::Display for Scheme {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.name())?;
        let Scheme::Biquadratic(r) = self else {
            return Ok(());
        };
        match *r {
            CornerRule::DooSabin => Ok(()),
            CornerRule::AngleBisector { l } => write!(f, ":l={l}"),
            CornerRule::CutWidth { d } => write!(f, ":d={d}"),
            CornerRule::VectorSum { alpha, reflex } => {
                write!(f, ":alpha={alpha}")?;
                if reflex == ReflexMode::Inward {
                    write!(f, ":reflex=inward")?;
                }
                Ok(())
            }
            CornerRule::Cylindrical { r }
            | CornerRule::Minimum { r }
            | CornerRule::Combination { r } => {
                write!(f, ":r={r}")
            }
        }
    }
}

impl std::str::FromStr for Scheme {
    type Err = SchemeError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let mut parts = s.trim().split(':');
        let name = parts.next().unwrap_or("").trim();
        let (mut alpha, mut radius, mut distance, mut width) = (None, None, None, None);
        let mut reflex = ReflexMode::AsPrinted;
        for opt in parts {
            let (k, v) = opt
                .split_once('=')
                .ok_or_else(|| SchemeError::BadOption(opt.to_string()))?;
            let (k, v) = (k.trim(), v.trim());
            if k == "reflex" {
                reflex = match v {
                    "inward" => ReflexMode::Inward,
                    "as-printed" => ReflexMode::AsPrinted,
                    _ => return Err(SchemeError::BadOption(opt.to_string())),
                };
                if name != "vector-sum" {
                    return Err(SchemeError::UnexpectedParam {
                        scheme: name.into(),
                        param: k.into(),
                    });
                }
                continue;
            }
            let x: f64 = v
                .parse()
                .map_err(|_| SchemeError::BadNumber(v.to_string()))?;
            let (slot, owner): (&mut Option<f64>, &[&str]) = match k {
                "alpha" | "a" => (&mut alpha, &["vector-sum"]),
                "r" | "radius" => (&mut radius, &["cylindrical", "minimum", "combination"]),
                "l" | "distance" => (&mut distance, &["angle-bisector"]),
                "d" | "width" => (&mut width, &["cut-width"]),
                _ => {
                    return Err(SchemeError::UnexpectedParam {
                        scheme: name.into(),
                        param: k.into(),
                    });
                }
            };
            if !owner.contains(&name)
                && (BIQUADRATIC_NAMES.contains(&name) || PRIMAL_NAMES.contains(&name))
            {
                return Err(SchemeError::UnexpectedParam {
                    scheme: name.into(),
                    param: k.into(),
                });
            }
            *slot = Some(x);
        }
        Scheme::from_name(name, alpha, radius, distance, width, reflex)
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
        assert!(matches!(
            "foo".parse::<Scheme>(),
            Err(SchemeError::Unknown(_))
        ));
        assert!(matches!(
            "combination".parse::<Scheme>(),
            Err(SchemeError::Missing { .. })
        ));
        assert!(matches!(
            "vector-sum:alpha=0.5".parse::<Scheme>(),
            Err(SchemeError::Param(_))
        ));
        assert!(matches!(
            "cut-width:d=-1".parse::<Scheme>(),
            Err(SchemeError::Param(_))
        ));
        assert!(matches!(
            "cut-width:d=nan".parse::<Scheme>(),
            Err(SchemeError::Param(_))
        ));
        assert!(matches!(
            "doo-sabin:r=1".parse::<Scheme>(),
            Err(SchemeError::UnexpectedParam { .. })
        ));
        assert!(matches!(
            "cut-width:d=x".parse::<Scheme>(),
            Err(SchemeError::BadNumber(_))
        ));
        assert!(matches!(parse_pipeline(" , "), Err(SchemeError::Empty)));
        assert!(matches!(
            "loop:r=1".parse::<Scheme>(),
            Err(SchemeError::UnexpectedParam { .. })
        ));
    }
}
