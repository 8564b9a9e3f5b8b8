# SPDX-License-Identifier: Apache-2.0
"""The DRCC as a LiteX peripheral: a Wishbone slave on the SoC's main bus, one
interrupt, and the two CAN channels' pins.

    from drcc_litex import add_drcc
    add_drcc(soc, pads=platform.request("can"), origin=0x9000_0000)

`pads` has `a_tx`, `a_rx`, `b_tx`, `b_rx` (TXD / RXD of two CAN
transceivers, 1 = recessive); without pads the pins are left to the caller
(`soc.drcc.chan_a_tx` ...). The Verilog comes from the repository's `rtl-out/`
(`top = "drcc"`, `"drcc_m0"` or `"drcc_small"`, the same ports); the register
map is `docs/registers.md` and the C header `rtl-out/drcc_regs.h`, at `origin`.

The core's `rst` is the SoC's system reset, synchronous to `sys`, as the core
requires (README, "Integrate it"). The core is a 32-bit Wishbone B4 classic
slave with word addresses and 64 registers: the region is 0x100 bytes, and the
core decodes the low six bits of LiteX's word address.
"""

import os

from migen import ClockSignal, Instance, ResetSignal, Signal

from litex.gen import LiteXModule
from litex.soc.integration.soc import SoCRegion
from litex.soc.interconnect import wishbone

# The repository's generated Verilog, next to this file's folder.
RTL_DIR = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "rtl-out"))

# The tops with the DRCC's ports.
TOPS = ("drcc", "drcc_m0", "drcc_small")

# Bytes of the register window: 64 word registers.
REGION_SIZE = 0x100


class _Irq:
    """What LiteX's IRQ interconnect reads from a peripheral: `ev.irq`."""

    def __init__(self, irq):
        self.irq = irq


class DRCC(LiteXModule):
    """One DRCC instance: `bus` (Wishbone, 32-bit, word addresses), `ev.irq`,
    and the CAN pins `chan_a_tx`, `chan_a_rx`, `chan_b_tx`, `chan_b_rx`."""

    def __init__(self, platform, pads=None, top="drcc"):
        if top not in TOPS:
            raise ValueError(f"top {top!r}: choose one of {', '.join(TOPS)}")
        self.bus = wishbone.Interface(data_width=32, address_width=30, addressing="word")
        self.irq = Signal()
        self.ev = _Irq(self.irq)
        self.chan_a_tx = Signal(reset=1)
        self.chan_a_rx = Signal(reset=1)
        self.chan_b_tx = Signal(reset=1)
        self.chan_b_rx = Signal(reset=1)

        self.specials += Instance(
            top,
            i_clk=ClockSignal("sys"),
            i_rst=ResetSignal("sys"),
            i_wb_cyc_i=self.bus.cyc,
            i_wb_stb_i=self.bus.stb,
            i_wb_we_i=self.bus.we,
            i_wb_adr_i=self.bus.adr[:6],
            i_wb_dat_i=self.bus.dat_w,
            i_wb_sel_i=self.bus.sel,
            o_wb_dat_o=self.bus.dat_r,
            o_wb_ack_o=self.bus.ack,
            o_wb_err_o=self.bus.err,
            o_irq=self.irq,
            o_chan_a_tx=self.chan_a_tx,
            i_chan_a_rx=self.chan_a_rx,
            o_chan_b_tx=self.chan_b_tx,
            i_chan_b_rx=self.chan_b_rx,
        )
        # A refused access (INT_STATUS.illegal, a partial write to a whole-word
        # register) ends with err instead of ack (bus_contract.md section 1).

        if pads is not None:
            self.comb += [
                pads.a_tx.eq(self.chan_a_tx),
                self.chan_a_rx.eq(pads.a_rx),
                pads.b_tx.eq(self.chan_b_tx),
                self.chan_b_rx.eq(pads.b_rx),
            ]

        platform.add_source(os.path.join(RTL_DIR, f"{top}.v"))


def add_drcc(soc, name="drcc", pads=None, origin=None, top="drcc", with_irq=True):
    """Adds a DRCC to `soc` as `soc.<name>`: a slave of the main bus at
    `origin` (or wherever LiteX places it), and an interrupt when the SoC has a
    CPU with interrupts."""
    drcc = DRCC(soc.platform, pads=pads, top=top)
    soc.add_module(name=name, module=drcc)
    soc.bus.add_slave(
        name=name,
        slave=drcc.bus,
        region=SoCRegion(origin=origin, size=REGION_SIZE, cached=False),
    )
    if with_irq and hasattr(soc, "irq") and soc.irq.enabled:
        soc.irq.add(name, use_loc_if_exists=True)
    return drcc
