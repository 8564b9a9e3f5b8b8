//! One clock of the DMR control lock-step: the inputs of the clock (following the
//! channel's protocol), the block in rust-hdl's simulator and the model's
//! `DmrBlock` stepped with them, the shadow engine, and the environment's answer
//! to the block's outputs.

use super::checks::Coverage;
use super::stimulus::*;
use drcc_cosim::frame::Frame;
use drcc_cosim::model::drcc::dmr::engine::{Engine, Raised};
use drcc_cosim::model::drcc::dmr::mailboxes::{Key, Mailboxes};
use drcc_cosim::model::drcc::dmr::{DmrBlock, DmrEvents, DmrInputs};
use drcc_cosim::model::drcc::regs::dmr::M_DEFAULT;
use drcc_hdl::dmr::control::DmrControl;
use rust_hdl::prelude::*;

pub struct Bench {
    pub uut: Box<DmrControl>,
    pub model: DmrBlock,
    pub r: Rng,
    pub cfg: Cfg,
    pub chan: [Chan; 2],
    /// Entries in the test-side queue (pushes in, the block's `pop` out).
    pub q_count: u8,
    pub rd_sel: bool,
    pub hold: bool,
    pub hold_left: u32,
    pub prev_hold: bool,
    pub rd: Frame,
    /// Mailbox test: enable mailboxes over the pool keys.
    pub mailboxes: bool,
    pub cov: Coverage,
    pub clock: u64,
    pub seed: u64,
}

pub fn bits<const N: usize>(v: u64) -> Bits<N> {
    v.into()
}

pub fn key30(k: &Key) -> u64 {
    k.id as u64 | (k.ide as u64) << 29
}

impl Bench {
    pub fn new(seed: u64, mailboxes: bool) -> Self {
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
    pub fn setup_mailboxes(&mut self) {
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

    pub fn frame(&mut self, cs_share: f64) -> Frame {
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
    pub fn walk_err_state(&mut self, l: usize) {
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

    pub fn run(&mut self, clocks: u64) {
        for _ in 0..clocks {
            self.step();
        }
    }

    pub fn step(&mut self) {
        self.clock += 1;
        let (rst, hold, push, inputs) = self.draw_inputs();
        self.drive(rst, hold, &inputs);

        // ---- the raises, and the engine's verdict on them (shadow of the model) ----
        let raised = self.raises();
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
                shadow_mbx.clear_for_recovery();
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
        self.follow(rst, hold, push, &ev, &at);
    }

    /// This clock's inputs, drawn: reset, hold (reset mode), the channels'
    /// attempts, frames and error states, a push, the read data register.
    /// Returns (rst, hold, push, the model's inputs).
    fn draw_inputs(&mut self) -> (bool, bool, bool, DmrInputs) {
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
        (rst, hold, push, inputs)
    }

    /// The block's inputs for this clock, clock low, settled.
    fn drive(&mut self, rst: bool, hold: bool, inputs: &DmrInputs) {
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
        u.tick.next = inputs.tick;
        u.reset_mode_q.next = inputs.reset_mode_q;
        u.done_dcl.next = inputs.done[0];
        u.done_rcl.next = inputs.done[1];
        u.failed_dcl.next = inputs.failed[0];
        u.failed_rcl.next = inputs.failed[1];
        u.rx_valid_dcl.next = inputs.rx_valid[0];
        u.rx_valid_rcl.next = inputs.rx_valid[1];
        u.rx_ide_dcl.next = inputs.rx_frame[0].ide;
        u.rx_ide_rcl.next = inputs.rx_frame[1].ide;
        u.rx_rtr_dcl.next = inputs.rx_frame[0].rtr;
        u.rx_rtr_rcl.next = inputs.rx_frame[1].rtr;
        u.rx_dlc_dcl.next = bits(inputs.rx_frame[0].dlc as u64);
        u.rx_dlc_rcl.next = bits(inputs.rx_frame[1].dlc as u64);
        u.rx_id_dcl.next = bits(inputs.rx_frame[0].id as u64);
        u.rx_id_rcl.next = bits(inputs.rx_frame[1].id as u64);
        u.err_state_dcl.next = bits(self.chan[0].err_state as u64);
        u.err_state_rcl.next = bits(self.chan[1].err_state as u64);
        u.q_count.next = bits(self.q_count as u64);
        u.rd_ide.next = self.rd.ide;
        u.rd_id.next = bits(self.rd.id as u64);
        u.rd_sel.next = self.rd_sel;
        u.eval_fault.next = false;
        u.eval_line.next = false;
        u.eval_tx.next = false;
        u.eval_deviation.next = false;
        u.eval_mb.next = bits(0);
        assert!(simulate(u, 400), "did not settle");
    }

    /// The block's raises of this clock (before the edge).
    fn raises(&self) -> Raised {
        let u = &self.uut;
        Raised {
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
        }
    }

    /// The environment follows the block's outputs: the TX queue, the read
    /// selection, the channels' attempts (started, aborted, ended by a restart).
    fn follow(&mut self, rst: bool, hold: bool, push: bool, ev: &DmrEvents, at: &str) {
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
}

pub fn key_of(v: u64) -> Key {
    Key {
        ide: v >> 29 & 1 != 0,
        id: (v & 0x1FFF_FFFF) as u32,
    }
}
