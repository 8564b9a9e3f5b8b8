//! The decode, the read side and the refusals of the DMR registers (word indices
//! 25..35; DMR contract §2), combinational on the bus address and data and on
//! the stored values, so that no always block both takes a write and flags it
//! (`super::dmr_regs` takes the write; the register block merges `word` and
//! `illegal`). Refused (§2.2), on the values before the write edge: a zero
//! timeout, tick or recovery delay; an enabled mailbox with limit 0; equal
//! connection-service identifiers, or new ones while a mailbox is enabled; a
//! mailbox identifier equal to a connection-service identifier; `MB_SEL` beyond
//! the generated mailboxes; any cfg register outside reset mode; with `M = 0`
//! every window write. `MB_ID`, `MB_MASK` and `MB_CFG` read 0 outside reset mode
//! (§2.1), and the window reads 0 with `M = 0`. In a configuration without the
//! DMR function (drcc_contract.md §1.1) no DMR register is writable: every write
//! is refused and they keep their reset values.

use super::map::placed;
use super::registers::{self as map, MAP};
use crate::channel::sized::Param;
use rust_hdl::prelude::*;

/// Decode, reads and refusals of the DMR registers of a DRCC with `M` mailboxes.
#[derive(LogicBlock)]
pub struct DmrCheck<const M: usize> {
    // ---- the access ----
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data on the bus.
    pub wdat: Signal<In, Bits<32>>,
    /// `CTRL.reset_mode`.
    pub reset_mode: Signal<In, Bit>,
    // ---- stored values (super::dmr_regs) ----
    /// `DMR_CFG`.
    pub cfg_word: Signal<In, Bits<32>>,
    /// `DMR_TIME`.
    pub time_word: Signal<In, Bits<32>>,
    /// `DMR_CS.cs_id_dcl`.
    pub cs_id_dcl: Signal<In, Bits<11>>,
    /// `DMR_CS.cs_id_rcl`.
    pub cs_id_rcl: Signal<In, Bits<11>>,
    /// `MB_SEL`.
    pub mb_sel: Signal<In, Bits<4>>,
    /// `MB_CFG.enable` of every mailbox.
    pub mb_enable: Signal<In, Bits<16>>,
    /// `MB_CFG.limit` of every mailbox, mailbox i in `[8i+6:8i]`.
    pub mb_limits: Signal<In, Bits<128>>,
    /// `MB_ID` of mailbox `mb_sel` (memory read data; valid in reset mode).
    pub mb_id_word: Signal<In, Bits<31>>,
    /// `MB_MASK` of mailbox `mb_sel` (valid in reset mode).
    pub mb_mask: Signal<In, Bits<29>>,
    // ---- status words (the DMR function) ----
    /// `DMR_STATUS`.
    pub status_word: Signal<In, Bits<32>>,
    /// `DMR_CS_COUNT`.
    pub cs_count_word: Signal<In, Bits<32>>,
    /// `DMR_RX_STATS`.
    pub rx_stats_word: Signal<In, Bits<32>>,
    /// `MB_STATE` of mailbox `mb_sel`.
    pub mb_state_word: Signal<In, Bits<32>>,
    // ---- verdict ----
    /// `adr` is one of the DMR registers: `word` is its value.
    pub hit: Signal<Out, Bit>,
    /// The addressed DMR register's value.
    pub word: Signal<Out, Bits<32>>,
    /// `adr` is a writable DMR register.
    pub writable: Signal<Out, Bit>,
    /// A write of `wdat` to `adr` now is refused (§2.2).
    pub illegal: Signal<Out, Bit>,
    // ---- internals ----
    sel_enabled: Signal<Local, Bit>,
    sel_limit: Signal<Local, Bits<7>>,
    sel_enable_word: Signal<Local, Bits<32>>,
    wr_is_cs: Signal<Local, Bit>,
    stored_is_cs: Signal<Local, Bit>,
    a_cfg: Constant<Bits<6>>,
    a_time: Constant<Bits<6>>,
    a_cs: Constant<Bits<6>>,
    a_status: Constant<Bits<6>>,
    a_cs_count: Constant<Bits<6>>,
    a_rx_stats: Constant<Bits<6>>,
    a_sel: Constant<Bits<6>>,
    a_id: Constant<Bits<6>>,
    a_mask: Constant<Bits<6>>,
    a_mbcfg: Constant<Bits<6>>,
    a_state: Constant<Bits<6>>,
    /// Bit i set for every generated mailbox i < M (`MB_SEL` indices taken).
    mailbox_mask: Constant<Bits<16>>,
    no_mailboxes: Constant<Bit>,
    enable_bit: Constant<Bits<32>>,
    zero7: Constant<Bits<7>>,
    zero16: Constant<Bits<16>>,
    zero32: Constant<Bits<32>>,
    /// The configuration has the CiA 701 DMR function (generation parameter).
    pub(crate) dmr_present: Param<1, 1>,
}

impl<const M: usize> DmrCheck<M> {
    /// The checks of a DRCC generated with `M` DMR mailboxes (0..16).
    pub fn new() -> Self {
        let mailboxes = M as u32;
        assert!(
            mailboxes <= 16,
            "at most 16 DMR mailboxes (MB_SEL is 4 bits)"
        );
        // the positions this block fixes structurally
        for (reg, field, lsb, width) in [
            ("DMR_CFG", "timeout", 0, 16),
            ("DMR_TIME", "tick_bits", 0, 16),
            ("DMR_TIME", "recovery_delay", 16, 16),
            ("DMR_CS", "cs_id_dcl", 0, 11),
            ("DMR_CS", "cs_id_rcl", 16, 11),
            ("MB_SEL", "index", 0, 4),
            ("MB_ID", "id", 0, 29),
            ("MB_ID", "ide", 29, 1),
            ("MB_ID", "dir", 30, 1),
            ("MB_MASK", "mask", 0, 29),
            ("MB_CFG", "limit", 0, 7),
            ("MB_CFG", "enable", 31, 1),
        ] {
            placed(&MAP, reg, field, lsb, width);
        }
        let adr = |i: u32| Constant::new((i as u64).into());
        Self {
            adr: Default::default(),
            wdat: Default::default(),
            reset_mode: Default::default(),
            cfg_word: Default::default(),
            time_word: Default::default(),
            cs_id_dcl: Default::default(),
            cs_id_rcl: Default::default(),
            mb_sel: Default::default(),
            mb_enable: Default::default(),
            mb_limits: Default::default(),
            mb_id_word: Default::default(),
            mb_mask: Default::default(),
            status_word: Default::default(),
            cs_count_word: Default::default(),
            rx_stats_word: Default::default(),
            mb_state_word: Default::default(),
            hit: Default::default(),
            word: Default::default(),
            writable: Default::default(),
            illegal: Default::default(),
            sel_enabled: Default::default(),
            sel_limit: Default::default(),
            sel_enable_word: Default::default(),
            wr_is_cs: Default::default(),
            stored_is_cs: Default::default(),
            a_cfg: adr(map::DMR_CFG),
            a_time: adr(map::DMR_TIME),
            a_cs: adr(map::DMR_CS),
            a_status: adr(map::DMR_STATUS),
            a_cs_count: adr(map::DMR_CS_COUNT),
            a_rx_stats: adr(map::DMR_RX_STATS),
            a_sel: adr(map::MB_SEL),
            a_id: adr(map::MB_ID),
            a_mask: adr(map::MB_MASK),
            a_mbcfg: adr(map::MB_CFG),
            a_state: adr(map::MB_STATE),
            mailbox_mask: Constant::new(((1u64 << mailboxes) - 1).into()),
            no_mailboxes: Constant::new(mailboxes == 0),
            enable_bit: Constant::new((1u64 << 31).into()),
            zero7: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
            dmr_present: Default::default(),
        }
    }
}

impl<const M: usize> Default for DmrCheck<M> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const M: usize> Logic for DmrCheck<M> {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- the selected mailbox ----
        self.sel_enabled.next = self.mb_enable.val().get_bit(self.mb_sel.val().index());
        self.sel_limit.next = self
            .mb_limits
            .val()
            .get_bits::<7>(self.mb_sel.val().index() * 8);
        self.sel_enable_word.next = self.zero32.val();
        if self.sel_enabled.val() {
            self.sel_enable_word.next = self.enable_bit.val();
        }
        // a base identifier equal to a CS identifier (§2.2): the written MB_ID,
        // and the stored one (memory read data at mb_sel, valid in reset mode)
        self.wr_is_cs.next = !self.wdat.val().get_bit(29)
            & ((self.wdat.val().get_bits::<11>(0) == self.cs_id_dcl.val())
                | (self.wdat.val().get_bits::<11>(0) == self.cs_id_rcl.val()));
        self.stored_is_cs.next = !self.mb_id_word.val().get_bit(29)
            & ((self.mb_id_word.val().get_bits::<11>(0) == self.cs_id_dcl.val())
                | (self.mb_id_word.val().get_bits::<11>(0) == self.cs_id_rcl.val()));

        // ---- decode and reads (§2.1) ----
        self.hit.next = true;
        self.writable.next = true;
        self.word.next = self.zero32.val();
        if self.adr.val() == self.a_cfg.val() {
            self.word.next = self.cfg_word.val();
        } else if self.adr.val() == self.a_time.val() {
            self.word.next = self.time_word.val();
        } else if self.adr.val() == self.a_cs.val() {
            self.word.next = bit_cast::<32, 11>(self.cs_id_dcl.val())
                | (bit_cast::<32, 11>(self.cs_id_rcl.val()) << 16);
        } else if self.adr.val() == self.a_sel.val() {
            self.word.next = bit_cast::<32, 4>(self.mb_sel.val());
        } else if self.adr.val() == self.a_id.val() {
            if self.reset_mode.val() & !self.no_mailboxes.val() {
                self.word.next = bit_cast::<32, 31>(self.mb_id_word.val());
            }
        } else if self.adr.val() == self.a_mask.val() {
            if self.reset_mode.val() & !self.no_mailboxes.val() {
                self.word.next = bit_cast::<32, 29>(self.mb_mask.val());
            }
        } else if self.adr.val() == self.a_mbcfg.val() {
            if self.reset_mode.val() & !self.no_mailboxes.val() {
                self.word.next =
                    bit_cast::<32, 7>(self.sel_limit.val()) | self.sel_enable_word.val();
            }
        } else if self.adr.val() == self.a_status.val() {
            self.writable.next = false;
            self.word.next = self.status_word.val();
        } else if self.adr.val() == self.a_cs_count.val() {
            self.writable.next = false;
            self.word.next = self.cs_count_word.val();
        } else if self.adr.val() == self.a_rx_stats.val() {
            self.writable.next = false;
            self.word.next = self.rx_stats_word.val();
        } else if self.adr.val() == self.a_state.val() {
            self.writable.next = false;
            if !self.no_mailboxes.val() {
                self.word.next = self.mb_state_word.val();
            }
        } else {
            self.hit.next = false;
            self.writable.next = false;
        }

        // §1.1: without the DMR function its registers take no write (the
        // register block then flags every write to them as illegal)
        if !self.dmr_present.val().any() {
            self.writable.next = false;
        }

        // ---- refusals (§2.2) ----
        self.illegal.next = false;
        if self.adr.val() == self.a_sel.val() {
            // not a cfg register: a mailbox can be watched while the DRCC runs
            // index >= M, as a lookup so that no configuration compares against
            // a constant its range decides (M = 0 and M = 16)
            self.illegal.next = !self
                .mailbox_mask
                .val()
                .get_bit(self.wdat.val().get_bits::<4>(0).index());
        } else if self.writable.val() & !self.reset_mode.val() {
            self.illegal.next = true;
        } else if self.no_mailboxes.val()
            & ((self.adr.val() == self.a_id.val())
                | (self.adr.val() == self.a_mask.val())
                | (self.adr.val() == self.a_mbcfg.val()))
        {
            // M = 0: there is no mailbox for the window to address (§2)
            self.illegal.next = true;
        } else if self.adr.val() == self.a_cfg.val() {
            self.illegal.next = self.wdat.val().get_bits::<16>(0) == self.zero16.val();
        } else if self.adr.val() == self.a_time.val() {
            self.illegal.next = (self.wdat.val().get_bits::<16>(0) == self.zero16.val())
                | (self.wdat.val().get_bits::<16>(16) == self.zero16.val());
        } else if self.adr.val() == self.a_cs.val() {
            self.illegal.next = (self.wdat.val().get_bits::<11>(0)
                == self.wdat.val().get_bits::<11>(16))
                | self.mb_enable.val().any();
        } else if self.adr.val() == self.a_id.val() {
            self.illegal.next = self.sel_enabled.val() & self.wr_is_cs.val();
        } else if self.adr.val() == self.a_mbcfg.val() {
            self.illegal.next = self.wdat.val().get_bit(31)
                & ((self.wdat.val().get_bits::<7>(0) == self.zero7.val())
                    | self.stored_is_cs.val());
        }
    }
}
