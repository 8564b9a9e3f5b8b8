# SPDX-License-Identifier: Apache-2.0
"""Register access to one DRCC node of the bench, one class per host bus.

Each class drives node N's slave in the wrapper (dual_bus.v, dual_bus_apb.v,
dual_bus_axi.v: ports nN_*) with a bus-functional model from the package index
and offers the same two calls, so the tests in test_dual_bus.py run unchanged
on every bus:

- ``await read(index)``: the word at register `index` (docs/registers.md) as
  read, as a string of 32 bits, MSB first, unknown bits ('x', 'z') and all.
  Reads are never refused (cosim/src/model/bus_contract.md §1): an error
  response to a read fails the test here.
- ``await write(index, value, strb=0xF)``: writes the byte lanes `strb` selects
  and returns the bus's response, OK or ERR (refused: Wishbone ERR, APB
  PSLVERR, AXI4-Lite SLVERR).

To drive the DRCC from another bus model, write one more class like these.
"""

import logging
import warnings

# cocotbext-axi passes its results in Event.data, which cocotb 2 deprecates.
warnings.filterwarnings("ignore", "The data field", DeprecationWarning)

OK, ERR = "OK", "ERR"

BUSES = ("wishbone", "apb", "axi")

# The Verilog wrapper of each bus (its module has the file's name) and the DRCC
# top it instantiates (rtl-out/<top>.v).
WRAPPERS = {
    "wishbone": ("dual_bus", "drcc"),
    "apb": ("dual_bus_apb", "drcc_apb"),
    "axi": ("dual_bus_axi", "drcc_axi"),
}


def _quiet(*names):
    """The models log every transfer at INFO; the bench logs what fails."""
    for name in names:
        logging.getLogger(name).setLevel(logging.WARNING)


class WishboneAccess:
    """Wishbone B4 classic (word addresses, SEL, ERR) with cocotbext-wishbone."""

    def __init__(self, dut, n):
        from cocotbext.wishbone.driver import WBOp, WishboneMaster

        _quiet(f"cocotb.{dut._name}.n{n}")
        self._op = WBOp
        names = ("cyc", "stb", "we", "adr", "datwr", "datrd", "sel", "ack", "err")
        self.wb = WishboneMaster(
            dut, f"n{n}", dut.clk, width=32, timeout=16, signals_dict={s: s for s in names}
        )

    async def write(self, index, value, strb=0xF):
        res = await self.wb.send_cycle([self._op(adr=index, dat=value, sel=strb)])
        return {1: OK, 2: ERR}[res[0].ack]  # cocotbext-wishbone: 1 ACK, 2 ERR

    async def read(self, index):
        res = await self.wb.send_cycle([self._op(adr=index)])
        assert res[0].ack == 1, f"read of register {index} not acknowledged ({res[0].ack})"
        return str(res[0].datrd)


class ApbAccess:
    """APB4 (byte addresses, PSTRB, PSLVERR) with cocotbext-apb's ApbHost.

    ApbHost checks PSLVERR against an expectation given before the transfer
    (`error_expected`) and raises in its own task when they differ; the bench
    wants to see the response instead. So the host's bus leaves `pslverr` out
    and this class reads it, with `prdata`, in the clock where the host ends the
    transfer: ApbHost returns from read() and write() in that clock, after it
    saw `pready` = 1 (checked here)."""

    def __init__(self, dut, n):
        from cocotbext.apb import ApbBus, ApbHost

        _quiet(f"cocotb.apb_host.n{n}")
        bus = ApbBus.from_prefix(dut, f"n{n}", optional_signals=["penable", "pstrb"])
        self.host = ApbHost(bus, dut.clk)
        self.pready = getattr(dut, f"n{n}_pready")
        self.pslverr = getattr(dut, f"n{n}_pslverr")
        self.prdata = getattr(dut, f"n{n}_prdata")

    def _response(self):
        assert self.pready.value == 1, "ApbHost returned outside the transfer's last clock"
        return ERR if self.pslverr.value == 1 else OK

    async def write(self, index, value, strb=0xF):
        await self.host.write(4 * index, value, strb=strb)
        return self._response()

    async def read(self, index):
        await self.host.read(4 * index)
        bits = str(self.prdata.value)  # ApbHost's own value has 'x' made 0
        assert self._response() == OK, f"read of register {index} answered PSLVERR"
        return bits


class AxiLiteAccess:
    """AXI4-Lite (byte addresses, WSTRB, BRESP/RRESP) with cocotbext-axi.

    Writes go through AxiLiteMasterWrite (a byte-lane write is the bytes at
    their address: `strb` must select contiguous lanes). Reads go through the
    package's AR source and R sink directly, because AxiLiteMasterRead turns
    `rdata` into an integer and stops on a word with unknown bits, which
    Icarus shows in RX_ID's fields while the RX FIFO is empty."""

    def __init__(self, dut, n):
        from cocotbext.axi import AxiLiteMasterWrite, AxiLiteReadBus, AxiLiteWriteBus
        from cocotbext.axi.axil_channels import (
            AxiLiteARSource,
            AxiLiteARTransaction,
            AxiLiteRSink,
        )

        _quiet(f"cocotb.{dut._name}.n{n}")
        self.writer = AxiLiteMasterWrite(AxiLiteWriteBus.from_prefix(dut, f"n{n}"), dut.clk)
        read_bus = AxiLiteReadBus.from_prefix(dut, f"n{n}")
        self.ar = AxiLiteARSource(read_bus.ar, dut.clk)
        self.r = AxiLiteRSink(read_bus.r, dut.clk)
        self._ar_txn = AxiLiteARTransaction

    async def write(self, index, value, strb=0xF):
        lanes = [i for i in range(4) if strb >> i & 1]
        assert lanes and lanes == list(range(lanes[0], lanes[-1] + 1)), (
            f"AxiLiteMasterWrite writes contiguous byte lanes only, not {strb:#x}"
        )
        data = value.to_bytes(4, "little")[lanes[0] : lanes[-1] + 1]
        resp = await self.writer.write(4 * index + lanes[0], data)
        return {0b00: OK, 0b10: ERR}[int(resp.resp)]  # OKAY, SLVERR

    async def read(self, index):
        await self.ar.send(self._ar_txn(araddr=4 * index))
        r = await self.r.recv()
        assert str(r.rresp) == "00", f"read of register {index} answered {r.rresp}"
        return str(r.rdata)


ACCESS = {"wishbone": WishboneAccess, "apb": ApbAccess, "axi": AxiLiteAccess}
