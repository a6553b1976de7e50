#!/usr/bin/env bash
# Fuzzing fxview's file readers with libFuzzer under AddressSanitizer + UndefinedBehaviorSanitizer.
#   scripts/fuzz.sh build [BUILD]            configure and build the harnesses (default build/sanitize)
#   scripts/fuzz.sh replay [BUILD]           run every corpus input once: the regression check (CTest)
#   scripts/fuzz.sh campaign [SECONDS] [BUILD]  fuzz each harness for SECONDS (default 300); new
#                                            crashes land in BUILD/fuzz-crashes, new inputs in BUILD/fuzz-corpus
# Inputs: tests/fuzz/corpus/<harness>/ (crafted cases, one per defect found so far) plus the shipped
# files of each kind (effects, textures, spectra, presets, colord-data's spectra).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
action=${1:-replay}
harnesses=(fuzz_effect fuzz_brdf_file fuzz_texture fuzz_spectral fuzz_brdf_data fuzz_obj fuzz_preset fuzz_environment fuzz_plugin fuzz_values)
# Every report is fatal; memory per input is bounded the way users expect fxview to bound it.
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
limits=(-rss_limit_mb=2560 -malloc_limit_mb=1024 -timeout=20)

build() {
  local dir=$1
  cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DFXVIEW_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
  cmake --build "$dir" --target fuzz_harnesses -j "$(nproc)"
}

# The shipped files of a harness's kind, as that harness reads them (textures get the selector byte).
seeds() {
  local harness=$1 out=$2
  mkdir -p "$out"
  case $harness in
    fuzz_effect) find "$root/effects" "$root/tests/effects" -name '*.fx' -o -name '*.cgfx' -o -name '*.glsl' | while read -r f; do cp "$f" "$out/"; done ;;
    fuzz_texture)
      local i=0 ext
      for ext in png jpg bmp tga hdr exr dds ftxt; do
        find "$root/textures" "$root/tests/effects" -iname "*.$ext" | while read -r f; do
          { printf "\\$(printf '%03o' "$i")"; cat "$f"; } >"$out/$(basename "$f").bin"
        done
        i=$((i + 1))
      done ;;
    fuzz_spectral) find /usr/share/colord/illuminant /usr/share/colord/ref -maxdepth 1 -type f -size -64k 2>/dev/null | head -20 | while read -r f; do cp "$f" "$out/"; done ;;
    fuzz_brdf_file) find "$root/tests/effects" -name '*.brdf' | while read -r f; do cp "$f" "$out/"; done ;;
    fuzz_brdf_data) cp "$root/textures/sample-brdf.csv" "$out/" ;;
    fuzz_preset) find "$root/effects" -name '*.json' | while read -r f; do cp "$f" "$out/"; done ;;
    fuzz_environment)  # the selector byte as the harness reads it: format index, +8 for six faces
      local j=0 e
      for e in png hdr exr dds; do
        find "$root/textures" "$root/tests/effects" -iname "*.$e" -size -256k | head -3 | while read -r f; do
          { printf "\\$(printf '%03o' "$j")"; cat "$f"; } >"$out/$(basename "$f").one"
          { printf "\\$(printf '%03o' $((j + 8)))"; cat "$f"; } >"$out/$(basename "$f").six"
        done
        j=$((j + 1))
      done ;;
  esac
}

case $action in
  build) build "${2:-$root/build/sanitize}" ;;
  replay)
    dir=${2:-$root/build/sanitize}
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    failed=0 inputs=0
    for harness in "${harnesses[@]}"; do
      [[ -x "$dir/fuzz/$harness" ]] || { echo "fuzz: $dir/fuzz/$harness is missing (run scripts/fuzz.sh build)"; exit 1; }
      seeds "$harness" "$work/$harness"
      mapfile -t files < <(find "$root/tests/fuzz/corpus/$harness" "$work/$harness" -type f | sort)
      inputs=$((inputs + ${#files[@]}))
      if (cd "$work" && "$dir/fuzz/$harness" "${limits[@]}" "${files[@]}" >"$work/$harness.log" 2>&1); then
        echo "fuzz: $harness: ${#files[@]} inputs replayed, no finding"
      else
        echo "fuzz: $harness FAILED:"; tail -40 "$work/$harness.log"; failed=$((failed + 1))
      fi
    done
    echo "fuzz replay: $inputs inputs through ${#harnesses[@]} harnesses"
    echo "$(( ${#harnesses[@]} - failed )) passed, $failed failed"
    [[ $failed -eq 0 ]] ;;
  campaign)
    seconds=${2:-300}
    dir=${3:-$root/build/sanitize}
    build "$dir"
    mkdir -p "$dir/fuzz-crashes"
    for harness in "${harnesses[@]}"; do
      corpus="$dir/fuzz-corpus/$harness"
      mkdir -p "$corpus"
      cp -n "$root/tests/fuzz/corpus/$harness/"* "$corpus/" 2>/dev/null || true
      seeds "$harness" "$corpus"
      echo "fuzz: $harness for ${seconds}s"
      dict=()
      [[ -f "$root/tests/fuzz/$harness.dict" ]] && dict=(-dict="$root/tests/fuzz/$harness.dict")
      (cd "$dir/fuzz-crashes" && "$dir/fuzz/$harness" "${limits[@]}" "${dict[@]}" -max_len=65536 -max_total_time="$seconds" \
        -artifact_prefix="$dir/fuzz-crashes/$harness-" "$corpus") || echo "fuzz: $harness found a problem: see $dir/fuzz-crashes"
    done ;;
  *) echo "usage: scripts/fuzz.sh build|replay|campaign [SECONDS] [BUILD]" >&2; exit 2 ;;
esac
