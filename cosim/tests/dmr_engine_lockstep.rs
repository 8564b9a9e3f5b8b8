//! Block-level lock-step of the DMR engine (DMR contract §4.1-§4.4): the rust-hdl
//! `DmrEngine`, with the identifier memory `MailboxCfg` wired as in the DRCC top,
//! in rust-hdl's simulator against the reference model's `Engine` + `Mailboxes`,
//! on the same seeded random stimulus. Every clock compares the verdict (`fault*`,
//! combinational on the registers before the edge) with the model's return value,
//! and after the edge `e_state` and `MB_STATE` of a window that sweeps all 16
//! mailboxes. The stimulus is biased so both fault kinds on both lines and both
//! directions, lowest-index matches, misses, saturation, bursts (a flag set again
//! while pending), `clear_state` and `hold` are reached; each is counted and the
//! counts must be non-zero.

use drcc_cosim::model::drcc::dmr::engine::{Engine, Raised, E_EVAL, E_IDLE, E_SCAN, E_UPDATE};
use drcc_cosim::model::drcc::dmr::mailboxes::{Key, Mailboxes, RECEIVE, TRANSMIT};
use drcc_hdl::dmr::engine::{DmrEngine, MAILBOXES};
use drcc_hdl::dmr::mailbox_cfg::MailboxCfg;
use rust_hdl::prelude::*;

mod block_support;
use block_support::{settle, Rng};

/// `MailboxCfg` + `DmrEngine`, wired as the DRCC top will: the memory's read port
/// is the host's (`MB_SEL`) while held, the engine's while running.
#[derive(LogicBlock, Default)]
struct Bench<const M: usize> {
    clk: Signal<In, Clock>,
    hold: Signal<In, Bit>,
    clear_state: Signal<In, Bit>,
    timeout: Signal<In, Bits<16>>,
    ev: [Signal<In, Bit>; 6],
    key: [Signal<In, Bits<30>>; 6],
    eval: Signal<In, Bit>,
    mb_enable: Signal<In, Bits<16>>,
    mb_limits: Signal<In, Bits<128>>,
    mb_sel: Signal<In, Bits<4>>,
    we_id: Signal<In, Bit>,
    we_mask: Signal<In, Bit>,
    wdat: Signal<In, Bits<31>>,
    cfg: MailboxCfg,
    eng: DmrEngine<M>,
}

impl<const M: usize> Logic for Bench<M> {
    fn update(&mut self) {
        self.cfg.clk.next = self.clk.val();
        self.eng.clk.next = self.clk.val();
        self.cfg.read_address.next = if self.hold.val() {
            self.mb_sel.val()
        } else {
            self.eng.cfg_addr.val()
        };
        self.cfg.write_address.next = self.mb_sel.val();
        self.cfg.we_id.next = self.we_id.val();
        self.cfg.we_mask.next = self.we_mask.val();
        self.cfg.wdat.next = self.wdat.val();
        let e = &mut self.eng;
        e.hold.next = self.hold.val();
        e.clear_state.next = self.clear_state.val();
        e.timeout.next = self.timeout.val();
        e.tx_dcl.next = self.ev[0].val();
        e.tx_rcl.next = self.ev[1].val();
        e.rx_dcl.next = self.ev[2].val();
        e.rx_rcl.next = self.ev[3].val();
        e.req_dcl.next = self.ev[4].val();
        e.req_rcl.next = self.ev[5].val();
        e.key_tx_dcl.next = self.key[0].val();
        e.key_tx_rcl.next = self.key[1].val();
        e.key_rx_dcl.next = self.key[2].val();
        e.key_rx_rcl.next = self.key[3].val();
        e.key_req_dcl.next = self.key[4].val();
        e.key_req_rcl.next = self.key[5].val();
        e.eval.next = self.eval.val();
        e.mb_enable.next = self.mb_enable.val();
        e.mb_limits.next = self.mb_limits.val();
        e.cfg_id_word.next = self.cfg.id_word.val();
        e.cfg_mask.next = self.cfg.mask.val();
        e.mb_sel.next = self.mb_sel.val();
    }
}

/// One event input of a clock: none, or a key.
type Events = [Option<Key>; 6];

/// The inputs of one clock.
#[derive(Clone, Copy, Default)]
struct Inputs {
    hold: bool,
    clear_state: bool,
    ev: Events,
    eval: bool,
    mb_sel: u8,
    /// A configuration write through `MailboxCfg` (only while held): id or mask.
    write: Option<(bool, u32)>,
}

/// The verdict of an edge: (line, tx, deviation, mailbox).
type Verdict = (u8, bool, bool, u8);

/// How often the stimulus reached each path (asserted non-zero).
#[derive(Default, Debug)]
struct Coverage {
    states: [u64; 4],
    jobs: [u64; 6],
    evals: u64,
    found: u64,
    missed: u64,
    /// A job whose match was not the first matching candidate's competitor: a
    /// key matched by 2+ mailboxes (the lowest wins).
    multi_match: u64,
    faults: [[[u64; 2]; 2]; 2], // [deviation][tx][line]
    saturated: u64,
    again: u64,
    taken_and_set: u64,
    eval_overrun: u64,
    clear_over_write: u64,
    holds: u64,
    /// §4.2 settling: a mailbox's first timeout after a recovery re-balanced.
    rebalanced: u64,
    /// §4.2 debt: a copy brought an owed mailbox's counter back to 0.
    debts_paid: u64,
}

/// A run phase's character.
#[derive(Clone, Copy)]
struct Phase {
    /// Mean clocks between raises of one source.
    rate: [u64; 6],
    /// Clocks between `dmr_tick`s (0: none).
    eval_every: u64,
    /// Keys from the configured mailboxes (else random), percent.
    match_bias: u64,
    /// Every key aims at one mailbox per direction (saturation).
    focus: bool,
    /// Mean clocks between `clear_state`s (0: none).
    clear_every: u64,
}

struct Lockstep<const M: usize> {
    uut: Box<Bench<M>>,
    eng: Engine,
    mbx: Mailboxes,
    rng: Rng,
    timeout: u16,
    clock: u64,
    cov: Coverage,
}

impl<const M: usize> Lockstep<M> {
    fn new(seed: u64) -> Self {
        let mut uut = Box::<Bench<M>>::default();
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        let mut l = Lockstep {
            uut,
            eng: Engine::default(),
            mbx: Mailboxes::new(M),
            rng: Rng::new(seed),
            timeout: 100,
            clock: 0,
            cov: Coverage::default(),
        };
        l.settle();
        l
    }

    fn settle(&mut self) {
        settle(self.uut.as_mut(), "the DMR engine bench");
    }

    /// The configuration inputs the HDL reads from the (model's) registers.
    fn apply_cfg(&mut self) {
        let mut en = 0u64;
        let mut limits = Bits::<128>::default();
        for (i, b) in self.mbx.mb.iter().enumerate() {
            en |= (b.enable as u64) << i;
            for k in 0..7 {
                limits = limits.replace_bit(8 * i + k, b.limit & (1 << k) != 0);
            }
        }
        self.uut.mb_enable.next = en.into();
        self.uut.mb_limits.next = limits;
        self.uut.timeout.next = (self.timeout as u64).into();
    }

    /// One clock: both sides, compared.
    fn step(&mut self, i: &Inputs) {
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.hold.next = i.hold;
        u.clear_state.next = i.clear_state;
        for s in 0..6 {
            u.ev[s].next = i.ev[s].is_some();
            let k = i.ev[s].unwrap_or_default();
            u.key[s].next = ((k.id as u64) | (k.ide as u64) << 29).into();
        }
        u.eval.next = i.eval;
        u.mb_sel.next = (i.mb_sel as u64).into();
        u.we_id.next = matches!(i.write, Some((false, _)));
        u.we_mask.next = matches!(i.write, Some((true, _)));
        u.wdat.next = (i.write.map_or(0, |w| w.1) as u64).into();
        self.settle();
        // The verdict, combinational on the registers before the edge.
        let e = &self.uut.eng;
        let hdl: Option<Verdict> = e.fault.val().then(|| {
            (
                e.fault_line.val() as u8,
                e.fault_tx.val(),
                e.fault_deviation.val(),
                e.fault_mb.val().to_u64() as u8,
            )
        });
        self.uut.clk.next = Clock::from(true);
        self.settle();
        // The model's edge (DmrBlock::edge / hold order).
        let pre = self.eng;
        let pre_mbx = self.mbx.clone();
        let model: Option<Verdict> = if i.hold {
            self.eng = Engine::default();
            self.mbx.clear_state();
            None
        } else {
            let r = Raised {
                tx: [i.ev[0], i.ev[1]],
                rx: [i.ev[2], i.ev[3]],
                req: [i.ev[4], i.ev[5]],
                eval: i.eval,
            };
            let f = self.eng.edge(&r, &mut self.mbx, self.timeout);
            if i.clear_state {
                self.mbx.clear_for_recovery();
            }
            f.map(|f| {
                (
                    f.verdict.line as u8,
                    f.verdict.dir == TRANSMIT,
                    f.verdict.deviation,
                    f.mb,
                )
            })
        };
        if let Some((b, data)) = i.write {
            // The same configuration write into the model (held, MB_SEL addressed).
            let mb = &mut self.mbx.mb[i.mb_sel as usize];
            if b {
                mb.mask = data & 0x1FFF_FFFF;
            } else {
                mb.id = data & 0x1FFF_FFFF;
                mb.ide = data >> 29 & 1 == 1;
                mb.dir = data >> 30 & 1 == 1;
            }
        }
        let e = &self.uut.eng;
        let ctx = || {
            format!(
                "clock {}: inputs hold={} clear={} eval={} ev={:?}; model before {:?}",
                self.clock, i.hold, i.clear_state, i.eval, i.ev, pre
            )
        };
        assert_eq!(hdl, model, "verdict (line, tx, deviation, mb); {}", ctx());
        assert_eq!(
            e.e_state.val().to_u64() as u8,
            self.eng.e_state,
            "e_state; {}",
            ctx()
        );
        let sel = i.mb_sel as usize;
        assert_eq!(
            e.mb_state_word.val().to_u64() as u32,
            self.mbx.mb[sel].state_reg(),
            "MB_STATE of mailbox {sel}; {}",
            ctx()
        );
        self.cover(i, &pre, &pre_mbx, model);
        self.clock += 1;
    }

    fn cover(&mut self, i: &Inputs, pre: &Engine, pre_mbx: &Mailboxes, v: Option<Verdict>) {
        let c = &mut self.cov;
        c.states[pre.e_state as usize] += 1;
        if i.hold {
            return;
        }
        if let Some((line, tx, dev, _)) = v {
            c.faults[dev as usize][tx as usize][line as usize] += 1;
        }
        let pend = [
            pre.pend_tx[0],
            pre.pend_tx[1],
            pre.pend_rx[0],
            pre.pend_rx[1],
            pre.pend_req[0],
            pre.pend_req[1],
        ];
        c.again += pend
            .iter()
            .zip(i.ev.iter())
            .filter(|(p, e)| **p && e.is_some())
            .count() as u64;
        if pre.pend_eval && i.eval {
            c.eval_overrun += 1;
        }
        if pre.e_state == E_IDLE {
            if let Some(s) = (0..6).find(|&s| pend[s]) {
                c.jobs[s] += 1;
                c.taken_and_set += i.ev[s].is_some() as u64;
            } else if pre.pend_eval {
                c.evals += 1;
            }
        }
        if pre.e_state == E_UPDATE {
            if pre.e_found {
                c.found += 1;
                let dir = if pre.e_kind == drcc_cosim::model::drcc::dmr::engine::Kind::Rx {
                    RECEIVE
                } else {
                    TRANSMIT
                };
                let n = pre_mbx
                    .mb
                    .iter()
                    .filter(|b| b.matches(&pre.e_key, dir))
                    .count();
                c.multi_match += (n > 1) as u64;
                let b = &pre_mbx.mb[pre.e_hit as usize];
                let at_limit =
                    (b.counter == 127 && pre.e_line == 0) || (b.counter == -128 && pre.e_line == 1);
                c.saturated += (at_limit
                    && pre.e_kind != drcc_cosim::model::drcc::dmr::engine::Kind::Req)
                    as u64;
                let step = if pre.e_line == 0 { 1 } else { -1 };
                c.debts_paid += (b.owed
                    && pre.e_kind != drcc_cosim::model::drcc::dmr::engine::Kind::Req
                    && b.counter as i16 + step == 0) as u64;
                c.clear_over_write += i.clear_state as u64;
            } else {
                c.missed += 1;
            }
        }
        if pre.e_state == E_EVAL && !i.hold {
            let b = &pre_mbx.mb[pre.e_i as usize];
            let expired = b.counter != 0 && b.timer <= 1;
            let within = (b.counter as i16).abs() <= b.limit as i16;
            c.rebalanced += (b.enable && b.settle && !b.owed && expired && within) as u64;
        }
        if pre.e_state == E_EVAL && i.clear_state && pre_mbx.mb[pre.e_i as usize].enable {
            c.clear_over_write += 1;
        }
    }

    /// A held phase: configure every mailbox identically on both sides.
    fn configure(&mut self) {
        self.cov.holds += 1;
        let r = &mut self.rng;
        // A small pool of identifiers, so keys often match several mailboxes.
        let pool: Vec<(bool, u32)> = (0..6)
            .map(|_| {
                let ide = r.one_in(3);
                let id = if ide {
                    r.below(1 << 29) as u32
                } else {
                    r.below(1 << 11) as u32
                };
                (ide, id)
            })
            .collect();
        self.timeout = 1 + r.below(8) as u16;
        let mut writes = Vec::new();
        for m in 0..M {
            let (ide, id) = pool[r.below(pool.len() as u64) as usize];
            let dir = r.one_in(2);
            let mask: u32 = match r.below(5) {
                0 => 0x1FFF_FFFF,
                1 => 0x7FF,
                2 => 0x1FFF_FFF0,
                3 => r.below(1 << 29) as u32,
                _ => 0x1FFF_FF00,
            };
            let word = id | (ide as u32) << 29 | (dir as u32) << 30;
            writes.push((m as u8, false, word));
            writes.push((m as u8, true, mask));
            let b = &mut self.mbx.mb[m];
            b.enable = !r.one_in(5);
            b.limit = if r.one_in(8) {
                127
            } else {
                1 + r.below(4) as u8
            };
        }
        self.apply_cfg();
        for (m, is_mask, w) in writes {
            let sel = m;
            self.step(&Inputs {
                hold: true,
                mb_sel: sel,
                write: Some((is_mask, w)),
                ..Default::default()
            });
        }
        for k in 0..20 {
            self.step(&Inputs {
                hold: true,
                mb_sel: k % M as u8,
                ..Default::default()
            });
        }
    }

    /// A key for source `s` (0/1 TX, 2/3 RX, 4/5 REQ): mostly one a mailbox of the
    /// right direction matches, sometimes with bits outside its mask changed.
    fn key(&mut self, s: usize, bias: u64, focus: bool) -> Key {
        let r = &mut self.rng;
        if r.below(100) >= bias {
            let ide = r.one_in(2);
            return Key {
                ide,
                id: if ide {
                    r.below(1 << 29) as u32
                } else {
                    r.below(1 << 11) as u32
                },
            };
        }
        let dir = if s == 2 || s == 3 { RECEIVE } else { TRANSMIT };
        let cands: Vec<usize> = (0..M)
            .filter(|&m| self.mbx.mb[m].dir == dir && (self.mbx.mb[m].enable || !focus))
            .collect();
        let m = if focus && !cands.is_empty() {
            cands[0]
        } else if cands.is_empty() {
            r.below(M as u64) as usize
        } else {
            cands[r.below(cands.len() as u64) as usize]
        };
        let b = &self.mbx.mb[m];
        let width = if b.ide { 0x1FFF_FFFF } else { 0x7FF };
        let noise = r.next() as u32 & width & !b.mask;
        Key {
            ide: b.ide,
            id: (b.id ^ noise) & width,
        }
    }

    /// A running phase of `clocks` clocks.
    fn run(&mut self, p: Phase, clocks: u64) {
        let start = self.clock;
        while self.clock - start < clocks {
            let mut i = Inputs {
                mb_sel: (self.clock % M as u64) as u8,
                ..Default::default()
            };
            for s in 0..6 {
                if p.rate[s] != 0 && self.rng.one_in(p.rate[s]) {
                    i.ev[s] = Some(self.key(s, p.match_bias, p.focus));
                }
            }
            i.eval = p.eval_every != 0 && self.clock.is_multiple_of(p.eval_every);
            i.clear_state = p.clear_every != 0 && self.rng.one_in(p.clear_every);
            if p.clear_every != 0 && self.rng.one_in(6000) {
                // A short stretch in reset mode, the configuration kept.
                for _ in 0..1 + self.rng.below(3) {
                    self.step(&Inputs {
                        hold: true,
                        mb_sel: (self.clock % M as u64) as u8,
                        ..Default::default()
                    });
                }
                self.cov.holds += 1;
                continue;
            }
            self.step(&i);
        }
    }

    fn phase(&mut self) -> (Phase, u64) {
        let r = &mut self.rng;
        let sparse = 150;
        let burst = 4 + r.below(12);
        let mut rate = [sparse; 6];
        let kind = r.below(5);
        match kind {
            // Balanced, realistic rate (§4.4).
            0 => {}
            // Bursts: flags set again while pending, jobs back to back.
            1 => rate = [burst; 6],
            // One line lags or is silent: deviations and timeouts against it.
            2 | 3 => {
                let quiet = r.below(2) as usize;
                let slow = if kind == 2 { 0 } else { 600 };
                for s in [quiet, 2 + quiet, 4 + quiet] {
                    rate[s] = slow;
                }
                for s in [1 - quiet, 3 - quiet, 5 - quiet] {
                    rate[s] = 40 + r.below(120);
                }
            }
            // No evaluation, one line only, fast, one mailbox: counters saturate.
            _ => {
                let quiet = r.below(2) as usize;
                rate = [0; 6];
                rate[1 - quiet] = 20;
                rate[3 - quiet] = 20;
            }
        }
        let saturate = kind == 4;
        let eval_every = match (kind, r.below(6)) {
            (4, _) => 0,
            (_, 0) => 5 + r.below(12), // shorter than a round: pend_eval overruns
            _ => 40 + r.below(200),
        };
        let phase = Phase {
            rate,
            eval_every,
            match_bias: if saturate { 100 } else { 85 },
            focus: saturate,
            clear_every: if saturate { 0 } else { 1500 },
        };
        (phase, 2000 + r.below(4000))
    }
}

/// Runs `seed` for `clocks` clocks, counting into `cov` (the earlier seeds' counts).
fn lockstep<const M: usize>(seed: u64, clocks: u64, cov: Coverage) -> Coverage {
    let mut l = Lockstep::<M>::new(seed);
    l.cov = cov;
    l.configure();
    while l.clock < clocks {
        if l.rng.one_in(4) {
            l.configure();
        }
        let (p, n) = l.phase();
        l.run(p, n);
    }
    l.cov
}

#[test]
fn dmr_engine_lockstep_with_the_model() {
    lockstep_covers_every_case::<MAILBOXES>(1..=4, 60_000);
}

/// A DRCC generated with fewer mailboxes (the generation parameter `M`, §2): the
/// engine's schedule is `M + 2` clocks a job, `M + 1` an evaluation (§4.3).
#[test]
fn dmr_engine_lockstep_with_the_model_five_mailboxes() {
    lockstep_covers_every_case::<5>(11..=13, 60_000);
}

/// Lock step on the seeds; every coverage count of the §4 cases is non-zero.
fn lockstep_covers_every_case<const M: usize>(seeds: std::ops::RangeInclusive<u64>, clocks: u64) {
    let mut total = Coverage::default();
    for seed in seeds {
        total = lockstep::<M>(seed, clocks, total);
    }
    println!("coverage (M = {M}): {total:#?}");
    let t = &total;
    assert!(
        t.states.iter().all(|&n| n > 0),
        "every engine state: {:?}",
        t.states
    );
    assert!(
        t.jobs.iter().all(|&n| n > 0),
        "every event source: {:?}",
        t.jobs
    );
    assert!(t.evals > 0 && t.found > 0 && t.missed > 0 && t.multi_match > 0);
    for d in 0..2 {
        for tx in 0..2 {
            for l in 0..2 {
                assert!(
                    t.faults[d][tx][l] > 0,
                    "fault deviation={d} tx={tx} line={l} never found: {:?}",
                    t.faults
                );
            }
        }
    }
    assert!(t.saturated > 0, "a counter step at saturation");
    assert!(t.again > 0, "a flag set again while pending");
    assert!(t.taken_and_set > 0, "a flag taken and set at one edge");
    assert!(t.eval_overrun > 0, "pend_eval set while pending");
    assert!(t.clear_over_write > 0, "clear_state over an engine write");
    assert!(t.holds > 0);
    assert!(t.rebalanced > 0, "a settling mailbox re-balanced");
    assert!(t.debts_paid > 0, "a late copy paid an owed mailbox's debt");
}

#[test]
fn states_are_the_contracts() {
    // §4.3 numbering of the e_state probe.
    use drcc_hdl::dmr::engine as h;
    assert_eq!(
        [h::E_IDLE, h::E_SCAN, h::E_UPDATE, h::E_EVAL],
        [E_IDLE as u64, E_SCAN as u64, E_UPDATE as u64, E_EVAL as u64]
    );
}
