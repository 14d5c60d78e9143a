//! Negative numbers as flag values: `--eye -2.5,-4,8` as well as `--eye=-2.5,-4,8`.
//!
//! clap takes a word that starts with `-` after a flag for another flag unless the argument
//! allows hyphen values; a number list such as `-2.5,-4,8` is not a number to its
//! `allow_negative_numbers`. No flag of Prism's starts with a digit or a point, so a word that
//! does (`-2.5`, `-.5`, `-2.5,-4,8`) after a long flag that takes a value is that flag's value:
//! the two words are joined as `--flag=value` before parsing, for every flag of every
//! subcommand alike.

use clap::CommandFactory;
use std::collections::HashSet;
use std::ffi::OsString;

/// The long names of every flag, in any subcommand, that takes a value.
fn flags_with_values() -> HashSet<String> {
    fn walk(cmd: &clap::Command, out: &mut HashSet<String>) {
        for arg in cmd.get_arguments() {
            if let Some(long) = arg.get_long()
                && arg.get_action().takes_values()
            {
                out.insert(long.to_string());
            }
        }
        for sub in cmd.get_subcommands() {
            walk(sub, out);
        }
    }
    let mut out = HashSet::new();
    walk(&super::Cli::command(), &mut out);
    out
}

/// Whether a word is a negative number or a list that starts with one.
fn negative(word: &str) -> bool {
    let mut chars = word.chars();
    chars.next() == Some('-') && chars.next().is_some_and(|c| c.is_ascii_digit() || c == '.')
}

/// `args` with each long flag that takes a value joined to a following negative number.
pub fn joined(args: impl IntoIterator<Item = OsString>) -> Vec<OsString> {
    let takes = flags_with_values();
    let mut out: Vec<OsString> = Vec::new();
    let mut args = args.into_iter().peekable();
    let mut after_separator = false;
    while let Some(a) = args.next() {
        let text = a.to_str().unwrap_or("");
        after_separator |= text == "--";
        let value = !after_separator
            && text
                .strip_prefix("--")
                .is_some_and(|name| !name.contains('=') && takes.contains(name))
            && args.peek().and_then(|n| n.to_str()).is_some_and(negative);
        if value {
            let v = args.next().unwrap_or_default();
            let mut both = a.clone();
            both.push("=");
            both.push(v);
            out.push(both);
        } else {
            out.push(a);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(s: &str) -> Vec<OsString> {
        s.split(' ').map(OsString::from).collect()
    }

    #[test]
    fn a_negative_value_joins_its_flag() {
        assert_eq!(
            joined(words("prism render a.obj --eye -2.5,-4,8 -o b.png")),
            words("prism render a.obj --eye=-2.5,-4,8 -o b.png")
        );
        assert_eq!(
            joined(words("prism render a.obj --eye -.5,1,2")),
            words("prism render a.obj --eye=-.5,1,2")
        );
    }

    #[test]
    fn other_words_stay_as_they_are() {
        // A flag without a value, a flag given with `=`, a word that is not a number, a path
        // after `--`.
        for s in [
            "prism render a.obj --wireframe -o b.png",
            "prism render a.obj --eye=-1,2,3",
            "prism render a.obj --eye 1,2,3",
            "prism render -- --eye -1",
        ] {
            assert_eq!(joined(words(s)), words(s), "{s}");
        }
    }
}
