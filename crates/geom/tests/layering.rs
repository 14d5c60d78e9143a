//! No import circles between the source files of a crate (docs/architecture.md, "Layering"):
//! read from the files' own `use` lines and inline paths (`crate::`, `super::`, `self::`), each
//! name resolved to the deepest module file that exists; two files that reach each other along
//! such imports are a circle; the failure names every circle found.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

type Module = Vec<String>;

fn modules(src: &Path) -> BTreeMap<Module, PathBuf> {
    let mut out = BTreeMap::new();
    let mut stack = vec![src.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let rel = path.strip_prefix(src).unwrap().with_extension("");
                let mut parts: Module = rel
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().to_string())
                    .collect();
                if matches!(
                    parts.last().map(String::as_str),
                    Some("mod" | "lib" | "main")
                ) {
                    parts.pop();
                }
                out.insert(parts, path);
            }
        }
    }
    out
}

/// The text without comments and without its `#[cfg(test)]` part.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    let mut out = String::new();
    let mut rest = text;
    while let Some(a) = rest.find("/*") {
        out.push_str(&rest[..a]);
        rest = rest[a..].find("*/").map_or("", |b| &rest[a + b + 2..]);
    }
    out.push_str(rest);
    out.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Module paths named by `text`, written in module `here`.
fn named(text: &str, here: &Module) -> Vec<Module> {
    let resolve = |kind: &str, rest: Vec<String>| -> Module {
        let mut start: Module = match kind {
            "crate" => Vec::new(),
            "self" => here.clone(),
            _ => here[..here.len().saturating_sub(1)].to_vec(),
        };
        let mut rest = rest.into_iter().peekable();
        if kind == "super" {
            while rest.peek().is_some_and(|p| p == "super") {
                start.pop();
                rest.next();
            }
        }
        start.extend(rest.filter(|p| p != "self"));
        start
    };
    let b = text.as_bytes();
    let mut out = Vec::new();
    for kind in ["crate", "super", "self"] {
        let mut from = 0;
        while let Some(i) = text[from..].find(kind) {
            let at = from + i;
            from = at + kind.len();
            if at > 0 && ident(b[at - 1] as char) || !text[from..].starts_with("::") {
                continue;
            }
            // The path: identifiers joined by `::`, then maybe one `{…}` group.
            let mut parts = Vec::new();
            let mut j = from;
            while text[j..].starts_with("::") {
                j += 2;
                let len = text[j..]
                    .find(|c: char| !ident(c))
                    .unwrap_or(text.len() - j);
                if len == 0 {
                    break;
                }
                parts.push(text[j..j + len].to_string());
                j += len;
            }
            if text[j..].starts_with('{') {
                let end = text[j..].find('}').map_or(text.len(), |e| j + e);
                for item in text[j + 1..end].split(',') {
                    let item = item.split(" as ").next().unwrap_or("").trim();
                    if item.is_empty() || item.contains('{') {
                        continue;
                    }
                    let mut p = parts.clone();
                    p.extend(item.split("::").map(|s| s.trim().to_string()));
                    out.push(resolve(kind, p));
                }
            }
            out.push(resolve(kind, parts));
        }
    }
    out
}

fn circles(src: &Path) -> Vec<Vec<Module>> {
    let mods = modules(src);
    let mut edges: BTreeMap<&Module, BTreeSet<&Module>> = BTreeMap::new();
    for (m, path) in &mods {
        let text = code(&std::fs::read_to_string(path).unwrap());
        let set = edges.entry(m).or_default();
        for mut t in named(&text, m) {
            while !t.is_empty() && !mods.contains_key(&t) {
                t.pop();
            }
            if !t.is_empty() && &t != m {
                set.insert(mods.get_key_value(&t).unwrap().0);
            }
        }
    }
    // Reachability by depth-first search from each module (the crates are a few hundred files).
    let reach = |from: &Module| -> BTreeSet<&Module> {
        let mut seen = BTreeSet::new();
        let mut stack: Vec<&Module> = edges[from].iter().copied().collect();
        while let Some(v) = stack.pop() {
            if seen.insert(v) {
                stack.extend(edges[v].iter().copied());
            }
        }
        seen
    };
    let all: BTreeMap<&Module, BTreeSet<&Module>> = mods.keys().map(|m| (m, reach(m))).collect();
    let mut out: Vec<Vec<Module>> = Vec::new();
    for m in mods.keys() {
        let comp: Vec<Module> = mods
            .keys()
            .filter(|n| all[m].contains(n) && all[n].contains(m))
            .cloned()
            .collect();
        if comp.len() > 1 && !out.contains(&comp) {
            out.push(comp);
        }
    }
    out
}

#[test]
fn no_source_file_imports_one_that_imports_it_back() {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for name in ["geom", "viewport", "app"] {
        let src = crates.join(name).join("src");
        let found = circles(&src);
        let shown: Vec<String> = found
            .iter()
            .map(|c| {
                c.iter()
                    .map(|m| m.join("::"))
                    .collect::<Vec<_>>()
                    .join(" <-> ")
            })
            .collect();
        assert!(found.is_empty(), "{name}: {shown:#?}");
    }
}

/// The check finds a circle when there is one (a module and its parent naming each other).
#[test]
fn the_check_sees_a_circle() {
    let dir = std::env::temp_dir().join(format!("prism-layering-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("a")).unwrap();
    std::fs::write(dir.join("lib.rs"), "mod a;\nmod b;\n").unwrap();
    std::fs::write(dir.join("a/mod.rs"), "use crate::b::X;\npub struct Y;\n").unwrap();
    std::fs::write(dir.join("b.rs"), "use crate::a::{Y};\npub struct X;\n").unwrap();
    let found = circles(&dir);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(found.len(), 1, "{found:?}");
}
