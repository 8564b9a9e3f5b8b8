//! Reception of the DMR connection service (DMR contract §7): a received frame
//! with `ide = 0`, `rtr = 0`, `dlc = 0` and identifier `cs_id_dcl` or `cs_id_rcl`
//! is a CS frame; on line L the identifier `cs_id[L]` counts good, the other
//! line's counts bad (miswiring), in `DMR_CS_COUNT` (saturating, cleared only by
//! `rst`). A CS frame raises no `RX` and never reaches the RX path; every other
//! frame is delivered to both.

use super::sat_count::SatCount8;
use rust_hdl::prelude::*;

/// CS frame detection and the four CS counts.
#[derive(LogicBlock)]
pub struct DmrCsRx {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// The DRCC `rst`: the counts to 0.
    pub rst: Signal<In, Bit>,
    /// The DMR function runs (CS frames count only then).
    pub run: Signal<In, Bit>,
    // ---- configuration ----
    /// `DMR_CS.cs_id_dcl`.
    pub cs_id_dcl: Signal<In, Bits<11>>,
    /// `DMR_CS.cs_id_rcl`.
    pub cs_id_rcl: Signal<In, Bits<11>>,
    // ---- the DCL channel's received frame ----
    /// `rx_valid`.
    pub rx_valid_dcl: Signal<In, Bit>,
    /// `rx_ide`.
    pub rx_ide_dcl: Signal<In, Bit>,
    /// `rx_rtr`.
    pub rx_rtr_dcl: Signal<In, Bit>,
    /// `rx_dlc`.
    pub rx_dlc_dcl: Signal<In, Bits<4>>,
    /// `rx_id[10:0]` (a base frame's `rx_id[28:11]` read 0).
    pub rx_id_dcl: Signal<In, Bits<11>>,
    // ---- the RCL channel's received frame ----
    /// `rx_valid`.
    pub rx_valid_rcl: Signal<In, Bit>,
    /// `rx_ide`.
    pub rx_ide_rcl: Signal<In, Bit>,
    /// `rx_rtr`.
    pub rx_rtr_rcl: Signal<In, Bit>,
    /// `rx_dlc`.
    pub rx_dlc_rcl: Signal<In, Bits<4>>,
    /// `rx_id[10:0]`.
    pub rx_id_rcl: Signal<In, Bits<11>>,
    // ---- outputs ----
    /// A DCL frame that is not a CS frame: `RX(DCL)` and the RX path (combinational).
    pub deliver_dcl: Signal<Out, Bit>,
    /// An RCL frame that is not a CS frame (combinational).
    pub deliver_rcl: Signal<Out, Bit>,
    /// `DMR_CS_COUNT`: [7:0] DCL good, [15:8] DCL bad, [23:16] RCL good, [31:24] RCL bad.
    pub cs_count_word: Signal<Out, Bits<32>>,
    // ---- counts ----
    /// DCL good.
    pub dcl_good: SatCount8,
    /// DCL bad.
    pub dcl_bad: SatCount8,
    /// RCL good.
    pub rcl_good: SatCount8,
    /// RCL bad.
    pub rcl_bad: SatCount8,
    // ---- internals ----
    base_dcl: Signal<Local, Bit>,
    base_rcl: Signal<Local, Bit>,
    dcl_id_dcl: Signal<Local, Bit>,
    dcl_id_rcl: Signal<Local, Bit>,
    rcl_id_dcl: Signal<Local, Bit>,
    rcl_id_rcl: Signal<Local, Bit>,
    cs_dcl: Signal<Local, Bit>,
    cs_rcl: Signal<Local, Bit>,
    zero4: Constant<Bits<4>>,
}

impl Default for DmrCsRx {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            run: Default::default(),
            cs_id_dcl: Default::default(),
            cs_id_rcl: Default::default(),
            rx_valid_dcl: Default::default(),
            rx_ide_dcl: Default::default(),
            rx_rtr_dcl: Default::default(),
            rx_dlc_dcl: Default::default(),
            rx_id_dcl: Default::default(),
            rx_valid_rcl: Default::default(),
            rx_ide_rcl: Default::default(),
            rx_rtr_rcl: Default::default(),
            rx_dlc_rcl: Default::default(),
            rx_id_rcl: Default::default(),
            deliver_dcl: Default::default(),
            deliver_rcl: Default::default(),
            cs_count_word: Default::default(),
            dcl_good: Default::default(),
            dcl_bad: Default::default(),
            rcl_good: Default::default(),
            rcl_bad: Default::default(),
            base_dcl: Default::default(),
            base_rcl: Default::default(),
            dcl_id_dcl: Default::default(),
            dcl_id_rcl: Default::default(),
            rcl_id_dcl: Default::default(),
            rcl_id_rcl: Default::default(),
            cs_dcl: Default::default(),
            cs_rcl: Default::default(),
            zero4: Constant::new(0.into()),
        }
    }
}

impl Logic for DmrCsRx {
    #[hdl_gen]
    fn update(&mut self) {
        self.dcl_good.clk.next = self.clk.val();
        self.dcl_bad.clk.next = self.clk.val();
        self.rcl_good.clk.next = self.clk.val();
        self.rcl_bad.clk.next = self.clk.val();
        // §7 a CS frame: base data frame, DLC 0, one of the two CS identifiers
        // (a base frame's rx_id[28:11] read 0, timing contract: only [10:0] compare).
        self.base_dcl.next = self.rx_valid_dcl.val()
            & !self.rx_ide_dcl.val()
            & !self.rx_rtr_dcl.val()
            & (self.rx_dlc_dcl.val() == self.zero4.val());
        self.dcl_id_dcl.next = self.rx_id_dcl.val() == self.cs_id_dcl.val();
        self.dcl_id_rcl.next = self.rx_id_dcl.val() == self.cs_id_rcl.val();
        self.cs_dcl.next = self.base_dcl.val() & (self.dcl_id_dcl.val() | self.dcl_id_rcl.val());
        self.base_rcl.next = self.rx_valid_rcl.val()
            & !self.rx_ide_rcl.val()
            & !self.rx_rtr_rcl.val()
            & (self.rx_dlc_rcl.val() == self.zero4.val());
        self.rcl_id_dcl.next = self.rx_id_rcl.val() == self.cs_id_dcl.val();
        self.rcl_id_rcl.next = self.rx_id_rcl.val() == self.cs_id_rcl.val();
        self.cs_rcl.next = self.base_rcl.val() & (self.rcl_id_dcl.val() | self.rcl_id_rcl.val());
        // Good: the line's own identifier; bad: the other line's (miswiring).
        self.dcl_good.inc.next = self.run.val() & self.cs_dcl.val() & self.dcl_id_dcl.val();
        self.dcl_bad.inc.next = self.run.val() & self.cs_dcl.val() & !self.dcl_id_dcl.val();
        self.rcl_good.inc.next = self.run.val() & self.cs_rcl.val() & self.rcl_id_rcl.val();
        self.rcl_bad.inc.next = self.run.val() & self.cs_rcl.val() & !self.rcl_id_rcl.val();
        self.dcl_good.rst.next = self.rst.val();
        self.dcl_bad.rst.next = self.rst.val();
        self.rcl_good.rst.next = self.rst.val();
        self.rcl_bad.rst.next = self.rst.val();
        // not gated by `run` here: the control gates it (a combinational path from
        // `run` through this block would close a false loop in the top for Verilator)
        self.deliver_dcl.next = self.rx_valid_dcl.val() & !self.cs_dcl.val();
        self.deliver_rcl.next = self.rx_valid_rcl.val() & !self.cs_rcl.val();
        self.cs_count_word.next = bit_cast::<32, 8>(self.dcl_good.count.val())
            | (bit_cast::<32, 8>(self.dcl_bad.count.val()) << 8)
            | (bit_cast::<32, 8>(self.rcl_good.count.val()) << 16)
            | (bit_cast::<32, 8>(self.rcl_bad.count.val()) << 24);
    }
}
