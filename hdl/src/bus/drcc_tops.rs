//! The DRCC on an APB or an AXI4-Lite bus (`cosim/src/model/bus_contract.md`
//! §4): the DRCC top ([`DrccTop`]) behind the front end of [`super::apb`] or
//! [`super::axi_lite`]. The register map, the interrupt and the CAN pins are
//! the Wishbone top's; the probes are not ports here (an integrator's top has
//! no use for them, and the register block is signed off on the Wishbone top).

use super::apb::ApbBridge;
use super::axi_lite::AxiLiteBridge;
use crate::config::DrccConfig;
use crate::drcc::DrccTop;
use rust_hdl::prelude::*;

/// The DRCC with an APB4 slave (`rtl-out/drcc_apb.v` with `M` = 16).
#[derive(LogicBlock, Default)]
pub struct DrccApb<const M: usize> {
    // ---- clock and reset ----
    /// Clock (`PCLK`). The channels' bit timing (`BTR`) counts its periods.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high (`PRESETn` inverted); hold
    /// it for at least 4 clock edges (README "Integrate it").
    pub rst: Signal<In, Bit>,
    // ---- APB4 slave (bus_contract.md §2; registers: docs/registers.md) ----
    /// Select: this slave is addressed (setup and access phases).
    pub s_apb_psel: Signal<In, Bit>,
    /// Enable: the access phase.
    pub s_apb_penable: Signal<In, Bit>,
    /// Direction: 1 = write.
    pub s_apb_pwrite: Signal<In, Bit>,
    /// Byte address of the register; `[1:0]` are ignored.
    pub s_apb_paddr: Signal<In, Bits<8>>,
    /// Write data, a word or the lanes its strobes select.
    pub s_apb_pwdata: Signal<In, Bits<32>>,
    /// Write strobes: `TX_ID`, `TX_CTRL`, `TX_DATA0/1` take the selected bytes,
    /// a partial write to another register is refused. APB3: tie to `4'b1111`.
    pub s_apb_pstrb: Signal<In, Bits<4>>,
    /// Read data, valid with `pready`, else 0.
    pub s_apb_prdata: Signal<Out, Bits<32>>,
    /// Ready: 1 in the second clock of every access phase (one wait state).
    pub s_apb_pready: Signal<Out, Bit>,
    /// Slave error with `pready`: the access was refused (`INT_STATUS.illegal`).
    pub s_apb_pslverr: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered: `|(INT_STATUS & INT_ENABLE)`.
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
    bridge: ApbBridge<8, 6>,
    core: DrccTop<M>,
}

impl<const M: usize> DrccApb<M> {
    /// The DRCC generated with `cfg` (`drcc generate --config`) behind APB.
    pub fn with_config(cfg: &DrccConfig) -> Self {
        Self {
            core: DrccTop::with_config(cfg),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for DrccApb<M> {
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
        // the register port
        self.core.clk.next = self.clk.val();
        self.core.rst.next = self.rst.val();
        self.core.wb_cyc_i.next = self.bridge.wb_cyc_o.val();
        self.core.wb_stb_i.next = self.bridge.wb_cyc_o.val();
        self.core.wb_we_i.next = self.bridge.wb_we_o.val();
        self.core.wb_adr_i.next = self.bridge.wb_adr_o.val();
        self.core.wb_dat_i.next = self.bridge.wb_dat_o.val();
        self.core.wb_sel_i.next = self.bridge.wb_sel_o.val();
        self.bridge.wb_dat_i.next = self.core.wb_dat_o.val();
        self.bridge.wb_ack_i.next = self.core.wb_ack_o.val();
        self.bridge.wb_err_i.next = self.core.wb_err_o.val();
        // interrupt and pins
        self.irq.next = self.core.irq.val();
        self.chan_a_tx.next = self.core.chan_a_tx.val();
        self.core.chan_a_rx.next = self.chan_a_rx.val();
        self.chan_b_tx.next = self.core.chan_b_tx.val();
        self.core.chan_b_rx.next = self.chan_b_rx.val();
    }
}

/// The DRCC with an AXI4-Lite slave (`rtl-out/drcc_axi.v` with `M` = 16).
#[derive(LogicBlock, Default)]
pub struct DrccAxi<const M: usize> {
    // ---- clock and reset ----
    /// Clock (`ACLK`). The channels' bit timing (`BTR`) counts its periods.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high (`ARESETn` inverted); hold
    /// it for at least 4 clock edges (README "Integrate it").
    pub rst: Signal<In, Bit>,
    // ---- AXI4-Lite slave (bus_contract.md §3; registers: docs/registers.md) ----
    /// Write byte address; `[1:0]` are ignored.
    pub s_axi_awaddr: Signal<In, Bits<8>>,
    /// Write address valid.
    pub s_axi_awvalid: Signal<In, Bit>,
    /// Write address ready: no write address is held.
    pub s_axi_awready: Signal<Out, Bit>,
    /// Write data, a word or the lanes its strobes select.
    pub s_axi_wdata: Signal<In, Bits<32>>,
    /// Write strobes: `TX_ID`, `TX_CTRL`, `TX_DATA0/1` take the selected bytes,
    /// a partial write to another register is refused (`SLVERR`).
    pub s_axi_wstrb: Signal<In, Bits<4>>,
    /// Write data valid.
    pub s_axi_wvalid: Signal<In, Bit>,
    /// Write data ready: no write data is held.
    pub s_axi_wready: Signal<Out, Bit>,
    /// Write response: `2'b00` OKAY, `2'b10` SLVERR (refused, `INT_STATUS.illegal`).
    pub s_axi_bresp: Signal<Out, Bits<2>>,
    /// Write response valid, held until `bready`.
    pub s_axi_bvalid: Signal<Out, Bit>,
    /// Write response ready.
    pub s_axi_bready: Signal<In, Bit>,
    /// Read byte address; `[1:0]` are ignored.
    pub s_axi_araddr: Signal<In, Bits<8>>,
    /// Read address valid.
    pub s_axi_arvalid: Signal<In, Bit>,
    /// Read address ready: no read address is held.
    pub s_axi_arready: Signal<Out, Bit>,
    /// Read data, held with `rvalid`.
    pub s_axi_rdata: Signal<Out, Bits<32>>,
    /// Read response: always `2'b00` OKAY (reads are never refused).
    pub s_axi_rresp: Signal<Out, Bits<2>>,
    /// Read data valid, held until `rready`.
    pub s_axi_rvalid: Signal<Out, Bit>,
    /// Read data ready.
    pub s_axi_rready: Signal<In, Bit>,
    /// Interrupt request, active-high level, registered: `|(INT_STATUS & INT_ENABLE)`.
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
    bridge: AxiLiteBridge<8, 6>,
    core: DrccTop<M>,
}

impl<const M: usize> DrccAxi<M> {
    /// The DRCC generated with `cfg` (`drcc generate --config`) behind AXI4-Lite.
    pub fn with_config(cfg: &DrccConfig) -> Self {
        Self {
            core: DrccTop::with_config(cfg),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for DrccAxi<M> {
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
        // the register port
        self.core.clk.next = self.clk.val();
        self.core.rst.next = self.rst.val();
        self.core.wb_cyc_i.next = self.bridge.wb_cyc_o.val();
        self.core.wb_stb_i.next = self.bridge.wb_cyc_o.val();
        self.core.wb_we_i.next = self.bridge.wb_we_o.val();
        self.core.wb_adr_i.next = self.bridge.wb_adr_o.val();
        self.core.wb_dat_i.next = self.bridge.wb_dat_o.val();
        self.core.wb_sel_i.next = self.bridge.wb_sel_o.val();
        self.bridge.wb_dat_i.next = self.core.wb_dat_o.val();
        self.bridge.wb_ack_i.next = self.core.wb_ack_o.val();
        self.bridge.wb_err_i.next = self.core.wb_err_o.val();
        // interrupt and pins
        self.irq.next = self.core.irq.val();
        self.chan_a_tx.next = self.core.chan_a_tx.val();
        self.core.chan_a_rx.next = self.chan_a_rx.val();
        self.chan_b_tx.next = self.core.chan_b_tx.val();
        self.core.chan_b_rx.next = self.chan_b_rx.val();
    }
}
