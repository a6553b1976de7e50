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
# Issue #14: the Fourier films' speed-up over the 1 nm loop, measured in one run.
"$fxview" bench effects/spectral/thinfilm.fx --techniques FresnelExact,FresnelFourier,Bubble,BubbleFourier --frames 10 | tee "$out/bench-fourier.md"
# Issue #25 item 7: the Fourier films under the sky (the sky's own tables) against their point-light time.
"$fxview" bench effects/spectral/thinfilm.fx --techniques FresnelFourier,BubbleFourier --frames 10 --environment sky:35 | tee "$out/bench-fourier-sky.md"
for t in FresnelFourier BubbleFourier; do
  "$fxview" compare effects/spectral/thinfilm.fx -t "$t" --environment sky:35 --size 96x96 --json | tee -a "$out/compare-fourier-sky.jsonl" || true
done
# Issue #15: the BRDF grid on the NVIDIA driver (brdf-check figures, the grid against its CPU reference).
"$fxview" brdf-check tests/effects/brdf/ggx_single_scattering.brdf --set alpha=1 --json | tee "$out/brdf-check-ggx.json" || true
"$fxview" compare effects/brdf/analytic.fx --technique BrdfGrid --size 256x256 --json | tee "$out/compare-brdf-grid.jsonl" || true
# Issue #12: image-based lighting on the NVIDIA driver (GPU against the CPU split sum and sampled
# environment light; seamless cube filtering and fixed-point texture weights are the driver's), the
# ground truth, the furnace and a metal preset.
"$fxview" compare effects/brdf/analytic.fx --environment studio --ground-truth --size 96x96 --json --heatmap "$out/compare-ibl.png" | tee "$out/compare-ibl.jsonl" || true
"$fxview" compare effects/brdf/analytic.fx -t PBR --environment sky --size 96x96 --json | tee "$out/compare-ibl-sky.jsonl" || true
"$fxview" render effects/brdf/analytic.fx -t PBR --set BaseColor=1,1,1 --set Metallic=1 --set LightIrradiance=0 --set Roughness=1 --environment furnace --size 64x64 --out "$out/furnace.pfm"
"$fxview" render effects/brdf/analytic.fx --preset effects/brdf/presets/gold.json --size 256x256 --out "$out/gold.png"
# The sweeps of every effect (issue #10) and the film-fit round trip on the NVIDIA driver's GLSL.
for effect in debug examples/textured brdf/analytic brdf/measured spectral/wavelength spectral/cd spectral/thinfilm; do
  "$fxview" compare "effects/$effect.fx" --sweep --sweep-random 1 --size 24x24 | tail -3 | tee "$out/sweep-$(basename "$effect").txt" || true
done
rgb=$("$fxview" pick effects/spectral/thinfilm.fx -t FresnelExact --set Thickness=450 --set Variation=0 --mesh sphere --size 64x64 --at 32,32 --json |
      python3 -c "import json,sys; print(','.join('%.9g' % v for v in json.load(sys.stdin)['rgba'][:3]))")
"$fxview" plugin run effects/spectral/thinfilm.fx ThicknessFromColour --set TargetColour="$rgb" | tee "$out/film-fit-450nm.txt" || true
# Issue #24: legacy Cg/HLSL effects on the NVIDIA driver (the translated GLSL is SPIRV-Cross's, the
# uniform blocks std140): the corpus checks and renders, the thesis' Cg against the CPU references.
for effect in tests/effects/legacy/*.fx tests/effects/legacy/*.cgfx effects/legacy/*.cgfx; do
  "$fxview" check "$effect" | tail -1 | tee -a "$out/legacy-check.txt" || true
  "$fxview" render "$effect" --mesh sphere --size 128x128 --out "$out/legacy-$(basename "$effect").png" 2>/dev/null || true
done
"$fxview" compare effects/legacy/wavelength.cgfx --sweep --size 24x24 | tail -3 | tee "$out/compare-legacy-thesis.txt" || true
"$fxview" compare effects/legacy/thinfilm.cgfx -t Fresnel --size 96x96 | tail -1 | tee -a "$out/compare-legacy-thesis.txt" || true
# Code 13's slack was derived from llvmpipe's acos/asin errors: does the NVIDIA driver stay within it?
"$fxview" compare effects/legacy/thinfilm.cgfx -t PathDifference --sweep --sweep-random 3 --size 24x24 | tail -3 | tee -a "$out/compare-legacy-thesis.txt" || true
# Issue #24: LoopByCount follows its parameter live.
for n in 0 3 10; do "$fxview" render tests/effects/legacy/loop_count.fx --set Count=$n --size 8x8 --out "$out/loop-$n.pfm" || true; done
# Issue #25: the CD's orders diffracting the studio and the sky, films against their ground truth.
for environment in studio sky:35; do
  "$fxview" compare effects/spectral/cd.fx -t Orders --mesh disc --camera-rotate -25,15,0 --environment "$environment" --size 96x96 --json | tee -a "$out/compare-cd-environment.jsonl" || true
done
"$fxview" bench effects/spectral/cd.fx --techniques Thesis,Orders --mesh disc --camera-rotate 50,0,0 --light-angle 15 --frames 5 | tee "$out/bench-cd-ceiling.md"
"$fxview" compare effects/spectral/thinfilm.fx -t BubbleFourier --environment sky:35 --ground-truth --size 96x96 --json | tee "$out/compare-film-truth.jsonl" || true
# wavelength.fx's lobes under the sky and the studio (filtered importance sampling through the driver's
# cube filtering) against the CPU reference and the ground truth, and its cost.
for environment in sky studio; do
  "$fxview" compare effects/spectral/wavelength.fx --environment "$environment" --ground-truth --size 64x64 --json | tee -a "$out/compare-wavelength-environment.jsonl" || true
done
"$fxview" bench effects/spectral/wavelength.fx --techniques Lambert,Phong,Blinn --frames 5 --environment studio | tee "$out/bench-wavelength-studio.md"
"$fxview" compare effects/spectral/wavelength.fx --light-radius 1 --ground-truth --size 64x64 --json | tee "$out/compare-wavelength-lamp.jsonl" || true
# Issue #25 item 3: films of varying thickness (the damped series) against the thickness-averaged film,
# and the scene light's spectrum followed by the spectral effects.
for t in FresnelFourier BubbleFourier; do
  "$fxview" compare effects/spectral/thinfilm.fx -t "$t" --set ThicknessSpread=100 --ground-truth --size 64x64 --json | tee -a "$out/compare-film-spread.jsonl" || true
done
"$fxview" compare effects/spectral/wavelength.fx -t Phong --light-spectrum F11 --size 64x64 --json | tee "$out/compare-light-spectrum.jsonl" || true
# Issue #25 item 2: an RGB image uplifted to spectra (Jakob & Hanika) lighting films, lobes and orders,
# against the CPU reference and each direction's own uplifted spectrum.
for t in "thinfilm.fx BubbleFourier" "wavelength.fx Phong" "cd.fx Orders"; do
  set -- $t
  "$fxview" compare "effects/spectral/$1" -t "$2" --mesh "$([ "$1" = cd.fx ] && echo disc || echo sphere)" --environment textures/colour_room.hdr --ground-truth --size 64x64 --json | tee -a "$out/compare-uplifted-image.jsonl" || true
done
# Issue #25 item 1: flat lights (a disc, a window) through the orders and wavelength.fx's lobes; the
# photometric intensity (a white Lambertian facing 120 lx shows 120 / pi), and the cost of the orders.
for shape in "--light-shape disc --light-angle 15" "--light-shape rectangle --light-size 3,1"; do
  "$fxview" compare effects/spectral/cd.fx -t Orders --mesh disc --camera-rotate 50,0,0 $shape --size 96x96 --json | tee -a "$out/compare-flat-lights.jsonl" || true
  "$fxview" compare effects/spectral/wavelength.fx $shape --ground-truth --size 64x64 --json | tee -a "$out/compare-flat-lights.jsonl" || true
  "$fxview" bench effects/spectral/cd.fx --techniques Thesis,Orders --mesh disc --camera-rotate 50,0,0 $shape --frames 5 | tee -a "$out/bench-cd-flat.md" || true
done
"$fxview" pick effects/spectral/wavelength.fx -t Lambert --set Kd=1 --set ObjectSpectrum=E --light-position 0,0,3 --light-intensity 120lx --size 33x33 --at 16,16 | tee "$out/pick-photometric.txt" || true
# Films mirroring a sized light, and rough films through their lobe (the filtered gather on the driver).
"$fxview" compare effects/spectral/thinfilm.fx -t BubbleFourier --light-shape rectangle --light-size 2,1 --light-position 0,1,4 --size 64x64 --json | tee "$out/compare-film-lamp.jsonl" || true
# Rough films in four strata of viewing angle: GPU = CPU, the ground truth, and their cost against smooth.
for r in 0.2 0.4 0.7; do for t in BubbleFourier FresnelFourier FresnelExact; do
  "$fxview" compare effects/spectral/thinfilm.fx -t $t --set Roughness=$r --environment sky:35 --ground-truth --size 48x48 --json | tee -a "$out/compare-rough-film.jsonl" || true
done; done
# A sized light through a rough film's lobe, point by point, against the integral over the light.
for shape in "--light-angle 10" "--light-shape disc --light-angle 10" "--light-shape rectangle --light-size 2,1"; do
  "$fxview" compare effects/spectral/thinfilm.fx -t FresnelFourier --set Roughness=0.6 $shape --light-position 0,1,4 --ground-truth --size 48x48 --json | tee -a "$out/compare-rough-film-lamp.jsonl" || true
done
for r in 0 0.4; do
  "$fxview" bench effects/spectral/thinfilm.fx --techniques FresnelFourier,BubbleFourier,FresnelExact --environment sky:35 --set Roughness=$r --frames 5 | tee -a "$out/bench-rough-film.md" || true
done
# Issue #28: a .brdf's own importance sampling (isFunc) through the NVIDIA driver, and PBR's sampled
# specular lobe against the CPU split sum and the ground truth.
"$fxview" brdf-check tests/effects/brdf/explorer/is_func_sampler.brdf --phi-i 0 --json | tee "$out/brdf-check-isfunc.json" || true
"$fxview" compare effects/brdf/analytic.fx -t PBR --preset effects/brdf/presets/gold.json --environment studio --ground-truth --size 64x64 --json | tee "$out/compare-pbr-lobe.jsonl" || true
# Issue #25 item 1: BRDF effects under sized lights (the balance heuristic over the light's points and the
# lobe's directions) against their CPU twin and the integral over the light, and what they cost.
for shape in "--light-angle 15" "--light-shape disc --light-angle 15" "--light-shape rectangle --light-size 3,1"; do
  "$fxview" compare effects/brdf/analytic.fx $shape --ground-truth --size 64x64 --json | tee -a "$out/compare-brdf-area.jsonl" || true
  "$fxview" compare effects/brdf/measured.fx $shape --ground-truth --size 64x64 --json | tee -a "$out/compare-brdf-area.jsonl" || true
  "$fxview" bench effects/brdf/analytic.fx --techniques Lambert,PBR,CookTorranceGGX $shape --frames 5 | tee -a "$out/bench-brdf-area.md" || true
done
# The CD's orders under large lights through bands (LampBand) against every order at every nm, and their cost head-on.
for shape in "--light-angle 25" "--light-shape disc --light-angle 25" "--light-shape rectangle --light-size 3,1" "--light-shape rectangle --light-angle 40" "--light-shape disc --light-angle 60" "--light-shape rectangle --light-angle 60"; do
  "$fxview" compare effects/spectral/cd.fx -t Orders --mesh disc --light-position 0,1.5,3 --set EnvironmentWeight=0 $shape --ground-truth --size 96x96 --json | tee -a "$out/compare-cd-bands.jsonl" || true
  "$fxview" bench effects/spectral/cd.fx --techniques Thesis,Orders --mesh disc --light-position 0,1.5,3 $shape --frames 5 | tee -a "$out/bench-cd-bands.md" || true
done
