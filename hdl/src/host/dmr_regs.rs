//! The DMR registers of the DRCC (word indices 25..35; DMR contract §2): the
//! CiA 701 configuration (`DMR_CFG`, `DMR_TIME`, `DMR_CS`), the mailbox window
//! (`MB_SEL`, `MB_ID`, `MB_MASK`, `MB_CFG`, `MB_STATE`) and the read side of the
//! DMR status words. It sits beside the register block (`super::wishbone`),
//! which hands it every taken write and merges its read word and verdict.
//!
//! The refusals of contract §2.2 are decided here, on the values before the
//! write edge: a zero timeout, tick or recovery delay; an enabled mailbox with
//! limit 0; equal connection-service identifiers, or new ones while a mailbox
//! is enabled; a mailbox identifier equal to a connection-service identifier;
//! `MB_SEL` beyond the generated mailboxes; any cfg register outside reset mode.
//! Field positions are fixed here and checked against the table (`placed`).

use super::map::placed;
use super::registers::{self as map, MAP};
use rust_hdl::prelude::*;

/// `limit` slot width in `mb_limits` (7 bits used).
const SLOT: usize = 8;

/// The DMR registers.
#[derive(LogicBlock)]
pub struct DmrRegs {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register to its table reset value.
    pub rst: Signal<In, Bit>,
    // ---- register decoder ----
    /// A Wishbone write is taken at this edge (any address).
    pub wr: Signal<In, Bit>,
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// `CTRL.reset_mode`: cfg registers are writable, the mailbox memory readable.
    pub reset_mode: Signal<In, Bit>,
    /// `adr` is one of the DMR registers (25..35): `word` is its value.
    pub hit: Signal<Out, Bit>,
    /// The addressed DMR register's value.
    pub word: Signal<Out, Bits<32>>,
    /// `adr` is a writable DMR register (the others are read only).
    pub writable: Signal<Out, Bit>,
    /// The write at this edge is refused (§2.2): `INT_STATUS.illegal`.
    pub illegal: Signal<Out, Bit>,
    // ---- status words in (the DMR function) ----
    /// `DMR_STATUS`.
    pub status_word: Signal<In, Bits<32>>,
    /// `DMR_CS_COUNT`.
    pub cs_count_word: Signal<In, Bits<32>>,
    /// `DMR_RX_STATS`.
    pub rx_stats_word: Signal<In, Bits<32>>,
    /// `MB_STATE` of mailbox `mb_sel`.
    pub mb_state_word: Signal<In, Bits<32>>,
    // ---- the selected mailbox's stored identifier and mask (memory read data) ----
    /// `MB_ID` of mailbox `mb_sel` ([30] dir, [29] ide, [28:0] id); valid in
    /// reset mode, where the memory is read at `mb_sel`.
    pub mb_id_word: Signal<In, Bits<31>>,
    /// `MB_MASK` of mailbox `mb_sel`; valid in reset mode.
    pub mb_mask: Signal<In, Bits<29>>,
    // ---- configuration out ----
    /// `DMR_CFG.timeout`: mailbox and CS timeout, DMR ticks (never 0).
    pub timeout: Signal<Out, Bits<16>>,
    /// `DMR_CFG.cs_period`: DMR ticks between periodic CS frames, 0 = none.
    pub cs_period: Signal<Out, Bits<16>>,
    /// `DMR_TIME.tick_bits`: nominal bit times per DMR tick (never 0).
    pub tick_bits: Signal<Out, Bits<16>>,
    /// `DMR_TIME.recovery_delay`: DMR ticks (never 0).
    pub recovery_delay: Signal<Out, Bits<16>>,
    /// `DMR_CS.cs_id_dcl`: base identifier of the CS frame on the DCL.
    pub cs_id_dcl: Signal<Out, Bits<11>>,
    /// `DMR_CS.cs_id_rcl`: base identifier of the CS frame on the RCL.
    pub cs_id_rcl: Signal<Out, Bits<11>>,
    /// `MB_SEL`: the mailbox of the window registers.
    pub mb_sel: Signal<Out, Bits<4>>,
    /// `MB_CFG.enable` of every mailbox, bit i = mailbox i.
    pub mb_enable: Signal<Out, Bits<16>>,
    /// `MB_CFG.limit` of every mailbox, mailbox i in `[8i+6:8i]`.
    pub mb_limits: Signal<Out, Bits<128>>,
    // ---- mailbox memory writes (address `mb_sel`, data `wdat`) ----
    /// Write `MB_ID` ([30:0] of `wdat`) at this edge.
    pub mb_we_id: Signal<Out, Bit>,
    /// Write `MB_MASK` ([28:0] of `wdat`) at this edge.
    pub mb_we_mask: Signal<Out, Bit>,
    // ---- registers ----
    cfg_q: DFF<Bits<32>>,
    time_q: DFF<Bits<32>>,
    cs_dcl_q: DFF<Bits<11>>,
    cs_rcl_q: DFF<Bits<11>>,
    sel_q: DFF<Bits<4>>,
    enable_q: DFF<Bits<16>>,
    limits_q: DFF<Bits<128>>,
    // ---- internals ----
    shift: Signal<Local, Bits<8>>,
    sel_enabled: Signal<Local, Bit>,
    limits_at_sel: Signal<Local, Bits<128>>,
    sel_limit: Signal<Local, Bits<7>>,
    wr_is_cs: Signal<Local, Bit>,
    stored_is_cs: Signal<Local, Bit>,
    // ---- constants (indices, reset values) ----
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
    mailboxes: Constant<Bits<5>>,
    cfg_reset: Constant<Bits<32>>,
    time_reset: Constant<Bits<32>>,
    cs_dcl_reset: Constant<Bits<11>>,
    cs_rcl_reset: Constant<Bits<11>>,
    limits_reset: Constant<Bits<128>>,
    slot_mask: Constant<Bits<128>>,
    zero4: Constant<Bits<4>>,
    zero7: Constant<Bits<7>>,
    zero16: Constant<Bits<16>>,
    zero32: Constant<Bits<32>>,
}

impl DmrRegs {
    /// The registers of a DRCC generated with `mailboxes` DMR mailboxes (0..16).
    pub fn new(mailboxes: u32) -> Self {
        assert!(mailboxes <= 16, "at most 16 DMR mailboxes (MB_SEL is 4 bits)");
        for (reg, field, lsb, width) in [
            ("DMR_CFG", "timeout", 0, 16),
            ("DMR_CFG", "cs_period", 16, 16),
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
        let reset = |r: &str| Constant::new((map::register(r).unwrap().reset_value() as u64).into());
        let field = |r: &str, f: &str| MAP.field(r, f).reset as u64;
        let limit = field("MB_CFG", "limit");
        let mut limits = Bits::<128>::default();
        let mut slot = Bits::<128>::default();
        for i in 0..SLOT {
            slot = slot.replace_bit(i, true);
        }
        for i in 0..16 {
            for b in 0..7 {
                limits = limits.replace_bit(i * SLOT + b, limit & (1 << b) != 0);
            }
        }
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            adr: Default::default(),
            wdat: Default::default(),
            reset_mode: Default::default(),
            hit: Default::default(),
            word: Default::default(),
            writable: Default::default(),
            illegal: Default::default(),
            status_word: Default::default(),
            cs_count_word: Default::default(),
            rx_stats_word: Default::default(),
            mb_state_word: Default::default(),
            mb_id_word: Default::default(),
            mb_mask: Default::default(),
            timeout: Default::default(),
            cs_period: Default::default(),
            tick_bits: Default::default(),
            recovery_delay: Default::default(),
            cs_id_dcl: Default::default(),
            cs_id_rcl: Default::default(),
            mb_sel: Default::default(),
            mb_enable: Default::default(),
            mb_limits: Default::default(),
            mb_we_id: Default::default(),
            mb_we_mask: Default::default(),
            cfg_q: Default::default(),
            time_q: Default::default(),
            cs_dcl_q: Default::default(),
            cs_rcl_q: Default::default(),
            sel_q: Default::default(),
            enable_q: Default::default(),
            limits_q: Default::default(),
            shift: Default::default(),
            sel_enabled: Default::default(),
            limits_at_sel: Default::default(),
            sel_limit: Default::default(),
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
            mailboxes: Constant::new((mailboxes as u64).into()),
            cfg_reset: reset("DMR_CFG"),
            time_reset: reset("DMR_TIME"),
            cs_dcl_reset: Constant::new(field("DMR_CS", "cs_id_dcl").into()),
            cs_rcl_reset: Constant::new(field("DMR_CS", "cs_id_rcl").into()),
            limits_reset: Constant::new(limits),
            slot_mask: Constant::new(slot),
            zero4: Constant::new(0.into()),
            zero7: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl Default for DmrRegs {
    fn default() -> Self {
        Self::new(super::dmr_registers::MAILBOXES)
    }
}

impl Logic for DmrRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, cfg_q, time_q, cs_dcl_q, cs_rcl_q, sel_q, enable_q, limits_q);
        // ---- the selected mailbox ----
        self.shift.next = bit_cast::<8, 4>(self.sel_q.q.val()) << 3;
        self.sel_enabled.next = self.enable_q.q.val().get_bit(self.sel_q.q.val().index());
        self.limits_at_sel.next = self.limits_q.q.val() >> self.shift.val();
        self.sel_limit.next = self.limits_at_sel.val().get_bits::<7>(0);
        // a base identifier equal to a CS identifier (§2.2): the written MB_ID, and
        // the stored one (memory read data at mb_sel, valid in reset mode)
        self.wr_is_cs.next = !self.wdat.val().get_bit(29)
            & ((self.wdat.val().get_bits::<11>(0) == self.cs_dcl_q.q.val())
                | (self.wdat.val().get_bits::<11>(0) == self.cs_rcl_q.q.val()));
        self.stored_is_cs.next = !self.mb_id_word.val().get_bit(29)
            & ((self.mb_id_word.val().get_bits::<11>(0) == self.cs_dcl_q.q.val())
                | (self.mb_id_word.val().get_bits::<11>(0) == self.cs_rcl_q.q.val()));

        // ---- reads (§2.1): the mailbox configuration only in reset mode ----
        self.hit.next = true;
        self.writable.next = true;
        self.word.next = self.zero32.val();
        if self.adr.val() == self.a_cfg.val() {
            self.word.next = self.cfg_q.q.val();
        } else if self.adr.val() == self.a_time.val() {
            self.word.next = self.time_q.q.val();
        } else if self.adr.val() == self.a_cs.val() {
            self.word.next = bit_cast::<32, 11>(self.cs_dcl_q.q.val())
                | (bit_cast::<32, 11>(self.cs_rcl_q.q.val()) << 16);
        } else if self.adr.val() == self.a_sel.val() {
            self.word.next = bit_cast::<32, 4>(self.sel_q.q.val());
        } else if self.adr.val() == self.a_id.val() {
            if self.reset_mode.val() {
                self.word.next = bit_cast::<32, 31>(self.mb_id_word.val());
            }
        } else if self.adr.val() == self.a_mask.val() {
            if self.reset_mode.val() {
                self.word.next = bit_cast::<32, 29>(self.mb_mask.val());
            }
        } else if self.adr.val() == self.a_mbcfg.val() {
            if self.reset_mode.val() {
                self.word.next = bit_cast::<32, 7>(self.sel_limit.val())
                    | (bit_cast::<32, 1>(self.sel_enabled.val().into()) << 31);
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
            self.word.next = self.mb_state_word.val();
        } else {
            self.hit.next = false;
            self.writable.next = false;
        }

        // ---- writes (§2.2) ----
        self.illegal.next = false;
        self.mb_we_id.next = false;
        self.mb_we_mask.next = false;
        if self.wr.val() & self.writable.val() {
            if self.adr.val() == self.a_sel.val() {
                // not a cfg register: a mailbox can be watched while running
                if bit_cast::<5, 4>(self.wdat.val().get_bits::<4>(0)) >= self.mailboxes.val() {
                    self.illegal.next = true;
                } else {
                    self.sel_q.d.next = self.wdat.val().get_bits::<4>(0);
                }
            } else if !self.reset_mode.val() {
                self.illegal.next = true;
            } else if self.adr.val() == self.a_cfg.val() {
                if self.wdat.val().get_bits::<16>(0) == self.zero16.val() {
                    self.illegal.next = true;
                } else {
                    self.cfg_q.d.next = self.wdat.val();
                }
            } else if self.adr.val() == self.a_time.val() {
                if (self.wdat.val().get_bits::<16>(0) == self.zero16.val())
                    | (self.wdat.val().get_bits::<16>(16) == self.zero16.val())
                {
                    self.illegal.next = true;
                } else {
                    self.time_q.d.next = self.wdat.val();
                }
            } else if self.adr.val() == self.a_cs.val() {
                if (self.wdat.val().get_bits::<11>(0) == self.wdat.val().get_bits::<11>(16))
                    | self.enable_q.q.val().any()
                {
                    self.illegal.next = true;
                } else {
                    self.cs_dcl_q.d.next = self.wdat.val().get_bits::<11>(0);
                    self.cs_rcl_q.d.next = self.wdat.val().get_bits::<11>(16);
                }
            } else if self.adr.val() == self.a_id.val() {
                if self.sel_enabled.val() & self.wr_is_cs.val() {
                    self.illegal.next = true;
                } else {
                    self.mb_we_id.next = true;
                }
            } else if self.adr.val() == self.a_mask.val() {
                self.mb_we_mask.next = true;
            } else if self.adr.val() == self.a_mbcfg.val() {
                if self.wdat.val().get_bit(31)
                    & ((self.wdat.val().get_bits::<7>(0) == self.zero7.val())
                        | self.stored_is_cs.val())
                {
                    self.illegal.next = true;
                } else {
                    self.enable_q.d.next = self
                        .enable_q
                        .q
                        .val()
                        .replace_bit(self.sel_q.q.val().index(), self.wdat.val().get_bit(31));
                    self.limits_q.d.next = (self.limits_q.q.val()
                        & !(self.slot_mask.val() << self.shift.val()))
                        | (bit_cast::<128, 7>(self.wdat.val().get_bits::<7>(0)) << self.shift.val());
                }
            }
        }
        if self.rst.val() {
            self.cfg_q.d.next = self.cfg_reset.val();
            self.time_q.d.next = self.time_reset.val();
            self.cs_dcl_q.d.next = self.cs_dcl_reset.val();
            self.cs_rcl_q.d.next = self.cs_rcl_reset.val();
            self.sel_q.d.next = self.zero4.val();
            self.enable_q.d.next = self.zero16.val();
            self.limits_q.d.next = self.limits_reset.val();
            self.mb_we_id.next = false;
            self.mb_we_mask.next = false;
        }

        // ---- outputs ----
        self.timeout.next = self.cfg_q.q.val().get_bits::<16>(0);
        self.cs_period.next = self.cfg_q.q.val().get_bits::<16>(16);
        self.tick_bits.next = self.time_q.q.val().get_bits::<16>(0);
        self.recovery_delay.next = self.time_q.q.val().get_bits::<16>(16);
        self.cs_id_dcl.next = self.cs_dcl_q.q.val();
        self.cs_id_rcl.next = self.cs_rcl_q.q.val();
        self.mb_sel.next = self.sel_q.q.val();
        self.mb_enable.next = self.enable_q.q.val();
        self.mb_limits.next = self.limits_q.q.val();
    }
}

#[test]
fn dmr_regs_synthesizes() {
    let mut uut = DmrRegs::default();
    uut.connect_all();
    let v = generate_verilog(&uut);
    std::fs::write("/tmp/dmr_regs.v", &v).unwrap();
    yosys_validate("dmr_regs", &v).unwrap();
}
