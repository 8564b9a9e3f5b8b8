#!/usr/bin/env bash
# Lint gate for the emitted Verilog: verilator -Wall with the commented waiver
# file, an Icarus compile, and a yosys elaboration followed by `check -assert`
# (no latches, no combinational loops, nothing undriven).
#
# Usage: bash hdl/lint/lint.sh [TOP | FILE.v ...]
#   TOP      rtl-out/TOP.v (default: every rtl-out/*.v)
#   FILE.v   any Verilog file whose top module is named after the file
#            (`drcc generate --config` output)
#
# yosys stops after `proc; flatten`: latches are inferred (and reported) by
# `proc`, and `check` finds loops and undriven nets on the word-level netlist as
# well as after technology mapping, at a tenth of the time of a full `synth`.
# Synthesis itself is `drcc synth` and tests/synth.rs. The files are linted in
# parallel; a failing file's messages are printed whole.
set -euo pipefail
cd "$(dirname "$0")/../.."
need() {
    command -v "$1" >/dev/null 2>&1 || { echo "lint: $1 not found: install it with \`apt-get install $2\`" >&2; exit 2; }
}
need verilator verilator
need iverilog iverilog
need yosys yosys

files=()
if [ $# -eq 0 ]; then
    files=(rtl-out/*.v)
else
    for arg in "$@"; do
        case "$arg" in
        *.v) files+=("$arg") ;;
        *) files+=("rtl-out/$arg.v") ;;
        esac
    done
fi
for file in "${files[@]}"; do
    [ -f "$file" ] || { echo "lint: $file: no such file (give a top of rtl-out/ or a .v file)" >&2; exit 2; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
waivers=hdl/lint/verilator_waivers.vlt

# lint_one FILE: the three checks of one file; its messages are printed whole
# when one fails.
lint_one() {
    local file=$1 top
    top=$(basename "$file" .v)
    if (
        set -e
        verilator --lint-only -Wall "$waivers" "$file" --top-module "$top" \
            || { echo "lint: $top: verilator --lint-only -Wall failed"; exit 1; }
        iverilog -g2005 -o "$work/$top.vvp" -s "$top" "$file" \
            || { echo "lint: $top: iverilog failed"; exit 1; }
        yosys -q -l "$work/$top.yosys.log" -p "read_verilog $file; hierarchy -check -top $top; \
proc; flatten; opt_clean; check -assert; \
select -assert-none t:\$*latch* t:\$_DLATCH*_ t:\$_SR_*" >/dev/null \
            && ! grep -q "Latch inferred" "$work/$top.yosys.log" \
            || { echo "lint: $top: yosys check -assert failed:"; tail -20 "$work/$top.yosys.log"; exit 1; }
    ) >"$work/$top.out" 2>&1; then
        echo "lint: $top: clean (verilator -Wall, iverilog, yosys check -assert)"
    else
        cat "$work/$top.out" >&2
        return 1
    fi
}

# Every file at once: the machine's scheduler shares the CPUs.
pids=()
for file in "${files[@]}"; do
    lint_one "$file" &
    pids+=($!)
done
failed=0
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
if [ "$failed" -ne 0 ]; then
    echo "lint: failed (messages above)" >&2
    exit 1
fi
echo "lint: ${#files[@]} file(s) clean"
