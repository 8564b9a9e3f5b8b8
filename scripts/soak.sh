#!/usr/bin/env bash
# The soak: the long runs that `.ci/run` samples instead of running whole, for a
# scheduled job (nightly cron, or a GitHub Actions `schedule:` trigger) on a
# machine with the CI tools (`.ci/run` installs them; run it once first).
#
# - every test named `soak_*` (ignored by `cargo test`; each one's doc comment
#   says what `.ci/run` runs of it instead);
# - the dual-bus, DMR (first copy) and star fault campaigns at full size, sharded over the
#   machine's cores (`drcc campaign`; for a cluster see scripts/campaign/).
#
# Usage: bash scripts/soak.sh [CAMPAIGN_COUNT]   (default 100000 per topology)
# Exit status: 0 when every soak test passes and no campaign scenario fails.
set -euo pipefail
cd "$(dirname "$0")/.."
count="${1:-100000}"
case "$count" in
'' | *[!0-9]*) echo "soak: CAMPAIGN_COUNT must be a number of scenarios, got '$count'" >&2; exit 2 ;;
esac

export CI="${CI:-1}"
export DRCC_REQUIRE_VERILATOR=1
if [[ -x target/py-venv/bin/python ]]; then
  export DRCC_PYTHON="$PWD/target/py-venv/bin/python"
fi

echo "== soak tests"
cargo test --release --workspace -- --ignored soak_

echo "== campaigns ($count single faults per topology)"
cargo build --release
out="soak-results/$(date -u +%Y%m%dT%H%M%SZ)"
mkdir -p "$out"
# each run fails (exit 1) when a single-fault scenario loses, duplicates or locks up
for topology in dual dmr star; do
  ./target/release/drcc campaign --topology "$topology" --faults single \
    --count "$count" --seed 1 --out "$out/$topology.jsonl"
done
./target/release/drcc campaign merge "$out/dual.jsonl" "$out/dmr.jsonl" "$out/star.jsonl"
