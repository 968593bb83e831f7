# Named tasks of the development loop (CONTRIBUTING.md). The whole suite is `make test`, which
# is the README's test command and what CI runs.

CARGO ?= cargo

.PHONY: help fmt lint quick test doc book calculator bench bless

help:
	@echo "make fmt    format every crate (cargo fmt)"
	@echo "make lint   clippy on every crate and target, warnings are errors"
	@echo "make quick  the unit tests of every crate and the checks of the docs (a few minutes after a build)"
	@echo "make test   every test, Rust and Python: bash tests/all.sh (about 30 min on 2 cores from clean)"
	@echo "make doc    the API docs, warnings are errors"
	@echo "make book   the guide as an mdBook under target/book, its calculator page built (installs mdbook with cargo if missing)"
	@echo "make calculator  the calculator page's engine: the model as WebAssembly in docs/calculator/engine.js"
	@echo "make bench  the criterion benchmarks behind docs/performance.md, as one table (bash benches/figures.sh)"
	@echo "make bless  regenerate the generated outputs the tests compare against (then read the diff)"

fmt:
	$(CARGO) fmt --all

lint:
	$(CARGO) clippy --workspace --all-targets --release -- -D warnings

quick:
	$(CARGO) test --release --workspace --lib
	$(CARGO) test --release -p ballscrew-suite --test doc_paths --test architecture --test readme_numbers
	$(CARGO) test --release -p ballscrew-suite --doc
	$(CARGO) test --release -p ballscrew-cli --test readme --test vocabulary

test:
	bash tests/all.sh

doc:
	RUSTDOCFLAGS="-D warnings" $(CARGO) doc --workspace --no-deps

calculator:
	bash crates/wasm/build-page.sh

book: calculator
	@command -v mdbook >/dev/null || $(CARGO) install mdbook --locked --no-default-features --features search
	mdbook build docs

bench:
	bash benches/figures.sh

bless:
	INSTA_UPDATE=always $(CARGO) test --release -p ballscrew-cli --test snapshots
	BALLSCREW_BLESS=1 $(CARGO) test --release -p ballscrew-cli --test diagnose_cli the_guides_xjtu
	BALLSCREW_BLESS=1 $(CARGO) test --release -p ballscrew-config --test spec_reference the_page_is_the_rendered_table_of_keys
	git status --short
