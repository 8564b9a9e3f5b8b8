//! Random error stress: 3 to 5 nodes exchange random traffic while random faults
//! hit the bus (`drcc_testbench::fault_gen`, the fault kinds of
//! `drcc_cosim::bus`): single-bit flips, glitches shorter than a bit (some at a
//! node's sample point), flipped bits in chosen fields (ACK slot, EOF,
//! intermission, suspend, error flags and delimiters, bus-off ...), stuck-dominant
//! windows (some longer than 17 bits: error passive; one per episode held in the
//! middle of a frame until its transmitter is bus-off), stuck-recessive windows,
//! and faults on one node's transmitter or receiver only. Then the faults stop and
//! the run goes on fault free until every frame has been sent.
//!
//! Every configuration runs short seeded *episodes* (the bus scans its whole fault
//! list every clock while faults are pending, so short fault lists are cheap, and
//! every episode ends with its own recovery to check):
//! - model vs Verilator, in lock step (every output and probe of every node at
//!   every clock, `drcc_cosim::cosim::lockstep`): six configurations, 125 k to
//!   1 Mbit/s, 8 and 24 MHz clocks, brp 0 to 11, SJW 1 to 4, one with triple
//!   sampling; more than 1,000,000 bit times in all
//!   (`verilator_runs_cover_a_million_bit_times`);
//! - model vs rust-hdl: about 20,000 bit times.
//!
//! Besides zero divergence, every episode checks, from ISO 11898-1 and not from
//! either engine's view of itself:
//! - liveness: after the faults stop, every node reaches bus idle (field IDLE, not
//!   bus-off) within a bound (a bus-off node after its 128 x 11 recessive bits),
//!   then all nodes are idle together; the run ends with every frame sent
//!   (`tx_pending` clear) and, 11 recessive bits after the last frame, every node
//!   idle (an error-passive transmitter after its 8 suspend bits);
//! - integrity: every frame a node accepts (`rx_valid`) is a frame another node
//!   submitted, every submitted frame is sent (`tx_done`) exactly once;
//! - once all nodes have been idle together after the faults: no error or
//!   overload flag, counters only go down, every frame sent is delivered once to
//!   every other node, and 11 recessive bits on the bus mean every node idle;
//! - the faults did something (over a configuration): error flags, non-zero
//!   counters, entries into error passive and bus-off, every bus-off recovered.
//!
//! Two more tests check fault confinement of a node whose transceiver dies
//! (receiver or transmitter stuck recessive): by ISO 11898-1 bit monitoring it
//! reads its own dominant bits recessive, so it is bus-off within a few hundred
//! bit times and the other nodes communicate although the fault persists.
//!
//! Soak runs: `DRCC_STRESS_SCALE=k` runs k times as many episodes, and
//! `DRCC_STRESS_SEED=s` draws other traffic and faults (every seed shifted by
//! `s << 16`); the defaults are what CI runs.
//!
//! A missing Verilator skips locally and fails in CI (`CI` or
//! `DRCC_REQUIRE_VERILATOR` set). On a divergence the test prints it (cycle, bit,
//! node, signal, both values) and leaves the VCDs of both engines around it and
//! the episode's scenario with its faults (`scenario.toml`, for `drcc cosim`) in a
//! directory under the cargo target tmp dir, whose path it prints.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::PathBuf;
use std::rc::Rc;
use std::time::Instant;

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::cosim::{compare_samples, lockstep, CosimError, CosimOptions};
use drcc_cosim::model::field;
use drcc_cosim::system::{NodeEvent, System};
use drcc_cosim::{ChannelEngine, ChannelInputs, ChannelOutputs, Frame, Probes};
use drcc_testbench::engines::{available, make_engine};
use drcc_testbench::fault_gen::{plan, FaultEvent, FaultParams, FaultPlan};
use drcc_testbench::random::Traffic;
use drcc_testbench::run::build_system_with;
use drcc_testbench::scenario::Expectations;
use drcc_testbench::{EngineKind, Scenario};

mod checks;
mod dead_node;
mod episode;
mod faults;
mod watch;

use checks::*;
use episode::*;
use faults::*;
use watch::*;

/// Longest frame on the bus in bit times (extended, 8 data bytes, worst-case
/// stuffing, ACK delimiter, EOF and intermission), rounded up.
const MAX_FRAME_BITS: u64 = 160;

/// After the faults stop, every node must be idle within this many bit times: a
/// bus-off node needs 128 occurrences of 11 recessive bits (rule l), and a busy
/// bus gives at least one per frame; plus the frame and error frame in progress.
const SETTLE_BOUND_BITS: u64 = 128 * MAX_FRAME_BITS + 4 * MAX_FRAME_BITS;

/// One stress configuration: `episodes` seeded runs (seeds `seed`, `seed + 1`,
/// ...), each with its own traffic and faults and its own fault-free end. Short
/// episodes keep the bus's fault list short (it is scanned every clock while
/// faults are pending) and give many recoveries to check.
#[derive(Clone, Copy, Debug)]
struct Stress {
    name: &'static str,
    seed: u64,
    nodes: usize,
    clock_hz: u64,
    bitrate: u64,
    triple_sampling: bool,
    /// Bit timing instead of the solver's (same clocks per bit): brp, tseg1,
    /// tseg2, sjw.
    timing: Option<(u8, u8, u8, u8)>,
    episodes: u64,
    /// Faults are injected from bit 25 to this bit of every episode; the traffic
    /// goes on for a quarter more, then the run goes on until every frame is sent.
    fault_bits: u64,
    /// Bit times the configuration covers at least (asserted).
    min_bits: u64,
}

/// The model vs Verilator configurations (their `min_bits` add up to more than
/// 1,000,000).
const VERILATOR_RUNS: [Stress; 6] = [
    Stress {
        name: "3n-8MHz-1M",
        seed: 0x5_7E55_0100,
        nodes: 3,
        clock_hz: 8_000_000,
        bitrate: 1_000_000,
        triple_sampling: false,
        timing: None,
        episodes: 40,
        fault_bits: 8000,
        min_bits: 400_000,
    },
    Stress {
        name: "4n-8MHz-500k-sjw4",
        seed: 0x5_7E55_0200,
        nodes: 4,
        clock_hz: 8_000_000,
        bitrate: 500_000,
        triple_sampling: false,
        // SJW 4, the largest jump.
        timing: Some((0, 10, 5, 4)),
        episodes: 46,
        fault_bits: 4000,
        min_bits: 250_000,
    },
    Stress {
        name: "5n-24MHz-500k-brp2",
        seed: 0x5_7E55_0300,
        nodes: 5,
        clock_hz: 24_000_000,
        bitrate: 500_000,
        triple_sampling: false,
        timing: None,
        episodes: 50,
        fault_bits: 2000,
        min_bits: 150_000,
    },
    Stress {
        name: "3n-24MHz-1M-brp1-sjw1",
        seed: 0x5_7E55_0400,
        nodes: 3,
        clock_hz: 24_000_000,
        bitrate: 1_000_000,
        triple_sampling: false,
        // SJW 1, the smallest jump.
        timing: Some((1, 8, 3, 1)),
        episodes: 30,
        fault_bits: 3000,
        min_bits: 120_000,
    },
    Stress {
        name: "4n-8MHz-125k-brp3-triple",
        seed: 0x5_7E55_0500,
        nodes: 4,
        clock_hz: 8_000_000,
        bitrate: 125_000,
        triple_sampling: true,
        timing: None,
        episodes: 20,
        fault_bits: 2000,
        min_bits: 60_000,
    },
    Stress {
        name: "3n-24MHz-125k-brp11",
        seed: 0x5_7E55_0600,
        nodes: 3,
        clock_hz: 24_000_000,
        bitrate: 125_000,
        triple_sampling: false,
        timing: None,
        episodes: 14,
        fault_bits: 2000,
        min_bits: 40_000,
    },
];

/// The model vs rust-hdl configuration.
const RUSTHDL_RUN: Stress = Stress {
    name: "3n-8MHz-1M-rusthdl",
    seed: 0x5_7E55_0700,
    nodes: 3,
    clock_hz: 8_000_000,
    bitrate: 1_000_000,
    triple_sampling: false,
    timing: None,
    episodes: 2,
    fault_bits: 7000,
    min_bits: 18_000,
};

fn verilator_present() -> bool {
    drcc_tools::verilated("can_channel top", available(EngineKind::Verilator)).is_some()
}

#[test]
fn verilator_runs_cover_a_million_bit_times() {
    let total: u64 = VERILATOR_RUNS.iter().map(|r| r.min_bits).sum();
    assert!(total >= 1_000_000, "{total}");
}

#[test]
fn stress_3_nodes_8mhz_1m_vs_verilator() {
    stress_vs_verilator(0);
}

#[test]
fn stress_4_nodes_8mhz_500k_sjw4_vs_verilator() {
    stress_vs_verilator(1);
}

#[test]
fn stress_5_nodes_24mhz_500k_brp2_vs_verilator() {
    stress_vs_verilator(2);
}

#[test]
fn stress_3_nodes_24mhz_1m_brp1_sjw1_vs_verilator() {
    stress_vs_verilator(3);
}

#[test]
fn stress_4_nodes_8mhz_125k_triple_vs_verilator() {
    stress_vs_verilator(4);
}

#[test]
fn stress_3_nodes_24mhz_125k_brp11_vs_verilator() {
    stress_vs_verilator(5);
}

#[test]
fn stress_vs_rusthdl() {
    stress(&RUSTHDL_RUN, EngineKind::RustHdl);
}

fn stress_vs_verilator(i: usize) {
    if verilator_present() {
        stress(&VERILATOR_RUNS[i], EngineKind::Verilator);
    }
}
