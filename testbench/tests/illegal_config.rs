//! Illegal bit-timing configurations are clamped by the RTL and the reference
//! model alike (timing contract §6), and refused by the scenario loader.
//!
//! The lock-step part drives two nodes directly (the `System` refuses illegal
//! timings, as the CLI does) with configurations outside ISO 11898-1 and compares
//! the Verilated RTL with the model at every clock. The expected bit length comes
//! from the contract's clamping rule, measured on the `tx` pin of the model.

use drcc_cosim::engine::model::ModelEngine;
use drcc_cosim::engine::verilator::VerilatorEngine;
use drcc_cosim::{BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs, Frame};

fn frames() -> [Frame; 2] {
    [
        Frame {
            id: 0x155,
            ide: false,
            rtr: false,
            dlc: 2,
            data: [0xAA, 0x0F, 0, 0, 0, 0, 0, 0],
        },
        Frame {
            id: 0x1ABC_DE01,
            ide: true,
            rtr: false,
            dlc: 1,
            data: [0x81, 0, 0, 0, 0, 0, 0, 0],
        },
    ]
}

/// Runs two nodes of each engine on two wired-AND buses in lock step.
/// Returns the model's per-cycle tx of node 0.
fn lockstep(timing: BitTiming, cycles: usize) -> Vec<bool> {
    let mut rtl: Vec<VerilatorEngine> = (0..2).map(|_| VerilatorEngine::new().unwrap()).collect();
    let mut model: Vec<ModelEngine> = (0..2).map(|_| ModelEngine::new()).collect();
    let recessive = ChannelOutputs {
        tx: true,
        ..Default::default()
    };
    let (mut out_r, mut out_m) = (vec![recessive; 2], vec![recessive; 2]);
    let mut tx0 = Vec::with_capacity(cycles);
    for cycle in 0..cycles {
        let (bus_r, bus_m) = (out_r.iter().all(|o| o.tx), out_m.iter().all(|o| o.tx));
        for n in 0..2 {
            let mut inp = ChannelInputs {
                rst: cycle < 4,
                timing,
                ..Default::default()
            };
            if cycle == 10 + 3 * n {
                inp.tx_req = true;
                inp.tx_frame = frames()[n];
            }
            inp.rx = bus_r;
            out_r[n] = rtl[n].step(&inp);
            inp.rx = bus_m;
            out_m[n] = model[n].step(&inp);
            assert_eq!(
                out_r[n], out_m[n],
                "cycle {cycle} node {n}: RTL and model differ for {timing:?}"
            );
        }
        tx0.push(out_m[0].tx);
    }
    tx0
}

/// Shortest run of equal tx values between two changes: one bit for a frame
/// that contains isolated bits (0x155 / 0xAA patterns do).
fn shortest_bit(tx: &[bool]) -> usize {
    let mut best = usize::MAX;
    let mut run = 0;
    let mut first = true;
    for w in tx.windows(2) {
        run += 1;
        if w[0] != w[1] {
            if !first {
                best = best.min(run);
            }
            first = false;
            run = 0;
        }
    }
    best
}

fn verilator_or_skip() -> bool {
    drcc_tools::verilated("can_channel top", VerilatorEngine::new()).is_some()
}

#[test]
fn short_bit_time_is_clamped_to_8_tq_in_rtl_and_model() {
    if !verilator_or_skip() {
        return;
    }
    // 1 + 1 + 1 = 3 tq: TSEG1 is raised to 7 - TSEG2 = 6 -> 8 tq of 2 clocks.
    let t = BitTiming {
        brp: 1,
        tseg1: 1,
        tseg2: 1,
        sjw: 1,
        triple_sampling: false,
    };
    let tx = lockstep(t, 3000);
    assert_eq!(shortest_bit(&tx), 16, "8 tq x 2 clocks per bit");
}

#[test]
fn tseg1_too_short_for_read_back_is_clamped() {
    if !verilator_or_skip() {
        return;
    }
    // brp 0, tseg1 1, tseg2 8: 10 tq, but TSEG1 is raised to 3 clocks -> 12 clocks.
    let t = BitTiming {
        brp: 0,
        tseg1: 1,
        tseg2: 8,
        sjw: 1,
        triple_sampling: false,
    };
    let tx = lockstep(t, 3000);
    assert_eq!(shortest_bit(&tx), 12);
}

#[test]
fn sjw_above_tseg2_is_clamped_and_engines_agree() {
    if !verilator_or_skip() {
        return;
    }
    let t = BitTiming {
        brp: 0,
        tseg1: 8,
        tseg2: 2,
        sjw: 4,
        triple_sampling: false,
    };
    let tx = lockstep(t, 3000);
    assert_eq!(shortest_bit(&tx), 11);
}

#[test]
fn loader_refuses_what_the_hardware_would_clamp() {
    for (t, field) in [
        (
            BitTiming {
                brp: 1,
                tseg1: 1,
                tseg2: 1,
                sjw: 1,
                triple_sampling: false,
            },
            "tq per bit",
        ),
        (
            BitTiming {
                brp: 0,
                tseg1: 8,
                tseg2: 2,
                sjw: 4,
                triple_sampling: false,
            },
            "sjw",
        ),
        (
            BitTiming {
                brp: 0,
                tseg1: 1,
                tseg2: 8,
                sjw: 1,
                triple_sampling: false,
            },
            "tseg1",
        ),
    ] {
        let err = t.validate().expect_err("illegal timing must be refused");
        assert!(err.contains(field), "`{err}` should name {field}");
    }
}
