//! The channel's error counter reset `err_reset` (timing contract §4.5): TEC = REC
//! = 0 and error active at the edge, unless the node is bus-off; the node stays on
//! the bus with its pending frame. The model, the rust-hdl block and the Verilated
//! RTL run in lock step; the expected counter values come from ISO 11898-1 12.1.4
//! (rule c: +8 per error flag of a transmitter; exception 1: an error-passive
//! transmitter's ACK error adds nothing; rule d: +8 per bit error in its own active
//! flag; bus-off above 255, recovery after 128 x 11 recessive bits).

use drcc_cosim::engine::model::ModelEngine;
use drcc_cosim::engine::rusthdl::RustHdlEngine;
use drcc_cosim::engine::verilator::VerilatorEngine;
use drcc_cosim::{BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs, Frame};

/// Clocks per bit of the default timing (8 tq of one clock).
const BIT: usize = 8;

fn frame() -> Frame {
    Frame {
        id: 0x2A5,
        ide: false,
        rtr: false,
        dlc: 1,
        data: [0x5A, 0, 0, 0, 0, 0, 0, 0],
    }
}

/// One node on a bus of its own, stepped on every engine at once; the bus is the
/// node's own `tx` (a lone node: nobody acknowledges) or forced recessive (its
/// transceiver hears nothing: every dominant bit it sends is a bit error).
struct Lone {
    engines: Vec<(&'static str, Box<dyn ChannelEngine>)>,
    out: ChannelOutputs,
    cycle: usize,
    rx_stuck_recessive: bool,
}

impl Lone {
    fn new(rx_stuck_recessive: bool) -> Option<Lone> {
        let mut engines: Vec<(&'static str, Box<dyn ChannelEngine>)> = vec![
            ("model", Box::new(ModelEngine::new())),
            ("rust-hdl", Box::new(RustHdlEngine::new())),
        ];
        if let Some(v) = drcc_tools::verilated("can_channel top", VerilatorEngine::new()) {
            engines.push(("verilator", Box::new(v)));
        }
        Some(Lone {
            engines,
            out: ChannelOutputs {
                tx: true,
                ..Default::default()
            },
            cycle: 0,
            rx_stuck_recessive,
        })
    }

    /// One clock with `tx_req` / `err_reset` as given; every engine must agree.
    fn step(&mut self, tx_req: bool, err_reset: bool) -> ChannelOutputs {
        let inputs = ChannelInputs {
            rst: self.cycle < 4,
            rx: self.out.tx || self.rx_stuck_recessive,
            timing: BitTiming::default(),
            tx_req,
            tx_frame: frame(),
            err_reset,
            ..Default::default()
        };
        let mut first: Option<ChannelOutputs> = None;
        for (name, e) in self.engines.iter_mut() {
            let o = e.step(&inputs);
            if let Some(f) = first {
                assert_eq!(o, f, "cycle {}: {name} differs from the model", self.cycle);
            }
            first = Some(o);
        }
        self.cycle += 1;
        self.out = first.unwrap();
        self.out
    }

    /// Steps until `until` holds for the outputs, at most `limit` clocks.
    fn run_until(&mut self, limit: usize, until: impl Fn(&ChannelOutputs) -> bool) {
        for _ in 0..limit {
            if until(&self.step(false, false)) {
                return;
            }
        }
        panic!(
            "condition not reached within {limit} clocks: {:?}",
            self.out
        );
    }
}

#[test]
fn err_reset_clears_an_error_passive_transmitter_and_keeps_its_frame() {
    let mut n = Lone::new(false).unwrap();
    for _ in 0..10 {
        n.step(false, false);
    }
    n.step(true, false);
    // A lone transmitter gets an ACK error per attempt: TEC + 8 (rule c) while error
    // active, so 16 attempts make it error passive at TEC 128; exception 1 then
    // keeps it there.
    n.run_until(16 * 80 * BIT, |o| o.probes.err_state == 1);
    assert_eq!(n.out.probes.tec, 128);
    assert!(
        n.out.diag.err_warning,
        "TEC 128 is above the default EWL 96"
    );
    assert!(n.out.tx_pending);
    let o = n.step(false, true);
    assert_eq!(
        (o.probes.tec, o.probes.rec, o.probes.err_state),
        (0, 0, 0),
        "counters cleared and error active at the err_reset edge"
    );
    assert!(!o.diag.err_warning);
    assert!(o.tx_pending, "the pending frame is kept");
    // The next attempt fails by ACK error again, now error active: TEC 8 (rule c),
    // without re-integration in between (the attempt follows the next intermission).
    n.run_until(120 * BIT, |o| o.probes.tec != 0);
    assert_eq!((n.out.probes.tec, n.out.probes.err_state), (8, 0));
}

#[test]
fn err_reset_leaves_a_bus_off_node_alone() {
    let mut n = Lone::new(true).unwrap();
    for _ in 0..10 {
        n.step(false, false);
    }
    n.step(true, false);
    // Its SOF reads recessive: bit error, TEC + 8, then every bit of its active
    // error flag reads recessive too (rule d, +8 each) until it is error passive;
    // from then on every attempt's SOF adds 8: bus-off above 255.
    n.run_until(40 * 40 * BIT, |o| o.probes.err_state == 2);
    let tec = n.out.probes.tec;
    assert!(tec > 255, "bus-off at TEC > 255, got {tec}");
    let o = n.step(false, true);
    assert_eq!(
        (o.probes.tec, o.probes.err_state),
        (tec, 2),
        "a bus-off node ignores err_reset (12.1.4.4: only the recovery clears it)"
    );
    // Recovery: 128 runs of 11 recessive bits, then TEC = REC = 0.
    n.run_until((128 * 11 + 20) * BIT, |o| o.probes.err_state != 2);
    assert_eq!((n.out.probes.tec, n.out.probes.rec), (0, 0));
}
