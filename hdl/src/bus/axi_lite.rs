//! The AXI4-Lite front end (`cosim/src/model/bus_contract.md` §3): an AXI4-Lite
//! slave on the register port of a DRCC or a hub. The three request channels
//! are taken into holding registers independently (AW, W and AR in any order);
//! one register-port access runs at a time, writes and reads alternating when
//! both are ready; its answer becomes the B or R response (`SLVERR` for a
//! refused access), held until the master takes it. Every output is a register
//! or a register's inverse, never an input: the bridge adds no combinational
//! path from the interconnect to the interconnect.

use rust_hdl::prelude::*;

/// AXI4-Lite slave to Wishbone B4 classic master (the register port). `A` is
/// the byte address's width, `W = A - 2` the word index's (as [`super::apb::ApbBridge`]).
#[derive(LogicBlock)]
pub struct AxiLiteBridge<const A: usize, const W: usize> {
    // ---- clock and reset ----
    /// System clock (`ACLK`).
    pub clk: Signal<In, Clock>,
    /// Synchronous reset, active high (`ARESETn` inverted): nothing held.
    pub rst: Signal<In, Bit>,
    // ---- AXI4-Lite write address channel ----
    /// Write byte address; `[1:0]` are ignored (word registers).
    pub s_axi_awaddr: Signal<In, Bits<A>>,
    /// Write address valid.
    pub s_axi_awvalid: Signal<In, Bit>,
    /// Write address ready: no write address is held.
    pub s_axi_awready: Signal<Out, Bit>,
    // ---- AXI4-Lite write data channel ----
    /// Write data.
    pub s_axi_wdata: Signal<In, Bits<32>>,
    /// Write strobes, lane i = `wdata[8i+7:8i]`.
    pub s_axi_wstrb: Signal<In, Bits<4>>,
    /// Write data valid.
    pub s_axi_wvalid: Signal<In, Bit>,
    /// Write data ready: no write data is held.
    pub s_axi_wready: Signal<Out, Bit>,
    // ---- AXI4-Lite write response channel ----
    /// Write response: `2'b00` OKAY, `2'b10` SLVERR (refused).
    pub s_axi_bresp: Signal<Out, Bits<2>>,
    /// Write response valid, held until `bready`.
    pub s_axi_bvalid: Signal<Out, Bit>,
    /// Write response ready.
    pub s_axi_bready: Signal<In, Bit>,
    // ---- AXI4-Lite read address channel ----
    /// Read byte address; `[1:0]` are ignored.
    pub s_axi_araddr: Signal<In, Bits<A>>,
    /// Read address valid.
    pub s_axi_arvalid: Signal<In, Bit>,
    /// Read address ready: no read address is held.
    pub s_axi_arready: Signal<Out, Bit>,
    // ---- AXI4-Lite read data channel ----
    /// Read data, held with `rvalid`.
    pub s_axi_rdata: Signal<Out, Bits<32>>,
    /// Read response: always `2'b00` OKAY (reads are never refused).
    pub s_axi_rresp: Signal<Out, Bits<2>>,
    /// Read data valid, held until `rready`.
    pub s_axi_rvalid: Signal<Out, Bit>,
    /// Read data ready.
    pub s_axi_rready: Signal<In, Bit>,
    // ---- register port (to the register block) ----
    /// Wishbone cycle and strobe: an access is in progress.
    pub wb_cyc_o: Signal<Out, Bit>,
    /// Write enable.
    pub wb_we_o: Signal<Out, Bit>,
    /// Word index.
    pub wb_adr_o: Signal<Out, Bits<W>>,
    /// Write data.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Byte lanes.
    pub wb_sel_o: Signal<Out, Bits<4>>,
    // ---- register port (from the register block) ----
    /// Read data with the ack.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Acknowledge.
    pub wb_ack_i: Signal<In, Bit>,
    /// Error: the access was refused.
    pub wb_err_i: Signal<In, Bit>,
    // ---- held requests ----
    aw_full: DFF<Bit>,
    aw_adr: DFF<Bits<W>>,
    w_full: DFF<Bit>,
    w_dat: DFF<Bits<32>>,
    w_strb: DFF<Bits<4>>,
    ar_full: DFF<Bit>,
    ar_adr: DFF<Bits<W>>,
    // ---- the access in progress ----
    cyc: DFF<Bit>,
    we: DFF<Bit>,
    /// The last access started was a write (the other kind goes first next).
    last_write: DFF<Bit>,
    // ---- responses ----
    bvalid: DFF<Bit>,
    bresp: DFF<Bits<2>>,
    rvalid: DFF<Bit>,
    rdata: DFF<Bits<32>>,
    rresp: DFF<Bits<2>>,
    // ---- decode ----
    /// A write may start: address and data held, no B waiting.
    write_ready: Signal<Local, Bit>,
    /// A read may start: address held, no R waiting.
    read_ready: Signal<Local, Bit>,
    /// The register port answered the access in progress.
    done: Signal<Local, Bit>,
    okay: Constant<Bits<2>>,
    slverr: Constant<Bits<2>>,
    zero4: Constant<Bits<4>>,
    zero_adr: Constant<Bits<W>>,
    zero32: Constant<Bits<32>>,
}

impl<const A: usize, const W: usize> Default for AxiLiteBridge<A, W> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            s_axi_awaddr: Default::default(),
            s_axi_awvalid: Default::default(),
            s_axi_awready: Default::default(),
            s_axi_wdata: Default::default(),
            s_axi_wstrb: Default::default(),
            s_axi_wvalid: Default::default(),
            s_axi_wready: Default::default(),
            s_axi_bresp: Default::default(),
            s_axi_bvalid: Default::default(),
            s_axi_bready: Default::default(),
            s_axi_araddr: Default::default(),
            s_axi_arvalid: Default::default(),
            s_axi_arready: Default::default(),
            s_axi_rdata: Default::default(),
            s_axi_rresp: Default::default(),
            s_axi_rvalid: Default::default(),
            s_axi_rready: Default::default(),
            wb_cyc_o: Default::default(),
            wb_we_o: Default::default(),
            wb_adr_o: Default::default(),
            wb_dat_o: Default::default(),
            wb_sel_o: Default::default(),
            wb_dat_i: Default::default(),
            wb_ack_i: Default::default(),
            wb_err_i: Default::default(),
            aw_full: Default::default(),
            aw_adr: Default::default(),
            w_full: Default::default(),
            w_dat: Default::default(),
            w_strb: Default::default(),
            ar_full: Default::default(),
            ar_adr: Default::default(),
            cyc: Default::default(),
            we: Default::default(),
            last_write: Default::default(),
            bvalid: Default::default(),
            bresp: Default::default(),
            rvalid: Default::default(),
            rdata: Default::default(),
            rresp: Default::default(),
            write_ready: Default::default(),
            read_ready: Default::default(),
            done: Default::default(),
            okay: Constant::new(0.into()),
            slverr: Constant::new(2.into()),
            zero4: Constant::new(0.into()),
            zero_adr: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl<const A: usize, const W: usize> Logic for AxiLiteBridge<A, W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, aw_full, aw_adr, w_full, w_dat, w_strb, ar_full, ar_adr, cyc, we,
            last_write, bvalid, bresp, rvalid, rdata, rresp
        );
        // 1. the request channels, each into its holding register
        if self.s_axi_awvalid.val() & !self.aw_full.q.val() {
            self.aw_full.d.next = true;
            self.aw_adr.d.next = self.s_axi_awaddr.val().get_bits::<W>(2);
        }
        if self.s_axi_wvalid.val() & !self.w_full.q.val() {
            self.w_full.d.next = true;
            self.w_dat.d.next = self.s_axi_wdata.val();
            self.w_strb.d.next = self.s_axi_wstrb.val();
        }
        if self.s_axi_arvalid.val() & !self.ar_full.q.val() {
            self.ar_full.d.next = true;
            self.ar_adr.d.next = self.s_axi_araddr.val().get_bits::<W>(2);
        }

        // 2. start an access; a held response blocks only its own kind, and
        // the kinds alternate when both are ready
        self.write_ready.next = self.aw_full.q.val() & self.w_full.q.val() & !self.bvalid.q.val();
        self.read_ready.next = self.ar_full.q.val() & !self.rvalid.q.val();
        if !self.cyc.q.val() {
            if self.write_ready.val() & (!self.read_ready.val() | !self.last_write.q.val()) {
                self.cyc.d.next = true;
                self.we.d.next = true;
                self.last_write.d.next = true;
            } else if self.read_ready.val() {
                self.cyc.d.next = true;
                self.we.d.next = false;
                self.last_write.d.next = false;
            }
        }

        // 3. end it: the register port's answer is the response
        self.done.next = self.wb_ack_i.val() | self.wb_err_i.val();
        if self.cyc.q.val() & self.done.val() {
            self.cyc.d.next = false;
            if self.we.q.val() {
                self.aw_full.d.next = false;
                self.w_full.d.next = false;
                self.bvalid.d.next = true;
                self.bresp.d.next = self.okay.val();
                if self.wb_err_i.val() {
                    self.bresp.d.next = self.slverr.val();
                }
            } else {
                self.ar_full.d.next = false;
                self.rvalid.d.next = true;
                self.rdata.d.next = self.wb_dat_i.val();
                self.rresp.d.next = self.okay.val();
                if self.wb_err_i.val() {
                    self.rresp.d.next = self.slverr.val();
                }
            }
        }

        // 4. the responses, until the master takes them
        if self.bvalid.q.val() & self.s_axi_bready.val() {
            self.bvalid.d.next = false;
        }
        if self.rvalid.q.val() & self.s_axi_rready.val() {
            self.rvalid.d.next = false;
        }

        if self.rst.val() {
            self.aw_full.d.next = false;
            self.aw_adr.d.next = self.zero_adr.val();
            self.w_full.d.next = false;
            self.w_dat.d.next = self.zero32.val();
            self.w_strb.d.next = self.zero4.val();
            self.ar_full.d.next = false;
            self.ar_adr.d.next = self.zero_adr.val();
            self.cyc.d.next = false;
            self.we.d.next = false;
            self.last_write.d.next = false;
            self.bvalid.d.next = false;
            self.bresp.d.next = self.okay.val();
            self.rvalid.d.next = false;
            self.rdata.d.next = self.zero32.val();
            self.rresp.d.next = self.okay.val();
        }

        // outputs: registers only
        self.s_axi_awready.next = !self.aw_full.q.val();
        self.s_axi_wready.next = !self.w_full.q.val();
        self.s_axi_arready.next = !self.ar_full.q.val();
        self.s_axi_bvalid.next = self.bvalid.q.val();
        self.s_axi_bresp.next = self.bresp.q.val();
        self.s_axi_rvalid.next = self.rvalid.q.val();
        self.s_axi_rdata.next = self.rdata.q.val();
        self.s_axi_rresp.next = self.rresp.q.val();
        self.wb_cyc_o.next = self.cyc.q.val();
        self.wb_we_o.next = self.we.q.val();
        self.wb_adr_o.next = self.ar_adr.q.val();
        if self.we.q.val() {
            self.wb_adr_o.next = self.aw_adr.q.val();
        }
        self.wb_dat_o.next = self.w_dat.q.val();
        self.wb_sel_o.next = self.w_strb.q.val();
    }
}
