//! Bit timing logic (ISO 11898-1:2015, 11.3): prescaler, the SYNC/TSEG1/TSEG2
//! segment counter, hard synchronisation, resynchronisation with the jump width,
//! the sample point (with optional triple sampling) and the start of each
//! transmitted bit. The exact per-clock algorithm is the timing contract §3
//! (`cosim/src/model/timing_contract.md`); this block implements it line by line.
//!
//! Decisions where the standard leaves room:
//! - The prescaler runs freely; edges are seen with one-time-quantum resolution.
//! - SJW is clamped to TSEG2 (`min(sjw, tseg2)`), so a configuration with
//!   SJW > PHASE_SEG2 can never shorten a bit below SYNC_SEG + TSEG1.
//! - A node that is sending a dominant bit never resynchronises (8.7.7).
//!
//! Timing structure: the decisions of a tick (`sample`, `bit_start`) feed the
//! whole bit stream processor in the same clock, so they are made from registered
//! flags only. `tick_q` is the prescaler's `tick` computed one clock ahead;
//! `last1` (last tq of TSEG1), `last2` (last tq of TSEG2), `res_sync` (a resync
//! in this TSEG2 tq is within SJW: the tq becomes SYNC_SEG) and `res_end` (after
//! a resync that shortens TSEG2 this tq ends it) are the comparisons of §3
//! evaluated for the state the registers hold, updated together with
//! `seg`/`quantum`/`tseg1_len`/`tseg2_len`. A resync in TSEG1 never samples in the
//! same tq (the jump is >= 1 tq), which is why `sample` needs only `last1`.

use crate::channel::BRP_BITS;
use rust_hdl::prelude::*;

/// Segment of the nominal bit time.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum Segment {
    Sync,
    Tseg1,
    Tseg2,
}

/// The bit timing logic of one channel.
#[derive(LogicBlock)]
pub struct BitTimingLogic {
    // clock and reset
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Channel reset: the bit timing restarts in SYNC_SEG with the bus taken as recessive.
    pub rst: Signal<In, Bit>,
    // configuration (minus-one encodings for the segment lengths)
    /// The BRP the prescaler counts from the next clock on (the configuration
    /// input while `rst` captures it).
    pub cfg_brp_next: Signal<In, Bits<BRP_BITS>>,
    /// TSEG1' in time quanta, clamped (`super::config`'s `tseg1_len`).
    pub cfg_tseg1_len: Signal<In, Bits<5>>,
    /// TSEG2 (PHASE_SEG2) in time quanta.
    pub cfg_tseg2_len: Signal<In, Bits<4>>,
    /// Resynchronisation jump width in time quanta, at most TSEG2.
    pub cfg_sjw_len: Signal<In, Bits<4>>,
    /// Triple sampling: the sample is the majority of the last three time quanta.
    pub cfg_triple: Signal<In, Bit>,
    // bus side
    /// Synchronized bus value, 1 = recessive (two clocks after the pin).
    pub rx_s: Signal<In, Bit>,
    /// The bit this node drives, 1 = recessive: a node sending a dominant bit never resynchronises
    /// (8.7.7).
    pub tx: Signal<In, Bit>,
    // from the bit stream processor
    /// Hard synchronisation is allowed (between frames, 11.3.2.1).
    pub hard_sync_enable: Signal<In, Bit>,
    // to the bit stream processor (valid in the clock of the event)
    /// The sample point of the current bit (one clock).
    pub sample: Signal<Out, Bit>,
    /// The bus level at the sample point, 1 = recessive (the majority of three with triple
    /// sampling).
    pub sampled: Signal<Out, Bit>,
    /// The start of a bit: the transmit pin may change.
    pub bit_start: Signal<Out, Bit>,
    /// This bit start is a hard synchronisation.
    pub hard_sync: Signal<Out, Bit>,
    // probes
    /// One-clock pulse, the clock after each sample point.
    pub sample_point: Signal<Out, Bit>,
    /// Bus value taken at the last sample point, 1 = recessive.
    pub last_sample: Signal<Out, Bit>,
    // state
    brp_cnt: DFF<Bits<BRP_BITS>>,
    seg: DFF<Segment>,
    quantum: DFF<Bits<5>>,
    tseg1_len: DFF<Bits<5>>,
    tseg2_len: DFF<Bits<4>>,
    rx_prev: DFF<Bit>,
    rx_prev2: DFF<Bit>,
    last_sample_q: DFF<Bit>,
    synced: DFF<Bit>,
    sample_point_q: DFF<Bit>,
    // registered decisions (see the header)
    tick_q: DFF<Bit>,
    last1: DFF<Bit>,
    last2: DFF<Bit>,
    res_sync: DFF<Bit>,
    res_end: DFF<Bit>,
    hse_q: DFF<Bit>,
    // combinational helpers
    tick: Signal<Local, Bit>,
    tseg1_nominal: Signal<Local, Bits<5>>,
    tseg2_nominal: Signal<Local, Bits<4>>,
    sjw_eff: Signal<Local, Bits<4>>,
    sync_ok: Signal<Local, Bit>,
    do_hard: Signal<Local, Bit>,
    do_resync: Signal<Local, Bit>,
    quantum_next: Signal<Local, Bits<5>>,
    pos_error: Signal<Local, Bits<5>>,
    pos_jump: Signal<Local, Bits<5>>,
    tseg1_eff: Signal<Local, Bits<5>>,
    tseg2_eff: Signal<Local, Bits<4>>,
    sample_value: Signal<Local, Bit>,
    brp_cnt_n: Signal<Local, Bits<BRP_BITS>>,
    quantum_next2: Signal<Local, Bits<5>>,
    q2_next: Signal<Local, Bits<4>>,
    q2_next2: Signal<Local, Bits<4>>,
    t2_short: Signal<Local, Bits<4>>,
    t2_short2: Signal<Local, Bits<4>>,
    ne_stay: Signal<Local, Bits<4>>,
    ne_short: Signal<Local, Bits<4>>,
    last1_stay: Signal<Local, Bit>,
    last2_stay: Signal<Local, Bit>,
    res_sync_stay: Signal<Local, Bit>,
    res_end_stay: Signal<Local, Bit>,
    last2_short: Signal<Local, Bit>,
    res_sync_short: Signal<Local, Bit>,
    res_end_short: Signal<Local, Bit>,
    last2_enter: Signal<Local, Bit>,
    res_sync_enter: Signal<Local, Bit>,
    res_end_enter: Signal<Local, Bit>,
    last1_enter: Signal<Local, Bit>,
    one4: Constant<Bits<4>>,
    one5: Constant<Bits<5>>,
    one_brp: Constant<Bits<BRP_BITS>>,
    zero5: Constant<Bits<5>>,
    zero_brp: Constant<Bits<BRP_BITS>>,
}

impl Default for BitTimingLogic {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            cfg_brp_next: Default::default(),
            cfg_tseg1_len: Default::default(),
            cfg_tseg2_len: Default::default(),
            cfg_sjw_len: Default::default(),
            cfg_triple: Default::default(),
            rx_s: Default::default(),
            tx: Default::default(),
            hard_sync_enable: Default::default(),
            sample: Default::default(),
            sampled: Default::default(),
            bit_start: Default::default(),
            hard_sync: Default::default(),
            sample_point: Default::default(),
            last_sample: Default::default(),
            brp_cnt: Default::default(),
            seg: Default::default(),
            quantum: Default::default(),
            tseg1_len: Default::default(),
            tseg2_len: Default::default(),
            rx_prev: Default::default(),
            rx_prev2: Default::default(),
            last_sample_q: Default::default(),
            synced: Default::default(),
            sample_point_q: Default::default(),
            tick_q: Default::default(),
            last1: Default::default(),
            last2: Default::default(),
            res_sync: Default::default(),
            res_end: Default::default(),
            hse_q: Default::default(),
            tick: Default::default(),
            tseg1_nominal: Default::default(),
            tseg2_nominal: Default::default(),
            sjw_eff: Default::default(),
            sync_ok: Default::default(),
            do_hard: Default::default(),
            do_resync: Default::default(),
            quantum_next: Default::default(),
            pos_error: Default::default(),
            pos_jump: Default::default(),
            tseg1_eff: Default::default(),
            tseg2_eff: Default::default(),
            sample_value: Default::default(),
            brp_cnt_n: Default::default(),
            quantum_next2: Default::default(),
            q2_next: Default::default(),
            q2_next2: Default::default(),
            t2_short: Default::default(),
            t2_short2: Default::default(),
            ne_stay: Default::default(),
            ne_short: Default::default(),
            last1_stay: Default::default(),
            last2_stay: Default::default(),
            res_sync_stay: Default::default(),
            res_end_stay: Default::default(),
            last2_short: Default::default(),
            res_sync_short: Default::default(),
            res_end_short: Default::default(),
            last2_enter: Default::default(),
            res_sync_enter: Default::default(),
            res_end_enter: Default::default(),
            last1_enter: Default::default(),
            one4: Constant::new(1.into()),
            one5: Constant::new(1.into()),
            one_brp: Constant::new(1.into()),
            zero5: Constant::new(0.into()),
            zero_brp: Constant::new(0.into()),
        }
    }
}

impl Logic for BitTimingLogic {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            brp_cnt,
            seg,
            quantum,
            tseg1_len,
            tseg2_len,
            rx_prev,
            rx_prev2,
            last_sample_q,
            synced,
            sample_point_q,
            tick_q,
            last1,
            last2,
            res_sync,
            res_end,
            hse_q
        );
        // Nominal lengths from the minus-one encodings; SJW clamped to TSEG2.
        // Lengths in tq, clamped and registered by the configuration block.
        self.tseg1_nominal.next = self.cfg_tseg1_len.val();
        self.tseg2_nominal.next = self.cfg_tseg2_len.val();
        self.sjw_eff.next = self.cfg_sjw_len.val();
        // Prescaler: one time quantum every BRP+1 clocks. `tick` is
        // (brp_cnt >= BRP), registered one clock ahead from the next count.
        self.tick.next = self.tick_q.q.val();
        if self.rst.val() || self.tick.val() {
            self.brp_cnt_n.next = self.zero_brp.val();
        } else {
            self.brp_cnt_n.next = self.brp_cnt.q.val() + self.one_brp.val();
        }
        self.brp_cnt.d.next = self.brp_cnt_n.val();
        self.tick_q.d.next = self.brp_cnt_n.val() >= self.cfg_brp_next.val();
        // 11.3.2: recessive-to-dominant edge, previous sample recessive, once per bit.
        self.sync_ok.next = self.rx_prev.q.val()
            && !self.rx_s.val()
            && self.last_sample_q.q.val()
            && !self.synced.q.val();
        self.do_hard.next = self.sync_ok.val() && self.hard_sync_enable.val();
        self.do_resync.next = self.sync_ok.val() && !self.hard_sync_enable.val() && self.tx.val();
        self.quantum_next.next = self.quantum.q.val() + self.one5.val();
        self.quantum_next2.next = self.quantum_next.val() + self.one5.val();
        // Positive phase error e = q+1 (edge in TSEG1), jump min(e, SJW).
        self.pos_error.next = self.quantum.q.val() + self.one5.val();
        if self.pos_error.val() > bit_cast::<5, 4>(self.sjw_eff.val()) {
            self.pos_jump.next = bit_cast::<5, 4>(self.sjw_eff.val());
        } else {
            self.pos_jump.next = self.pos_error.val();
        }
        if self.do_resync.val() {
            self.tseg1_eff.next = self.tseg1_len.q.val() + self.pos_jump.val();
        } else {
            self.tseg1_eff.next = self.tseg1_len.q.val();
        }
        // Negative phase error |e| = t2 - q (edge in TSEG2): see `res_sync`.
        self.t2_short.next = self.tseg2_len.q.val() - self.sjw_eff.val();
        if self.do_resync.val() {
            self.tseg2_eff.next = self.t2_short.val();
        } else {
            self.tseg2_eff.next = self.tseg2_len.q.val();
        }
        // The registered decisions for the state of the next tq (see the header):
        // entering TSEG1 (q=0, t1=T1) or TSEG2 (q=0), staying in TSEG2 with t2 kept
        // or shortened by a resync, staying in TSEG1 without a resync.
        self.last1_enter.next = self.one5.val() >= self.tseg1_nominal.val();
        self.last1_stay.next = self.quantum_next2.val() >= self.tseg1_len.q.val();
        self.last2_enter.next = self.one4.val() >= self.tseg2_len.q.val();
        self.res_sync_enter.next = self.tseg2_len.q.val() <= self.sjw_eff.val();
        self.res_end_enter.next = self.one4.val() >= self.t2_short.val();
        self.q2_next.next = self.quantum_next.val().get_bits::<4>(0);
        self.q2_next2.next = self.quantum_next2.val().get_bits::<4>(0);
        self.last2_stay.next = self.q2_next2.val() >= self.tseg2_len.q.val();
        self.ne_stay.next = self.tseg2_len.q.val() - self.q2_next.val();
        self.res_sync_stay.next = self.ne_stay.val() <= self.sjw_eff.val();
        self.res_end_stay.next = self.q2_next2.val() >= self.t2_short.val();
        self.last2_short.next = self.q2_next2.val() >= self.t2_short.val();
        self.ne_short.next = self.t2_short.val() - self.q2_next.val();
        self.res_sync_short.next = self.ne_short.val() <= self.sjw_eff.val();
        self.t2_short2.next = self.t2_short.val() - self.sjw_eff.val();
        self.res_end_short.next = self.q2_next2.val() >= self.t2_short2.val();
        // Sample value, single or majority of three quanta (triple sampling).
        if self.cfg_triple.val() {
            self.sample_value.next = (self.rx_prev2.q.val() && self.rx_prev.q.val())
                || (self.rx_prev.q.val() && self.rx_s.val())
                || (self.rx_prev2.q.val() && self.rx_s.val());
        } else {
            self.sample_value.next = self.rx_s.val();
        }

        // `sample` for the bit stream processor: the TSEG1 branch below, with
        // `hard_sync_enable` one clock late. It changes only at SAMPLE edges and reset,
        // and in the clock after either `last1` is 0, so the late copy is exact
        // wherever it matters.
        self.hse_q.d.next = self.hard_sync_enable.val();
        self.sample.next = self.tick.val()
            && self.last1.q.val()
            && !(self.sync_ok.val() && (self.hse_q.q.val() || self.tx.val()));
        self.bit_start.next = false;
        self.hard_sync.next = false;
        self.sample_point_q.d.next = false;
        if self.tick.val() {
            self.rx_prev.d.next = self.rx_s.val();
            self.rx_prev2.d.next = self.rx_prev.q.val();
            if self.do_hard.val() {
                // Hard synchronisation: this quantum becomes SYNC_SEG.
                self.seg.d.next = Segment::Tseg1;
                self.quantum.d.next = self.zero5.val();
                self.tseg1_len.d.next = self.tseg1_nominal.val();
                self.tseg2_len.d.next = self.tseg2_nominal.val();
                self.synced.d.next = true;
                self.bit_start.next = true;
                self.hard_sync.next = true;
                self.last1.d.next = self.last1_enter.val();
                self.last2.d.next = false;
                self.res_sync.d.next = false;
                self.res_end.d.next = false;
            } else {
                match self.seg.q.val() {
                    Segment::Sync => {
                        self.seg.d.next = Segment::Tseg1;
                        self.quantum.d.next = self.zero5.val();
                        self.tseg1_len.d.next = self.tseg1_nominal.val();
                        self.tseg2_len.d.next = self.tseg2_nominal.val();
                        if self.do_resync.val() {
                            self.synced.d.next = true;
                        }
                        self.last1.d.next = self.last1_enter.val();
                        self.last2.d.next = false;
                        self.res_sync.d.next = false;
                        self.res_end.d.next = false;
                    }
                    Segment::Tseg1 => {
                        if self.do_resync.val() {
                            self.synced.d.next = true;
                        }
                        self.tseg1_len.d.next = self.tseg1_eff.val();
                        // q+1 >= t1 (`last1`); with a resync never: the jump is
                        // at least one tq and q < t1.
                        if self.last1.q.val() && !self.do_resync.val() {
                            // Sample point: end of TSEG1 (`sample` above).
                            self.sample_point_q.d.next = true;
                            self.last_sample_q.d.next = self.sample_value.val();
                            self.synced.d.next = false;
                            self.seg.d.next = Segment::Tseg2;
                            self.quantum.d.next = self.zero5.val();
                            self.last1.d.next = false;
                            self.last2.d.next = self.last2_enter.val();
                            self.res_sync.d.next = self.res_sync_enter.val();
                            self.res_end.d.next = self.res_end_enter.val();
                        } else {
                            self.quantum.d.next = self.quantum_next.val();
                            if self.do_resync.val() {
                                // q+2 >= t1 + min(q+1, SJW'): only from the last tq
                                // with a jump of one tq.
                                self.last1.d.next = self.last1.q.val()
                                    && ((self.quantum.q.val() == self.zero5.val())
                                        || (self.sjw_eff.val() == self.one4.val()));
                            } else {
                                self.last1.d.next = self.last1_stay.val();
                            }
                        }
                    }
                    Segment::Tseg2 => {
                        if self.do_resync.val() && self.res_sync.q.val() {
                            // Edge within SJW before the bit end: this quantum is SYNC_SEG.
                            self.seg.d.next = Segment::Tseg1;
                            self.quantum.d.next = self.zero5.val();
                            self.tseg1_len.d.next = self.tseg1_nominal.val();
                            self.tseg2_len.d.next = self.tseg2_nominal.val();
                            self.synced.d.next = true;
                            self.bit_start.next = true;
                            self.last1.d.next = self.last1_enter.val();
                            self.last2.d.next = false;
                            self.res_sync.d.next = false;
                            self.res_end.d.next = false;
                        } else {
                            if self.do_resync.val() {
                                self.synced.d.next = true;
                            }
                            self.tseg2_len.d.next = self.tseg2_eff.val();
                            if (self.do_resync.val() && self.res_end.q.val())
                                || (!self.do_resync.val() && self.last2.q.val())
                            {
                                self.seg.d.next = Segment::Sync;
                                self.quantum.d.next = self.zero5.val();
                                self.bit_start.next = true;
                                self.last2.d.next = false;
                                self.res_sync.d.next = false;
                                self.res_end.d.next = false;
                            } else {
                                self.quantum.d.next = self.quantum_next.val();
                                if self.do_resync.val() {
                                    self.last2.d.next = self.last2_short.val();
                                    self.res_sync.d.next = self.res_sync_short.val();
                                    self.res_end.d.next = self.res_end_short.val();
                                } else {
                                    self.last2.d.next = self.last2_stay.val();
                                    self.res_sync.d.next = self.res_sync_stay.val();
                                    self.res_end.d.next = self.res_end_stay.val();
                                }
                            }
                        }
                    }
                    _ => {
                        self.seg.d.next = Segment::Sync;
                        self.last1.d.next = false;
                        self.last2.d.next = false;
                        self.res_sync.d.next = false;
                        self.res_end.d.next = false;
                    }
                }
            }
        }
        self.sampled.next = self.sample_value.val();
        self.sample_point.next = self.sample_point_q.q.val();
        self.last_sample.next = self.last_sample_q.q.val();

        if self.rst.val() {
            self.seg.d.next = Segment::Sync;
            self.quantum.d.next = self.zero5.val();
            self.tseg1_len.d.next = self.tseg1_nominal.val();
            self.tseg2_len.d.next = self.tseg2_nominal.val();
            self.rx_prev.d.next = true;
            self.rx_prev2.d.next = true;
            self.last_sample_q.d.next = true;
            self.synced.d.next = false;
            self.sample_point_q.d.next = false;
            self.last1.d.next = false;
            self.last2.d.next = false;
            self.res_sync.d.next = false;
            self.res_end.d.next = false;
        }
    }
}
