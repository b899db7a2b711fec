# `make test` runs every test of the project: formatting, clippy (warnings denied), Rust unit,
# property, integration and doc tests, and the Python cross-checks (installed into .venv).
VENV := .venv
PY := $(VENV)/bin/python

.PHONY: test rust python e2e fixtures bench example

test: rust python e2e

rust:
	cargo fmt --all -- --check
	cargo clippy --workspace --all-targets -- -D warnings
	cargo test --workspace

python: $(VENV)/.installed
	cargo build --release -p lac-cli
	LAC_BIN=$(CURDIR)/target/release/lac $(PY) -m pytest -q tools/reference

# The editor in a real browser: Debian's chromium (installed when missing; CI runs as root),
# playwright-core from npm, the release `lac serve` on a free port of 127.0.0.1.
e2e:
	test -x /usr/bin/chromium || (apt-get update && apt-get install -y chromium)
	cd crates/lac-serve/e2e && npm ci --no-audit --no-fund
	cargo build --release -p lac-cli
	cd crates/lac-serve/e2e && LAC_BIN=$(CURDIR)/target/release/lac node --test --test-concurrency=1

$(VENV)/.installed: tools/reference/requirements.txt
	python3 -m venv $(VENV)
	$(VENV)/bin/pip install --quiet --disable-pip-version-check -r tools/reference/requirements.txt
	touch $@

# Regenerate the 40-digit reference fixtures (about 15 minutes; the output is committed).
fixtures: $(VENV)/.installed
	$(PY) tools/reference/generate_fixtures.py
	$(PY) tools/reference/compound_fixtures.py
	$(PY) tools/reference/quasi_fixtures.py -j 2
	$(PY) tools/reference/space_fixtures.py -j 2

# Criterion benchmarks (medians quoted in issue notes); the Clothoids timing for comparison.
bench: $(VENV)/.installed
	cargo bench -p lac --bench segment
	cargo bench -p lac --bench compound
	cargo bench -p lac --bench quasi
	cargo bench -p lac --bench space
	$(PY) tools/reference/bench_clothoids.py

# The main job: a clothoid-to-spiral segment drawn as SVG with its curvature comb.
example:
	cargo run --release -p lac-cli -- segment --points "-1,0 -0.2,0.8 1,0" --alpha 0.5 \
		--format svg --comb --evolute -o segment.svg
