//! Reference model: configuration captured in reset mode and clamping (timing
//! contract §6), operating modes (§7), single-shot and `tx_abort` (§8).
//! Expected values come from the contract's text and ISO 11898-1, computed by hand
//! (bit lengths, synchronisation arithmetic of §3) or by the independent helpers.

#[path = "../model_support/mod.rs"]
mod model_support;

use drcc_cosim::{BitTiming, ChannelOutputs, ControllerConfig, Frame, Mode};
use model_support::{code, timing, Bus, Tester};

mod configuration;
mod modes;
mod single_shot_abort;

const KIND_STUFF: u8 = 2;
const KIND_CRC: u8 = 3;
const KIND_FORM: u8 = 4;
const KIND_ACK: u8 = 5;

fn frame(id: u32, data: &[u8]) -> Frame {
    let mut d = [0u8; 8];
    d[..data.len()].copy_from_slice(data);
    Frame {
        id,
        ide: false,
        rtr: false,
        dlc: data.len() as u8,
        data: d,
    }
}

fn cfg(mode: Mode) -> ControllerConfig {
    ControllerConfig {
        mode,
        ..ControllerConfig::default()
    }
}

fn single_shot() -> ControllerConfig {
    ControllerConfig {
        single_shot: true,
        ..ControllerConfig::default()
    }
}

/// Lengths of the runs of equal values strictly between the first and the last
/// transition of `tx` (the SOF, lengthened by the hard synchronisation, and the
/// recessive tail are left out).
fn inner_runs(tx: &[bool]) -> Vec<usize> {
    let edges: Vec<usize> = (1..tx.len()).filter(|&i| tx[i] != tx[i - 1]).collect();
    edges.windows(2).map(|w| w[1] - w[0]).collect()
}

/// Records every output of node `n` while stepping the bus `clocks` times.
fn record(bus: &mut Bus, clocks: u32, n: usize) -> Vec<ChannelOutputs> {
    (0..clocks).map(|_| bus.step(&[])[n]).collect()
}

/// Node `n`'s `tx` from its first dominant bit (SOF) up to its `tx_done`.
fn frame_tx(outs: &[ChannelOutputs]) -> Vec<bool> {
    let start = outs.iter().position(|o| !o.tx).expect("no SOF");
    let end = outs.iter().position(|o| o.tx_done).expect("no tx_done");
    outs[start..end].iter().map(|o| o.tx).collect()
}

/// The bit length seen on a transmitter's `tx` pin: with data 0x55 there are
/// one-bit runs, and without resynchronisation (a lone transmitter sends every
/// dominant edge itself) every run is a whole number of bits.
fn assert_bit_length(tx: &[bool], clocks: usize, what: &str) {
    let runs = inner_runs(tx);
    assert!(runs.len() > 10, "{what}: too few transitions");
    assert_eq!(*runs.iter().min().unwrap(), clocks, "{what}: bit length");
    for r in &runs {
        assert_eq!(r % clocks, 0, "{what}: run of {r} clocks");
    }
}

fn with_brp(t: BitTiming, brp: u16) -> BitTiming {
    BitTiming { brp, ..t }
}
