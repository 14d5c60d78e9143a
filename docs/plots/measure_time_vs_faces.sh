#!/usr/bin/env bash
# Measures Catmull–Clark level 1, OBJ file to OBJ file, whole process, for Prism and
# OpenSubdiv's runner (../shared/peers, `peer_subdiv --lib osd`) on quad tori of 10k, 100k,
# 1M and 5M faces, runs alternated with `sync` between; also the refinement alone (Prism's
# `prism bench`, the runner's own `time_ms=`). Writes CSV rows to stdout:
#   faces,tool,what,seconds
# Usage: docs/plots/measure_time_vs_faces.sh PEER_BINARY TORUS_10K TORUS_100K TORUS_1M TORUS_5M
# (the tori: e.g. the snippet in docs/primal.md with n × n = 100², 316², 1000², 2236²).
set -euo pipefail
peer=$1
shift
prism=${PRISM:-target/release/prism}
out=$(mktemp -d)
echo "faces,tool,what,seconds"
for input in "$@"; do
    faces=$(grep -c '^f ' "$input")
    runs=3
    [ "$faces" -gt 2000000 ] && runs=1
    for _ in $(seq "$runs"); do
        sync
        /usr/bin/time -f "%e" -o "$out/t" "$prism" subdivide "$input" -o "$out/p.obj" \
            --scheme catmull-clark --levels 1 >/dev/null 2>&1
        echo "$faces,prism,whole,$(cat "$out/t")"
        rm -f "$out/p.obj"
        sync
        /usr/bin/time -f "%e" -o "$out/t" "$peer" --lib osd --scheme catmull-clark --levels 1 \
            "$input" "$out/o.obj" >/dev/null 2>"$out/err"
        echo "$faces,opensubdiv,whole,$(cat "$out/t")"
        ms=$(grep -o 'time_ms=[0-9.]*' "$out/err" | head -1 | cut -d= -f2)
        printf '%s,opensubdiv,refine,%.4f\n' "$faces" "$(echo "$ms / 1000" | bc -l)"
        rm -f "$out/o.obj"
    done
    ms=$("$prism" bench "$input" --scheme catmull-clark --runs "$runs" | grep -o 'time_ms=[0-9.]*' | cut -d= -f2)
    printf '%s,prism,refine,%.4f\n' "$faces" "$(echo "$ms / 1000" | bc -l)"
done
rm -rf "$out"
