# SPDX-License-Identifier: Apache-2.0
"""Runs the dual-bus bench (test_dual_bus.py on dual_bus.v and rtl-out/drcc.v)
on one simulator with cocotb's runner:

    python run.py icarus BUILD_DIR
    python run.py verilator BUILD_DIR     (cocotb 2 needs Verilator 5.036 or newer)

Exit 0 when every test passes; the results are in BUILD_DIR/results.xml.
"""

import os
import sys

from cocotb_tools.runner import get_runner

HERE = os.path.dirname(os.path.abspath(__file__))
RTL = os.path.normpath(os.path.join(HERE, "..", "..", "rtl-out", "drcc.v"))


def main(sim, build_dir):
    runner = get_runner(sim)
    build_args = ["-Wno-fatal", "-Wno-lint", "-Wno-style"] if sim == "verilator" else []
    runner.build(
        sources=[RTL, os.path.join(HERE, "dual_bus.v")],
        hdl_toplevel="dual_bus",
        build_dir=build_dir,
        build_args=build_args,
        always=True,
    )
    results = runner.test(
        hdl_toplevel="dual_bus",
        test_module="test_dual_bus",
        test_dir=HERE,
        build_dir=build_dir,
        results_xml=os.path.join(build_dir, "results.xml"),
    )
    from cocotb_tools.runner import get_results

    tests, failed = get_results(results)
    print(f"cocotb {sim}: {tests - failed} passed, {failed} failed")
    return 0 if failed == 0 and tests > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "build-" + sys.argv[1])))
