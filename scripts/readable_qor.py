#!/usr/bin/env python3
"""What the readable Verilog costs on an FPGA: area and Fmax of a top's
`rtl-out/<top>.v` (the readable text `drcc generate` writes) against the same
logic before the readable step (`cargo run -p drcc-hdl --example emit -- TOP
--unreadable`: a module per flip-flop, channels A and B apart), side by side in
one run, with the ratio.

yosys's result depends on the order it meets the logic in, not only on the
logic, so one netlist per text says little: each text is also synthesised with
its modules in reverse order (the same Verilog, another order), and each netlist
is placed and routed with several nextpnr seeds. The ratio is of the pooled means.

Usage: python3 scripts/readable_qor.py TOP TARGET [SEEDS]
  TARGET: ice40 (iCE40UP5K, iCEBreaker) or ice40hx (iCE40HX8K breakout)
  SEEDS:  nextpnr seeds per netlist (default 5)
Needs yosys, nextpnr-ice40 and a built `drcc` (target/release/drcc). Run from the
repository root; it works in target/readable-qor/.
"""
import re
import statistics
import subprocess
import sys
from pathlib import Path

DEVICES = {
    "ice40": (["--up5k", "--package", "sg48"], "constraints/ice40/icebreaker.pcf"),
    "ice40hx": (["--hx8k", "--package", "ct256"], "constraints/ice40/hx8k_breakout.pcf"),
}


def fail(msg):
    print(f"readable_qor: {msg}", file=sys.stderr)
    sys.exit(2)


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        fail(f"{' '.join(map(str, cmd))} failed:\n{r.stderr[-2000:]}")
    return r.stdout


def reversed_modules(text):
    parts = re.split(r"(?m)^(?=module )", text)
    return parts[0] + "".join(reversed(parts[1:]))


def synth(work, name, text, top, wrapper):
    d = work / name
    d.mkdir(parents=True, exist_ok=True)
    (d / f"{top}.v").write_text(text)
    script = (
        f"read_verilog {top}.v; read_verilog {wrapper}; "
        f"synth_ice40 -flatten -top {top}_scan -json scan.json; tee -q -o stat.txt stat"
    )
    run(["yosys", "-q", "-p", script], cwd=d)
    luts = re.search(r"SB_LUT4\s+(\d+)", (d / "stat.txt").read_text())
    return d, int(luts.group(1)) if luts else 0


def place(d, device, pcf, seed):
    log = d / f"pnr_s{seed}.log"
    run(
        ["nextpnr-ice40", *device, "--json", "scan.json", "--pcf", pcf,
         "--pcf-allow-unconstrained", "--asc", f"s{seed}.asc", "--seed", str(seed),
         "--timing-allow-fail", "-q", "--log", str(log)],
        cwd=d,
    )
    text = log.read_text()
    fmax = re.findall(r"Max frequency for clock '[^']*': ([\d.]+) MHz", text)
    cells = re.search(r"ICESTORM_LC:\s+(\d+)/", text)
    return float(fmax[-1]), int(cells.group(1))


def main():
    if len(sys.argv) not in (3, 4) or sys.argv[2] not in DEVICES:
        fail("usage: readable_qor.py TOP ice40|ice40hx [SEEDS]")
    top, target = sys.argv[1], sys.argv[2]
    seeds = int(sys.argv[3]) if len(sys.argv) == 4 else 5
    device, pcf = DEVICES[target]
    repo = Path.cwd()
    drcc = repo / "target/release/drcc"
    if not drcc.exists() or not (repo / "rtl-out" / f"{top}.v").exists():
        fail("run from the repository root after `cargo build --release`")
    work = repo / "target/readable-qor" / f"{top}-{target}"
    # `drcc synth` checks rtl-out/ and writes the scan wrapper the tops are placed in.
    run([str(drcc), "synth", "--target", target, "--top", top, "--build-dir", str(work / "synth")])
    wrapper = work / "synth" / f"{top}-{target}" / f"{top}_scan.v"
    readable = (repo / "rtl-out" / f"{top}.v").read_text()
    unreadable = run(
        ["cargo", "run", "-q", "--release", "-p", "drcc-hdl", "--example", "emit", "--",
         top, "--unreadable"]
    )
    texts = {
        "unreadable": unreadable,
        "unreadable, modules reversed": reversed_modules(unreadable),
        "readable": readable,
        "readable, modules reversed": reversed_modules(readable),
    }
    rows, pooled = [], {"unreadable": [], "readable": []}
    for name, text in texts.items():
        d, luts = synth(work, name.replace(", ", "-").replace(" ", "_"), text, top, wrapper)
        results = [place(d, device, str(repo / pcf), s) for s in range(1, seeds + 1)]
        fmax = [f for f, _ in results]
        pooled[name.split(",")[0]].extend(fmax)
        rows.append((name, text.count("\nmodule ") + text.startswith("module "),
                     len(text.splitlines()), luts, results[0][1], fmax))
    print(f"### {top} on {target}: readable against unreadable Verilog ({seeds} nextpnr seeds per netlist)\n")
    print("| text | modules | lines | LUT4 (in the scan wrapper) | logic cells | Fmax by seed (MHz) | median | mean |")
    print("|---|---:|---:|---:|---:|---|---:|---:|")
    for name, mods, lines, luts, cells, fmax in rows:
        print(f"| {name} | {mods} | {lines} | {luts} | {cells} | {' '.join(f'{f:.2f}' for f in fmax)} "
              f"| {statistics.median(fmax):.2f} | {statistics.mean(fmax):.2f} |")
    u, r = pooled["unreadable"], pooled["readable"]
    lut_u = statistics.mean(x[3] for x in rows[:2])
    lut_r = statistics.mean(x[3] for x in rows[2:])
    print(f"\nreadable / unreadable: LUT4 {lut_r / lut_u:.3f}x (mean of both orders); "
          f"Fmax {statistics.mean(r) / statistics.mean(u):.3f}x (pooled means), "
          f"{statistics.median(r) / statistics.median(u):.3f}x (pooled medians)")


if __name__ == "__main__":
    main()
