# `make test` runs every test of the project: formatting, clippy (warnings denied), Rust unit,
# property, integration and doc tests (among them: every README figure is what its *Made by*
# command draws), the Python cross-checks (installed into .venv), the Python bindings, lac in
# FreeCAD and Inkscape (Debian's, installed when missing) and the editor in a browser.
#
# The dependency tree is compiled once with code generation: `cargo test` builds the `lac`
# binary for the integration tests in the test profile (opt-level 2) as target/debug/lac, and
# the Python cross-checks run that binary. Clippy checks the tree once more without code
# generation (build scripts and proc macros are shared). The Python bindings are compiled
# once more by `pip install ./crates/lac-py` (maturin), optimised, in target/python: lac and
# the few crates it needs (kurbo, serde, PyO3, rust-numpy, rayon), about 70 s of CPU cold.
VENV := .venv
PY := $(VENV)/bin/python
CARGO_TEST := cargo test --locked --workspace
# Property tests draw the same cases on every run, so that a red CI is reproducible; run
# `make rust PROPTEST_RNG_SEED=$$RANDOM` (any other number) to draw new ones.
PROPTEST_RNG_SEED ?= 20261123
export PROPTEST_RNG_SEED
LAC_BIN := $(or $(CARGO_TARGET_DIR),$(CURDIR)/target)/debug/lac

.PHONY: test check rust python py py-bench spiro integrations test-integrations \
	integrations-screenshots e2e docs fixtures bench example fuzz afl

test: rust python py test-integrations e2e

# The fast tier (a few minutes warm): formatting, clippy, every Rust test with the seeded
# fuzz driver cut to 2,000 inputs per entry point, two files of the Python cross-checks and
# one browser test. `make test` runs everything.
check: $(VENV)/.installed
	cargo fmt --all -- --check
	cargo clippy --locked --workspace --all-targets -- -D warnings
	LAC_FUZZ_COUNT=2000 $(CARGO_TEST) --quiet
	LAC_BIN=$(LAC_BIN) $(PY) -m pytest -q -x tools/reference/test_reference.py tools/reference/test_path.py
	test -x /usr/bin/chromium || (apt-get update && apt-get install -y chromium)
	cd crates/lac-serve/e2e && npm ci --no-audit --no-fund --silent
	cd crates/lac-serve/e2e && LAC_BIN=$(LAC_BIN) node --test --test-concurrency=1 \
		--test-name-pattern="^segment"

rust:
	cargo fmt --all -- --check
	cargo clippy --locked --workspace --all-targets -- -D warnings
	$(CARGO_TEST)

# `--no-run` is a no-op after `rust`; alone, it (re)builds the test-profile binary. The
# cross-checks run on all cores (pytest-xdist): about 80 s instead of 160 s here.
python: $(VENV)/.installed
	$(CARGO_TEST) --no-run --quiet
	LAC_BIN=$(LAC_BIN) $(PY) -m pytest -q -n auto tools/reference

# The editor in a real browser: Debian's chromium (installed when missing; CI runs as root),
# playwright-core from npm, the same `lac` binary serving on a free port of 127.0.0.1.
e2e:
	test -x /usr/bin/chromium || (apt-get update && apt-get install -y chromium)
	cd crates/lac-serve/e2e && npm ci --no-audit --no-fund
	$(CARGO_TEST) --no-run
	cd crates/lac-serve/e2e && LAC_BIN=$(LAC_BIN) node --test --test-concurrency=1

# The Python bindings (crates/lac-py): `pip install` as a user would (maturin, the
# workspace's `python` profile in target/python), then their tests against the same `lac`
# binary, and mypy --strict on the examples (which the tests run, writing PNGs).
py: $(VENV)/.installed
	PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(PY) -m pip install --quiet --disable-pip-version-check \
		--no-build-isolation --no-deps --force-reinstall ./crates/lac-py
	$(CARGO_TEST) --no-run --quiet
	LAC_BIN=$(LAC_BIN) $(PY) -m pytest -q crates/lac-py/tests
	$(VENV)/bin/mypy --strict crates/lac-py/examples

# lac inside FreeCAD and Inkscape (integrations/, docs/integrations.md). `make integrations`
# installs Debian's programs when missing (without recommends; root, as CI runs), the lac
# wheel where /usr/bin/python3 (and so FreeCAD and Inkscape) imports it, the workbench into
# FreeCAD's Mod folder and the extensions into Inkscape's. The wheel is the one `make py`
# builds (the same cargo build, so a few seconds after it).
INTEGRATION_PACKAGES := freecad-python3 inkscape python3-lxml python3-cssselect python3-numpy \
	xvfb xauth
WHEELS := $(or $(CARGO_TARGET_DIR),$(CURDIR)/target)/wheels
XVFB := QTWEBENGINE_DISABLE_SANDBOX=1 timeout 300 xvfb-run -a -s "-screen 0 1280x1024x24"
integrations: $(VENV)/.installed
	dpkg -s $(INTEGRATION_PACKAGES) >/dev/null 2>&1 || (apt-get update && \
		DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $(INTEGRATION_PACKAGES))
	rm -f $(WHEELS)/lac-*.whl
	PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(PY) -m pip wheel --quiet --disable-pip-version-check \
		--no-build-isolation --no-deps ./crates/lac-py -w $(WHEELS)
	/usr/bin/python3 integrations/install.py --wheel $(WHEELS)/lac-*.whl \
		--pip $(CURDIR)/$(VENV)/bin/pip

# Their tests, headless: FreeCAD's (freecadcmd, and its GUI under Xvfb) and the Inkscape
# extensions' against the test-profile `lac` (about 45 s after `integrations`).
test-integrations: integrations
	$(CARGO_TEST) --no-run --quiet
	freecadcmd integrations/freecad/tests/test_freecad.py
	$(XVFB) freecad integrations/freecad/tests/test_gui.py
	LAC_BIN=$(LAC_BIN) PYTHONPATH=/usr/share/inkscape/extensions /usr/bin/python3 \
		integrations/inkscape/tests/test_inkscape.py

# Redraw docs/integrations-freecad.png (FreeCAD's window) and docs/integrations-inkscape.png
# (integrations/inkscape/examples/sketch.svg before and after lac_spline and lac_comb, drawn
# by Inkscape).
INKEX := PYTHONPATH=/usr/share/inkscape/extensions /usr/bin/python3 integrations/inkscape
SKETCH := integrations/inkscape/examples/sketch.svg
integrations-screenshots: integrations
	LAC_SCREENSHOT=$(CURDIR)/docs/integrations-freecad.png $(XVFB) freecad \
		integrations/freecad/tests/test_gui.py
	$(INKEX)/lac_spline.py --alpha=-0.5 --id=after $(SKETCH) > $(WHEELS)/spline.svg
	$(INKEX)/lac_comb.py --id=after $(WHEELS)/spline.svg > $(WHEELS)/comb.svg
	inkscape $(WHEELS)/comb.svg --export-type=png --export-width=960 \
		--export-png-color-mode=RGB_8 --export-filename=docs/integrations-inkscape.png

# lac's splines with point types beside libspiro on 1,000 glyph-like outlines (one JSON line):
# needs Debian's libspiro-dev and a C compiler (installed when missing; root), not in `make test`.
spiro: py
	test -f /usr/include/spiroentrypoints.h || (apt-get update && apt-get install -y libspiro-dev)
	$(PY) tools/spiro/compare.py --count 1000

# lac from Python against Clothoids' build_G1 on the same alpha = -1 inputs (one JSON line).
py-bench: py
	$(PY) crates/lac-py/bench/bench_clothoids.py

$(VENV)/.installed: tools/reference/requirements.txt tools/reference/requirements-export.txt \
		crates/lac-py/requirements.txt
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install --quiet --disable-pip-version-check -r tools/reference/requirements.txt \
		-r tools/reference/requirements-export.txt -r crates/lac-py/requirements.txt
	touch $@

# Redraw the documentation's figures (docs/*.svg) from the *Made by* lines of README.md and
# docs/*.md with the freshly built `lac`; `make test` fails while a committed figure differs
# from what its command draws.
docs:
	LAC_WRITE_FIGURES=1 $(CARGO_TEST) --test it readme_figures -- --nocapture

# The seeded random and adversarial driver, a million inputs per entry point (make test runs
# a hundred thousand); FUZZ_SEED picks another stream. Exit code 1 on any panic, invariant
# violation or call over a second; `lac-fuzz --replay FILE` reruns printed inputs.
FUZZ_COUNT ?= 1000000
FUZZ_SEED ?= 1
fuzz:
	cargo run --locked --release -p lac-fuzz -- --count $(FUZZ_COUNT) --seed $(FUZZ_SEED)

# Coverage-guided fuzzing with AFL++ (afl.rs, stable Rust) for AFL_MINUTES (default 10): the
# same entry points and invariants as `make fuzz`, steered by coverage. Crashes land in
# target/afl/out/default/crashes; `lac-fuzz --decode FILE` prints each as a JSON input for
# crates/lac-fuzz/regressions/inputs.jsonl. Installs cargo-afl (and builds AFL++) when missing.
AFL_MINUTES ?= 10
AFL_TARGET := $(CURDIR)/target/afl
afl:
	command -v cargo-afl >/dev/null || cargo install --locked cargo-afl
	cargo afl config --build 2>/dev/null || true # (refuses when the AFL++ runtime is built already)
	cd crates/lac-fuzz/afl && CARGO_TARGET_DIR=$(AFL_TARGET) cargo afl build --release
	mkdir -p $(AFL_TARGET)/in && for i in 0 1 2 3 4 5 6; do printf "\\00$$i\\01\\02\\03" > $(AFL_TARGET)/in/entry$$i; done
	AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_NO_UI=1 \
		cargo afl fuzz -V $$(( $(AFL_MINUTES) * 60 )) -i $(AFL_TARGET)/in -o $(AFL_TARGET)/out \
		$(AFL_TARGET)/release/lac-afl

# Regenerate the 40-digit reference fixtures (about 15 minutes; the output is committed).
fixtures: $(VENV)/.installed
	$(PY) tools/reference/generate_fixtures.py
	$(PY) tools/reference/compound_fixtures.py
	$(PY) tools/reference/quasi_fixtures.py -j 2
	$(PY) tools/reference/space_fixtures.py -j 2

# Criterion benchmarks (medians quoted in issue notes); the Clothoids timing for comparison, and
# lac's solver and batch side by side with Clothoids on the same 20,000 clothoids, and lac's G2
# spline against a clothoid G2 spline on Clothoids' build_G1 (needs `make py` first).
bench: $(VENV)/.installed
	cargo bench -p lac --bench segment
	cargo bench -p lac --bench compound
	cargo bench -p lac --bench quasi
	cargo bench -p lac --bench space
	cargo bench -p lac --bench path
	cargo bench -p lac --bench spline
	cargo bench -p lac-export --bench export -- --warm-up-time 1 --measurement-time 3
	$(PY) tools/reference/bench_clothoids.py
	$(PY) tools/bench_vs_clothoids.py --repeats 3
	$(PY) tools/bench_spline_vs_clothoids.py --sets 200

# The main job: a clothoid-to-spiral segment drawn as SVG with its curvature comb.
example:
	cargo run --release -p lac-cli -- segment --points "-1,0 -0.2,0.8 1,0" --alpha 0.5 \
		--format svg --comb --evolute -o segment.svg
