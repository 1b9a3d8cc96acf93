# Seashells: `make run` builds the page and serves it; `make test` runs every test.
# Both install what is missing first, so they work on a fresh Debian machine.

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
PORT ?= 8000
TARGET := wasm32-unknown-unknown
WASM_BINDGEN_VERSION := $(shell sed -n 's/^wasm-bindgen = "=\(.*\)"/\1/p' Cargo.toml)
WASM := target/$(TARGET)/release/seashells_core.wasm
PKG := www/pkg
BIN := node_modules/.bin
export PATH := $(HOME)/.cargo/bin:$(PATH)
export XDG_RUNTIME_DIR ?= /tmp/seashells-runtime
APT := DEBIAN_FRONTEND=noninteractive apt-get

# Whether every npm package in package.json is installed at its version (binaryen for wasm-opt,
# playwright-core to drive Chromium, mediabunny to read recorded videos, jsqr to read QR codes,
# gltf-validator and three to check exported GLB files).
export NPM_INSTALLED := const fs = require('fs'); \
  const wanted = JSON.parse(fs.readFileSync('package.json', 'utf8')).devDependencies; \
  process.exit(Object.entries(wanted).every(([name, version]) => { \
    try { return JSON.parse(fs.readFileSync(`node_modules/$${name}/package.json`, 'utf8')).version === version; } \
    catch { return false; } }) ? 0 : 1);

.PHONY: run test build icons tested-cli bench fuzz test-engines-soak deps deps-build deps-browser deps-check lint test-native test-browser test-page test-files screenshots readme-pictures

run: build
	node tests/page/serve.mjs www $(PORT)

## Installation: each step skips what is already there.

deps-build:
	@rustup target list --installed | grep -qx $(TARGET) || rustup target add $(TARGET)
	@if [ "$$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen $(WASM_BINDGEN_VERSION)" ]; then \
	  echo "Installing wasm-bindgen-cli $(WASM_BINDGEN_VERSION) (about two minutes)"; \
	  cargo install wasm-bindgen-cli --version $(WASM_BINDGEN_VERSION); fi
	@command -v node >/dev/null || { $(APT) update && $(APT) install -y nodejs npm; }
	@node -e "$$NPM_INSTALLED" || npm ci --no-audit --no-fund

## The three browser engines from Debian's packages: Chromium and its driver, Firefox ESR,
## WebKitGTK's WebDriver (with its MiniBrowser), and Xvfb, the display Firefox and WebKit run
## headed on (only headed do they get WebGL2, from Mesa's llvmpipe).
deps-browser:
	@missing=""; \
	  command -v chromium >/dev/null || missing="$$missing chromium"; \
	  command -v chromedriver >/dev/null || missing="$$missing chromium-driver"; \
	  command -v firefox-esr >/dev/null || missing="$$missing firefox-esr"; \
	  command -v WebKitWebDriver >/dev/null || missing="$$missing webkit2gtk-driver"; \
	  command -v xvfb-run >/dev/null && command -v xauth >/dev/null || missing="$$missing xvfb xauth"; \
	  if [ -n "$$missing" ]; then $(APT) update && $(APT) install -y $$missing; fi

## Checkers nobody here wrote, for what leaves the product: trimesh for meshes (networkx and
## lxml for 3MF, Pillow for textures), MeshLab's filters (pymeshlab) for faces that cross
## one another, the Khronos glTF validator (npm, in deps-build).
deps-check:
	@python3 -c 'import trimesh, networkx, lxml, PIL, pymeshlab' 2>/dev/null || \
	  python3 -m pip install --quiet --disable-pip-version-check trimesh==5.2.0 networkx lxml pillow pymeshlab==2025.7.post1

deps: deps-build deps-browser deps-check

## Build: release wasm, wasm-bindgen, wasm-opt from npm's binaryen (for speed: -Os gives
## about the same size gzipped and slower code).

build: deps-build
	cargo build --lib --release --target $(TARGET)
	wasm-bindgen --target web --out-dir $(PKG) --out-name seashells $(WASM)
	$(BIN)/wasm-opt -O3 --enable-simd --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
	  --enable-mutable-globals --enable-reference-types --enable-multivalue \
	  $(PKG)/seashells_bg.wasm -o $(PKG)/seashells_bg.wasm
	@raw=$$(stat -c %s $(PKG)/seashells_bg.wasm); gz=$$(gzip -9c $(PKG)/seashells_bg.wasm | wc -c); \
	  printf 'wasm: %s bytes raw, %s bytes gzipped\n' $$raw $$gz
	@id=$$(cat www/*.html www/*.js www/*.css www/*.svg www/*.png www/*.webmanifest $(PKG)/seashells.js \
	  $(PKG)/seashells_bg.wasm | sha256sum | cut -c1-16); \
	  printf '// Written by make build: the id of this build, which names its offline copy (www/service-worker.js).\nself.BUILD = "%s";\n' $$id > $(PKG)/build.js; \
	  echo "build $$id"

## Tests.

lint:
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	cargo clippy --all-targets --target $(TARGET) -- -D warnings

test-native:
	cargo test

## The in-browser tests (tests/browser.rs, the only test target with #[wasm_bindgen_test]):
## built for wasm and run by wasm-bindgen-cli's test runner in headless Chromium.
test-browser: deps-build deps-browser
	CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
	  WASM_BINDGEN_TEST_WEBDRIVER_JSON=tests/webdriver.json CHROMEDRIVER=$$(command -v chromedriver) \
	  cargo test --target $(TARGET) --test browser

## The command line the file and page tests run: the test profile's build, whose
## dependencies `cargo test` has built already (about 20 s, against a minute for a release
## build of its own from a fresh clone; the tests take as long with either).
TESTED_CLI := target/debug/seashells

tested-cli:
	cargo build --profile test --bin seashells

## Page tests: the whole suite on Chromium, and the smoke suite of tests/page/engines.test.mjs
## on Firefox and WebKit (run alone, it takes Chromium too: every check it makes there, the
## other files make on Chromium already); all under Xvfb, which the headed engines need
## (headless Chromium ignores it).
XVFB := xvfb-run -a -s '-screen 0 1600x1200x24'

test-page: build deps-browser tested-cli
	SEASHELLS=$(TESTED_CLI) ENGINES=firefox,webkit $(XVFB) node --test --test-concurrency=1 tests/page/

## The smoke suite of tests/page/engines.test.mjs SOAK_RUNS times in a row on each of
## SOAK_ENGINES, each run in fresh browsers; prints each engine's passes and stops at the first
## failure (docs/browsers.md keeps the figures).
SOAK_RUNS ?= 20
SOAK_ENGINES ?= chromium,firefox,webkit
test-engines-soak: build deps-browser tested-cli
	@for engine in $$(echo $(SOAK_ENGINES) | tr , ' '); do \
	  for run in $$(seq 1 $(SOAK_RUNS)); do \
	    start=$$(date +%s); \
	    SEASHELLS=$(TESTED_CLI) ENGINES=$$engine $(XVFB) node --test tests/page/engines.test.mjs > /tmp/seashells-soak.log 2>&1 \
	      || { tail -40 /tmp/seashells-soak.log; echo "soak: $$engine failed run $$run of $(SOAK_RUNS) (whole log: /tmp/seashells-soak.log)"; exit 1; }; \
	    echo "soak: $$engine passed run $$run of $(SOAK_RUNS) in $$(( $$(date +%s) - start )) s"; \
	  done; \
	done

## Exported files read back by third-party libraries and checkers.
test-files: deps-build deps-check tested-cli
	SEASHELLS=$(TESTED_CLI) python3 -m unittest discover --start-directory tests/files --verbose

## Every phase in turn, each timed; the times are printed at the end (test-page includes the
## release build of the page). Without Cargo's incremental cache, which a run from a fresh
## clone never reads again and which was a third of target/ (CI's disk once ran out).
TEST_PHASES := deps lint test-native test-files test-browser test-page

test:
	@report=''; for phase in $(TEST_PHASES); do \
	  start=$$SECONDS; status=0; CARGO_INCREMENTAL=0 $(MAKE) --no-print-directory $$phase || status=$$?; \
	  report+=$$(printf '\n  %-13s %5d s' $$phase $$((SECONDS - start))); \
	  if [ $$status != 0 ]; then printf '\nmake test: %s FAILED; the phases run:%s\n' $$phase "$$report"; exit $$status; fi; \
	done; printf '\nmake test: every phase passed, in %d s:%s\n' $$SECONDS "$$report"

## Long runs of the property tests: the field table's (tests/any_link.rs), FUZZ_CASES links
## drawn over every field's whole range from a random seed (FUZZ_SEED=N repeats a run); and
## the page's simulator (tests/simulator.rs), SIM_RUNS seeds from SIM_FIRST (make test runs
## seeds 1 to 60; SEASHELLS_SIM_SEED=N replays one).
FUZZ_CASES ?= 1000
SIM_RUNS ?= 5000
SIM_FIRST ?= 1000
fuzz: deps-build
	SEASHELLS_FUZZ_CASES=$(FUZZ_CASES) $(if $(FUZZ_SEED),SEASHELLS_FUZZ_SEED=$(FUZZ_SEED)) \
	  cargo test --test native any_link:: -- --nocapture
	SEASHELLS_SIM_RUNS=$(SIM_RUNS) SEASHELLS_SIM_FIRST=$(SIM_FIRST) \
	  cargo test --test native simulator:: -- --nocapture

## Benchmarks print figures; they assert nothing. Before them, the one check too long for make
## test: every Murex preset at its own resolution against 384³ (make test compares it with 256³).
bench: build deps-browser
	cargo test --test native -- --ignored murex_resolutions::
	cargo build --release --bin seashells
	node tests/page/bench.mjs

## The page's app icons (www/icon-*.png, named by its manifest), drawn from www/favicon.svg.
icons: deps-browser
	node tests/page/icons.mjs

## The README's pictures, taken by the page tests that check what they show.
readme-pictures: build deps-browser
	$(XVFB) node --test --test-name-pattern='morphospace.*WebGL2' tests/page/map.test.mjs
	cp tests/page/screenshots/shape-map-WebGL2.png www/img/shape-map.png
	$(XVFB) node --test --test-name-pattern='breeding: the chosen.*WebGL2' tests/page/breed.test.mjs
	cp tests/page/screenshots/breed-generations-WebGL2.png www/img/breeding.png
	$(XVFB) node --test --test-name-pattern='the keys and a swipe' tests/page/stories.test.mjs
	cp tests/page/screenshots/story-step.png www/img/story-step.png
	ZOOM=1.8 $(XVFB) node tests/page/sheet.mjs www/img/murex-opening.png 4 400 \
	  'B_inside, the inside whorl (fig. 10)|v=1&preset=murex-cabritii&form.opening.shows=inside' \
	  'B_opening, what is carved (fig. 10)|v=1&preset=murex-cabritii&form.opening.shows=opening' \
	  'carved by eq. 14 alone (fig. 11)|v=1&preset=murex-cabritii&form.opening.wall=0' \
	  'with the inside wall, eq. 15 (fig. 11)|v=1&preset=murex-cabritii'
	ZOOM=1.8 $(XVFB) node tests/page/sheet.mjs www/img/murex-textures-fig12.png 4 400 \
	  'the four textures of fig. 12|v=1&preset=murex-cabritii&form.resolution=192' \
	  'where each lies: spines red, canal spines blue|v=1&preset=murex-cabritii&form.resolution=192&form.textures.spines.tip=c01818&form.textures.canal_spines.tip=1830c0' \
	  'Conus on the spines, Volutoconus on the canal, stripes on the bumps|v=1&preset=murex-cabritii&form.resolution=192&form.textures.spines.look=image&form.textures.spines.image=conus-marmoreus&form.textures.canal_spines.look=image&form.textures.canal_spines.image=volutoconus-bednalli&form.textures.bumps.look=image&form.textures.bumps.image=stripes' \
	  'Conus marmoreus on the body|v=1&preset=murex-cabritii&form.resolution=192&form.textures.body.look=image&form.textures.body.image=conus-marmoreus'
	ZOOM=1.6 $(XVFB) node tests/page/sheet.mjs www/img/murex-resolutions.png 3 400 \
	  'Murex cabritii at 128³|v=1&preset=murex-cabritii&form.resolution=128' \
	  'Murex pecten at 128³|v=1&preset=murex-pecten&form.resolution=128' \
	  'spines by reaction-diffusion at 128³|v=1&preset=murex-rd-spines&form.resolution=128' \
	  'Murex cabritii at 384³|v=1&preset=murex-cabritii&form.resolution=384' \
	  'Murex pecten at 384³|v=1&preset=murex-pecten&form.resolution=384' \
	  'spines by reaction-diffusion at 384³|v=1&preset=murex-rd-spines&form.resolution=384'

## Pictures of one shell from four sides (the opening head-on first), to look at: make screenshots LINK='v=1&preset=…' [TURN=20]

screenshots: build deps-browser
	node tests/page/views.mjs '$(or $(LINK),v=1&preset=murex-cabritii)' tests/page/screenshots/views '$(or $(LINK),v=1&preset=murex-cabritii)' '$(or $(TURN),0)'
