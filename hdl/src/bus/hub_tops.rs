//! The ReCANcentrate hub on an APB or an AXI4-Lite bus
//! (`cosim/src/model/bus_contract.md` §4): the hub ([`Hub`]) behind the front
//! end of [`super::apb`] or [`super::axi_lite`], offered by `drcc generate
//! --config` with `bus = "apb"` or `"axi4-lite"`. The register map, the
//! interrupt and the links are the Wishbone hub's; its probes are not ports.

use super::apb::ApbBridge;
use super::axi_lite::AxiLiteBridge;
use crate::hub::hub::Hub;
use rust_hdl::prelude::*;

/// The hub with an APB4 slave (hub A: `H` = 0, hub B: `H` = 1).
#[derive(LogicBlock, Default)]
pub struct HubApb<const N: usize, const M: usize, const P: usize, const H: usize> {
    // ---- clock and reset ----
    /// Clock (`PCLK`). The hub's bit timing (`BTR`) counts its periods.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high (`PRESETn` inverted); hold
    /// it for at least 4 clock edges (README "Integrate it").
    pub rst: Signal<In, Bit>,
    // ---- APB4 slave (bus_contract.md §2; registers: hub_contract.md §8) ----
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
    /// Write strobes: every hub register is written whole: a
    /// partial write is refused. APB3: tie to `4'b1111`.
    pub s_apb_pstrb: Signal<In, Bits<4>>,
    /// Read data, valid with `pready`, else 0.
    pub s_apb_prdata: Signal<Out, Bits<32>>,
    /// Ready: 1 in the second clock of every access phase (one wait state).
    pub s_apb_pready: Signal<Out, Bit>,
    /// Slave error with `pready`: the access was refused (`INT_STATUS.illegal`).
    pub s_apb_pslverr: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered: `|(INT_STATUS & INT_ENABLE)`.
    pub irq: Signal<Out, Bit>,
    // ---- node links and interlinks (1 = recessive; hub_contract.md §1) ----
    /// Node transmit values, bit i = node i's `tx` (N bits); each is
    /// synchronized by two flip-flops.
    pub uplink: Signal<In, Bits<N>>,
    /// What node i receives, bit i (N bits); recessive from configuration on.
    pub downlink: Signal<Out, Bits<N>>,
    /// This hub's contribution on each of the M interlinks; recessive from
    /// configuration on. Wire it to the twin's `sublink_in`.
    pub sublink_out: Signal<Out, Bits<M>>,
    /// The twin hub's contribution, bit j = interlink j (M bits); each is
    /// synchronized by two flip-flops.
    pub sublink_in: Signal<In, Bits<M>>,
    // ---- blocks ----
    bridge: ApbBridge<8, 6>,
    core: Hub<N, M, P, H>,
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Logic for HubApb<N, M, P, H> {
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
        self.core.uplink.next = self.uplink.val();
        self.downlink.next = self.core.downlink.val();
        self.sublink_out.next = self.core.sublink_out.val();
        self.core.sublink_in.next = self.sublink_in.val();
    }
}

/// The hub with an AXI4-Lite slave (hub A: `H` = 0, hub B: `H` = 1).
#[derive(LogicBlock, Default)]
pub struct HubAxi<const N: usize, const M: usize, const P: usize, const H: usize> {
    // ---- clock and reset ----
    /// Clock (`ACLK`). The hub's bit timing (`BTR`) counts its periods.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high (`ARESETn` inverted); hold
    /// it for at least 4 clock edges (README "Integrate it").
    pub rst: Signal<In, Bit>,
    // ---- AXI4-Lite slave (bus_contract.md §3; registers: hub_contract.md §8) ----
    /// Write byte address; `[1:0]` are ignored.
    pub s_axi_awaddr: Signal<In, Bits<8>>,
    /// Write address valid.
    pub s_axi_awvalid: Signal<In, Bit>,
    /// Write address ready: no write address is held.
    pub s_axi_awready: Signal<Out, Bit>,
    /// Write data, a word or the lanes its strobes select.
    pub s_axi_wdata: Signal<In, Bits<32>>,
    /// Write strobes: every hub register is written whole: a
    /// partial write is refused (`SLVERR`).
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
    // ---- node links and interlinks (1 = recessive; hub_contract.md §1) ----
    /// Node transmit values, bit i = node i's `tx` (N bits); each is
    /// synchronized by two flip-flops.
    pub uplink: Signal<In, Bits<N>>,
    /// What node i receives, bit i (N bits); recessive from configuration on.
    pub downlink: Signal<Out, Bits<N>>,
    /// This hub's contribution on each of the M interlinks; recessive from
    /// configuration on. Wire it to the twin's `sublink_in`.
    pub sublink_out: Signal<Out, Bits<M>>,
    /// The twin hub's contribution, bit j = interlink j (M bits); each is
    /// synchronized by two flip-flops.
    pub sublink_in: Signal<In, Bits<M>>,
    // ---- blocks ----
    bridge: AxiLiteBridge<8, 6>,
    core: Hub<N, M, P, H>,
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Logic for HubAxi<N, M, P, H> {
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
        self.core.uplink.next = self.uplink.val();
        self.downlink.next = self.core.downlink.val();
        self.sublink_out.next = self.core.sublink_out.val();
        self.core.sublink_in.next = self.sublink_in.val();
    }
}
