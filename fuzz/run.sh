#!/usr/bin/env bash
# Seeds the corpora and runs every fuzz target for SECONDS each (default 600), one after
# the other; prints each run's last libFuzzer status line. A crash stops the script with
# libFuzzer's report and leaves the input under fuzz/artifacts/TARGET/: add it under
# fuzz/regressions/TARGET/ (replayed by crates/geom/tests/fuzz_regressions.rs) with the fix.
#   fuzz/run.sh [SECONDS] [TARGET...]
# Needs cargo-fuzz (`cargo install cargo-fuzz --locked`); the stable toolchain does with
# RUSTC_BOOTSTRAP=1. No sanitizer (Prism's crates forbid no unsafe, but hold none of their
# own), debug assertions on, so that an integer overflow is a crash as in a debug build.
set -euo pipefail
cd "$(dirname "$0")"
seconds=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj document polyline sections scene step stl ply)
shared=../../shared/meshes
[ -d "$shared" ] || shared=../../../shared/meshes

seed() { # seed TARGET FILE...
    mkdir -p "corpus/$1"
    local t=$1
    shift
    for f in "$@"; do [ -f "$f" ] && cp -n "$f" "corpus/$t/" || true; done
}
seed obj ../assets/*.obj "$shared"/opensubdiv/*.obj
seed step ../assets/*.obj "$shared"/opensubdiv/*.obj
seed document ../assets/*.prism.json
seed sections ../assets/*.skin.json
seed scene ../assets/*.envelope.json
mkdir -p corpus/stl
[ -f corpus/stl/cube.stl ] || printf 'solid c\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid c\n' > corpus/stl/cube.stl
mkdir -p corpus/ply
[ -f corpus/ply/tetra.ply ] || printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n' > corpus/ply/tetra.ply
mkdir -p corpus/polyline
printf '%s' '{"closed": true, "points": [[1,0],[0,1],[-1,0],[0,-1]]}' > corpus/polyline/square.json
printf '%s' '{"closed": false, "points": [[0,0],[1,0],[1.5,0.8],[1.2,2]]}' > corpus/polyline/open.json
printf '%s' '{"closed": true, "points": [[0,0],[2,0],[2,1],[1,1],[1,2],[0,2]]}' > corpus/polyline/l.json

export RUSTC_BOOTSTRAP=1
cargo fuzz build -s none -a
mkdir -p logs
for t in "${targets[@]}"; do
    echo "== $t: $seconds s"
    if ! cargo fuzz run -s none -a "$t" "corpus/$t" -- -max_total_time="$seconds" \
        -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 > "logs/$t.log" 2>&1; then
        tail -40 "logs/$t.log"
        echo "fuzz target $t failed: the input is under fuzz/artifacts/$t/"
        exit 1
    fi
    grep -E "DONE|stat::number_of_executed_units|stat::peak_rss_mb" "logs/$t.log"
done
