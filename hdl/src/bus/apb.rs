//! The APB front end (`cosim/src/model/bus_contract.md` §2): an AMBA APB4
//! slave (`PSTRB`, `PREADY`, `PSLVERR`) on the register port of a DRCC or a hub.
//! It is wires only: the access phase (`psel & penable`) is the Wishbone
//! strobe, and the register port's one-clock answer is `pready`, so every
//! access phase lasts two clocks (one wait state) and a refused access ends
//! with `pslverr`.

use rust_hdl::prelude::*;

/// APB4 slave to Wishbone B4 classic master (the register port), no state.
/// `A` is the byte address's width, `W = A - 2` the word index's: 8 and 6 for
/// the native map and the hub (64 words), 9 and 7 for the SJA1000 view at
/// stride 4 (128 registers a word each).
#[derive(LogicBlock, Default)]
pub struct ApbBridge<const A: usize, const W: usize> {
    // ---- APB slave (from the master) ----
    /// Select: this slave is addressed (setup and access phases).
    pub s_apb_psel: Signal<In, Bit>,
    /// Enable: the access phase.
    pub s_apb_penable: Signal<In, Bit>,
    /// Direction: 1 = write.
    pub s_apb_pwrite: Signal<In, Bit>,
    /// Byte address; `[1:0]` are ignored (word registers).
    pub s_apb_paddr: Signal<In, Bits<A>>,
    /// Write data.
    pub s_apb_pwdata: Signal<In, Bits<32>>,
    /// Write strobes, lane i = `pwdata[8i+7:8i]` (APB3: tie to `4'b1111`).
    pub s_apb_pstrb: Signal<In, Bits<4>>,
    // ---- APB slave (to the master) ----
    /// Read data, valid with `pready`, else 0.
    pub s_apb_prdata: Signal<Out, Bits<32>>,
    /// Ready: 1 in the second clock of every access phase.
    pub s_apb_pready: Signal<Out, Bit>,
    /// Slave error with `pready`: the access was refused (`INT_STATUS.illegal`).
    pub s_apb_pslverr: Signal<Out, Bit>,
    // ---- register port (to the register block) ----
    /// Wishbone cycle and strobe: the access phase.
    pub wb_cyc_o: Signal<Out, Bit>,
    /// Write enable.
    pub wb_we_o: Signal<Out, Bit>,
    /// Word index (`paddr[A-1:2]`).
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
}

impl<const A: usize, const W: usize> Logic for ApbBridge<A, W> {
    #[hdl_gen]
    fn update(&mut self) {
        self.wb_cyc_o.next = self.s_apb_psel.val() & self.s_apb_penable.val();
        self.wb_we_o.next = self.s_apb_pwrite.val();
        self.wb_adr_o.next = self.s_apb_paddr.val().get_bits::<W>(2);
        self.wb_dat_o.next = self.s_apb_pwdata.val();
        self.wb_sel_o.next = self.s_apb_pstrb.val();
        self.s_apb_prdata.next = self.wb_dat_i.val();
        self.s_apb_pready.next = self.wb_ack_i.val() | self.wb_err_i.val();
        self.s_apb_pslverr.next = self.wb_err_i.val();
    }
}
