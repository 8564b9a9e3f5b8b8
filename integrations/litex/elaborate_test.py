# SPDX-License-Identifier: Apache-2.0
"""Elaborates a LiteX SoC with a DRCC on its main bus, as an integrator would:
a SoC without CPU whose bus master is a UART bridge (UARTBone), the DRCC from
`drcc_litex.add_drcc` with its CAN pins on the platform. Writes the SoC's Verilog
into OUT_DIR and checks that it instantiates the core, that the core's region
is on the bus, and that Icarus compiles the SoC's top with `rtl-out/drcc.v`.

    python elaborate_test.py OUT_DIR     (exit 0 and "PASS" when it holds)
"""

import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))

from litex.build.generic_platform import IOStandard, Pins, Subsignal  # noqa: E402
from litex.build.lattice import LatticeiCE40Platform  # noqa: E402
from litex.soc.integration.builder import Builder  # noqa: E402
from litex.soc.integration.soc_core import SoCCore  # noqa: E402

from drcc_litex import RTL_DIR, add_drcc  # noqa: E402

_io = [
    ("clk12", 0, Pins("35"), IOStandard("LVCMOS33")),
    ("serial", 0, Subsignal("rx", Pins("6")), Subsignal("tx", Pins("9")), IOStandard("LVCMOS33")),
    (
        "can",
        0,
        Subsignal("a_tx", Pins("3")),
        Subsignal("a_rx", Pins("2")),
        Subsignal("b_tx", Pins("47")),
        Subsignal("b_rx", Pins("4")),
        IOStandard("LVCMOS33"),
    ),
]


class Platform(LatticeiCE40Platform):
    default_clk_name = "clk12"
    default_clk_period = 1e9 / 12e6

    def __init__(self):
        LatticeiCE40Platform.__init__(self, "ice40-up5k-sg48", _io, toolchain="icestorm")


def main(out_dir):
    platform = Platform()
    soc = SoCCore(
        platform,
        clk_freq=int(12e6),
        cpu_type=None,
        integrated_sram_size=0,
        with_uart=False,
        with_timer=False,
        with_ctrl=False,
        ident="DRCC LiteX elaboration test",
    )
    soc.add_uartbone(name="serial", baudrate=115200)
    drcc = add_drcc(soc, pads=platform.request("can"), origin=0x9000_0000)
    builder = Builder(soc, output_dir=out_dir, compile_software=False, compile_gateware=False)
    builder.build(build_name="drcc_soc", run=False)

    top = os.path.join(out_dir, "gateware", "drcc_soc.v")
    text = open(top).read()
    assert "drcc drcc(" in text or "drcc drcc (" in text, "the SoC does not instantiate the drcc core"
    regions = soc.bus.regions
    assert "drcc" in regions, f"no drcc region on the bus: {list(regions)}"
    assert regions["drcc"].origin == 0x9000_0000 and regions["drcc"].size == 0x100
    assert drcc.bus.data_width == 32
    vvp = os.path.join(out_dir, "drcc_soc.vvp")
    subprocess.run(
        ["iverilog", "-g2012", "-o", vvp, "-s", "drcc_soc", top, os.path.join(RTL_DIR, "drcc.v")],
        check=True,
    )
    print("PASS: LiteX SoC with the DRCC elaborated and compiled")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "build-litex")
