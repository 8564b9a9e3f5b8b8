//! The generation-time sizes of the DRCC (drcc_contract.md §1.1, §6, §7) on all
//! three engines in lock step (model built with the configuration's sizes,
//! rust-hdl's simulator of the block built with it, the Verilated top): a TX
//! queue takes exactly `TX_QUEUE_DEPTH` frames and refuses the next push, and the
//! RX FIFO holds exactly `RX_FIFO_DEPTH` frames and counts the next as an overrun,
//! for the default `drcc` (8, 32) and `drcc_small` (4, 8). The expected depths
//! are the contract's numbers, not read from any engine.
//!
//! The history size `H` is exercised by `drcc_small_faults.rs` (every dual-bus
//! fault scenario on `drcc_small`, model and RTL in lock step).

use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::engine::drcc_rusthdl;
use drcc_cosim::engine::drcc_verilator::{DrccSmallVerilatorEngine, DrccVerilatorEngine};
use drcc_cosim::host::btr;
use drcc_cosim::model::drcc::DrccParams;
use drcc_hdl::config::DrccConfig;
use drcc_hdl::host::registers::{self as map, SwitchPolicy, MAP};

/// The engines in lock step; both channels on one wire of their own (each
/// channel's rx pin reads the wired AND of both tx pins of the previous clock).
struct Bench {
    engines: Vec<Box<dyn DrccEngine>>,
    cycle: u64,
    wire: bool,
}

impl Bench {
    /// `drcc` (contract sizes: TX queues 8, RX FIFO 32).
    fn default_build() -> Self {
        let v = DrccVerilatorEngine::new().map(|e| Box::new(e) as Box<dyn DrccEngine>);
        Self::start(
            vec![
                Box::new(DrccModelEngine::with_params(&DrccParams::DEFAULT)),
                drcc_rusthdl::drcc(),
            ],
            v,
        )
    }

    /// `drcc_small` (contract sizes: TX queues 4, RX FIFO 8).
    fn small_build() -> Self {
        let v = DrccSmallVerilatorEngine::new().map(|e| Box::new(e) as Box<dyn DrccEngine>);
        Self::start(
            vec![
                Box::new(DrccModelEngine::with_params(&DrccParams::SMALL)),
                drcc_rusthdl::with_config(&DrccConfig::SMALL),
            ],
            v,
        )
    }

    fn start(
        mut engines: Vec<Box<dyn DrccEngine>>,
        verilated: Result<Box<dyn DrccEngine>, String>,
    ) -> Self {
        engines.extend(drcc_tools::verilated("DRCC top", verilated));
        let mut b = Bench {
            engines,
            cycle: 0,
            wire: true,
        };
        for _ in 0..3 {
            b.step(DrccInputs {
                rst: true,
                ..Default::default()
            });
        }
        b
    }

    /// One clock on every engine, every output compared with the model's.
    fn step(&mut self, mut i: DrccInputs) -> DrccOutputs {
        i.chan_a_rx = self.wire;
        i.chan_b_rx = self.wire;
        let outs: Vec<DrccOutputs> = self.engines.iter_mut().map(|e| e.step(&i)).collect();
        for (e, o) in self.engines.iter().zip(&outs).skip(1) {
            assert_eq!(
                o,
                &outs[0],
                "cycle {}: {} differs from the model",
                self.cycle,
                e.name()
            );
        }
        self.cycle += 1;
        self.wire = outs[0].chan_a_tx & outs[0].chan_b_tx;
        outs[0]
    }

    fn access(&mut self, we: bool, adr: u32, dat: u32) -> u32 {
        let o = self.step(DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr as u8,
            wb_dat_w: dat,
            ..Default::default()
        });
        assert!(o.wb_ack != o.wb_err, "no answer");
        self.step(DrccInputs::default());
        o.wb_dat_r
    }

    fn write(&mut self, adr: u32, dat: u32) {
        self.access(true, adr, dat);
    }

    fn read(&mut self, adr: u32) -> u32 {
        self.access(false, adr, 0)
    }

    /// Normal mode, both channels active, 8 clocks a bit.
    fn configure(&mut self) {
        self.write(map::BTR, btr(0, 5, 2, 1, false, 96));
        self.write(map::CTRL, ctrl(true));
        self.write(map::CTRL, ctrl(false));
    }

    /// Stages a base data frame with identifier `id` and DLC 1 for `queue` and
    /// pushes it; tells whether the push was refused (`INT_STATUS.illegal`,
    /// cleared again).
    fn push_refused(&mut self, queue: u32, id: u32) -> bool {
        let illegal = put("INT_STATUS", "illegal", 1);
        self.write(map::TX_ID, id);
        self.write(
            map::TX_CTRL,
            put("TX_CTRL", "dlc", 1) | put("TX_CTRL", "queue", queue),
        );
        self.write(map::TX_DATA0, id & 0xFF);
        self.write(map::TX_CMD, put("TX_CMD", "push", 1));
        let refused = self.read(map::INT_STATUS) & illegal != 0;
        self.write(map::INT_STATUS, illegal);
        refused
    }

    fn status(&mut self, field: &str) -> u32 {
        MAP.field("STATUS", field).get(self.read(map::STATUS))
    }
}

fn put(reg: &str, field: &str, v: u32) -> u32 {
    MAP.field(reg, field).put(v)
}

/// CTRL in normal mode (not redundancy), error-passive policy.
fn ctrl(reset_mode: bool) -> u32 {
    put("CTRL", "reset_mode", reset_mode as u32)
        | put("CTRL", "policy", SwitchPolicy::ErrorPassive.code())
        | put("CTRL", "k", 1)
}

/// §6: a queue takes `depth` frames, the next push is refused and stores nothing.
fn queue_takes(mut b: Bench, depth: u32) {
    b.configure();
    // queue B: channel B sends the head on the shared wire, channel A receives
    // it; no transmission completes within the pushes (a frame is ~400 clocks)
    let start = b.cycle;
    for k in 0..depth {
        assert!(!b.push_refused(1, 0x100 + k), "push {k} of {depth} refused");
    }
    assert!(b.push_refused(1, 0x1FF), "push {} accepted", depth + 1);
    assert_eq!(b.status("txq_b_count"), depth);
    assert!(
        b.cycle - start < 300,
        "pushes took {} clocks",
        b.cycle - start
    );
}

/// §7: the FIFO holds `depth` frames; the next frame received is an overrun.
fn fifo_holds(mut b: Bench, depth: u32, queue_depth: u32) {
    b.configure();
    let overrun = put("INT_STATUS", "overrun", 1);
    let mut pushed = 0;
    while b.status("rx_count") < depth || b.read(map::STATS0) >> 16 == 0 {
        assert!(b.cycle < 40_000, "no overrun after {} clocks", b.cycle);
        if pushed < depth + 1 && b.status("txq_a_count") < queue_depth {
            assert!(!b.push_refused(0, 0x200 + pushed));
            pushed += 1;
        } else {
            for _ in 0..50 {
                b.step(DrccInputs::default());
            }
        }
    }
    assert_eq!(b.status("rx_count"), depth, "the FIFO is full at its depth");
    assert_eq!(
        MAP.field("STATS0", "overruns").get(b.read(map::STATS0)),
        1,
        "exactly one frame dropped"
    );
    assert_ne!(b.read(map::INT_STATUS) & overrun, 0);
}

#[test]
fn tx_queues_take_their_configured_depth() {
    queue_takes(Bench::default_build(), 8);
    queue_takes(Bench::small_build(), 4);
}

#[test]
fn small_rx_fifo_overruns_at_its_configured_depth() {
    fifo_holds(Bench::small_build(), 8, 4);
}

#[test]
fn default_rx_fifo_overruns_at_its_configured_depth() {
    fifo_holds(Bench::default_build(), 32, 8);
}

/// §1.1: `drcc_small` has neither the DMR function nor the replicated-star node:
/// a `CTRL` write setting `dmr` or `star` is refused as a whole (nothing stored,
/// `INT_STATUS.illegal`), and so is a write to a DMR register (it keeps its reset
/// value, DMR contract §2.1: `DMR_CFG` 100), where `drcc` takes the same words.
#[test]
fn small_refuses_the_modes_it_lacks() {
    let illegal = put("INT_STATUS", "illegal", 1);
    let dmr = ctrl(true) | put("CTRL", "dmr", 1);
    let star = ctrl(true)
        | put("CTRL", "star", 1)
        | put(
            "CTRL",
            "redundancy",
            drcc_hdl::host::registers::Mode::Redundancy.code(),
        );
    for (mut b, has_modes) in [
        (Bench::small_build(), false),
        (Bench::default_build(), true),
    ] {
        for word in [dmr, star] {
            let before = b.read(map::CTRL);
            b.write(map::CTRL, word);
            let refused = b.read(map::INT_STATUS) & illegal != 0;
            b.write(map::INT_STATUS, illegal);
            assert_eq!(refused, !has_modes, "CTRL {word:#x} refused");
            let after = b.read(map::CTRL);
            if has_modes {
                assert_eq!(after, word, "stored");
                b.write(map::CTRL, ctrl(true));
            } else {
                assert_eq!(after, before, "nothing stored");
            }
        }
        assert_eq!(b.read(map::DMR_CFG), 100, "reset value");
        b.write(map::DMR_CFG, 50);
        let refused = b.read(map::INT_STATUS) & illegal != 0;
        assert_eq!(refused, !has_modes, "DMR_CFG write refused");
        let want = if has_modes { 50 } else { 100 };
        assert_eq!(b.read(map::DMR_CFG), want);
    }
}
