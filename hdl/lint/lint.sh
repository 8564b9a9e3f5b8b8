#!/usr/bin/env bash
# Lint gate for the emitted Verilog in rtl-out/: verilator -Wall with the
# commented waiver file, an Icarus compile, and yosys synthesis followed by
# `check -assert` (no latches, no combinational loops, nothing undriven).
# Usage: bash hdl/lint/lint.sh [TOP ...]   (default: every rtl-out/*.v)
set -euo pipefail
cd "$(dirname "$0")/../.."
need() {
    command -v "$1" >/dev/null 2>&1 || { echo "lint: $1 not found: install it with \`apt-get install $2\`" >&2; exit 2; }
}
need verilator verilator
need iverilog iverilog
need yosys yosys
tops=("$@")
if [ ${#tops[@]} -eq 0 ]; then
    for f in rtl-out/*.v; do tops+=("$(basename "$f" .v)"); done
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for top in "${tops[@]}"; do
    file="rtl-out/$top.v"
    echo "lint: $top: verilator --lint-only -Wall"
    verilator --lint-only -Wall hdl/lint/verilator_waivers.vlt "$file" --top-module "$top"
    echo "lint: $top: iverilog"
    iverilog -g2005 -o "$work/$top.vvp" -s "$top" "$file"
    echo "lint: $top: yosys synth + check -assert"
    yosys -q -l "$work/$top.yosys.log" -p "read_verilog $file; synth -flatten -top $top; check -assert; select -assert-none t:\$*latch* t:\$_DLATCH*_ t:\$_SR_*" >/dev/null \
        && ! grep -q "Latch inferred" "$work/$top.yosys.log" \
        || { echo "lint: $top: yosys found a problem, see its log:" >&2; tail -20 "$work/$top.yosys.log" >&2; exit 1; }
done
echo "lint: ${#tops[@]} top(s) clean"
