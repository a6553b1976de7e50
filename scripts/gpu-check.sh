#!/usr/bin/env bash
# The NVIDIA half of issue #2's check, for a session that has the device machine: run it THERE from
# the repository root, with build/bin/fxview built here and the glvnd .debs of the device README
# unpacked first. It records the renderer, the normal view at 64x64 (gpu.pfm: compare it here with
# `fxview render --size 64x64 --out llvmpipe.pfm`; the issue asks for at most 1/255 difference),
# the GPU-vs-CPU comparison of every shipped effect and their frame times.
set -euo pipefail
out=${OUT:-out}/gpu-check
mkdir -p "$out"
fxview=build/bin/fxview
"$fxview" info --backend egl --json | tee "$out/info.json"
"$fxview" info --backend egl-device --json | tee "$out/info-device.json" || true
"$fxview" render --size 64x64 --out "$out/gpu.pfm"
"$fxview" compare effects/spectral/wavelength.fx --json --heatmap "$out/compare.png" | tee "$out/compare.jsonl" || true
"$fxview" compare effects/spectral/thinfilm.fx --size 96x96 --json --heatmap "$out/compare-thinfilm.png" | tee "$out/compare-thinfilm.jsonl" || true
"$fxview" compare effects/spectral/cd.fx --mesh disc --camera-rotate 50,0,0 --size 96x96 --json --heatmap "$out/compare-cd.png" | tee "$out/compare-cd.jsonl" || true
"$fxview" compare effects/brdf/analytic.fx --json --heatmap "$out/compare-brdf.png" | tee "$out/compare-brdf.jsonl" || true
"$fxview" compare effects/brdf/measured.fx --json --heatmap "$out/compare-measured.png" | tee "$out/compare-measured.jsonl" || true
"$fxview" compare effects/examples/textured.fx --mesh torus --json --heatmap "$out/compare-textured.png" | tee "$out/compare-textured.jsonl" || true
"$fxview" compare effects/debug.fx --json | tee "$out/compare-debug.jsonl" || true
for effect in spectral/wavelength spectral/thinfilm spectral/cd brdf/analytic brdf/measured; do
  "$fxview" bench "effects/$effect.fx" --frames 10 | tee "$out/bench-$(basename "$effect").md"
done
