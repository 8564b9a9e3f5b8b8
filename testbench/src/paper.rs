//! The DRCC paper's simulation test (seed 003, section IV, Figs. 5-8), reproduced:
//! node 0 is a DRCC in redundancy mode that must send one message; on line A
//! nobody acknowledges (node 1's channel A is in listen-only mode, so it hears the
//! frame but never drives the ACK slot), on line B node 1 acknowledges. Channel A's
//! TEC climbs by 8 per failed attempt (ISO 11898-1 rule 3, ACK error) until the
//! switch policy gives up on A; the main FSM aborts on A and sends the same message
//! on B, where it succeeds once.
//!
//! The run measures the switchover: from the start of node 0's first attempt (its
//! first SOF on line A) to its SOF on line B and to `tx_success`, in bit times.

use drcc_cosim::dual::lockstep::compare;
use drcc_cosim::dual::vcd::DrccVcdWriter;
use drcc_cosim::dual::DualBusSystem;
use drcc_cosim::host::{btr, HostConfig, Policy};
use drcc_cosim::Frame;

use crate::dual::{drcc_engine, DualObserver};
use crate::engines::EngineKind;

/// Clock of the paper scenarios, Hz.
pub const CLOCK_HZ: u64 = 8_000_000;

/// A bit rate of the 8 MHz clock: name, bits per second, BRP (8 tq per bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rate {
    pub name: &'static str,
    pub bps: u64,
    pub brp: u16,
}

impl Rate {
    pub const K125: Rate = Rate {
        name: "125 kbit/s",
        bps: 125_000,
        brp: 7,
    };
    pub const K500: Rate = Rate {
        name: "500 kbit/s",
        bps: 500_000,
        brp: 1,
    };
    pub const M1: Rate = Rate {
        name: "1 Mbit/s",
        bps: 1_000_000,
        brp: 0,
    };
    pub const ALL: [Rate; 3] = [Rate::K125, Rate::K500, Rate::M1];

    /// Clocks per bit (8 tq of `brp + 1` clocks).
    pub fn clocks_per_bit(&self) -> u64 {
        8 * (self.brp as u64 + 1)
    }
}

/// The message node 0 sends (an 8-byte frame of 0xAA like the paper's Fig. 7
/// `chan_b_bsp_tx_data_*`).
pub fn paper_frame() -> Frame {
    Frame {
        id: 0x0A5,
        ide: false,
        rtr: false,
        dlc: 8,
        data: [0xAA; 8],
    }
}

/// What the run showed (clock numbers are absolute cycles).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PaperReport {
    /// Distinct values channel A's TEC took, in order.
    pub tec_a: Vec<u16>,
    /// Main FSM states of node 0, in order of change.
    pub states: Vec<u8>,
    /// Clock of node 0's first SOF on line A, and on line B.
    pub first_sof_a: Option<u64>,
    pub first_sof_b: Option<u64>,
    /// Clocks at which `transmission_ack` / `tx_success` / `tx_failure` were 1.
    pub transmission_ack: Vec<u64>,
    pub tx_success: Vec<u64>,
    pub tx_failure: Vec<u64>,
    /// `tx_ok_channel` / `tx_failure_channel` after the run.
    pub tx_ok_channel: u8,
    pub tx_failure_channel: u8,
    /// `chan_a_bsp_node_error_passive` rose at this clock.
    pub error_passive_at: Option<u64>,
    /// Clocks at which node 1 delivered the frame to its host, and the channel.
    pub received_by_node1: Vec<(u64, u8)>,
    pub clocks_per_bit: u64,
}

impl PaperReport {
    /// Bit times from the first SOF on A to the SOF on B.
    pub fn bits_to_b(&self) -> Option<f64> {
        Some((self.first_sof_b? - self.first_sof_a?) as f64 / self.clocks_per_bit as f64)
    }
    /// Bit times from the first SOF on A to `tx_success`.
    pub fn bits_to_success(&self) -> Option<f64> {
        Some((*self.tx_success.first()? - self.first_sof_a?) as f64 / self.clocks_per_bit as f64)
    }
}

/// Runs the paper scenario on `kind` (and, with `cosim`, in lock step with a second
/// engine: a divergence is an error), optionally writing the paper-named VCD.
pub fn run_paper(
    policy: Policy,
    rate: Rate,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    vcd: Option<&mut Vec<u8>>,
) -> Result<PaperReport, String> {
    run_paper_observed(policy, rate, kind, cosim, vcd, &mut |_| Ok(()))
}

/// [`run_paper`], also calling `observe` with the main system after every clock
/// (traffic taps).
pub fn run_paper_observed(
    policy: Policy,
    rate: Rate,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    vcd: Option<&mut Vec<u8>>,
    observe: DualObserver,
) -> Result<PaperReport, String> {
    let timing = btr(rate.brp, 5, 2, 1, false, 96);
    let node0 = HostConfig {
        btr: timing,
        redundancy: true,
        policy,
        dual_tx: false,
        // Long enough that channel A is not tried again within the run.
        recovery_bits: 60_000,
        ..HostConfig::default()
    };
    let node1 = HostConfig {
        btr: timing,
        redundancy: false,
        policy: Policy::None,
        mode_a: 1, // listen-only: hears line A, never acknowledges
        ..HostConfig::default()
    };
    let build = |k: EngineKind| -> Result<DualBusSystem, String> {
        let engines = vec![drcc_engine(k)?, drcc_engine(k)?];
        let mut sys = DualBusSystem::new(engines, vec![node0, node1])?;
        sys.node_mut(0)
            .host
            .submit(40 * rate.clocks_per_bit(), paper_frame(), 0);
        Ok(sys)
    };
    let mut sys = build(kind)?;
    let mut other = cosim.map(build).transpose()?;
    let cpb = rate.clocks_per_bit();
    let mut w = match vcd {
        Some(buf) => Some(
            DrccVcdWriter::new(
                buf,
                CLOCK_HZ,
                2,
                &format!(
                    "DRCC paper Figs. 5-8: channel A without acknowledgement, {}, policy {policy:?}",
                    rate.name
                ),
            )
            .map_err(|e| e.to_string())?,
        ),
        None => None,
    };
    let mut r = PaperReport {
        clocks_per_bit: cpb,
        ..PaperReport::default()
    };
    // Enough for 32 failed attempts (bus-off) plus the frame on B.
    let max = 6_000 * cpb;
    let mut done_at = None;
    let mut prev = sys.node(0).outputs;
    for cycle in 0..max {
        sys.step();
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&sys, o) {
                return Err(format!("paper scenario ({policy:?}, {}): {d}", rate.name));
            }
        }
        if let Some(w) = w.as_mut() {
            w.write_cycle(&sys).map_err(|e| e.to_string())?;
        }
        observe(&sys)?;
        let out = sys.node(0).outputs;
        let p = out.probes;
        if r.tec_a.last() != Some(&p.chan_a_bsp_tx_err_cnt) {
            r.tec_a.push(p.chan_a_bsp_tx_err_cnt);
        }
        if r.states.last() != Some(&p.state) {
            r.states.push(p.state);
        }
        if prev.chan_a_tx && !out.chan_a_tx && r.first_sof_a.is_none() {
            r.first_sof_a = Some(cycle);
        }
        if prev.chan_b_tx && !out.chan_b_tx && r.first_sof_b.is_none() {
            r.first_sof_b = Some(cycle);
        }
        if p.transmission_ack {
            r.transmission_ack.push(cycle);
        }
        if p.tx_success {
            r.tx_success.push(cycle);
            done_at.get_or_insert(cycle);
        }
        if p.tx_failure {
            r.tx_failure.push(cycle);
        }
        if p.chan_a_bsp_node_error_passive && !prev.probes.chan_a_bsp_node_error_passive {
            r.error_passive_at.get_or_insert(cycle);
        }
        r.tx_ok_channel = p.tx_ok_channel;
        r.tx_failure_channel = p.tx_failure_channel;
        prev = out;
        if done_at.is_some_and(|d| cycle >= d + 200 * cpb) {
            break;
        }
    }
    if let Some(mut w) = w {
        w.finish(sys.cycle()).map_err(|e| e.to_string())?;
    }
    r.received_by_node1 = sys
        .node(1)
        .host
        .received
        .iter()
        .filter(|x| x.frame == paper_frame())
        .map(|x| (x.cycle, x.channel))
        .collect();
    Ok(r)
}

/// The paper's measured switching time (Fig. 8: "25 ms or so").
pub const PAPER_SWITCH_MS: f64 = 25.0;

/// The switch policies the benchmark compares.
pub const BENCH_POLICIES: [(Policy, &str); 3] = [
    (Policy::ErrorPassive, "error-passive (paper)"),
    (Policy::KFailed(3), "k-failed, k = 3"),
    (Policy::KFailed(1), "k-failed, k = 1"),
];

/// Switchover benchmark: for every bit rate and policy, the time and bit count from
/// node 0's first attempt on A to its SOF on B and to `tx_success`, beside the
/// paper's 25 ms, as a Markdown table. Measured on `kind` (the model is exact to
/// the clock; the RTL gives the same numbers, as the lock-step tests show).
pub fn switchover_table(kind: EngineKind) -> Result<String, String> {
    let mut t = String::new();
    t.push_str(&format!(
        "Switchover, channel A without acknowledgement (8 MHz clock, engine {kind}); \
         time from node 0's first SOF on A\n\n\
         | bit rate | policy | attempts on A | to SOF on B | to tx_success | paper's 25 ms / ours | error-passive / ours |\n\
         |---|---|---:|---:|---:|---:|---:|\n"
    ));
    for rate in Rate::ALL {
        let mut paper_mode_ms = None;
        for (policy, name) in BENCH_POLICIES {
            let r = run_paper(policy, rate, kind, None, None)?;
            // Failed attempts on A = TEC increments by 8 before the switch.
            let failed = r.tec_a.windows(2).take_while(|w| w[1] > w[0]).count();
            let to_b = r.bits_to_b().ok_or("no SOF on B")?;
            let to_ok = r.bits_to_success().ok_or("no tx_success")?;
            let ms = |bits: f64| bits * 1000.0 / rate.bps as f64;
            let same_rate = *paper_mode_ms.get_or_insert(ms(to_ok));
            t.push_str(&format!(
                "| {} | {} | {} | {:.0} bits = {:.3} ms | {:.0} bits = {:.3} ms | {:.0}x | {:.1}x |\n",
                rate.name,
                name,
                failed,
                to_b,
                ms(to_b),
                to_ok,
                ms(to_ok),
                PAPER_SWITCH_MS / ms(to_ok),
                same_rate / ms(to_ok)
            ));
        }
    }
    Ok(t)
}
