//! Block-level lock-step of the DMR control (`drcc_hdl::dmr::control::DmrControl`)
//! against the reference model's `DmrBlock` (`dmr_contract.md` §3, §5-§7): both get
//! the same seeded random inputs every clock, inputs that keep the channel's
//! protocol (a `tx_done` / `tx_failed` only for an attempt the block requested, an
//! abort ends it soon, a restart or reset cancels it), and every output and every
//! observable register is compared after every edge.
//!
//! The engine is not part of the block. How its events are checked:
//! 1. the raises (`raise_*`, `key_*`) are compared each edge with the events §4.1
//!    names, derived from the model's registers before the edge (`REQ(L)` = the
//!    `req` register with the read data's key, `TX(L)` = `tx_done` of a host copy
//!    while neither line has `tx_fault` with `key_sent`, `RX(L)` = the model's
//!    `rx_deliver` with the frame's key);
//! 2. a shadow of the model's engine (a clone of `eng` and `mbx` before the edge,
//!    stepped with the block's raises, then `clear_state` if the block says
//!    `clear_mailboxes`) must equal the model's `eng` and `mbx` after the edge: the
//!    model's engine latched exactly what the block raised (flags, keys, jobs);
//! 3. the shadow's verdict is what the block gets on `eval_*` (the verdict at the
//!    edge of the fault). With every mailbox disabled (first test) there is none;
//!    the second test enables mailboxes whose keys the traffic uses, so the model's
//!    own evaluation judges lines and the block hears the same verdict.

use drcc_cosim::frame::Frame;
use drcc_cosim::model::drcc::dmr::engine::{Engine, Raised};
use drcc_cosim::model::drcc::dmr::mailboxes::{Key, Mailboxes};
use drcc_cosim::model::drcc::dmr::{DmrBlock, DmrEvents, DmrInputs};
use drcc_cosim::model::drcc::regs::dmr::M_DEFAULT;
use drcc_cosim::model::drcc::regs::idx;
use drcc_hdl::dmr::control::DmrControl;
use rust_hdl::prelude::*;

/// splitmix64: seeded, deterministic.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    /// True with probability `p`.
    fn chance(&mut self, p: f64) -> bool {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 <= p
    }
    fn range(&mut self, lo: u64, hi: u64) -> u64 {
        lo + self.below(hi - lo + 1)
    }
}

/// The configuration (from `DmrRegs` in the DRCC); small, so that every timer runs
/// out many times.
#[derive(Clone, Copy, Debug)]
struct Cfg {
    timeout: u16,
    cs_period: u16,
    tick_bits: u16,
    recovery_delay: u16,
    cs_id: [u32; 2],
}

impl Cfg {
    fn random(r: &mut Rng) -> Self {
        let dcl = r.range(0x700, 0x7FF) as u32;
        let mut rcl = r.range(0x700, 0x7FF) as u32;
        if rcl == dcl {
            rcl ^= 1;
        }
        Cfg {
            timeout: r.range(2, 12) as u16,
            cs_period: if r.chance(0.3) {
                0
            } else {
                r.range(1, 12) as u16
            },
            tick_bits: r.range(1, 4) as u16,
            recovery_delay: r.range(1, 10) as u16,
            cs_id: [dcl, rcl],
        }
    }

    /// Into the model's register words (§2.1).
    fn apply(&self, m: &mut DmrBlock) {
        m.cfg = self.timeout as u32 | (self.cs_period as u32) << 16;
        m.time = self.tick_bits as u32 | (self.recovery_delay as u32) << 16;
        m.cs = self.cs_id[0] | self.cs_id[1] << 16;
    }
}

/// The frame keys of the traffic in the mailbox test (none is a CS identifier).
const POOL: [(bool, u32); 4] = [
    (false, 0x100),
    (false, 0x101),
    (true, 0x0123_4567),
    (false, 0x2A5),
];

/// One attempt of a channel: clocks left and whether it ends in `tx_failed`.
#[derive(Clone, Copy, Debug)]
struct Attempt {
    left: u32,
    fail: bool,
}

/// What makes the random inputs of one line follow the channel's protocol.
#[derive(Clone, Copy, Debug, Default)]
struct Chan {
    att: Option<Attempt>,
    err_state: u8,
    /// Clocks left in the present error state (1 or 2).
    err_left: u32,
}

/// How often each path was reached (asserted non-zero at the end).
#[derive(Debug, Default)]
struct Coverage {
    edges: u64,
    holds: u64,
    rsts: u64,
    dmr_ticks: u64,
    host_req: [u64; 2],
    cs_req: [u64; 2],
    periodic_cs: u64,
    first_copies: u64,
    pops: u64,
    cs_success: u64,
    recoveries: u64,
    cs_failed: u64,
    busoff: u64,
    eval_tx: u64,
    eval_rx: u64,
    eval_rx_ignored: u64,
    deletion_abort: u64,
    cs_abort: u64,
    returns: u64,
    restarts: u64,
    acl_switches: u64,
    state: [u64; 4],
    cs_good: u64,
    cs_bad: u64,
    raise_tx: u64,
    raise_rx: u64,
    raise_req: u64,
    raise_eval: u64,
}

struct Bench {
    uut: Box<DmrControl>,
    model: DmrBlock,
    r: Rng,
    cfg: Cfg,
    chan: [Chan; 2],
    /// Entries in the test-side queue (pushes in, the block's `pop` out).
    q_count: u8,
    rd_sel: bool,
    hold: bool,
    hold_left: u32,
    prev_hold: bool,
    rd: Frame,
    /// Mailbox test: enable mailboxes over the pool keys.
    mailboxes: bool,
    cov: Coverage,
    clock: u64,
    seed: u64,
}

fn bits<const N: usize>(v: u64) -> Bits<N> {
    v.into()
}

fn key30(k: &Key) -> u64 {
    k.id as u64 | (k.ide as u64) << 29
}

impl Bench {
    fn new(seed: u64, mailboxes: bool) -> Self {
        let mut uut = Box::<DmrControl>::default();
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        assert!(simulate(uut.as_mut(), 400));
        let mut r = Rng(seed);
        let cfg = Cfg::random(&mut r);
        let mut b = Bench {
            uut,
            model: DmrBlock::new(M_DEFAULT),
            r,
            cfg,
            chan: [Chan::default(); 2],
            q_count: 0,
            rd_sel: false,
            hold: true,
            hold_left: 3,
            prev_hold: true,
            rd: Frame::default(),
            mailboxes,
            cov: Coverage::default(),
            clock: 0,
            seed,
        };
        b.setup_mailboxes();
        b
    }

    /// The mailbox test's configuration (after every `rst`, which clears `enable`
    /// and `limit`): transmit and receive mailboxes over the pool keys.
    fn setup_mailboxes(&mut self) {
        if !self.mailboxes {
            return;
        }
        for (i, b) in self.model.mbx.mb.iter_mut().enumerate().take(8) {
            let (ide, id) = POOL[i % 4];
            b.ide = ide;
            b.id = id;
            b.dir = i < 4;
            b.mask = 0x1FFF_FFFF;
            b.limit = 1 + (i as u8 % 3);
            b.enable = true;
        }
    }

    fn frame(&mut self, cs_share: f64) -> Frame {
        let r = &mut self.r;
        if r.chance(cs_share) {
            // a CS frame: the line's own identifier, the other one, or a near miss
            let id = self.cfg.cs_id[r.below(2) as usize];
            let mut f = Frame {
                id,
                ..Frame::default()
            };
            match r.below(8) {
                0 => f.dlc = r.range(1, 15) as u8,
                1 => f.rtr = true,
                2 => f.ide = true,
                _ => {}
            }
            return f;
        }
        let (ide, id) = if self.mailboxes || r.chance(0.5) {
            POOL[r.below(4) as usize]
        } else if r.chance(0.5) {
            (true, r.below(1 << 29) as u32)
        } else {
            // a base frame's rx_id[28:11] read 0 (timing contract)
            (false, r.below(0x700) as u32)
        };
        Frame {
            id,
            ide,
            rtr: r.chance(0.1),
            dlc: r.below(16) as u8,
            data: [0; 8],
        }
    }

    /// The error state of a line's channel: mostly error active, sometimes passive,
    /// sometimes bus-off for a while (§6 bus-off faults).
    fn walk_err_state(&mut self, l: usize) {
        let c = &mut self.chan[l];
        if c.err_left > 0 {
            c.err_left -= 1;
            if c.err_left == 0 {
                c.err_state = if c.err_state == 1 && self.r.chance(0.5) {
                    c.err_left = self.r.range(20, 300) as u32;
                    2
                } else {
                    0
                };
            }
        } else if self.r.chance(0.0015) {
            c.err_state = 1;
            c.err_left = self.r.range(5, 100) as u32;
        }
    }

    fn run(&mut self, clocks: u64) {
        for _ in 0..clocks {
            self.step();
        }
    }

    fn step(&mut self) {
        self.clock += 1;
        // ---- this clock's inputs ----
        let rst = self.clock <= 2 || self.r.chance(0.0003);
        if self.hold_left > 0 {
            self.hold_left -= 1;
            self.hold = self.hold_left > 0;
        } else if self.r.chance(0.0008) {
            self.hold = true;
            self.hold_left = self.r.range(1, 40) as u32;
        }
        if self.hold && self.r.chance(0.05) {
            // the configuration changes only in reset mode
            self.cfg = Cfg::random(&mut self.r);
        }
        let hold = self.hold;
        // reset_mode_q: the DRCC's registered reset mode, 1 the clock after hold
        let reset_mode_q = self.prev_hold;
        self.prev_hold = hold;
        let tick = self.r.chance(0.3);
        let mut done = [false; 2];
        let mut failed = [false; 2];
        let mut rx_valid = [false; 2];
        let mut rx_frame = [Frame::default(); 2];
        for l in 0..2 {
            if let Some(mut a) = self.chan[l].att {
                a.left -= 1;
                if a.left == 0 {
                    done[l] = !a.fail;
                    failed[l] = a.fail;
                    self.chan[l].att = None;
                } else {
                    self.chan[l].att = Some(a);
                }
            }
            // with mailboxes, frames a frame's time apart (§4.4: else the engine's
            // event jobs starve the evaluation)
            if self.r.chance(if self.mailboxes { 0.012 } else { 0.06 }) {
                rx_valid[l] = true;
                rx_frame[l] = self.frame(0.3);
            } else if self.r.chance(0.5) {
                // an idle channel's rx outputs hold old values
                rx_frame[l] = self.frame(0.3);
            }
            self.walk_err_state(l);
        }
        let push =
            !hold && self.q_count < 8 && self.r.chance(if self.mailboxes { 0.03 } else { 0.08 });
        // the read data register: the entry of the line rd_sel served last edge
        let (ide, id) = if self.mailboxes || self.r.chance(0.5) {
            POOL[self.r.below(4) as usize]
        } else {
            (true, self.r.below(1 << 29) as u32)
        };
        self.rd = Frame {
            id,
            ide,
            ..Frame::default()
        };
        let rd_sel = self.rd_sel;
        let inputs = DmrInputs {
            running: !hold,
            tick,
            reset_mode_q,
            done,
            failed,
            rx_valid,
            rx_frame,
            err_state: [self.chan[0].err_state, self.chan[1].err_state],
            q_count: self.q_count,
            rd: self.rd,
            rd_sel: rd_sel as u8,
        };

        // ---- the block: clk low, inputs, settle ----
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.rst.next = rst;
        u.hold.next = hold;
        u.timeout.next = bits(self.cfg.timeout as u64);
        u.cs_period.next = bits(self.cfg.cs_period as u64);
        u.tick_bits.next = bits(self.cfg.tick_bits as u64);
        u.recovery_delay.next = bits(self.cfg.recovery_delay as u64);
        u.cs_id_dcl.next = bits(self.cfg.cs_id[0] as u64);
        u.cs_id_rcl.next = bits(self.cfg.cs_id[1] as u64);
        u.tick.next = tick;
        u.reset_mode_q.next = reset_mode_q;
        u.done_dcl.next = done[0];
        u.done_rcl.next = done[1];
        u.failed_dcl.next = failed[0];
        u.failed_rcl.next = failed[1];
        u.rx_valid_dcl.next = rx_valid[0];
        u.rx_valid_rcl.next = rx_valid[1];
        u.rx_ide_dcl.next = rx_frame[0].ide;
        u.rx_ide_rcl.next = rx_frame[1].ide;
        u.rx_rtr_dcl.next = rx_frame[0].rtr;
        u.rx_rtr_rcl.next = rx_frame[1].rtr;
        u.rx_dlc_dcl.next = bits(rx_frame[0].dlc as u64);
        u.rx_dlc_rcl.next = bits(rx_frame[1].dlc as u64);
        u.rx_id_dcl.next = bits(rx_frame[0].id as u64);
        u.rx_id_rcl.next = bits(rx_frame[1].id as u64);
        u.err_state_dcl.next = bits(self.chan[0].err_state as u64);
        u.err_state_rcl.next = bits(self.chan[1].err_state as u64);
        u.q_count.next = bits(self.q_count as u64);
        u.rd_ide.next = self.rd.ide;
        u.rd_id.next = bits(self.rd.id as u64);
        u.rd_sel.next = rd_sel;
        u.eval_fault.next = false;
        u.eval_line.next = false;
        u.eval_tx.next = false;
        u.eval_deviation.next = false;
        u.eval_mb.next = bits(0);
        assert!(simulate(u, 400), "did not settle");

        // ---- the raises, and the engine's verdict on them (shadow of the model) ----
        let u = &self.uut;
        let raised = Raised {
            tx: [
                u.raise_tx_dcl
                    .val()
                    .then(|| key_of(u.key_tx_dcl.val().to_u64())),
                u.raise_tx_rcl
                    .val()
                    .then(|| key_of(u.key_tx_rcl.val().to_u64())),
            ],
            rx: [
                u.raise_rx_dcl
                    .val()
                    .then(|| key_of(u.key_rx_dcl.val().to_u64())),
                u.raise_rx_rcl
                    .val()
                    .then(|| key_of(u.key_rx_rcl.val().to_u64())),
            ],
            req: [
                u.raise_req_dcl
                    .val()
                    .then(|| key_of(u.key_req_dcl.val().to_u64())),
                u.raise_req_rcl
                    .val()
                    .then(|| key_of(u.key_req_rcl.val().to_u64())),
            ],
            eval: u.raise_eval.val(),
        };
        let c = self.model.clone();
        let running = !rst && !hold;
        let mut shadow_eng: Engine = c.eng;
        let mut shadow_mbx: Mailboxes = c.mbx.clone();
        let verdict = if running {
            shadow_eng.edge(&raised, &mut shadow_mbx, c.timeout())
        } else {
            None
        };
        if let Some(f) = verdict {
            let u = self.uut.as_mut();
            u.eval_fault.next = true;
            u.eval_line.next = f.verdict.line == 1;
            u.eval_tx.next = f.verdict.dir;
            u.eval_deviation.next = f.verdict.deviation;
            u.eval_mb.next = bits(f.mb as u64);
            assert!(simulate(u, 400), "did not settle");
            if f.verdict.dir {
                self.cov.eval_tx += 1;
            } else if c.tx_fault[f.verdict.line] {
                self.cov.eval_rx_ignored += 1;
            } else {
                self.cov.eval_rx += 1;
            }
        }
        // combinational outputs of this edge
        let u = &self.uut;
        let got_ev = DmrEvents {
            pop: u.pop.val().to_u64() as u8,
            tx_done: u.tx_done_evt.val(),
            int: u.int_evt.val(),
            acl_switch: u.acl_switch.val(),
            rx_deliver: [u.rx_deliver_dcl.val(), u.rx_deliver_rcl.val()],
        };
        let clear_mailboxes = u.clear_mailboxes.val();

        // ---- the edge ----
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(true);
        assert!(simulate(u, 400), "did not settle");
        let ev = if rst {
            self.model.rst();
            self.setup_mailboxes();
            DmrEvents::default()
        } else {
            self.cfg.apply(&mut self.model);
            self.model.edge(&inputs)
        };
        self.cfg.apply(&mut self.model);

        // ---- compare ----
        let at = format!("seed {} clock {}", self.seed, self.clock);
        if running {
            self.check_raises(&c, &inputs, &raised, &ev, &at);
            if clear_mailboxes {
                shadow_mbx.clear_state();
            }
            assert_eq!(shadow_eng, self.model.eng, "{at}: engine registers");
            assert_eq!(shadow_mbx, self.model.mbx, "{at}: mailboxes");
        } else {
            let none = [raised.tx, raised.rx, raised.req];
            assert!(
                none.iter().flatten().all(Option::is_none) && !clear_mailboxes,
                "{at}: events while held"
            );
        }
        assert_eq!(got_ev.pop, ev.pop, "{at}: pop");
        assert_eq!(got_ev.tx_done, ev.tx_done, "{at}: tx_done_evt");
        assert_eq!(got_ev.int, ev.int, "{at}: int_evt");
        assert_eq!(got_ev.acl_switch, ev.acl_switch, "{at}: acl_switch");
        assert_eq!(got_ev.rx_deliver, ev.rx_deliver, "{at}: rx_deliver");
        self.check_registers(&at);
        self.coverage(&c, &inputs, &ev, rst, hold);
        let n = |k: &[Option<Key>; 2]| k.iter().flatten().count() as u64;
        self.cov.raise_tx += n(&raised.tx);
        self.cov.raise_rx += n(&raised.rx);
        self.cov.raise_req += n(&raised.req);

        // ---- the environment follows the block's outputs ----
        assert!(ev.pop <= self.q_count, "{at}: pop beyond the queue");
        self.q_count = self.q_count - ev.pop + push as u8;
        self.rd_sel = !hold && !rst && !self.rd_sel;
        let u = &self.uut;
        let tx_req = [u.tx_req_dcl.val(), u.tx_req_rcl.val()];
        let abort = [u.tx_abort_dcl.val(), u.tx_abort_rcl.val()];
        let restart = [u.restart_dcl.val(), u.restart_rcl.val()];
        for l in 0..2 {
            // the channel's rst (hold, rst, reset_mode_q, restart) ends any attempt
            if rst || hold || restart[l] || self.prev_hold {
                self.chan[l].att = None;
                if restart[l] || (rst && self.r.chance(0.5)) {
                    self.chan[l].err_state = 0;
                    self.chan[l].err_left = 0;
                }
                continue;
            }
            if tx_req[l] {
                assert!(self.chan[l].att.is_none(), "{at}: tx_req during an attempt");
                // mostly a frame's time; sometimes long (arbitration lost, errors),
                // so that CS attempts time out
                let left = match self.r.below(10) {
                    0 => self.r.range(60, 300),
                    1 | 2 => self.r.range(15, 60),
                    _ => self.r.range(1, 15),
                };
                self.chan[l].att = Some(Attempt {
                    left: left as u32,
                    // only aborts fail in DMR mode (§5); a rare unprovoked failure
                    // still checks the rule the model defines for it
                    fail: self.r.chance(0.01),
                });
            }
            if abort[l] {
                if let Some(a) = &mut self.chan[l].att {
                    // an abort usually ends the attempt soon; it may lose the race
                    if self.r.chance(0.85) {
                        a.fail = true;
                        a.left = a.left.min(self.r.range(1, 4) as u32);
                    }
                }
            }
        }
    }

    /// §4.1 events from the model's registers before the edge (`c`), against the
    /// block's raises.
    fn check_raises(&self, c: &DmrBlock, i: &DmrInputs, raised: &Raised, ev: &DmrEvents, at: &str) {
        for l in 0..2 {
            let o = 1 - l;
            let rx =
                (i.rx_valid[l] && !c.is_cs_frame(&i.rx_frame[l])).then(|| Key::of(&i.rx_frame[l]));
            assert_eq!(
                rx.is_some(),
                ev.rx_deliver[l],
                "{at}: RX({l}) vs the model's rx_deliver"
            );
            assert_eq!(raised.rx[l], rx, "{at}: RX({l})");
            let req = c.req[l].then(|| Key::of(&i.rd));
            assert_eq!(raised.req[l], req, "{at}: REQ({l})");
            let tx = (i.done[l] && !c.cs_busy[l] && c.busy[l] && !c.tx_fault[l] && !c.tx_fault[o])
                .then_some(c.key_sent[l]);
            assert_eq!(raised.tx[l], tx, "{at}: TX({l})");
        }
        assert_eq!(raised.eval, c.dmr_tick, "{at}: eval");
    }

    /// Every register of the model against the block's.
    fn check_registers(&self, at: &str) {
        let m = &self.model;
        let u = &self.uut;
        let tb = &u.time_base;
        assert_eq!(tb.tb_cnt.q.val().to_u64(), m.tb_cnt as u64, "{at}: tb_cnt");
        assert_eq!(tb.tick_q.q.val(), m.dmr_tick, "{at}: dmr_tick");
        assert_eq!(u.dmr_tick.val(), m.dmr_tick, "{at}: dmr_tick out");
        assert_eq!(u.raise_eval.val(), m.dmr_tick, "{at}: raise_eval");
        assert_eq!(
            tb.period_cnt.q.val().to_u64(),
            m.period_cnt as u64,
            "{at}: period_cnt"
        );
        let offs = [u.off_dcl.val().to_u64(), u.off_rcl.val().to_u64()];
        let tx_req = [u.tx_req_dcl.val(), u.tx_req_rcl.val()];
        let cs_req = [u.cs_req_dcl.val(), u.cs_req_rcl.val()];
        let abort = [u.tx_abort_dcl.val(), u.tx_abort_rcl.val()];
        let restart = [u.restart_dcl.val(), u.restart_rcl.val()];
        let tx_fault = [u.dcl_tx_fault.val(), u.rcl_tx_fault.val()];
        let rx_fault = [u.dcl_rx_fault.val(), u.rcl_rx_fault.val()];
        for (l, line) in [&u.dcl, &u.rcl].into_iter().enumerate() {
            assert_eq!(offs[l], m.off[l] as u64, "{at}: off[{l}]");
            assert_eq!(tx_req[l], m.tx_req(l), "{at}: tx_req[{l}]");
            assert_eq!(cs_req[l], m.cs_req[l], "{at}: cs_req[{l}]");
            assert_eq!(abort[l], m.abort[l], "{at}: abort[{l}]");
            assert_eq!(restart[l], m.restart[l], "{at}: restart[{l}]");
            assert_eq!(tx_fault[l], m.tx_fault[l], "{at}: tx_fault[{l}]");
            assert_eq!(rx_fault[l], m.rx_fault[l], "{at}: rx_fault[{l}]");
            assert_eq!(line.req_q.q.val(), m.req[l], "{at}: req[{l}]");
            assert_eq!(line.busy_q.q.val(), m.busy[l], "{at}: busy[{l}]");
            assert_eq!(line.cs_busy_q.q.val(), m.cs_busy[l], "{at}: cs_busy[{l}]");
            assert_eq!(line.cs_live_q.q.val(), m.cs_live[l], "{at}: cs_live[{l}]");
            assert_eq!(line.cs_due_q.q.val(), m.cs_due[l], "{at}: cs_due[{l}]");
            assert_eq!(
                line.rec_pending_q.q.val(),
                m.rec_pending[l],
                "{at}: rec_pending[{l}]"
            );
            assert_eq!(line.busoff_q.q.val(), m.busoff_q[l], "{at}: busoff_q[{l}]");
            assert_eq!(
                line.key_sent_q.q.val().to_u64(),
                key30(&m.key_sent[l]),
                "{at}: key_sent[{l}]"
            );
            // One timer per line: the CS timer while an attempt is live, else the
            // recovery timer (the model keeps two; a live attempt has rec_timer 0).
            assert!(
                !m.cs_live[l] || m.rec_timer[l] == 0,
                "{at}: cs_live with rec_timer"
            );
            let t = if m.cs_busy[l] && m.cs_live[l] {
                m.cs_timer[l]
            } else {
                m.rec_timer[l]
            };
            assert_eq!(line.timer_q.q.val().to_u64(), t as u64, "{at}: timer[{l}]");
        }
        assert_eq!(u.acl.val(), m.acl != 0, "{at}: acl");
        assert_eq!(
            u.dmr_state.val().to_u64(),
            m.dmr_state as u64,
            "{at}: dmr_state"
        );
        let st = &u.status;
        assert_eq!(st.cause_q.q.val().to_u64(), m.cause as u64, "{at}: cause");
        assert_eq!(
            st.cause_line_q.q.val(),
            m.cause_line != 0,
            "{at}: cause_line"
        );
        assert_eq!(
            st.cause_mb_q.q.val().to_u64(),
            m.cause_mb as u64,
            "{at}: cause_mb"
        );
        let read = |adr| m.read(adr, false, 0).unwrap() as u64;
        assert_eq!(
            u.status_word.val().to_u64(),
            read(idx::DMR_STATUS),
            "{at}: DMR_STATUS"
        );
        assert_eq!(
            u.cs_count_word.val().to_u64(),
            read(idx::DMR_CS_COUNT),
            "{at}: DMR_CS_COUNT"
        );
    }

    fn coverage(&mut self, c: &DmrBlock, i: &DmrInputs, ev: &DmrEvents, rst: bool, hold: bool) {
        let m = &self.model;
        let v = &mut self.cov;
        v.edges += 1;
        if rst {
            v.rsts += 1;
            return;
        }
        if hold {
            v.holds += 1;
            return;
        }
        v.dmr_ticks += m.dmr_tick as u64;
        v.first_copies += ev.tx_done as u64;
        v.pops += (ev.pop > 0) as u64;
        v.acl_switches += ev.acl_switch as u64;
        v.state[m.dmr_state as usize] += 1;
        v.raise_eval += c.dmr_tick as u64;
        for l in 0..2 {
            v.host_req[l] += m.req[l] as u64;
            v.cs_req[l] += m.cs_req[l] as u64;
            v.restarts += m.restart[l] as u64;
            if c.cs_busy[l] && !m.cs_busy[l] && c.cs_live[l] && !m.tx_fault[l] && !m.rx_fault[l] {
                v.cs_success += 1;
                if c.tx_fault[l] || c.rx_fault[l] {
                    v.recoveries += 1;
                }
            }
            if m.abort[l] && c.busy[l] && m.tx_fault[l] && !c.tx_fault[l] {
                v.deletion_abort += 1;
            }
            if m.abort[l] && c.cs_busy[l] {
                v.cs_abort += 1;
            }
            // return: the line sends again while the other one sends
            if c.tx_fault[l] && !m.tx_fault[l] && !c.tx_fault[1 - l] && !m.tx_fault[1 - l] {
                v.returns += 1;
            }
            if !c.cs_due[l] && m.cs_due[l] && !c.tx_fault[l] && !c.rx_fault[l] {
                v.periodic_cs += 1;
            }
            v.cs_good += (m.cs_count[2 * l] > c.cs_count[2 * l]) as u64;
            v.cs_bad += (m.cs_count[2 * l + 1] > c.cs_count[2 * l + 1]) as u64;
        }
        for l in 0..2 {
            // the model's own conditions on its pre-edge registers (§6, §7)
            if c.cs_busy[l] && c.cs_live[l] && c.dmr_tick && c.cs_timer[l] == 1 {
                v.cs_failed += 1;
            }
            if !c.busoff_q[l] && i.err_state[l] == 2 {
                v.busoff += 1;
            }
        }
    }
}

fn key_of(v: u64) -> Key {
    Key {
        ide: v >> 29 & 1 != 0,
        id: (v & 0x1FFF_FFFF) as u32,
    }
}

fn report(name: &str, cov: &Coverage) {
    eprintln!("{name}: {cov:#?}");
}

fn check_coverage(cov: &Coverage, mailboxes: bool) {
    let named = [
        ("holds", cov.holds),
        ("rsts", cov.rsts),
        ("dmr_ticks", cov.dmr_ticks),
        ("host_req DCL", cov.host_req[0]),
        ("host_req RCL", cov.host_req[1]),
        ("cs_req DCL", cov.cs_req[0]),
        ("cs_req RCL", cov.cs_req[1]),
        ("periodic_cs", cov.periodic_cs),
        ("first_copies", cov.first_copies),
        ("pops", cov.pops),
        ("cs_success", cov.cs_success),
        ("recoveries", cov.recoveries),
        ("cs_failed", cov.cs_failed),
        ("busoff", cov.busoff),
        ("deletion_abort", cov.deletion_abort),
        ("cs_abort", cov.cs_abort),
        ("returns", cov.returns),
        ("restarts", cov.restarts),
        ("acl_switches", cov.acl_switches),
        ("state active", cov.state[0]),
        ("state disabled", cov.state[2]),
        ("state disconnected", cov.state[3]),
        ("cs_good", cov.cs_good),
        ("cs_bad", cov.cs_bad),
        ("raise_tx", cov.raise_tx),
        ("raise_rx", cov.raise_rx),
        ("raise_req", cov.raise_req),
        ("raise_eval", cov.raise_eval),
    ];
    for (n, v) in named {
        assert!(v > 0, "coverage: {n} never reached");
    }
    if mailboxes {
        for (n, v) in [
            ("eval tx fault", cov.eval_tx),
            ("eval rx fault", cov.eval_rx),
            ("eval rx fault on a tx-faulty line", cov.eval_rx_ignored),
            ("state passive", cov.state[1]),
        ] {
            assert!(v > 0, "coverage: {n} never reached");
        }
    }
}

const CLOCKS: u64 = 25_000;

/// Every mailbox disabled: the engine never judges; everything else of the block.
#[test]
fn dmr_control_lockstep_no_verdicts() {
    let mut total = Coverage::default();
    for seed in [1u64, 2, 3, 4] {
        let mut b = Bench::new(seed, false);
        b.run(CLOCKS);
        report(&format!("seed {seed}"), &b.cov);
        add(&mut total, &b.cov);
    }
    report("total", &total);
    check_coverage(&total, false);
    assert_eq!(total.eval_tx + total.eval_rx + total.eval_rx_ignored, 0);
}

/// Mailboxes enabled over the traffic's keys: the model's evaluation judges the
/// lines (deviations and timeouts, transmit and receive), the block gets the same
/// verdict on `eval_*`.
#[test]
fn dmr_control_lockstep_with_verdicts() {
    let mut total = Coverage::default();
    for seed in [11u64, 12, 13, 14] {
        let mut b = Bench::new(seed, true);
        b.run(CLOCKS);
        report(&format!("seed {seed}"), &b.cov);
        add(&mut total, &b.cov);
    }
    report("total", &total);
    check_coverage(&total, true);
}

fn add(t: &mut Coverage, c: &Coverage) {
    macro_rules! sum {
        ($($f:ident),*) => { $( t.$f += c.$f; )* };
    }
    sum!(
        edges,
        holds,
        rsts,
        dmr_ticks,
        periodic_cs,
        first_copies,
        pops,
        cs_success,
        recoveries,
        cs_failed,
        busoff,
        eval_tx,
        eval_rx,
        eval_rx_ignored,
        deletion_abort,
        cs_abort,
        returns,
        restarts,
        acl_switches,
        cs_good,
        cs_bad,
        raise_tx,
        raise_rx,
        raise_req,
        raise_eval
    );
    for l in 0..2 {
        t.host_req[l] += c.host_req[l];
        t.cs_req[l] += c.cs_req[l];
    }
    for s in 0..4 {
        t.state[s] += c.state[s];
    }
}
