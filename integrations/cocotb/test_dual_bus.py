# SPDX-License-Identifier: Apache-2.0
"""cocotb bench of two DRCC nodes on a dual bus (dual_bus.v, dual_bus_apb.v,
dual_bus_axi.v), driven through their host bus slaves as an integrator's bench
would. The bus is chosen by the environment variable DRCC_BUS (wishbone, apb,
axi; run.py sets it); every test runs unchanged on each, through the register
access classes of buses.py (read a word, write a word or some of its byte
lanes and get the bus's response):

- bring-up: the identification register, the bit timing, redundancy mode with
  the k-failed policy (k = 2) and every message on both lines with duplicate
  removal (CTRL.dual_tx);
- send and receive: node 0 sends frames, node 1 drains its RX FIFO from the
  interrupt as the README's handler does; every frame arrives once, intact;
- a line fault the redundancy hides: line A is cut in the middle of the
  traffic, and every frame still arrives exactly once;
- refused accesses: each ends with the bus's error response (Wishbone ERR, APB
  PSLVERR, AXI4-Lite SLVERR), sets INT_STATUS.illegal and changes nothing;
- byte lanes: TX_DATA0 takes the lanes a write selects, and a partial write to
  a word written only as a whole (BTR) is refused.

The register offsets and fields come from the generated C header
`rtl-out/drcc_regs.h`, as a driver's would. The clock runs at 8 MHz and the
reset value of BTR is 1 Mbit/s at that clock (8 quanta of one clock).
"""

import os
import re

import cocotb
from buses import ACCESS, ERR, OK
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, First, RisingEdge

HEADER = os.path.join(os.path.dirname(__file__), "..", "..", "rtl-out", "drcc_regs.h")

BUS = os.environ.get("DRCC_BUS", "wishbone")


def _regs():
    with open(HEADER) as f:
        text = f.read()
    pairs = re.findall(r"#define DRCC_(\w+) (0x[0-9A-Fa-f]+|[0-9]+)u", text)
    return {name: int(value, 0) for name, value in pairs}


R = _regs()

# A word no register uses (the map ends well before the last index, 63).
UNMAPPED = 63
assert all(v != UNMAPPED for k, v in R.items() if k.endswith("_INDEX"))

ILLEGAL = R["INT_STATUS_ILLEGAL_MASK"]


def idx(reg):
    return reg if isinstance(reg, int) else R[f"{reg}_INDEX"]


class Node:
    """One DRCC behind its bus slave; registers by name (or index)."""

    def __init__(self, dut, n):
        self.irq = getattr(dut, f"n{n}_irq")
        self.bus = ACCESS[BUS](dut, n)

    async def write(self, reg, value, strb=0xF):
        """Writes the lanes `strb` selects; returns the response, OK or ERR."""
        return await self.bus.write(idx(reg), value, strb)

    async def read_bits(self, reg):
        """The register's value as read, unknown bits and all (MSB first)."""
        return await self.bus.read(idx(reg))

    async def read(self, reg):
        bits = await self.read_bits(reg)
        assert set(bits) <= {"0", "1"}, f"{reg} reads unknown bits: {bits}"
        return int(bits, 2)

    async def illegal(self):
        """INT_STATUS.illegal, cleared after reading it."""
        seen = bool(await self.read("INT_STATUS") & ILLEGAL)
        assert await self.write("INT_STATUS", ILLEGAL) == OK
        return seen

    async def bring_up(self):
        assert await self.read("ID") == R["ID_RESET"], "identification register"
        assert await self.read("CTRL") & R["CTRL_RESET_MODE_MASK"], "reset mode after reset"
        ctrl = (
            R["CTRL_REDUNDANCY_MASK"]
            # k-failed, k = 2: a channel is judged failed after two failed
            # attempts, so a cut line costs two of them instead of the sixteen
            # the error-passive policy waits for (TEC 128); a simulator that
            # runs a few hundred clocks a second spends that time on it.
            | (2 << R["CTRL_POLICY_SHIFT"])
            | R["CTRL_DUAL_TX_MASK"]
            | (2 << R["CTRL_K_SHIFT"])
        )
        assert await self.write("CTRL", ctrl) == OK  # reset_mode = 0 in the same write
        assert not await self.read("CTRL") & R["CTRL_RESET_MODE_MASK"], "running"
        enable = R["INT_ENABLE_RX_MASK"] | R["INT_ENABLE_ILLEGAL_MASK"]
        assert await self.write("INT_ENABLE", enable) == OK

    async def send(self, ident, data):
        padded = bytes(data) + bytes(8 - len(data))
        for reg, value in [
            ("TX_ID", ident),
            ("TX_CTRL", len(data)),
            ("TX_DATA0", int.from_bytes(padded[0:4], "little")),
            ("TX_DATA1", int.from_bytes(padded[4:8], "little")),
            ("TX_CMD", R["TX_CMD_PUSH_MASK"]),
        ]:
            assert await self.write(reg, value) == OK, f"{reg} refused"

    async def drain(self):
        """The README's handler: clear INT_STATUS first, then drain the FIFO."""
        status = await self.read("INT_STATUS")
        assert await self.write("INT_STATUS", status) == OK
        assert not status & ILLEGAL, "no access of the handler is refused"
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
            assert await self.write("RX_CMD", R["RX_CMD_POP_MASK"]) == OK
            dlc = ctrl & R["RX_CTRL_DLC_MASK"]
            data = (d0.to_bytes(4, "little") + d1.to_bytes(4, "little"))[: min(dlc, 8)]
            frames.append((rx_id & R["RX_ID_ID_MASK"], data))


async def start(dut, bring_up=True):
    """Clock, the bus models, reset; then (`bring_up`) both nodes configured
    and joined to the bus. Returns the two nodes."""
    cocotb.start_soon(Clock(dut.clk, 125, unit="ns").start())
    dut.cut_a.value = 0
    dut.rst.value = 1
    await ClockCycles(dut.clk, 8)
    # The bus models start under reset, once the slaves' outputs are known.
    nodes = [Node(dut, 0), Node(dut, 1)]
    await ClockCycles(dut.clk, 1)
    dut.rst.value = 0
    await ClockCycles(dut.clk, 2)
    if bring_up:
        for n in nodes:
            await n.bring_up()
        # 11 recessive bits before a node joins the bus (bus integration).
        await ClockCycles(dut.clk, 8 * 16)
    return nodes


FRAMES = [(0x100 + k, bytes((k * 17 + j) & 0xFF for j in range(2 * k + 1))) for k in range(4)]

# Clocks of one frame on the bus, with margin: 8 clocks a bit, at most 135 bits.
FRAME_CLOCKS = 8 * 135


async def exchange(dut, tx, rx, frames, fault_after=None):
    """Sends `frames` one by one; the receiver drains its FIFO on its
    interrupt after each, and once more at the end, after a copy on the other
    line (CTRL.dual_tx) had time to arrive: every frame that arrived is in the
    list returned, duplicates and all."""
    got = []
    for k, (ident, data) in enumerate(frames):
        if fault_after is not None and k == fault_after:
            dut.cut_a.value = 1
        await tx.send(ident, data)
        # At most 40 frame times: a cut line costs failed attempts until the
        # policy judges the channel failed (two here; sixteen under the
        # error-passive policy).
        if not rx.irq.value:
            await First(RisingEdge(rx.irq), ClockCycles(dut.clk, 40 * FRAME_CLOCKS))
        got += await rx.drain()
        dut._log.info(f"frame {ident:#x} sent, {len(got)} received")
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
async def refused_accesses_answer_the_bus_error(dut):
    """Each refused write ends with the bus's error response, sets
    INT_STATUS.illegal and leaves the word as it was (bus_contract.md 1)."""
    tx, _ = await start(dut)
    assert await tx.write("INT_STATUS", 0xFFFFFFFF) == OK
    btr = await tx.read("BTR")
    for reg, value, why in [
        ("ID", 0x12345678, "read-only"),
        ("BTR", btr ^ 0x3F, "configuration outside reset mode"),
        ("RX_CMD", R["RX_CMD_POP_MASK"], "pop of the empty RX FIFO"),
        (UNMAPPED, 0xFFFFFFFF, "unmapped word"),
    ]:
        before = await tx.read(reg)
        assert await tx.write(reg, value) == ERR, f"{why}: the bus's error response"
        assert await tx.read(reg) == before, f"{why}: {reg} unchanged"
        assert await tx.illegal(), f"{why}: INT_STATUS.illegal"
    assert await tx.read("ID") == R["ID_RESET"]
    assert await tx.read(UNMAPPED) == 0, "an unmapped word reads 0"
    assert await tx.read("BTR") == btr


@cocotb.test()
async def byte_lanes(dut):
    """TX_DATA0 takes the byte lanes a write selects and keeps the others; a
    partial write to BTR, in reset mode where the whole word is taken, is
    refused with the bus's error response and changes nothing."""
    node, _ = await start(dut, bring_up=False)
    assert await node.read("CTRL") & R["CTRL_RESET_MODE_MASK"], "reset mode"
    assert await node.write("TX_DATA0", 0x44332211) == OK
    assert await node.write("TX_DATA0", 0x9999AB99, strb=0b0010) == OK
    assert await node.read("TX_DATA0") == 0x4433AB11, "byte 1 written, bytes 0, 2, 3 kept"
    assert await node.write("TX_DATA0", 0xCDEF9999, strb=0b1100) == OK
    assert await node.read("TX_DATA0") == 0xCDEFAB11, "bytes 2 and 3 written, 0 and 1 kept"
    assert not await node.illegal(), "byte-lane writes to TX_DATA0 are not refused"

    btr = await node.read("BTR")
    assert await node.write("BTR", btr ^ 0x1, strb=0b0001) == ERR, "partial BTR write"
    assert await node.read("BTR") == btr, "BTR unchanged"
    assert await node.illegal(), "INT_STATUS.illegal"
    assert await node.write("BTR", btr ^ 0x1) == OK, "the whole word is taken in reset mode"
    assert await node.read("BTR") == btr ^ 0x1
