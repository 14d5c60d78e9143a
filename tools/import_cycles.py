#!/usr/bin/env python3
"""Import circles between the source files of each crate, read from their own `use` lines.

Every `.rs` file under `crates/*/src` is a module (`mod.rs` and `lib.rs`/`main.rs` stand for
their folder). A file imports a module when one of its `use` lines (or a path written inline,
`crate::a::b::f(...)`) names it through `crate::`, `super::` or `self::`; the name is resolved
to the deepest module file that exists. Two files are in a circle when each reaches the other
along such imports (a strongly connected component of more than one file). A module's own
`mod.rs` re-exporting its children (`pub use child::X`) and children naming their parent's
items are both imports; a circle between a `mod.rs` and its own child is reported too.

Usage: `python3 tools/import_cycles.py` — prints each circle and exits 1 if there is any.
"""
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "crates")


def modules(src):
    """Module path (tuple) -> file, for one crate's src folder."""
    out = {}
    for dirpath, _, files in os.walk(src):
        for f in files:
            if not f.endswith(".rs"):
                continue
            rel = os.path.relpath(os.path.join(dirpath, f), src)
            parts = rel[:-3].split(os.sep)
            if parts[-1] in ("mod", "lib", "main"):
                parts = parts[:-1]
            out[tuple(parts)] = os.path.join(dirpath, f)
    return out


PATH = re.compile(r"\b(crate|super|self)((?:::[A-Za-z_][A-Za-z0-9_]*)+)")
GROUP = re.compile(r"\b(crate|super|self)((?:::[A-Za-z_][A-Za-z0-9_]*)*)::\{([^;]*?)\}", re.S)


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return "\n".join(line.split("//")[0] for line in text.split("\n"))


def targets(text, here):
    """The module paths a file at `here` names."""
    # `self` is the module itself and `super` its parent, for a folder's mod.rs as for a file.
    base = here
    found = []

    def resolve(kind, rest):
        if kind == "crate":
            start = ()
        elif kind == "self":
            start = base
        else:
            start = base[:-1]
            while rest and rest[0] == "super":
                start, rest = start[:-1], rest[1:]
        return start + tuple(rest)

    # Expand `a::{b, c::d}` groups one level (enough for this code base).
    for m in GROUP.finditer(text):
        head = [p for p in m.group(2).split("::") if p]
        for item in m.group(3).split(","):
            item = item.strip().split(" as ")[0].strip()
            if not item or item.startswith("{"):
                continue
            parts = [p for p in item.split("::") if p and p != "self"]
            found.append(resolve(m.group(1), head + parts))
    for m in PATH.finditer(text):
        parts = [p for p in m.group(2).split("::") if p]
        found.append(resolve(m.group(1), parts))
    return found


def main():
    circles = []
    for crate in sorted(os.listdir(ROOT)):
        src = os.path.join(ROOT, crate, "src")
        if not os.path.isdir(src):
            continue
        mods = modules(src)
        edges = {m: set() for m in mods}
        for m, f in mods.items():
            text = strip_comments(open(f, encoding="utf-8").read())
            # Test modules inside a file are not part of the build's layering.
            text = text.split("#[cfg(test)]")[0]
            for t in targets(text, m):
                while t and t not in mods:
                    t = t[:-1]
                if t != m and t in mods and t != ():
                    edges[m].add(t)
        # Tarjan's strongly connected components.
        index, low, stack, on, comps = {}, {}, [], set(), []
        counter = [0]
        sys.setrecursionlimit(10000)

        def visit(v):
            index[v] = low[v] = counter[0]
            counter[0] += 1
            stack.append(v)
            on.add(v)
            for w in edges[v]:
                if w not in index:
                    visit(w)
                    low[v] = min(low[v], low[w])
                elif w in on:
                    low[v] = min(low[v], index[w])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    comps.append(sorted(comp))

        for v in sorted(mods):
            if v not in index:
                visit(v)
        for c in comps:
            circles.append((crate, ["::".join(m) or "(root)" for m in c]))
    for crate, c in circles:
        print(f"{crate}: {' <-> '.join(c)}")
    print(f"{len(circles)} import circle(s)")
    return 1 if circles else 0


if __name__ == "__main__":
    sys.exit(main())
