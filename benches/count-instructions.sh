#!/usr/bin/env bash
# Instructions per run of `antipodal` (warm: on a prepared curve; cold: preparing and answering
# once) on the papers' shapes and the wavy cubic, of the medial axis (warm: on the region
# built; cold: from the file's bytes) on the medial benchmarks' shapes, and of the grasps of
# the grasp benchmark's batch of 100 outlines (polygons, periodic cubics; cold, one thread),
# counted by callgrind.
# Usage: benches/count-instructions.sh [FILE ...]   (needs valgrind; FILEs: antipodal's runs)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench --bench instructions --no-run -q 2>/dev/null
bin=$(ls -t "${CARGO_TARGET_DIR:-target}"/release/deps/instructions-* | grep -v '\.d$' | head -1)
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
    files=(fixtures/antipodal-ellipse.json fixtures/antipodal-limacon.json
           fixtures/antipodal-lemniscate.json fixtures/antipodal-convexities-3.json
           fixtures/antipodal-convexities-4.json fixtures/antipodal-bspline-wavy.json)
fi
count() {
    local out
    out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
        --toggle-collect='*measured*' "$bin" "$1" "$2" "$3" 2>/dev/null
    local total
    total=$(grep -E '^(summary|totals):' "$out" | head -1 | awk '{print $2}')
    rm -f "$out"
    echo $(( total / $3 ))
}
printf '%-45s %12s %12s %8s\n' file warm cold cold/warm
for f in "${files[@]}"; do
    w=$(count "$f" warm 50)
    c=$(count "$f" cold 5)
    printf '%-45s %12d %12d %8.1f\n' "$f" "$w" "$c" "$(echo "$c / $w" | bc -l)"
done
if [ $# -eq 0 ]; then
    for f in fixtures/region-pocket.json fixtures/periodic_cubic.json fixtures/profile-cam.json; do
        w=$(count "$f" medial-warm 20)
        c=$(count "$f" medial-cold 5)
        printf '%-45s %12d %12d %8.1f\n' "medial $f" "$w" "$c" "$(echo "$c / $w" | bc -l)"
    done
fi
if [ $# -eq 0 ]; then
    for kind in polygons outlines; do
        printf '%-45s %12d\n' "grasps: batch of 100 $kind" "$(count grasps "$kind" 1)"
    done
fi
