# SPDX-License-Identifier: Apache-2.0
"""cocotb bench of two DRCC nodes on a dual bus (dual_bus.v), driven through
their Wishbone slaves with cocotbext-wishbone, as an integrator's bench would:

- bring-up: the identification register, the bit timing, redundancy mode with
  every message on both lines and duplicate removal (CTRL.dual_tx);
- send and receive: node 0 sends frames, node 1 drains its RX FIFO from the
  interrupt as the README's handler does; every frame arrives once, intact;
- a line fault the redundancy hides: line A is cut in the middle of the
  traffic, and every frame still arrives exactly once;
- refused accesses: a write to a read-only register and a bit-timing write
  outside reset mode are refused (INT_STATUS.illegal), and change nothing.

The register offsets and fields come from the generated C header
`rtl-out/drcc_regs.h`, as a driver's would. The clock runs at 8 MHz and the
reset value of BTR is 1 Mbit/s at that clock (8 quanta of one clock).
"""

import os
import re

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, First, RisingEdge
from cocotbext.wishbone.driver import WBOp, WishboneMaster

HEADER = os.path.join(os.path.dirname(__file__), "..", "..", "rtl-out", "drcc_regs.h")


def _regs():
    with open(HEADER) as f:
        text = f.read()
    pairs = re.findall(r"#define DRCC_(\w+) (0x[0-9A-Fa-f]+|[0-9]+)u", text)
    return {name: int(value, 0) for name, value in pairs}


R = _regs()


ACK, ERR = 1, 2  # cocotbext-wishbone's reply codes


def idx(name):
    return R[f"{name}_INDEX"]


class Node:
    """One DRCC behind its Wishbone master."""

    def __init__(self, dut, n):
        self.irq = getattr(dut, f"n{n}_irq")
        self.wb = WishboneMaster(
            dut,
            f"n{n}",
            dut.clk,
            width=32,
            timeout=16,
            signals_dict={
                "cyc": "cyc",
                "stb": "stb",
                "we": "we",
                "adr": "adr",
                "datwr": "datwr",
                "datrd": "datrd",
                "ack": "ack",
                "err": "err",
            },
        )

    async def write(self, reg, value):
        """Writes a whole word; returns the reply: 1 ACK, 2 ERR (refused)."""
        res = await self.wb.send_cycle([WBOp(adr=idx(reg), dat=value)])
        return res[0].ack

    async def read_bits(self, reg):
        """The register's value as read, unknown bits and all."""
        res = await self.wb.send_cycle([WBOp(adr=idx(reg))])
        return str(res[0].datrd)  # MSB first

    async def read(self, reg):
        bits = await self.read_bits(reg)
        assert set(bits) <= {"0", "1"}, f"{reg} reads unknown bits: {bits}"
        return int(bits, 2)

    async def bring_up(self):
        assert await self.read("ID") == R["ID_RESET"], "identification register"
        assert await self.read("CTRL") & R["CTRL_RESET_MODE_MASK"], "reset mode after reset"
        ctrl = (
            R["CTRL_REDUNDANCY_MASK"]
            | (1 << R["CTRL_POLICY_SHIFT"])  # error passive
            | R["CTRL_DUAL_TX_MASK"]
            | (1 << R["CTRL_K_SHIFT"])
        )
        await self.write("CTRL", ctrl)  # reset_mode = 0 in the same write
        await self.write("INT_ENABLE", R["INT_ENABLE_RX_MASK"] | R["INT_ENABLE_ILLEGAL_MASK"])

    async def send(self, ident, data):
        await self.write("TX_ID", ident)
        await self.write("TX_CTRL", len(data))
        padded = bytes(data) + bytes(8 - len(data))
        await self.write("TX_DATA0", int.from_bytes(padded[0:4], "little"))
        await self.write("TX_DATA1", int.from_bytes(padded[4:8], "little"))
        await self.write("TX_CMD", R["TX_CMD_PUSH_MASK"])

    async def drain(self):
        """The README's handler: clear INT_STATUS first, then drain the FIFO."""
        status = await self.read("INT_STATUS")
        await self.write("INT_STATUS", status)
        frames = []
        while True:
            # RX_ID's other fields read the FIFO memory and are meaningful (and,
            # in simulation, known) only while rx_ready = 1 (docs/registers.md).
            if (await self.read_bits("RX_ID"))[0] != "1":
                return frames
            rx_id = await self.read("RX_ID")
            ctrl = await self.read("RX_CTRL")
            d0 = await self.read("RX_DATA0")
            d1 = await self.read("RX_DATA1")
            await self.write("RX_CMD", R["RX_CMD_POP_MASK"])
            dlc = ctrl & R["RX_CTRL_DLC_MASK"]
            data = (d0.to_bytes(4, "little") + d1.to_bytes(4, "little"))[: min(dlc, 8)]
            frames.append((rx_id & R["RX_ID_ID_MASK"], data))


async def start(dut):
    cocotb.start_soon(Clock(dut.clk, 125, unit="ns").start())
    dut.cut_a.value = 0
    dut.rst.value = 1
    await ClockCycles(dut.clk, 8)
    dut.rst.value = 0
    await ClockCycles(dut.clk, 2)
    nodes = [Node(dut, 0), Node(dut, 1)]
    for n in nodes:
        await n.bring_up()
    # 11 recessive bits before a node joins the bus (bus integration).
    await ClockCycles(dut.clk, 8 * 16)
    return nodes


FRAMES = [(0x100 + k, bytes((k * 17 + j) & 0xFF for j in range(2 * k + 1))) for k in range(4)]

# Clocks of one frame on the bus, with margin: 8 clocks a bit, at most 135 bits.
FRAME_CLOCKS = 8 * 135


async def exchange(dut, tx, rx, frames, fault_after=None):
    """Sends `frames` one by one; the receiver drains its FIFO on its interrupt,
    then once more after the copy on the other line had time to arrive."""
    got = []
    for k, (ident, data) in enumerate(frames):
        if fault_after is not None and k == fault_after:
            dut.cut_a.value = 1
        await tx.send(ident, data)
        # At most 40 frame times: a cut line costs error frames until the
        # channel is error passive (TEC 128) and the policy switches.
        await First(RisingEdge(rx.irq), ClockCycles(dut.clk, 40 * FRAME_CLOCKS))
        got += await rx.drain()
        await ClockCycles(dut.clk, 2 * FRAME_CLOCKS)
        got += await rx.drain()
    return got


@cocotb.test()
async def send_receive_and_hide_a_cut_line(dut):
    """Two frames on the whole bus, then line A is cut: every frame arrives
    exactly once and intact, before and after the fault."""
    tx, rx = await start(dut)
    got = await exchange(dut, tx, rx, FRAMES, fault_after=2)
    assert got == FRAMES, f"every frame exactly once across the fault: {got}"
    assert dut.line_b.value == 1, "the bus is idle at the end"
@cocotb.test()
async def refused_accesses_change_nothing(dut):
    tx, _ = await start(dut)
    btr = await tx.read("BTR")
    assert await tx.write("INT_STATUS", 0xFFFFFFFF) == ACK
    # read-only: refused with the bus's error response (bus_contract.md 1)
    assert await tx.write("ID", 0x12345678) == ERR
    assert await tx.read("ID") == R["ID_RESET"]
    assert await tx.read("INT_STATUS") & R["INT_STATUS_ILLEGAL_MASK"], "illegal set"
    await tx.write("INT_STATUS", R["INT_STATUS_ILLEGAL_MASK"])
    assert await tx.write("BTR", btr ^ 0x3F) == ERR  # outside reset mode
    assert await tx.read("BTR") == btr, "BTR unchanged outside reset mode"
    assert await tx.read("INT_STATUS") & R["INT_STATUS_ILLEGAL_MASK"], "illegal set"
