//! The devices of the test plan and their DMR configuration, and the time line of a
//! run.
//!
//! **Identifiers.** Device `d` (COS1 = 0 .. COM1 = 3) sends two messages, the seed's
//! `Dd.M1` and `Dd.M2` (Figure 2), as base identifiers `0x200 + 0x20 d` and `+ 1`
//! (lower identifiers win arbitration: COS1 first). Its mailboxes: mailbox 0 transmit,
//! identifier `0x200 + 0x20 d`, mask `0x7E0` (both of its messages); mailboxes 1..3
//! receive, one per other device with that device's identifier and the same mask. The
//! connection service keeps the table's identifiers `0x7EA` (DCL) and `0x7EB` (RCL),
//! which no mailbox matches (contract §2.2).
//!
//! **DMR timing** (contract §3, §4; 1 tick = 1 ms):
//! - `tick_bits = 125`: 1 ms ticks at 125 kbit/s;
//! - `timeout = 20` ticks: far above the normal skew of the two copies of a message
//!   (both lines carry the same traffic; a copy lags by a few frames, about 1 ms each
//!   at 125 kbit/s), short enough that a fault is found within a few messages;
//! - deviation `limit = 3` (the table's reset value): a device's messages come every
//!   ~4.4 ms, so a line that misses them exceeds it at the 4th, ~13 ms after the first
//!   (before the timeout);
//! - `DEDUP_CFG.window = 4000` bit times (32 ms) > `timeout x tick_bits` + one
//!   evaluation = 2500 + 125 bit times (contract §8: a frame that waits on the PCL
//!   must not expire before the ACL switch releases it);
//! - `recovery_delay`: the seed's 2 s (2000 ticks) makes a row about 5 s of simulated
//!   time; the table uses 200 ms ([`PlanConfig::standard`]), which exercises the same
//!   recovery path (delay, restart, connection service) ten times faster.
//!   [`PlanConfig::with_recovery`] gives any other delay (`drcc dmr --recovery-ms`).
//!
//! **Monitor.** The seed's test setup (Figure 9) is run by a test system with its
//! own CAN interface on the lines; the plan has it as a fifth node on both lines, a
//! DRCC in normal mode that sends nothing and acknowledges every frame. It matters
//! for the connection service: every device sends the *same* CS frame (one
//! identifier per line, DLC 0, no source address), and devices that start together
//! send it in lock step, as one frame with no receiver left to acknowledge it. The
//! monitor is what a real network always has: some node that is not transmitting.
//! (`monitor: false` runs the four devices alone.)
//!
//! **Time line** (ms): traffic from 5 ms to 100 ms before the end; a startup fault is
//! present from clock 0, a run-time one from 100 ms; both end at 400 ms; the run lasts
//! three recovery delays plus 100 ms beyond (a sender's recovery, then its receivers',
//! each a delay plus a timeout).

use drcc_cosim::host::dmr_config::{DmrConfig, DmrMailbox};
use drcc_cosim::host::{btr, HostConfig};

use super::marker::{Onset, Row, DEVICES};
use super::CLOCKS_PER_MS;

/// Identifier mask of a device's messages (its two identifiers).
pub const ID_MASK: u32 = 0x7E0;

/// Base identifier of device `d`'s messages (`Dd.M1`; `Dd.M2` is the next one).
pub fn base_id(device: usize) -> u32 {
    0x200 + 0x20 * device as u32
}

/// The parameters of the test plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanConfig {
    /// `DMR_CFG.timeout`, ticks (= ms).
    pub timeout_ms: u16,
    /// `DMR_TIME.recovery_delay`, ticks (= ms).
    pub recovery_ms: u16,
    /// `MB_CFG.limit` of every mailbox.
    pub limit: u8,
    /// `DEDUP_CFG.window`, bit times.
    pub window_bits: u16,
    /// Average bus load in percent (the seed: 85).
    pub load_percent: u64,
    /// A run-time fault's onset, ms.
    pub onset_ms: u64,
    /// Every fault's end, ms.
    pub fault_end_ms: u64,
    /// Traffic window, ms.
    pub traffic_start_ms: u64,
    pub traffic_end_ms: u64,
    /// Run length, ms.
    pub run_ms: u64,
    /// A monitor node on both lines (module docs).
    pub monitor: bool,
    /// `CTRL.first_copy` on every device (DMR contract §8.1): the first copy of a
    /// frame from either line is delivered; false is the seed's ACL rule.
    pub first_copy: bool,
}

impl PlanConfig {
    /// The configuration of the generated table (module docs): 200 ms recovery delay.
    pub fn standard() -> Self {
        PlanConfig::with_recovery(200)
    }

    /// The seed's 2 s recovery delay.
    pub fn seed() -> Self {
        PlanConfig::with_recovery(2000)
    }

    /// The standard plan with another recovery delay (ms, 1..=65535), the run
    /// stretched to fit it.
    pub fn with_recovery(recovery_ms: u16) -> Self {
        let fault_end_ms = 400;
        let run_ms = fault_end_ms + 3 * recovery_ms as u64 + 100;
        PlanConfig {
            timeout_ms: 20,
            recovery_ms,
            limit: 3,
            window_bits: 4000,
            load_percent: 85,
            onset_ms: 100,
            fault_end_ms,
            traffic_start_ms: 5,
            traffic_end_ms: run_ms - 100,
            run_ms,
            monitor: true,
            first_copy: false,
        }
    }

    /// The same plan with first-copy delivery (DMR contract §8.1) on every device.
    pub fn first_copy(self) -> Self {
        PlanConfig {
            first_copy: true,
            ..self
        }
    }

    /// The DMR configuration of device `device`.
    pub fn dmr_config(&self, device: usize) -> DmrConfig {
        let mut c = DmrConfig {
            timeout: self.timeout_ms,
            cs_period: 0,
            tick_bits: super::BITS_PER_MS as u16,
            recovery_delay: self.recovery_ms,
            first_copy: self.first_copy,
            ..DmrConfig::default()
        };
        let mailbox = |d: usize, transmit: bool| DmrMailbox {
            transmit,
            ide: false,
            id: base_id(d),
            mask: ID_MASK,
            limit: self.limit,
        };
        c.mailboxes[0] = Some(mailbox(device, true));
        let others = (0..DEVICES.len()).filter(|&d| d != device);
        for (slot, d) in others.enumerate() {
            c.mailboxes[1 + slot] = Some(mailbox(d, false));
        }
        c
    }

    /// The host configuration of device `device`: DMR mode at 125 kbit/s (BRP 0,
    /// TSEG1 5, TSEG2 2, SJW 1: 8 one-clock quanta per bit), every interrupt enabled.
    pub fn host_config(&self, device: usize) -> HostConfig {
        HostConfig::dmr(
            btr(0, 5, 2, 1, false, 96),
            self.dmr_config(device),
            self.window_bits,
        )
    }

    /// Nodes of the system: the devices and the monitor.
    pub fn nodes(&self) -> usize {
        DEVICES.len() + self.monitor as usize
    }

    /// The monitor: a DRCC in normal mode on both lines, sending nothing, its host
    /// draining what it receives (it acknowledges every frame, as a CAN interface in
    /// normal mode does).
    pub fn monitor_config(&self) -> HostConfig {
        HostConfig {
            btr: btr(0, 5, 2, 1, false, 96),
            redundancy: false,
            dedup_window: 0,
            dmr: None,
            ..HostConfig::default()
        }
    }

    /// Clock at which the fault of `row` starts.
    pub fn onset_clock(&self, row: &Row) -> u64 {
        match row.onset {
            Onset::Startup => 0,
            Onset::Runtime => self.onset_ms * CLOCKS_PER_MS,
        }
    }

    /// Clock at which every fault ends.
    pub fn fault_end_clock(&self) -> u64 {
        self.fault_end_ms * CLOCKS_PER_MS
    }

    /// Clocks of the run.
    pub fn run_clocks(&self) -> u64 {
        self.run_ms * CLOCKS_PER_MS
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dmr::BITS_PER_MS;

    #[test]
    fn the_window_exceeds_the_timeout_plus_one_evaluation() {
        // DMR contract §8.
        let c = PlanConfig::standard();
        let timeout_bits = c.timeout_ms as u64 * BITS_PER_MS;
        assert!(c.window_bits as u64 > timeout_bits + BITS_PER_MS);
        assert!(c.window_bits <= 32767, "DEDUP_CFG.window is 15 bits");
    }

    #[test]
    fn every_device_counts_its_own_messages_and_each_other_device() {
        let c = PlanConfig::standard();
        for d in 0..4 {
            let dmr = c.dmr_config(d);
            let mbs: Vec<DmrMailbox> = dmr.mailboxes.iter().flatten().copied().collect();
            assert_eq!(mbs.len(), 4);
            assert!(mbs[0].transmit && mbs[0].id == base_id(d));
            let mut rx: Vec<u32> = mbs[1..]
                .iter()
                .inspect(|m| assert!(!m.transmit))
                .map(|m| m.id)
                .collect();
            rx.sort_unstable();
            let want: Vec<u32> = (0..4).filter(|&o| o != d).map(base_id).collect();
            assert_eq!(rx, want);
            // No mailbox matches a connection-service identifier (contract §2.2).
            for cs in [dmr.cs_id_dcl as u32, dmr.cs_id_rcl as u32] {
                assert!(mbs.iter().all(|m| (cs ^ m.id) & m.mask != 0));
            }
        }
    }

    #[test]
    fn the_run_covers_three_recovery_delays_after_the_fault() {
        let c = PlanConfig::seed();
        assert_eq!(c.recovery_ms, 2000);
        assert_eq!(c.run_ms, 400 + 6000 + 100);
        assert!(c.traffic_end_ms < c.run_ms);
        assert_eq!(c.host_config(0).dmr.map(|d| d.recovery_delay), Some(2000));
    }
}
