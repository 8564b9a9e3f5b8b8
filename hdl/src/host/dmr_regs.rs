//! The storage of the DMR registers (DMR contract §2.1): `DMR_CFG`, `DMR_TIME`,
//! `DMR_CS`, `MB_SEL` and the per-mailbox `MB_CFG` fields (`limit`, `enable`);
//! `MB_ID` and `MB_MASK` go to the mailbox memory (`crate::dmr::mailbox_cfg`) as
//! write strobes. A taken write is stored unless `super::dmr_check` refuses it;
//! reset values come from the table. Generated for `M` mailboxes (0..16): the
//! `limit` and `enable` of a mailbox beyond `M` read 0 on the outputs, so
//! synthesis drops their registers (`MB_SEL` never selects one, `dmr_check`).

use super::registers::{self as map, MAP};
use rust_hdl::prelude::*;

/// `limit` slot width in `mb_limits` (7 bits used).
const SLOT: usize = 8;

/// The DMR registers' storage, for `M` mailboxes.
#[derive(LogicBlock)]
pub struct DmrRegs<const M: usize> {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register to its table reset value.
    pub rst: Signal<In, Bit>,
    // ---- the write ----
    /// A Wishbone write is taken at this edge (any address).
    pub wr: Signal<In, Bit>,
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// `super::dmr_check`: the address is a writable DMR register.
    pub writable: Signal<In, Bit>,
    /// `super::dmr_check`: the write is refused.
    pub refused: Signal<In, Bit>,
    // ---- stored values ----
    /// `DMR_CFG`.
    pub cfg_word: Signal<Out, Bits<32>>,
    /// `DMR_TIME`.
    pub time_word: Signal<Out, Bits<32>>,
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
    /// `MB_CFG.enable` of every mailbox, bit i = mailbox i (0 beyond `M`).
    pub mb_enable: Signal<Out, Bits<16>>,
    /// `MB_CFG.limit` of every mailbox, mailbox i in `[8i+6:8i]` (0 beyond `M`).
    pub mb_limits: Signal<Out, Bits<128>>,
    // ---- mailbox memory writes (address `mb_sel`, data `wdat`) ----
    /// Write `MB_ID` at this edge.
    pub mb_we_id: Signal<Out, Bit>,
    /// Write `MB_MASK` at this edge.
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
    take: Signal<Local, Bit>,
    shift: Signal<Local, Bits<8>>,
    slot_we: Signal<Local, Bits<128>>,
    limit7: Signal<Local, Bits<128>>,
    limit_rep: Signal<Local, Bits<128>>,
    a_cfg: Constant<Bits<6>>,
    a_time: Constant<Bits<6>>,
    a_cs: Constant<Bits<6>>,
    a_sel: Constant<Bits<6>>,
    a_id: Constant<Bits<6>>,
    a_mask: Constant<Bits<6>>,
    a_mbcfg: Constant<Bits<6>>,
    cfg_reset: Constant<Bits<32>>,
    time_reset: Constant<Bits<32>>,
    cs_dcl_reset: Constant<Bits<11>>,
    cs_rcl_reset: Constant<Bits<11>>,
    limits_reset: Constant<Bits<128>>,
    slot_mask: Constant<Bits<128>>,
    present: Constant<Bits<16>>,
    present_limits: Constant<Bits<128>>,
    zero4: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
}

impl<const M: usize> Default for DmrRegs<M> {
    fn default() -> Self {
        let adr = |i: u32| Constant::new((i as u64).into());
        let reset =
            |r: &str| Constant::new((map::register(r).unwrap().reset_value() as u64).into());
        let field = |r: &str, f: &str| MAP.field(r, f).reset as u64;
        let limit = field("MB_CFG", "limit");
        let mut limits = Bits::<128>::default();
        let mut slot = Bits::<128>::default();
        for b in 0..SLOT {
            slot = slot.replace_bit(b, true);
        }
        assert!(M <= 16, "DMR registers: M is 0..16 (MB_SEL is 4 bits)");
        let mut present = Bits::<16>::default();
        let mut present_limits = Bits::<128>::default();
        for i in 0..16 {
            for b in 0..7 {
                limits = limits.replace_bit(i * SLOT + b, limit & (1 << b) != 0);
                present_limits = present_limits.replace_bit(i * SLOT + b, i < M);
            }
            present = present.replace_bit(i, i < M);
        }
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            adr: Default::default(),
            wdat: Default::default(),
            writable: Default::default(),
            refused: Default::default(),
            cfg_word: Default::default(),
            time_word: Default::default(),
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
            take: Default::default(),
            shift: Default::default(),
            slot_we: Default::default(),
            limit7: Default::default(),
            limit_rep: Default::default(),
            a_cfg: adr(map::DMR_CFG),
            a_time: adr(map::DMR_TIME),
            a_cs: adr(map::DMR_CS),
            a_sel: adr(map::MB_SEL),
            a_id: adr(map::MB_ID),
            a_mask: adr(map::MB_MASK),
            a_mbcfg: adr(map::MB_CFG),
            cfg_reset: reset("DMR_CFG"),
            time_reset: reset("DMR_TIME"),
            cs_dcl_reset: Constant::new(field("DMR_CS", "cs_id_dcl").into()),
            cs_rcl_reset: Constant::new(field("DMR_CS", "cs_id_rcl").into()),
            limits_reset: Constant::new(limits),
            slot_mask: Constant::new(slot),
            present: Constant::new(present),
            present_limits: Constant::new(present_limits),
            zero4: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
        }
    }
}

impl<const M: usize> Logic for DmrRegs<M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, cfg_q, time_q, cs_dcl_q, cs_rcl_q, sel_q, enable_q, limits_q);
        self.take.next = self.wr.val() & self.writable.val() & !self.refused.val();
        self.shift.next = bit_cast::<8, 4>(self.sel_q.q.val()) << 3;
        self.slot_we.next = self.slot_mask.val() << self.shift.val();
        self.limit7.next = bit_cast::<128, 7>(self.wdat.val().get_bits::<7>(0));
        self.limit_rep.next = self.limit7.val()
            | (self.limit7.val() << 8)
            | (self.limit7.val() << 16)
            | (self.limit7.val() << 24)
            | (self.limit7.val() << 32)
            | (self.limit7.val() << 40)
            | (self.limit7.val() << 48)
            | (self.limit7.val() << 56)
            | (self.limit7.val() << 64)
            | (self.limit7.val() << 72)
            | (self.limit7.val() << 80)
            | (self.limit7.val() << 88)
            | (self.limit7.val() << 96)
            | (self.limit7.val() << 104)
            | (self.limit7.val() << 112)
            | (self.limit7.val() << 120);
        self.mb_we_id.next = self.take.val() & (self.adr.val() == self.a_id.val());
        self.mb_we_mask.next = self.take.val() & (self.adr.val() == self.a_mask.val());
        if self.take.val() {
            if self.adr.val() == self.a_cfg.val() {
                self.cfg_q.d.next = self.wdat.val();
            } else if self.adr.val() == self.a_time.val() {
                self.time_q.d.next = self.wdat.val();
            } else if self.adr.val() == self.a_cs.val() {
                self.cs_dcl_q.d.next = self.wdat.val().get_bits::<11>(0);
                self.cs_rcl_q.d.next = self.wdat.val().get_bits::<11>(16);
            } else if self.adr.val() == self.a_sel.val() {
                self.sel_q.d.next = self.wdat.val().get_bits::<4>(0);
            } else if self.adr.val() == self.a_mbcfg.val() {
                if self.wdat.val().get_bit(31) {
                    self.enable_q.d.next =
                        self.enable_q.q.val() | (self.one16.val() << self.sel_q.q.val());
                } else {
                    self.enable_q.d.next =
                        self.enable_q.q.val() & !(self.one16.val() << self.sel_q.q.val());
                }
                // a write enable per slot and the limit repeated in every slot: no
                // variable shift of the 128 bits (a barrel shifter on the FPGA)
                self.limits_q.d.next = (self.limits_q.q.val() & !self.slot_we.val())
                    | (self.limit_rep.val() & self.slot_we.val());
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
        }
        self.cfg_word.next = self.cfg_q.q.val();
        self.time_word.next = self.time_q.q.val();
        self.timeout.next = self.cfg_q.q.val().get_bits::<16>(0);
        self.cs_period.next = self.cfg_q.q.val().get_bits::<16>(16);
        self.tick_bits.next = self.time_q.q.val().get_bits::<16>(0);
        self.recovery_delay.next = self.time_q.q.val().get_bits::<16>(16);
        self.cs_id_dcl.next = self.cs_dcl_q.q.val();
        self.cs_id_rcl.next = self.cs_rcl_q.q.val();
        self.mb_sel.next = self.sel_q.q.val();
        self.mb_enable.next = self.enable_q.q.val() & self.present.val();
        self.mb_limits.next = self.limits_q.q.val() & self.present_limits.val();
    }
}
