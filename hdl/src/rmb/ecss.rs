//! ECSS bus selection (DRCC contract §12.2; ECSS-E-ST-50-15C's redundancy
//! object: `Bdefault`, `Ttoggle`, `Ntoggle`, `Ctoggle`): the bus a node uses is
//! the one on which it hears the redundancy master's heartbeat. Rules, first
//! match, at each edge while `on`:
//!
//! 1. a heartbeat on the bus in use: the missed-heartbeat clock restarts and
//!    the toggle bound is re-armed (`run` <= 0, `no_master` <= 0);
//! 2. after giving up (`no_master`), a heartbeat on the other bus: toggle there;
//! 3. once a heartbeat period has passed (`hb_cnt >= period`, the clock after
//!    its last tick): one more period missed; the `ttoggle`-th toggles, while
//!    `run < ntoggle`, else the node gives up and stays (`no_master`);
//! 4. at a bit tick: `hb_cnt` + 1 ([`HbClock`], a block of its own: the tick
//!    then reaches only the count and never the event, which Verilator would
//!    otherwise see as a loop through the register block and the bit tick).
//!
//! A toggle: `bus` flips, the clock restarts, `ev_toggle` (also when the node
//! gives up), and [`ToggleCount`] counts it in `ctoggle` (saturating, cleared
//! at `rst` and `STATS_CLR` only: a block of its own, so that `STATS_CLR` and
//! the event are ordered apart, no circular logic through the register block).
//! While `!on` (reset mode, normal mode, the policy off) the node sits on
//! `bdefault` with everything but `ctoggle` cleared.

use crate::host::map::lsb;
use crate::host::registers::MAP;
use rust_hdl::prelude::*;

/// The bus in use, by the master's heartbeat.
#[derive(LogicBlock)]
pub struct BusSelect {
    // ---- clock and control ----
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register 0.
    pub rst: Signal<In, Bit>,
    /// `CTRL.redundancy && ECSS_CFG.enable && !reset_mode`.
    pub on: Signal<In, Bit>,
    /// [`HbClock`]'s count: bit times since the clock restarted.
    pub hb_cnt: Signal<In, Bits<24>>,
    // ---- configuration (`ECSS_CFG`, `ECSS_HB`, `ECSS_PERIOD`) ----
    /// `bdefault`: the bus on leaving reset mode (0 A, 1 B).
    pub bdefault: Signal<In, Bit>,
    /// `ttoggle`: missed periods before a toggle (1..255).
    pub ttoggle: Signal<In, Bits<8>>,
    /// `ntoggle`: toggles in a row without a heartbeat.
    pub ntoggle: Signal<In, Bits<8>>,
    /// `period`: the consumer heartbeat time in bit times (never 0).
    pub period: Signal<In, Bits<24>>,
    /// The heartbeat: [28:0] id, [29] ide.
    pub hb: Signal<In, Bits<30>>,
    // ---- receptions ----
    /// Channel A `rx_valid`.
    pub rx_valid_a: Signal<In, Bit>,
    /// Channel A's frame `{rtr, ide, id}`: [30] rtr, [29] ide, [28:0] id.
    pub key_a: Signal<In, Bits<31>>,
    /// Channel B `rx_valid`.
    pub rx_valid_b: Signal<In, Bit>,
    /// Channel B's frame, laid out as `key_a`.
    pub key_b: Signal<In, Bits<31>>,
    // ---- out ----
    /// The bus in use: 0 A, 1 B (the main FSM's `VB`; `VA` is its inverse).
    pub bus: Signal<Out, Bit>,
    /// A toggle, or the node gives up (`INT_STATUS.bus_toggle`).
    pub ev_toggle: Signal<Out, Bit>,
    /// A toggle at this edge (`Ctoggle` counts it, [`ToggleCount`]).
    pub toggled: Signal<Out, Bit>,
    /// `ECSS_STATUS` but `ctoggle` (0 there).
    pub word: Signal<Out, Bits<32>>,
    /// [`HbClock`]: restart at this edge (rules 1-3, or off).
    pub clock_restart: Signal<Out, Bit>,
    /// [`HbClock`]: count ticks (not given up).
    pub clock_run: Signal<Out, Bit>,
    // ---- registers ----
    bus_q: DFF<Bit>,
    missed: DFF<Bits<8>>,
    run: DFF<Bits<8>>,
    no_master: DFF<Bit>,
    // ---- combinational ----
    /// The heartbeat's key with the identifier bits compared.
    want: Signal<Local, Bits<31>>,
    /// The bits compared: rtr, ide and 11 or 29 identifier bits.
    cmp: Signal<Local, Bits<31>>,
    hb_a: Signal<Local, Bit>,
    hb_b: Signal<Local, Bit>,
    hb_own: Signal<Local, Bit>,
    hb_other: Signal<Local, Bit>,
    toggle: Signal<Local, Bit>,
    /// Rule 3 gives up (`no_master` rises).
    give_up: Signal<Local, Bit>,
    /// Rules 1-3 (or `!on`) restart the missed-heartbeat clock.
    restart: Signal<Local, Bit>,
    // ---- constants ----
    mask_base: Constant<Bits<31>>,
    mask_ext: Constant<Bits<31>>,
    one8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
    s_bus: Constant<Bits<5>>,
    s_no_master: Constant<Bits<5>>,
    s_missed: Constant<Bits<5>>,
}

impl Default for BusSelect {
    fn default() -> Self {
        // the core ORs ToggleCount's count into [7:0] of `word`
        let ctoggle = MAP.field("ECSS_STATUS", "ctoggle");
        assert_eq!(
            (ctoggle.lsb, ctoggle.width),
            (0, 8),
            "ECSS_STATUS.ctoggle in [7:0]"
        );
        Self {
            clk: Default::default(),
            rst: Default::default(),
            on: Default::default(),
            hb_cnt: Default::default(),
            bdefault: Default::default(),
            ttoggle: Default::default(),
            ntoggle: Default::default(),
            period: Default::default(),
            hb: Default::default(),
            rx_valid_a: Default::default(),
            key_a: Default::default(),
            rx_valid_b: Default::default(),
            key_b: Default::default(),
            bus: Default::default(),
            ev_toggle: Default::default(),
            toggled: Default::default(),
            word: Default::default(),
            clock_restart: Default::default(),
            clock_run: Default::default(),
            bus_q: Default::default(),
            missed: Default::default(),
            run: Default::default(),
            no_master: Default::default(),
            want: Default::default(),
            cmp: Default::default(),
            hb_a: Default::default(),
            hb_b: Default::default(),
            hb_own: Default::default(),
            hb_other: Default::default(),
            toggle: Default::default(),
            give_up: Default::default(),
            restart: Default::default(),
            // rtr, ide and id[10:0]; the extended frame adds id[28:11]
            mask_base: Constant::new(0x6000_07FF_u64.into()),
            mask_ext: Constant::new(0x7FFF_FFFF_u64.into()),
            one8: Constant::new(1.into()),
            zero8: Constant::new(0.into()),
            s_bus: lsb(&MAP, "ECSS_STATUS", "bus", 1),
            s_no_master: lsb(&MAP, "ECSS_STATUS", "no_master", 1),
            s_missed: lsb(&MAP, "ECSS_STATUS", "missed", 8),
        }
    }
}

impl Logic for BusSelect {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, bus_q, missed, run, no_master);
        // a heartbeat: a data frame with the heartbeat's ide and identifier
        // (11 bits compared in a base frame, 29 in an extended one)
        if self.hb.val().get_bit(29) {
            self.cmp.next = self.mask_ext.val();
        } else {
            self.cmp.next = self.mask_base.val();
        }
        self.want.next = bit_cast::<31, 30>(self.hb.val()) & self.cmp.val();
        self.hb_a.next =
            self.rx_valid_a.val() & ((self.key_a.val() & self.cmp.val()) == self.want.val());
        self.hb_b.next =
            self.rx_valid_b.val() & ((self.key_b.val() & self.cmp.val()) == self.want.val());
        if self.bus_q.q.val() {
            self.hb_own.next = self.hb_b.val();
            self.hb_other.next = self.hb_a.val();
        } else {
            self.hb_own.next = self.hb_a.val();
            self.hb_other.next = self.hb_b.val();
        }

        // §12.2, first matching rule
        self.toggle.next = false;
        self.give_up.next = false;
        self.restart.next = true;
        if self.rst.val() | !self.on.val() {
            if self.rst.val() {
                self.bus_q.d.next = false;
            } else {
                self.bus_q.d.next = self.bdefault.val();
            }
            self.missed.d.next = self.zero8.val();
            self.run.d.next = self.zero8.val();
            self.no_master.d.next = false;
        } else if self.hb_own.val() {
            // 1. the master is heard on the bus in use
            self.missed.d.next = self.zero8.val();
            self.run.d.next = self.zero8.val();
            self.no_master.d.next = false;
        } else if self.no_master.q.val() & self.hb_other.val() {
            // 2. given up, the master is heard on the other bus: go there
            self.toggle.next = true;
            self.run.d.next = self.zero8.val();
            self.no_master.d.next = false;
        } else if !self.no_master.q.val() & (self.hb_cnt.val() >= self.period.val()) {
            // 3. a heartbeat period missed (registered values only)
            if (self.missed.q.val() + self.one8.val()) < self.ttoggle.val() {
                self.missed.d.next = self.missed.q.val() + self.one8.val();
            } else {
                self.missed.d.next = self.zero8.val();
                if self.run.q.val() < self.ntoggle.val() {
                    self.toggle.next = true;
                    self.run.d.next = self.run.q.val() + self.one8.val();
                } else {
                    self.no_master.d.next = true;
                    self.give_up.next = true;
                }
            }
        } else {
            self.restart.next = false;
        }
        if self.toggle.val() {
            self.bus_q.d.next = !self.bus_q.q.val();
            self.missed.d.next = self.zero8.val();
        }
        // 4. the missed-heartbeat clock ([`HbClock`]): restarted by rules 1-3
        // and while off, else one more bit time at each tick, stopped once
        // given up
        self.clock_restart.next = self.restart.val();
        self.clock_run.next = !self.no_master.q.val();
        self.ev_toggle.next = self.toggle.val() | self.give_up.val();
        self.toggled.next = self.toggle.val();
        self.bus.next = self.bus_q.q.val();
        self.word.next = (bit_cast::<32, 1>(self.bus_q.q.val().into()) << self.s_bus.val())
            | (bit_cast::<32, 1>(self.no_master.q.val().into()) << self.s_no_master.val())
            | (bit_cast::<32, 8>(self.missed.q.val()) << self.s_missed.val());
    }
}

/// `ECSS_STATUS.ctoggle`: the toggles, saturating at 255.
#[derive(LogicBlock)]
pub struct ToggleCount {
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or `STATS_CLR`: to 0 (wins over a toggle at the same edge).
    pub clear: Signal<In, Bit>,
    /// A toggle at this edge.
    pub toggled: Signal<In, Bit>,
    /// The count.
    pub count: Signal<Out, Bits<8>>,
    ctoggle: DFF<Bits<8>>,
    one8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
}

impl Default for ToggleCount {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            clear: Default::default(),
            toggled: Default::default(),
            count: Default::default(),
            ctoggle: Default::default(),
            one8: Constant::new(1.into()),
            max8: Constant::new(0xFF.into()),
            zero8: Constant::new(0.into()),
        }
    }
}

impl Logic for ToggleCount {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ctoggle);
        if self.toggled.val() & (self.ctoggle.q.val() != self.max8.val()) {
            self.ctoggle.d.next = self.ctoggle.q.val() + self.one8.val();
        }
        if self.clear.val() {
            self.ctoggle.d.next = self.zero8.val();
        }
        self.count.next = self.ctoggle.q.val();
    }
}

/// The missed-heartbeat clock `hb_cnt` (rule 4): bit times since the last
/// restart, counting while `run`.
#[derive(LogicBlock)]
pub struct HbClock {
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// Nominal bit-time tick (§4.3).
    pub tick: Signal<In, Bit>,
    /// To 0 at this edge.
    pub restart: Signal<In, Bit>,
    /// Count ticks.
    pub run: Signal<In, Bit>,
    /// `hb_cnt`.
    pub count: Signal<Out, Bits<24>>,
    hb_cnt: DFF<Bits<24>>,
    one24: Constant<Bits<24>>,
    zero24: Constant<Bits<24>>,
}

impl Default for HbClock {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            tick: Default::default(),
            restart: Default::default(),
            run: Default::default(),
            count: Default::default(),
            hb_cnt: Default::default(),
            one24: Constant::new(1.into()),
            zero24: Constant::new(0.into()),
        }
    }
}

impl Logic for HbClock {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, hb_cnt);
        if self.restart.val() {
            self.hb_cnt.d.next = self.zero24.val();
        } else if self.run.val() & self.tick.val() {
            self.hb_cnt.d.next = self.hb_cnt.q.val() + self.one24.val();
        }
        self.count.next = self.hb_cnt.q.val();
    }
}
