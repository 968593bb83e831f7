#!/usr/bin/env bash
# Every test of the project: Rust (workspace), the no_std builds of the core, and Python (the
# wheel built with maturin in a virtual environment this script creates).
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== formatting (cargo fmt --check)"
cargo fmt --all --check

echo "== lints (cargo clippy, warnings are errors; quiet: builds every crate, minutes from clean)"
cargo clippy --workspace --all-targets --release --quiet -- -D warnings

# The calculator page's test (crates/cli/tests/calculator.rs) builds the model for WebAssembly and
# drives the page in headless Chromium: both are asked for here; where either cannot be had, that
# test says so and is skipped.
echo "== looking for the wasm32-unknown-unknown target and a headless browser (the calculator page's test)"
timeout 300 rustup target add wasm32-unknown-unknown >/dev/null 2>&1 \
    || echo "   the wasm32-unknown-unknown target is not installable here: the calculator's test will skip"
if [ -z "${BALLSCREW_BROWSER:-}" ] && ! command -v chromium >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        echo "   installing Debian's chromium (quiet: a minute or two, once)"
        (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium) >/dev/null 2>&1 \
            || echo "   chromium is not installable here: the calculator's test will skip"
    else
        echo "   no chromium and no root to install it: the calculator's test will skip"
    fi
fi

echo "== Rust tests (workspace, release build first: minutes; tests/architecture.rs checks the layers and import cycles)"
cargo test --workspace --release

echo "== API docs build without warnings (broken or private links; quiet, a minute or two)"
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --quiet

echo "== the guide as a book (mdBook, docs/book.toml; a chapter missing from docs/ fails it)"
mdbook="$(command -v mdbook || true)"
if [ -z "$mdbook" ]; then
    echo "   installing mdbook 0.5.4 from crates.io into target/tools (quiet: a few minutes, once)"
    cargo install --quiet --locked mdbook --version 0.5.4 --no-default-features --features search --root target/tools
    mdbook=target/tools/bin/mdbook
fi
"$mdbook" build docs

echo "== core without std (host), with and without its one optional feature"
cargo build -p ballscrew-core --no-default-features --release
cargo build -p ballscrew-core --no-default-features --features serde --release
echo "== looking for the thumbv7em-none-eabihf target (rustup may download it: up to 5 min, quiet)"
if timeout 300 rustup target add thumbv7em-none-eabihf >/dev/null 2>&1 \
    || rustup target list --installed 2>/dev/null | grep -q thumbv7em-none-eabihf; then
    echo "== core for thumbv7em-none-eabihf (bare metal, no std)"
    cargo build -p ballscrew-core --no-default-features --target thumbv7em-none-eabihf --release
    cargo build -p ballscrew-core --no-default-features --features serde --target thumbv7em-none-eabihf --release
else
    echo "== thumbv7em-none-eabihf not installable here: the host no_std build above stands in"
fi

echo "== command-line binary for the Python parity tests, and the FMU library beside it (ballscrew fmu)"
cargo build --release -p ballscrew-cli -p ballscrew-fmu
target_dir="${CARGO_TARGET_DIR:-target}"
case "$target_dir" in /*) ;; *) target_dir="$PWD/$target_dir" ;; esac
export BALLSCREW_CLI="$target_dir/release/ballscrew"

echo "== Python: wheel in a fresh virtual environment, then pytest"
venv=target/venv
python3 -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --upgrade pip
# FMPy: the FMU tests (crates/py/tests/test_fmu.py) validate and simulate the FMU with it.
# Dask: the fleet test (crates/py/tests/test_fleet.py) runs the diagnosis on its workers too.
# pandas: the DataFrame paths (sweep's frame, predict and diagnose on a DataFrame) are tested.
echo "   installing maturin, pytest, fmpy, dask, pandas (quiet)"
"$venv/bin/python" -m pip install --quiet "maturin>=1.9.4,<2" pytest fmpy dask pandas
echo "   building and installing the wheel from crates/py (quiet: a release build, minutes)"
"$venv/bin/python" -m pip install --quiet --force-reinstall ./crates/py
echo "   pytest crates/py/tests"
"$venv/bin/python" -m pytest -q crates/py/tests
echo "== all tests passed"
