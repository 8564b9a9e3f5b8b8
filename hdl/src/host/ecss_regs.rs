//! The ECSS bus-selection registers (DRCC contract §12.1): `ECSS_CFG`,
//! `ECSS_HB` and `ECSS_PERIOD` stored here, `ECSS_STATUS` read from the
//! selection (`crate::rmb::ecss`). cfg registers: a whole-word write is stored in
//! reset mode and refused outside it (§9); in reset mode a write that would
//! store an illegal value (`ttoggle` 0, `period` 0, a reserved bit) is refused
//! as a whole, so the stored values are always legal. `rst` sets the table's
//! reset values; reset mode keeps them.
//!
//! The block answers the register block as the filters do: `hit` for its
//! addresses, `word` for the read, `writable` and `illegal` for a write. It is
//! two blocks wired together, as the DMR registers are: [`EcssDecode`], the
//! combinational answer, and [`EcssStore`], the registers that take `wr`; one
//! block would read `wr` and drive `writable` in one always block, which
//! Verilator sees as a loop through the register block (UNOPTFLAT).

use super::map::lsb;
use super::registers::{self as map, MAP};
use rust_hdl::prelude::*;

/// `ECSS_CFG.ttoggle` and `ntoggle` positions (checked against the table):
/// the decode slices at these literal indices (hdl_gen emits names as written).
const TTOGGLE: u32 = 0;
const NTOGGLE: u32 = 8;

fn adr(i: u32) -> Constant<Bits<6>> {
    Constant::new((i as u64).into())
}

fn reg(r: &str) -> &'static map::Register {
    map::register(r).expect("ECSS register in the map")
}

/// The answer to an access: hit, read word, refusal (§9, §12.1).
#[derive(LogicBlock)]
pub struct EcssDecode {
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// `CTRL.reset_mode`.
    pub reset_mode: Signal<In, Bit>,
    /// The stored `ECSS_CFG`, `ECSS_HB`, `ECSS_PERIOD`.
    pub cfg_word: Signal<In, Bits<32>>,
    /// The stored `ECSS_HB`: [28:0] id, [29] ide.
    pub hb_word: Signal<In, Bits<30>>,
    /// The stored `ECSS_PERIOD.period`, in nominal bit times.
    pub period_word: Signal<In, Bits<24>>,
    /// `ECSS_STATUS`.
    pub status_word: Signal<In, Bits<32>>,
    /// `adr` is one of the four registers.
    pub hit: Signal<Out, Bit>,
    /// `adr` is one of the three writable ones.
    pub writable: Signal<Out, Bit>,
    /// The addressed register's value (0 when not `hit`).
    pub word: Signal<Out, Bits<32>>,
    /// A write of `wdat` to `adr` is refused.
    pub illegal: Signal<Out, Bit>,
    bad: Signal<Local, Bit>,
    a_cfg: Constant<Bits<6>>,
    a_hb: Constant<Bits<6>>,
    a_period: Constant<Bits<6>>,
    a_status: Constant<Bits<6>>,
    /// `ECSS_CFG`'s reserved bits ([23:16], [30:25]).
    cfg_reserved: Constant<Bits<32>>,
    /// `ECSS_HB`'s reserved bits ([31:30]).
    hb_reserved: Constant<Bits<32>>,
    /// `ECSS_PERIOD`'s reserved bits ([31:24]).
    period_reserved: Constant<Bits<32>>,
    zero8: Constant<Bits<8>>,
    zero24: Constant<Bits<24>>,
    zero32: Constant<Bits<32>>,
}

impl Default for EcssDecode {
    fn default() -> Self {
        let reserved = |r: &str| Constant::new((!reg(r).defined() as u64 & 0xFFFF_FFFF).into());
        assert_eq!(MAP.field("ECSS_CFG", "ttoggle").lsb, TTOGGLE);
        assert_eq!(MAP.field("ECSS_CFG", "ntoggle").lsb, NTOGGLE);
        Self {
            adr: Default::default(),
            wdat: Default::default(),
            reset_mode: Default::default(),
            cfg_word: Default::default(),
            hb_word: Default::default(),
            period_word: Default::default(),
            status_word: Default::default(),
            hit: Default::default(),
            writable: Default::default(),
            word: Default::default(),
            illegal: Default::default(),
            bad: Default::default(),
            a_cfg: adr(map::ECSS_CFG),
            a_hb: adr(map::ECSS_HB),
            a_period: adr(map::ECSS_PERIOD),
            a_status: adr(map::ECSS_STATUS),
            cfg_reserved: reserved("ECSS_CFG"),
            hb_reserved: reserved("ECSS_HB"),
            period_reserved: reserved("ECSS_PERIOD"),
            zero8: Constant::new(0.into()),
            zero24: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl Logic for EcssDecode {
    #[hdl_gen]
    fn update(&mut self) {
        self.writable.next = (self.adr.val() == self.a_cfg.val())
            | (self.adr.val() == self.a_hb.val())
            | (self.adr.val() == self.a_period.val());
        self.hit.next = self.writable.val() | (self.adr.val() == self.a_status.val());
        self.word.next = self.zero32.val();
        if self.adr.val() == self.a_cfg.val() {
            self.word.next = self.cfg_word.val();
        } else if self.adr.val() == self.a_hb.val() {
            self.word.next = bit_cast::<32, 30>(self.hb_word.val());
        } else if self.adr.val() == self.a_period.val() {
            self.word.next = bit_cast::<32, 24>(self.period_word.val());
        } else if self.adr.val() == self.a_status.val() {
            self.word.next = self.status_word.val();
        }
        // §12.1: a value that would be illegal once stored refuses the write
        self.bad.next = false;
        if self.adr.val() == self.a_cfg.val() {
            self.bad.next = ((self.wdat.val() & self.cfg_reserved.val()) != self.zero32.val())
                | (self.wdat.val().get_bits::<8>(0) == self.zero8.val());
        } else if self.adr.val() == self.a_hb.val() {
            self.bad.next = (self.wdat.val() & self.hb_reserved.val()) != self.zero32.val();
        } else if self.adr.val() == self.a_period.val() {
            self.bad.next = ((self.wdat.val() & self.period_reserved.val()) != self.zero32.val())
                | (self.wdat.val().get_bits::<24>(0) == self.zero24.val());
        }
        // cfg registers (§9): outside reset mode refused
        self.illegal.next = self.writable.val() & (!self.reset_mode.val() | self.bad.val());
    }
}

/// The stored registers: a taken write that is not refused, `rst` to the
/// table's reset values.
#[derive(LogicBlock)]
pub struct EcssStore {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset.
    pub rst: Signal<In, Bit>,
    /// A whole-word write is taken at this edge (any address).
    pub wr: Signal<In, Bit>,
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// [`EcssDecode`]'s refusal.
    pub refused: Signal<In, Bit>,
    /// The stored words.
    pub cfg_word: Signal<Out, Bits<32>>,
    /// `ECSS_HB`: [28:0] the master's heartbeat identifier, [29] ide.
    pub hb_word: Signal<Out, Bits<30>>,
    /// `ECSS_PERIOD.period`: the heartbeat period in nominal bit times (never 0).
    pub period_word: Signal<Out, Bits<24>>,
    cfg_q: DFF<Bits<32>>,
    hb_q: DFF<Bits<30>>,
    period_q: DFF<Bits<24>>,
    a_cfg: Constant<Bits<6>>,
    a_hb: Constant<Bits<6>>,
    a_period: Constant<Bits<6>>,
    cfg_reset: Constant<Bits<32>>,
    hb_reset: Constant<Bits<30>>,
    period_reset: Constant<Bits<24>>,
}

impl Default for EcssStore {
    fn default() -> Self {
        let reset = |r: &str| reg(r).reset_value() as u64;
        assert_eq!(reg("ECSS_HB").defined() >> 30, 0, "ECSS_HB: 30 bits stored");
        assert_eq!(
            reg("ECSS_PERIOD").defined() >> 24,
            0,
            "ECSS_PERIOD: 24 bits stored"
        );
        assert_ne!(
            MAP.field("ECSS_CFG", "ttoggle").reset,
            0,
            "ttoggle resets legal"
        );
        assert_ne!(reset("ECSS_PERIOD"), 0, "period resets legal");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            adr: Default::default(),
            wdat: Default::default(),
            refused: Default::default(),
            cfg_word: Default::default(),
            hb_word: Default::default(),
            period_word: Default::default(),
            cfg_q: Default::default(),
            hb_q: Default::default(),
            period_q: Default::default(),
            a_cfg: adr(map::ECSS_CFG),
            a_hb: adr(map::ECSS_HB),
            a_period: adr(map::ECSS_PERIOD),
            cfg_reset: Constant::new(reset("ECSS_CFG").into()),
            hb_reset: Constant::new(reset("ECSS_HB").into()),
            period_reset: Constant::new(reset("ECSS_PERIOD").into()),
        }
    }
}

impl Logic for EcssStore {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, cfg_q, hb_q, period_q);
        if self.wr.val() & !self.refused.val() {
            if self.adr.val() == self.a_cfg.val() {
                self.cfg_q.d.next = self.wdat.val();
            } else if self.adr.val() == self.a_hb.val() {
                self.hb_q.d.next = self.wdat.val().get_bits::<30>(0);
            } else if self.adr.val() == self.a_period.val() {
                self.period_q.d.next = self.wdat.val().get_bits::<24>(0);
            }
        }
        if self.rst.val() {
            self.cfg_q.d.next = self.cfg_reset.val();
            self.hb_q.d.next = self.hb_reset.val();
            self.period_q.d.next = self.period_reset.val();
        }
        self.cfg_word.next = self.cfg_q.q.val();
        self.hb_word.next = self.hb_q.q.val();
        self.period_word.next = self.period_q.q.val();
    }
}

/// `ECSS_CFG`, `ECSS_HB`, `ECSS_PERIOD` and the read of `ECSS_STATUS`.
#[derive(LogicBlock)]
pub struct EcssRegs {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: the table's reset values.
    pub rst: Signal<In, Bit>,
    // ---- the register access ----
    /// A whole-word write is taken at this edge (any address).
    pub wr: Signal<In, Bit>,
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// `CTRL.reset_mode`: the registers are writable only then.
    pub reset_mode: Signal<In, Bit>,
    /// `ECSS_STATUS`, from the selection.
    pub status_word: Signal<In, Bits<32>>,
    /// `adr` is one of the four registers.
    pub hit: Signal<Out, Bit>,
    /// `adr` is one of the three writable ones.
    pub writable: Signal<Out, Bit>,
    /// The addressed register's value (0 when not `hit`).
    pub word: Signal<Out, Bits<32>>,
    /// A write to `adr` is refused (§9, §12.1).
    pub illegal: Signal<Out, Bit>,
    // ---- the stored configuration ----
    /// `ECSS_CFG.ttoggle` (never 0).
    pub ttoggle: Signal<Out, Bits<8>>,
    /// `ECSS_CFG.ntoggle`.
    pub ntoggle: Signal<Out, Bits<8>>,
    /// `ECSS_CFG.bdefault`: 0 A, 1 B.
    pub bdefault: Signal<Out, Bit>,
    /// `ECSS_CFG.enable`.
    pub enable: Signal<Out, Bit>,
    /// `ECSS_HB`: [28:0] id, [29] ide.
    pub hb: Signal<Out, Bits<30>>,
    /// `ECSS_PERIOD.period` in nominal bit times (never 0).
    pub period: Signal<Out, Bits<24>>,
    // ---- blocks ----
    decode: EcssDecode,
    store: EcssStore,
    p_bdefault: Constant<Bits<5>>,
    p_enable: Constant<Bits<5>>,
}

impl Default for EcssRegs {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            adr: Default::default(),
            wdat: Default::default(),
            reset_mode: Default::default(),
            status_word: Default::default(),
            hit: Default::default(),
            writable: Default::default(),
            word: Default::default(),
            illegal: Default::default(),
            ttoggle: Default::default(),
            ntoggle: Default::default(),
            bdefault: Default::default(),
            enable: Default::default(),
            hb: Default::default(),
            period: Default::default(),
            decode: Default::default(),
            store: Default::default(),
            p_bdefault: lsb(&MAP, "ECSS_CFG", "bdefault", 1),
            p_enable: lsb(&MAP, "ECSS_CFG", "enable", 1),
        }
    }
}

impl Logic for EcssRegs {
    #[hdl_gen]
    fn update(&mut self) {
        self.decode.adr.next = self.adr.val();
        self.decode.wdat.next = self.wdat.val();
        self.decode.reset_mode.next = self.reset_mode.val();
        self.decode.cfg_word.next = self.store.cfg_word.val();
        self.decode.hb_word.next = self.store.hb_word.val();
        self.decode.period_word.next = self.store.period_word.val();
        self.decode.status_word.next = self.status_word.val();
        self.hit.next = self.decode.hit.val();
        self.writable.next = self.decode.writable.val();
        self.word.next = self.decode.word.val();
        self.illegal.next = self.decode.illegal.val();
        self.store.clk.next = self.clk.val();
        self.store.rst.next = self.rst.val();
        self.store.wr.next = self.wr.val();
        self.store.adr.next = self.adr.val();
        self.store.wdat.next = self.wdat.val();
        self.store.refused.next = self.decode.illegal.val();
        self.ttoggle.next = self.store.cfg_word.val().get_bits::<8>(0);
        self.ntoggle.next = self.store.cfg_word.val().get_bits::<8>(8);
        self.bdefault.next = self
            .store
            .cfg_word
            .val()
            .get_bit(self.p_bdefault.val().index());
        self.enable.next = self
            .store
            .cfg_word
            .val()
            .get_bit(self.p_enable.val().index());
        self.hb.next = self.store.hb_word.val();
        self.period.next = self.store.period_word.val();
    }
}
