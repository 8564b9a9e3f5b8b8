//! Reception of the DMR connection service (DMR contract §7): a received frame
//! with `ide = 0`, `rtr = 0`, `dlc = 0` and identifier `cs_id_dcl` or `cs_id_rcl`
//! is a CS frame; on line L the identifier `cs_id[L]` counts good, the other
//! line's counts bad (miswiring), in `DMR_CS_COUNT` (saturating, cleared only by
//! `rst`). A CS frame raises no `RX` and never reaches the RX path; every other
//! frame is delivered to both.
//!
//! The detection of each line is a block of its own ([`CsDetect`]), apart from the
//! counts that `run` gates: in one `always` block, `run` would reach `deliver_*`
//! through the shared detection signals, and Verilator would see a combinational
//! loop through the DMR control (which drives `run` and reads `deliver_*`) and
//! evaluate both blocks again until they settle, at every clock.

use super::sat_count::SatCount8;
use rust_hdl::prelude::*;

/// CS frame detection and the four CS counts.
#[derive(LogicBlock, Default)]
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
    // ---- detection ----
    /// The DCL's frames (own identifier `cs_id_dcl`).
    pub detect_dcl: CsDetect,
    /// The RCL's frames (own identifier `cs_id_rcl`).
    pub detect_rcl: CsDetect,
}

impl Logic for DmrCsRx {
    #[hdl_gen]
    fn update(&mut self) {
        self.dcl_good.clk.next = self.clk.val();
        self.dcl_bad.clk.next = self.clk.val();
        self.rcl_good.clk.next = self.clk.val();
        self.rcl_bad.clk.next = self.clk.val();
        self.detect_dcl.rx_valid.next = self.rx_valid_dcl.val();
        self.detect_dcl.rx_ide.next = self.rx_ide_dcl.val();
        self.detect_dcl.rx_rtr.next = self.rx_rtr_dcl.val();
        self.detect_dcl.rx_dlc.next = self.rx_dlc_dcl.val();
        self.detect_dcl.rx_id.next = self.rx_id_dcl.val();
        self.detect_dcl.cs_id_own.next = self.cs_id_dcl.val();
        self.detect_dcl.cs_id_other.next = self.cs_id_rcl.val();
        self.detect_rcl.rx_valid.next = self.rx_valid_rcl.val();
        self.detect_rcl.rx_ide.next = self.rx_ide_rcl.val();
        self.detect_rcl.rx_rtr.next = self.rx_rtr_rcl.val();
        self.detect_rcl.rx_dlc.next = self.rx_dlc_rcl.val();
        self.detect_rcl.rx_id.next = self.rx_id_rcl.val();
        self.detect_rcl.cs_id_own.next = self.cs_id_rcl.val();
        self.detect_rcl.cs_id_other.next = self.cs_id_dcl.val();
        // Good: the line's own identifier; bad: the other line's (miswiring).
        self.dcl_good.inc.next = self.run.val() & self.detect_dcl.good.val();
        self.dcl_bad.inc.next = self.run.val() & self.detect_dcl.bad.val();
        self.rcl_good.inc.next = self.run.val() & self.detect_rcl.good.val();
        self.rcl_bad.inc.next = self.run.val() & self.detect_rcl.bad.val();
        self.dcl_good.rst.next = self.rst.val();
        self.dcl_bad.rst.next = self.rst.val();
        self.rcl_good.rst.next = self.rst.val();
        self.rcl_bad.rst.next = self.rst.val();
        // not gated by `run` here: the control gates it (a combinational path from
        // `run` through this block would close a false loop in the top for Verilator)
        self.deliver_dcl.next = self.detect_dcl.deliver.val();
        self.deliver_rcl.next = self.detect_rcl.deliver.val();
        self.cs_count_word.next = bit_cast::<32, 8>(self.dcl_good.count.val())
            | (bit_cast::<32, 8>(self.dcl_bad.count.val()) << 8)
            | (bit_cast::<32, 8>(self.rcl_good.count.val()) << 16)
            | (bit_cast::<32, 8>(self.rcl_bad.count.val()) << 24);
    }
}

/// CS frame detection on one line (DMR contract §7), combinational: the received
/// frame is a CS frame with the line's own identifier (good), with the other
/// line's only (bad), or no CS frame at all (delivered).
#[derive(LogicBlock)]
pub struct CsDetect {
    // ---- configuration ----
    /// The line's own CS identifier (`cs_id_dcl` on the DCL, `cs_id_rcl` on the RCL).
    pub cs_id_own: Signal<In, Bits<11>>,
    /// The other line's CS identifier.
    pub cs_id_other: Signal<In, Bits<11>>,
    // ---- the line's received frame ----
    /// `rx_valid`: a frame received at this edge.
    pub rx_valid: Signal<In, Bit>,
    /// `rx_ide`.
    pub rx_ide: Signal<In, Bit>,
    /// `rx_rtr`.
    pub rx_rtr: Signal<In, Bit>,
    /// `rx_dlc`.
    pub rx_dlc: Signal<In, Bits<4>>,
    /// `rx_id[10:0]` (a base frame's `rx_id[28:11]` read 0).
    pub rx_id: Signal<In, Bits<11>>,
    // ---- outputs ----
    /// A CS frame with the line's own identifier: counts good.
    pub good: Signal<Out, Bit>,
    /// A CS frame with the other line's identifier only: counts bad.
    pub bad: Signal<Out, Bit>,
    /// A frame that is not a CS frame: `RX` and the RX path.
    pub deliver: Signal<Out, Bit>,
    // ---- internals ----
    base: Signal<Local, Bit>,
    id_own: Signal<Local, Bit>,
    id_other: Signal<Local, Bit>,
    zero4: Constant<Bits<4>>,
}

impl Default for CsDetect {
    fn default() -> Self {
        Self {
            cs_id_own: Default::default(),
            cs_id_other: Default::default(),
            rx_valid: Default::default(),
            rx_ide: Default::default(),
            rx_rtr: Default::default(),
            rx_dlc: Default::default(),
            rx_id: Default::default(),
            good: Default::default(),
            bad: Default::default(),
            deliver: Default::default(),
            base: Default::default(),
            id_own: Default::default(),
            id_other: Default::default(),
            zero4: Constant::new(0.into()),
        }
    }
}

impl Logic for CsDetect {
    #[hdl_gen]
    fn update(&mut self) {
        // §7 a CS frame: base data frame, DLC 0, one of the two CS identifiers
        // (timing contract: only rx_id[10:0] compare).
        self.base.next = self.rx_valid.val()
            & !self.rx_ide.val()
            & !self.rx_rtr.val()
            & (self.rx_dlc.val() == self.zero4.val());
        self.id_own.next = self.rx_id.val() == self.cs_id_own.val();
        self.id_other.next = self.rx_id.val() == self.cs_id_other.val();
        self.good.next = self.base.val() & self.id_own.val();
        self.bad.next = self.base.val() & self.id_other.val() & !self.id_own.val();
        self.deliver.next =
            self.rx_valid.val() & !(self.base.val() & (self.id_own.val() | self.id_other.val()));
    }
}
