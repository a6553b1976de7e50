#!/bin/bash
# The full parameter sweep (`make sweep`): every shipped effect's techniques through their UI ranges
# with SWEEP_RANDOM random combinations (default 8) at larger images than the quick sweep that
# `make test` runs (tests/CMakeLists.txt). Effects run in parallel, JOBS at a time; each writes
# its table to $OUT/NAME.txt. Exits non-zero when any comparison failed. Takes about half an hour
# on 2 cores at the default sizes.
set -u
FXVIEW=${1:-build/bin/fxview}
OUT=${OUT:-build/sweep}
JOBS=${JOBS:-$(nproc)}
RANDOM_CASES=${SWEEP_RANDOM:-8}
mkdir -p "$OUT"
sweep() {  # effect size
    local name=${1//\//_}
    if "$FXVIEW" compare "effects/$1" --sweep --sweep-random "$RANDOM_CASES" --size "$2" > "$OUT/$name.txt" 2>&1; then
        echo "ok     $1 ($2): $(tail -n 1 "$OUT/$name.txt")"
    else
        echo "FAILED $1 ($2): $(tail -n 1 "$OUT/$name.txt") - see $OUT/$name.txt"
        return 1
    fi
}
export -f sweep
export FXVIEW OUT RANDOM_CASES
printf '%s\n' "debug.fx 64x64" "examples/textured.fx 64x64" "brdf/analytic.fx 64x64" "brdf/measured.fx 64x64" \
    "spectral/wavelength.fx 32x32" "spectral/cd.fx 32x32" "spectral/thinfilm.fx 32x32" "legacy/wavelength.cgfx 32x32" |
    xargs -P "$JOBS" -L 1 bash -c 'sweep "$0" "$1"'
