//! Unit tests of [`System`] and the toy engine `Ideal` the other modules'
//! tests share: the wired-AND bus, delivery order, the due-time queue, cycle
//! limits, faults, configuration and abort timing.

use super::*;
use crate::bus::{FaultKind, FaultTarget};
use crate::engine::Mode;

/// A toy engine for testing the plumbing: a requested frame is sent as one
/// dominant pulse of `dlc + 1` clocks once the line has been recessive for 3
/// clocks; a receiver measures the pulse and reports a frame with that `dlc`.
/// In listen-only mode a request is refused (`tx_failed`); `tx_abort` drops a
/// pending frame that is not being sent (`tx_failed`).
pub(crate) struct Ideal {
    pending: Option<Frame>,
    sending: u32,
    own: bool,
    quiet: u32,
    low_run: u32,
    out: ChannelOutputs,
}

impl Ideal {
    pub(crate) fn boxed() -> Box<dyn ChannelEngine> {
        Box::new(Ideal {
            pending: None,
            sending: 0,
            own: false,
            quiet: 0,
            low_run: 0,
            out: idle_outputs(),
        })
    }
}

impl ChannelEngine for Ideal {
    fn name(&self) -> &'static str {
        "ideal"
    }
    fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
        let mut o = ChannelOutputs {
            tx: true,
            rx_frame: self.out.rx_frame,
            ..Default::default()
        };
        if i.rst {
            *self = Ideal {
                pending: None,
                sending: 0,
                own: false,
                quiet: 0,
                low_run: 0,
                out: idle_outputs(),
            };
            return self.out;
        }
        if i.tx_abort && self.pending.is_some() && self.sending == 0 {
            self.pending = None;
            o.tx_failed = true;
        }
        if i.tx_req && self.pending.is_none() {
            if i.config.mode == Mode::ListenOnly {
                o.tx_failed = true;
            } else {
                self.pending = Some(i.tx_frame);
            }
        }
        // Receiver: measure dominant pulses not sent by ourselves.
        if !i.rx {
            self.low_run += 1;
            self.quiet = 0;
        } else {
            if self.low_run > 0 && !self.own {
                o.rx_valid = true;
                o.rx_frame = Frame {
                    dlc: (self.low_run - 1) as u8,
                    ..Default::default()
                };
            }
            if self.low_run > 0 {
                self.own = false;
            }
            self.low_run = 0;
            self.quiet += 1;
        }
        // Transmitter.
        if let Some(f) = self.pending {
            if self.sending == 0 && self.quiet >= 3 && i.rx {
                self.sending = f.dlc as u32 + 1;
                self.own = true;
            }
            if self.sending > 0 {
                o.tx = false;
                self.sending -= 1;
                if self.sending == 0 {
                    self.pending = None;
                    o.tx_done = true;
                }
            }
        }
        o.tx_pending = self.pending.is_some();
        self.out = o;
        o
    }
}

fn frame(dlc: u8) -> Frame {
    Frame {
        id: 0x100 + dlc as u32,
        dlc,
        ..Default::default()
    }
}

fn system(n: usize) -> System {
    System::new(
        (0..n).map(|_| Ideal::boxed()).collect(),
        BitTiming::default(),
    )
    .unwrap()
}

#[test]
fn rx_is_the_and_of_the_previous_tx() {
    let mut s = system(3);
    s.submit(1, 0, frame(4)).unwrap();
    let mut prev_tx = vec![true; 3];
    for _ in 0..60 {
        let sample = s.step().clone();
        let expect = prev_tx.iter().all(|&t| t);
        assert_eq!(sample.bus, expect, "cycle {}", sample.cycle);
        assert!(sample.rx.iter().all(|&r| r == expect));
        prev_tx = sample.outputs.iter().map(|o| o.tx).collect();
    }
}

#[test]
fn frames_are_delivered_to_the_others_in_order() {
    let mut s = system(3);
    s.submit(0, 0, frame(3)).unwrap();
    s.submit(0, 0, frame(1)).unwrap();
    s.submit(2, 50, frame(5)).unwrap();
    let out = s.run_until_idle(10_000);
    assert!(out.is_idle(), "{out:?}");
    let sent: Vec<(usize, u8)> = s.tx_done().iter().map(|e| (e.node, e.frame.dlc)).collect();
    assert_eq!(sent, vec![(0, 3), (0, 1), (2, 5)]);
    let got: Vec<(usize, u8)> = s
        .deliveries()
        .iter()
        .map(|e| (e.node, e.frame.dlc))
        .collect();
    assert_eq!(got, vec![(1, 3), (2, 3), (1, 1), (2, 1), (0, 5), (1, 5)]);
    // Bus idle for 11 bits at the end.
    assert!(s.cycle() >= 11 * 8);
}

#[test]
fn no_request_before_due_or_during_reset() {
    let mut s = system(2);
    s.set_reset_cycles(10);
    s.submit(0, 0, frame(0)).unwrap();
    s.submit(1, 40, frame(0)).unwrap();
    for _ in 0..100 {
        let sm = s.step();
        if sm.cycle < 10 {
            assert!(sm.rst && !sm.tx_req[0]);
        }
        if sm.tx_req[0] {
            assert_eq!(sm.cycle, 10);
        }
        if sm.tx_req[1] {
            assert!(sm.cycle >= 40);
        }
    }
    assert_eq!(s.tx_done().len(), 2);
    assert!(s.submit(2, 0, frame(0)).is_err());
}

#[test]
fn queue_keeps_due_order_then_submission_order() {
    let mut s = system(2);
    s.submit(0, 100, frame(7)).unwrap();
    s.submit(0, 0, frame(2)).unwrap();
    s.submit(0, 100, frame(3)).unwrap();
    assert!(s.run_until_idle(10_000).is_idle());
    let sent: Vec<u8> = s.tx_done().iter().map(|e| e.frame.dlc).collect();
    assert_eq!(sent, vec![2, 7, 3]);
}

#[test]
fn cycle_limit_and_faults() {
    let mut s = system(2);
    s.add_fault(Fault {
        target: FaultTarget::Bus,
        kind: FaultKind::StuckDominant,
        start: 20,
        cycles: 1_000_000,
    })
    .unwrap();
    s.submit(0, 0, frame(1)).unwrap();
    let out = s.run_until_idle(500);
    assert_eq!(out, RunOutcome::CycleLimit { cycle: 500 });
    assert!(!s.sample().bus);
}

/// Per clock: (step, config, tx_abort, tx_req) as a node was given them.
type Seen = std::rc::Rc<std::cell::RefCell<Vec<(u64, ControllerConfig, bool, bool)>>>;

/// Records the configuration and `tx_abort` it is given, around an `Ideal`.
struct Spy {
    inner: Box<dyn ChannelEngine>,
    seen: Seen,
    n: u64,
}

impl ChannelEngine for Spy {
    fn name(&self) -> &'static str {
        "spy"
    }
    fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
        self.seen
            .borrow_mut()
            .push((self.n, i.config, i.tx_abort, i.tx_req));
        self.n += 1;
        self.inner.step(i)
    }
}

#[test]
fn config_reaches_every_node_and_failures_are_recorded() {
    let seen = Seen::default();
    let engines: Vec<Box<dyn ChannelEngine>> = vec![
        Ideal::boxed(),
        Box::new(Spy {
            inner: Ideal::boxed(),
            seen: seen.clone(),
            n: 0,
        }),
    ];
    let mut s = System::new(engines, BitTiming::default()).unwrap();
    assert_eq!(s.configs(), &[ControllerConfig::default(); 2]);
    let quiet = ControllerConfig {
        mode: Mode::ListenOnly,
        ewl: 10,
        single_shot: true,
    };
    s.set_config(ControllerConfig {
        ewl: 50,
        ..ControllerConfig::default()
    });
    s.set_node_config(1, quiet).unwrap();
    assert!(s.set_node_config(2, quiet).is_err());
    s.submit(0, 0, frame(2)).unwrap();
    s.submit(1, 0, frame(3)).unwrap();
    assert!(s.run_until_idle(10_000).is_idle());
    // Node 1 (listen-only) had its request refused: a tx_failed, nothing sent.
    let failed: Vec<(usize, u8)> = s
        .tx_failed()
        .iter()
        .map(|e| (e.node, e.frame.dlc))
        .collect();
    assert_eq!(failed, vec![(1, 3)]);
    let sent: Vec<(usize, u8)> = s.tx_done().iter().map(|e| (e.node, e.frame.dlc)).collect();
    assert_eq!(sent, vec![(0, 2)]);
    assert_eq!(s.configs()[0].ewl, 50);
    let seen = seen.borrow();
    assert!(seen.iter().all(|&(_, c, abort, _)| c == quiet && !abort));
}

#[test]
fn abort_is_one_clock_after_reset_without_a_request() {
    let seen = Seen::default();
    let engines: Vec<Box<dyn ChannelEngine>> = vec![
        Ideal::boxed(),
        Box::new(Spy {
            inner: Ideal::boxed(),
            seen: seen.clone(),
            n: 0,
        }),
    ];
    let mut s = System::new(engines, BitTiming::default()).unwrap();
    // Node 0 keeps the line busy so node 1's frame stays pending for a while.
    s.submit(0, 0, frame(40)).unwrap();
    s.submit(1, 10, frame(1)).unwrap();
    s.submit(1, 12, frame(2)).unwrap();
    s.abort(1, 0).unwrap(); // during reset: raised at the first cycle after it
    s.abort(1, 20).unwrap();
    s.abort(1, 20).unwrap(); // the same cycle: one pulse
    assert!(s.abort(5, 0).is_err());
    assert!(s.run_until_idle(10_000).is_idle());
    let seen = seen.borrow();
    let aborts: Vec<u64> = seen.iter().filter(|x| x.2).map(|x| x.0).collect();
    assert_eq!(aborts, vec![DEFAULT_RESET_CYCLES, 20]);
    assert!(
        seen.iter().all(|x| !(x.2 && x.3)),
        "no request with an abort"
    );
    // The frame pending at cycle 20 (requested at cycle 10) was dropped; the
    // next one was requested after it and sent.
    let failed: Vec<(u64, u8)> = s
        .tx_failed()
        .iter()
        .map(|e| (e.cycle, e.frame.dlc))
        .collect();
    assert_eq!(failed, vec![(20, 1)]);
    let sent: Vec<(usize, u8)> = s.tx_done().iter().map(|e| (e.node, e.frame.dlc)).collect();
    assert_eq!(sent, vec![(0, 40), (1, 2)]);
}
