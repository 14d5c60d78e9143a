#!/usr/bin/env bash
# Makes every picture of docs/figures.md into DIR: each `prism …` command on that page with
# {out} replaced by DIR, in the page's order, with the prism of `cargo build --release` (or
# $PRISM). Stops at the first command that fails.
set -euo pipefail
dir=${1:?usage: docs/figures/make.sh DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
prism=${PRISM:-$root/target/release/prism}
mkdir -p "$dir"
cd "$root"
grep -o '`prism [^`]*{out}[^`]*`' docs/figures.md | tr -d '`' | while read -r line; do
    cmd=${line//\{out\}/$dir}
    echo "+ $cmd"
    # shellcheck disable=SC2086
    "$prism" ${cmd#prism } > /dev/null
done
echo "pictures in $dir"
