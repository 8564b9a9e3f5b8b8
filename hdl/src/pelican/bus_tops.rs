//! The SJA1000 view on an APB or an AXI4-Lite bus (`cosim/src/model/bus_contract.md`
//! §2, §3 and `pelican_contract.md` §2): the `drcc_pelican` top ([`DrccPelican`])
//! behind the front end of [`crate::bus::apb`] or [`crate::bus::axi_lite`], with a
//! 9-bit byte address. The view is offered on these buses at stride 4 only
//! (register `r` at byte `4r`, Linux `reg-io-width = <4>`): their reads carry
//! no byte lanes, so stride 1's one-byte loads cannot be told apart.

use super::top::DrccPelican;
use super::PelicanKeys;
use crate::bus::apb::ApbBridge;
use crate::bus::axi_lite::AxiLiteBridge;
use crate::config::DrccConfig;
use rust_hdl::prelude::*;

/// The SJA1000 view with an APB4 slave (`rtl-out/drcc_pelican_apb.v` with `M` = 16).
#[derive(LogicBlock, Default)]
pub struct DrccPelicanApb<const M: usize> {
    // ---- clock and reset ----
    /// Clock (`PCLK`): the SJA1000's oscillator `fosc` (a time quantum is
    /// `2 x (BRP + 1)` clocks, P-CFG-2).
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high (`PRESETn` inverted): the
    /// registers take their values of pelican_contract.md §16 (`MOD = 0x01`).
    pub rst: Signal<In, Bit>,
    // ---- APB4 slave (bus_contract.md §2; registers: docs/pelican.md) ----
    /// Select: this slave is addressed (setup and access phases).
    pub s_apb_psel: Signal<In, Bit>,
    /// Enable: the access phase.
    pub s_apb_penable: Signal<In, Bit>,
    /// Direction: 1 = write.
    pub s_apb_pwrite: Signal<In, Bit>,
    /// Byte address: register `r` at `4r` (`[8:2]`); `[1:0]` are ignored.
    pub s_apb_paddr: Signal<In, Bits<9>>,
    /// Write data: the register's byte in `[7:0]`.
    pub s_apb_pwdata: Signal<In, Bits<32>>,
    /// Write strobes: a write needs lane 0 (`pstrb[0]`), else it is refused
    /// with `PSLVERR` and `XIR.bus` (P-BUS-3). APB3: tie to `4'b1111`.
    pub s_apb_pstrb: Signal<In, Bits<4>>,
    /// Read data, valid with `pready`, else 0: the register's byte in `[7:0]`.
    pub s_apb_prdata: Signal<Out, Bits<32>>,
    /// Ready: 1 in the second clock of every access phase (one wait state).
    pub s_apb_pready: Signal<Out, Bit>,
    /// Slave error with `pready`: the access was refused (P-BUS-3).
    pub s_apb_pslverr: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered (P-IRQ-1). Invert it
    /// for the SJA1000's `INT#`.
    pub irq: Signal<Out, Bit>,
    // ---- CAN pins (1 = recessive); A is the paper's channel 1, B channel 2 ----
    /// Channel A CAN transmit pin, 1 = recessive from configuration on.
    pub chan_a_tx: Signal<Out, Bit>,
    /// Channel A CAN receive pin, 1 = recessive; synchronized by two flip-flops.
    pub chan_a_rx: Signal<In, Bit>,
    /// Channel B CAN transmit pin, 1 = recessive from configuration on.
    pub chan_b_tx: Signal<Out, Bit>,
    /// Channel B CAN receive pin, 1 = recessive; synchronized by two flip-flops.
    pub chan_b_rx: Signal<In, Bit>,
    // ---- blocks ----
    bridge: ApbBridge<9, 7>,
    /// The view's Wishbone top (public for probes in tests).
    pub pelican: DrccPelican<M>,
}

impl<const M: usize> DrccPelicanApb<M> {
    /// The view with the keys `k` (stride 4) over a core with the sizes of
    /// `cfg`, behind APB.
    pub fn with_config(cfg: &DrccConfig, k: &PelicanKeys) -> Self {
        Self {
            pelican: DrccPelican::with_config(cfg, k),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for DrccPelicanApb<M> {
    #[hdl_gen]
    fn update(&mut self) {
        self.bridge.s_apb_psel.next = self.s_apb_psel.val();
        self.bridge.s_apb_penable.next = self.s_apb_penable.val();
        self.bridge.s_apb_pwrite.next = self.s_apb_pwrite.val();
        self.bridge.s_apb_paddr.next = self.s_apb_paddr.val();
        self.bridge.s_apb_pwdata.next = self.s_apb_pwdata.val();
        self.bridge.s_apb_pstrb.next = self.s_apb_pstrb.val();
        self.s_apb_prdata.next = self.bridge.s_apb_prdata.val();
        self.s_apb_pready.next = self.bridge.s_apb_pready.val();
        self.s_apb_pslverr.next = self.bridge.s_apb_pslverr.val();
        // the view's Wishbone port
        self.pelican.clk.next = self.clk.val();
        self.pelican.rst.next = self.rst.val();
        self.pelican.wb_cyc_i.next = self.bridge.wb_cyc_o.val();
        self.pelican.wb_stb_i.next = self.bridge.wb_cyc_o.val();
        self.pelican.wb_we_i.next = self.bridge.wb_we_o.val();
        self.pelican.wb_adr_i.next = self.bridge.wb_adr_o.val();
        self.pelican.wb_dat_i.next = self.bridge.wb_dat_o.val();
        self.pelican.wb_sel_i.next = self.bridge.wb_sel_o.val();
        self.bridge.wb_dat_i.next = self.pelican.wb_dat_o.val();
        self.bridge.wb_ack_i.next = self.pelican.wb_ack_o.val();
        self.bridge.wb_err_i.next = self.pelican.wb_err_o.val();
        // interrupt and pins
        self.irq.next = self.pelican.irq.val();
        self.chan_a_tx.next = self.pelican.chan_a_tx.val();
        self.pelican.chan_a_rx.next = self.chan_a_rx.val();
        self.chan_b_tx.next = self.pelican.chan_b_tx.val();
        self.pelican.chan_b_rx.next = self.chan_b_rx.val();
    }
}

/// The SJA1000 view with an AXI4-Lite slave (`rtl-out/drcc_pelican_axi.v` with `M` = 16).
#[derive(LogicBlock, Default)]
pub struct DrccPelicanAxi<const M: usize> {
    // ---- clock and reset ----
    /// Clock (`ACLK`): the SJA1000's oscillator `fosc` (a time quantum is
    /// `2 x (BRP + 1)` clocks, P-CFG-2).
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high (`ARESETn` inverted): the
    /// registers take their values of pelican_contract.md §16 (`MOD = 0x01`).
    pub rst: Signal<In, Bit>,
    // ---- AXI4-Lite slave (bus_contract.md §3; registers: docs/pelican.md) ----
    /// Write byte address: register `r` at `4r` (`[8:2]`); `[1:0]` are ignored.
    pub s_axi_awaddr: Signal<In, Bits<9>>,
    /// Write address valid.
    pub s_axi_awvalid: Signal<In, Bit>,
    /// Write address ready: no write address is held.
    pub s_axi_awready: Signal<Out, Bit>,
    /// Write data: the register's byte in `[7:0]`.
    pub s_axi_wdata: Signal<In, Bits<32>>,
    /// Write strobes: a write needs lane 0 (`wstrb[0]`), else it is refused
    /// (`SLVERR`, `XIR.bus`, P-BUS-3).
    pub s_axi_wstrb: Signal<In, Bits<4>>,
    /// Write data valid.
    pub s_axi_wvalid: Signal<In, Bit>,
    /// Write data ready: no write data is held.
    pub s_axi_wready: Signal<Out, Bit>,
    /// Write response: `2'b00` OKAY, `2'b10` SLVERR (refused).
    pub s_axi_bresp: Signal<Out, Bits<2>>,
    /// Write response valid, held until `bready`.
    pub s_axi_bvalid: Signal<Out, Bit>,
    /// Write response ready.
    pub s_axi_bready: Signal<In, Bit>,
    /// Read byte address: register `r` at `4r` (`[8:2]`); `[1:0]` are ignored.
    pub s_axi_araddr: Signal<In, Bits<9>>,
    /// Read address valid.
    pub s_axi_arvalid: Signal<In, Bit>,
    /// Read address ready: no read address is held.
    pub s_axi_arready: Signal<Out, Bit>,
    /// Read data, held with `rvalid`: the register's byte in `[7:0]`.
    pub s_axi_rdata: Signal<Out, Bits<32>>,
    /// Read response: always `2'b00` OKAY (a stride-4 read is never refused).
    pub s_axi_rresp: Signal<Out, Bits<2>>,
    /// Read data valid, held until `rready`.
    pub s_axi_rvalid: Signal<Out, Bit>,
    /// Read data ready.
    pub s_axi_rready: Signal<In, Bit>,
    /// Interrupt request, active-high level, registered (P-IRQ-1). Invert it
    /// for the SJA1000's `INT#`.
    pub irq: Signal<Out, Bit>,
    // ---- CAN pins (1 = recessive); A is the paper's channel 1, B channel 2 ----
    /// Channel A CAN transmit pin, 1 = recessive from configuration on.
    pub chan_a_tx: Signal<Out, Bit>,
    /// Channel A CAN receive pin, 1 = recessive; synchronized by two flip-flops.
    pub chan_a_rx: Signal<In, Bit>,
    /// Channel B CAN transmit pin, 1 = recessive from configuration on.
    pub chan_b_tx: Signal<Out, Bit>,
    /// Channel B CAN receive pin, 1 = recessive; synchronized by two flip-flops.
    pub chan_b_rx: Signal<In, Bit>,
    // ---- blocks ----
    bridge: AxiLiteBridge<9, 7>,
    /// The view's Wishbone top (public for probes in tests).
    pub pelican: DrccPelican<M>,
}

impl<const M: usize> DrccPelicanAxi<M> {
    /// The view with the keys `k` (stride 4) over a core with the sizes of
    /// `cfg`, behind AXI4-Lite.
    pub fn with_config(cfg: &DrccConfig, k: &PelicanKeys) -> Self {
        Self {
            pelican: DrccPelican::with_config(cfg, k),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for DrccPelicanAxi<M> {
    #[hdl_gen]
    fn update(&mut self) {
        self.bridge.clk.next = self.clk.val();
        self.bridge.rst.next = self.rst.val();
        self.bridge.s_axi_awaddr.next = self.s_axi_awaddr.val();
        self.bridge.s_axi_awvalid.next = self.s_axi_awvalid.val();
        self.bridge.s_axi_wdata.next = self.s_axi_wdata.val();
        self.bridge.s_axi_wstrb.next = self.s_axi_wstrb.val();
        self.bridge.s_axi_wvalid.next = self.s_axi_wvalid.val();
        self.bridge.s_axi_bready.next = self.s_axi_bready.val();
        self.bridge.s_axi_araddr.next = self.s_axi_araddr.val();
        self.bridge.s_axi_arvalid.next = self.s_axi_arvalid.val();
        self.bridge.s_axi_rready.next = self.s_axi_rready.val();
        self.s_axi_awready.next = self.bridge.s_axi_awready.val();
        self.s_axi_wready.next = self.bridge.s_axi_wready.val();
        self.s_axi_bresp.next = self.bridge.s_axi_bresp.val();
        self.s_axi_bvalid.next = self.bridge.s_axi_bvalid.val();
        self.s_axi_arready.next = self.bridge.s_axi_arready.val();
        self.s_axi_rdata.next = self.bridge.s_axi_rdata.val();
        self.s_axi_rresp.next = self.bridge.s_axi_rresp.val();
        self.s_axi_rvalid.next = self.bridge.s_axi_rvalid.val();
        // the view's Wishbone port
        self.pelican.clk.next = self.clk.val();
        self.pelican.rst.next = self.rst.val();
        self.pelican.wb_cyc_i.next = self.bridge.wb_cyc_o.val();
        self.pelican.wb_stb_i.next = self.bridge.wb_cyc_o.val();
        self.pelican.wb_we_i.next = self.bridge.wb_we_o.val();
        self.pelican.wb_adr_i.next = self.bridge.wb_adr_o.val();
        self.pelican.wb_dat_i.next = self.bridge.wb_dat_o.val();
        self.pelican.wb_sel_i.next = self.bridge.wb_sel_o.val();
        self.bridge.wb_dat_i.next = self.pelican.wb_dat_o.val();
        self.bridge.wb_ack_i.next = self.pelican.wb_ack_o.val();
        self.bridge.wb_err_i.next = self.pelican.wb_err_o.val();
        // interrupt and pins
        self.irq.next = self.pelican.irq.val();
        self.chan_a_tx.next = self.pelican.chan_a_tx.val();
        self.pelican.chan_a_rx.next = self.chan_a_rx.val();
        self.chan_b_tx.next = self.pelican.chan_b_tx.val();
        self.pelican.chan_b_rx.next = self.chan_b_rx.val();
    }
}
