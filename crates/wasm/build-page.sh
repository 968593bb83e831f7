#!/usr/bin/env bash
# Builds the calculator page's engine: the model for wasm32-unknown-unknown (crates/wasm), and
# docs/calculator/engine.js, which carries the module's bytes (base64: a page opened from a file
# cannot fetch a .wasm) and `ballscrew init`'s template. Run from anywhere; needs the target
# (`rustup target add wasm32-unknown-unknown`, which this script asks for) and python3.
#
# BALLSCREW_CLI: the command line to take init's template from (default: built here).
set -euo pipefail
cd "$(dirname "$0")/../.."

if ! rustup target list --installed 2>/dev/null | grep -q '^wasm32-unknown-unknown$'; then
    echo "build-page: asking rustup for the wasm32-unknown-unknown target" >&2
    timeout 300 rustup target add wasm32-unknown-unknown >/dev/null
fi
# Its own target directory: the host build's lock and flags stay apart. Symbols stripped: the
# page needs none (about 100 KB less).
CARGO_TARGET_DIR=target/wasm RUSTFLAGS="-C strip=symbols" \
    cargo build --quiet --release -p ballscrew-wasm --target wasm32-unknown-unknown
wasm=target/wasm/wasm32-unknown-unknown/release/ballscrew_wasm.wasm

cli="${BALLSCREW_CLI:-}"
if [ -z "$cli" ]; then
    cargo build --quiet --release -p ballscrew-cli
    cli="${CARGO_TARGET_DIR:-target}/release/ballscrew"
fi
# The README's own screw of `ballscrew init` (docs/getting-started.md).
template="$("$cli" init --pitch-diameter-mm 32 --lead-mm 10 --ball-diameter-mm 6.35 --nuts 2 --preload-n 1500)"

python3 - "$wasm" docs/calculator/engine.js "$template" <<'PY'
import base64, json, os, sys
wasm, out, template = sys.argv[1], sys.argv[2], sys.argv[3]
data = open(wasm, "rb").read()
text = (
    "// Written by crates/wasm/build-page.sh: the model's WebAssembly module and init's template.\n"
    f"const BALLSCREW_WASM_BYTES = {len(data)};\n"
    f"const BALLSCREW_WASM_BASE64 = \"{base64.b64encode(data).decode()}\";\n"
    f"const BALLSCREW_INIT_TEMPLATE = {json.dumps(template + chr(10))};\n"
)
tmp = out + ".tmp"
open(tmp, "w").write(text)
os.replace(tmp, out)
print(f"build-page: {out} ({len(data)} bytes of WebAssembly)")
PY
