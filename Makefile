# The two commands of README.md:
#   make run   - install what is missing, build, render the built-in scene headless to out/*.png
#   make test  - install what is missing, build, run every test (CTest + doctest)
BUILD_DIR ?= build
BUILD_TYPE ?= RelWithDebInfo
JOBS ?= $(shell nproc)
FXVIEW = $(BUILD_DIR)/bin/fxview
MESHES = sphere torus cube plane disc knot
VIEWS = normals uv camera light

FUZZ_SECONDS ?= 300

.PHONY: deps build fuzz-build run test sweep fuzz sanitize clean

deps:
	./scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)
	cmake --build $(BUILD_DIR) -j $(JOBS)

run: build
	@mkdir -p out
	$(FXVIEW) info --backend egl
	@for mesh in $(MESHES); do \
	  $(FXVIEW) render --mesh $$mesh --size 512x512 --camera-rotate 20,-30,0 --samples 4 --out out/$$mesh-normals.png || exit 1; \
	done
	@for view in $(VIEWS); do \
	  $(FXVIEW) render --mesh knot --debug-view $$view --size 512x512 --samples 4 --out out/knot-$$view.png || exit 1; \
	done
	$(FXVIEW) render effects/examples/textured.fx --technique CheckerLambert --mesh torus --camera-rotate 30,0,0 --size 512x512 --samples 4 --out out/torus-checker.png
	$(FXVIEW) render effects/examples/textured.fx --technique Mirror --mesh knot --size 512x512 --samples 4 --out out/knot-mirror.png
	$(FXVIEW) render effects/debug.fx --technique Plain --mesh knot --set PlainColor=#d4a017 --size 512x512 --samples 4 --out out/knot-plain.png
	$(FXVIEW) render effects/spectral/wavelength.fx --technique Phong --set LightSpectrum=D65 --set ObjectSpectrum=TCS09 --mesh knot --size 512x512 --out out/knot-spectral-phong.png
	$(FXVIEW) render effects/spectral/wavelength.fx --technique Phong --set ObjectSpectrum=TCS09 --set Brightness=0.5 --environment sky:35 --mesh knot --size 512x512 --out out/knot-spectral-sky.png
	$(FXVIEW) render effects/spectral/thinfilm.fx --technique Bubble --set Thickness=250 --set Variation=600 --mesh sphere --size 512x512 --out out/sphere-bubble.png
	$(FXVIEW) render effects/spectral/thinfilm.fx --technique BubbleFourier --set Thickness=300 --set Variation=700 --environment sky:35 --mesh sphere --size 512x512 --out out/sphere-bubble-sky.png
	$(FXVIEW) render effects/spectral/thinfilm.fx --technique BubbleFourier --set Thickness=300 --set Variation=700 --environment textures/colour_room.hdr --mesh sphere --size 512x512 --out out/sphere-bubble-room.png
	$(FXVIEW) render effects/spectral/thinfilm.fx --technique MultiLayerFaster --mesh knot --size 512x512 --out out/knot-multilayer.png
	$(FXVIEW) render effects/brdf/analytic.fx --preset effects/brdf/presets/gold.json --technique PBR --mesh knot --size 512x512 --samples 4 --out out/knot-pbr-gold.png
	$(FXVIEW) render effects/brdf/analytic.fx --technique AshikhminShirley --mesh torus --camera-rotate 30,0,0 --size 512x512 --samples 4 --environment studio --tone-map pbr-neutral --out out/torus-ashikhmin-shirley.png
	@for metal in gold copper silver aluminium titanium; do \
	  $(FXVIEW) render effects/brdf/analytic.fx --preset effects/brdf/presets/$$metal.json --mesh sphere --size 512x512 --out out/sphere-$$metal.png || exit 1; \
	done
	$(FXVIEW) render effects/brdf/analytic.fx --preset effects/brdf/presets/gold.json --set Roughness=0.08 --environment sky:25,4500 --mesh knot --size 512x512 --out out/knot-gold-sky.png
	$(FXVIEW) render effects/brdf/analytic.fx --preset effects/brdf/presets/gold.json --set Roughness=0.12 --light-shape rectangle --light-size 2,3 --light-position -2,2,3 --mesh sphere --size 512x512 --out out/sphere-gold-window.png
	$(FXVIEW) compare effects/brdf/analytic.fx --technique PBR --environment studio --ground-truth --size 96x96 --heatmap out/compare-ibl.png
	$(FXVIEW) render effects/legacy/wavelength.cgfx --mesh knot --size 512x512 --out out/knot-thesis-cg.png
	$(FXVIEW) render tests/effects/legacy/glow.fx --mesh sphere --size 512x512 --out out/sphere-legacy-glow.png
	$(FXVIEW) render effects/spectral/cd.fx --mesh disc --camera-rotate 50,0,0 --light-angle 15 --size 512x512 --out out/disc-cd.png
	$(FXVIEW) render effects/spectral/cd.fx --mesh disc --camera-rotate 50,0,0 --light-angle 2 --size 512x512 --out out/disc-cd-lamp.png
	$(FXVIEW) render effects/spectral/cd.fx --mesh disc --camera-rotate 50,0,0 --light-shape rectangle --light-size 3,1 --size 512x512 --out out/disc-cd-window.png
	$(FXVIEW) render effects/spectral/cd.fx --mesh disc --environment studio --set Lamp=0 --camera-rotate -25,15,0 --size 512x512 --out out/disc-cd-studio.png
	$(FXVIEW) render effects/spectral/thinfilm.fx --technique FresnelFourier --mesh plane --set FilmIndex=1.5 --set SubstrateIndex=1.33 --set Thickness=150 --set Variation=900 --environment sky:35 --camera-rotate -70,0,0 --camera-distance 2.2 --size 512x512 --out out/plane-oil-sky.png
	$(FXVIEW) render effects/spectral/thinfilm.fx --technique FresnelFourier --mesh knot --set FilmIndex=2.4 --set SubstrateIndex=2.54 --set SubstrateKappa=3.43 --set Thickness=60 --set Variation=200 --set Brightness=1 --environment studio --size 512x512 --out out/knot-anodized-studio.png
	$(FXVIEW) spectra plot D65 A F11 TCS09 --out out/spectra.png
	$(FXVIEW) compare effects/spectral/wavelength.fx --heatmap out/compare.png
	$(FXVIEW) compare effects/spectral/thinfilm.fx --size 96x96 --heatmap out/compare-thinfilm.png
	$(FXVIEW) compare effects/spectral/cd.fx --mesh disc --camera-rotate 50,0,0 --size 96x96 --heatmap out/compare-cd.png
	$(FXVIEW) compare effects/spectral/cd.fx --technique Orders --mesh disc --camera-rotate 50,0,0 --light-angle 15 --size 96x96 --heatmap out/compare-cd-ceiling.png
	$(FXVIEW) compare effects/brdf/analytic.fx --heatmap out/compare-brdf.png
	$(FXVIEW) compare effects/examples/textured.fx --mesh torus --heatmap out/compare-textured.png
	$(FXVIEW) render --mesh sphere --size 256x256 --out out/sphere-normals.exr
	$(FXVIEW) pick --mesh sphere --size 256x256 --at 128,128
	$(FXVIEW) brdf-grid --model pbr --param base=0.9,0.6,0.3 --param roughness=0.3 --out out/gold-grid.csv
	$(FXVIEW) fit out/gold-grid.csv --out out/fit-gold.csv --preset out/fit-gold.json --preview out/fit-gold.png
	$(FXVIEW) render effects/brdf/measured.fx --technique Measured --set Measured=out/gold-grid.csv --mesh knot --size 512x512 --out out/knot-measured.png
	$(FXVIEW) render effects/brdf/measured.fx --technique Fitted --preset out/fit-gold.json --mesh knot --size 512x512 --out out/knot-fitted.png

# The sanitizer build of the fuzz harnesses (clang, ASan + UBSan) that the fuzz_replay test runs.
fuzz-build: deps
	./scripts/fuzz.sh build $(BUILD_DIR)/sanitize

test: build fuzz-build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The full parameter sweep (make test runs a quick one per technique): scripts/sweep.sh.
sweep: build
	JOBS=$(JOBS) OUT=$(BUILD_DIR)/sweep ./scripts/sweep.sh $(FXVIEW)

# A fuzzing campaign: every harness for FUZZ_SECONDS (default 300) on the corpora; findings go to
# $(BUILD_DIR)/sanitize/fuzz-crashes.
fuzz: deps
	./scripts/fuzz.sh campaign $(FUZZ_SECONDS) $(BUILD_DIR)/sanitize

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang): a second full build.
sanitize: deps fuzz-build
	CC=clang CXX=clang++ cmake -S . -B $(BUILD_DIR)/asan-suite -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFXVIEW_SANITIZE=ON
	cmake --build $(BUILD_DIR)/asan-suite -j $(JOBS)
	cd $(BUILD_DIR)/asan-suite && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS) -E fuzz_replay

clean:
	rm -rf $(BUILD_DIR) out
