#!/usr/bin/env bash
# Regenerates the figures of docs/performance.md: runs the criterion benchmarks of the evaluator
# (benches/evaluation.rs), the map lookup and the batches (crates/batch/benches/batch.rs), and
# prints their medians as one Markdown table with the machine's load before and after, ready to
# compare with the page. Usage: bash benches/figures.sh [criterion filter, default "realtime|map|batch"]
#
# Compare figures of one run only: on a shared or virtual machine the same build scatters by
# 10-40 % between runs (docs/performance.md); ratios taken in one run are what carry over.
set -euo pipefail
cd "$(dirname "$0")/.."
filter="${1:-realtime|map_lookup}"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)   cores: $(nproc)   $(date -u +%Y-%m-%d)" >&2
cargo bench --quiet --bench evaluation -- --warm-up-time 1 --measurement-time 3 "$filter" >&2
cargo bench --quiet -p ballscrew-batch --bench batch -- --warm-up-time 1 --measurement-time 5 >&2
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
python3 - <<'PY'
import json, pathlib
root = pathlib.Path("target/criterion")
rows = []
for est in sorted(root.glob("**/new/estimates.json")):
    name = "/".join(est.relative_to(root).parts[:-2])
    m = json.loads(est.read_text())["median"]
    ns = m["point_estimate"]
    lo, hi = m["confidence_interval"]["lower_bound"], m["confidence_interval"]["upper_bound"]
    fmt = lambda v: f"{v:.1f} ns" if v < 1e3 else f"{v / 1e3:.2f} us" if v < 1e6 else f"{v / 1e6:.2f} ms"
    rows.append(f"| `{name}` | {fmt(ns)} | {fmt(lo)} - {fmt(hi)} |")
print("| criterion benchmark | median | 95 % interval |\n|---|---|---|")
print("\n".join(rows))
PY
