//! One row of the test plan on one engine, or on two in lock step.
//!
//! Node `i < 4` is device `DEVICES[i]`; with [`PlanConfig::monitor`] node 4 is the
//! test system's monitor on both lines (it only acknowledges and receives).
//!
//! The four hosts configure DMR mode, read back `CTRL` and `DMR_CFG` (an engine that
//! does not take the DMR configuration is refused with a message naming it, instead of
//! producing a meaningless row), then submit their traffic ([`super::load`]). Each host
//! reads `DMR_STATUS` 1 ms before the fault ends ("at the end of the fault window")
//! and `DMR_STATUS`, `DMR_RX_STATS` and `DMR_CS_COUNT` at the end of the run. Every
//! clock the DMR probes give the times of the first fault flag and the first ACL
//! switch inside the fault window, the first clock after the fault at which every
//! device is "redundancy active" again, and the first relapse after that.

use std::collections::HashMap;
use std::time::Instant;

use drcc_cosim::dual::fault::Detach;
use drcc_cosim::dual::lockstep::compare;
use drcc_cosim::dual::vcd::DrccVcdWriter;
use drcc_cosim::dual::DualBusSystem;
use drcc_cosim::host::{reg, HostRead};
use drcc_cosim::system::DrccNode;
use drcc_hdl::host::registers::MAP;

use super::load::{decode, schedule};
use super::marker::{PlanFault, Row, DEVICES};
use super::probes::probe;
use super::report::{DeviceStatus, RowReport};
use super::setup::PlanConfig;
use super::{ms, CLOCKS_PER_MS, CLOCK_HZ};
use crate::dual::drcc_engine;
use crate::engines::EngineKind;

/// Reads per host: `CTRL` and `DMR_CFG` after configuration, `DMR_STATUS` at the end
/// of the fault window, `DMR_STATUS`, `DMR_RX_STATS`, `DMR_CS_COUNT` at the end.
const READS: usize = 6;

/// Clocks a run may overrun its length while the hosts finish their reads.
const READ_GRACE: u64 = 100_000;

/// Runs `row` of the plan `c` on `kind`, or on `kind` and `cosim` in lock step (then
/// the first divergence is an error). An engine other than the model runs in lock
/// step with the model when `cosim` is `None`.
pub fn run_row(
    c: &PlanConfig,
    row: Row,
    kind: EngineKind,
    cosim: Option<EngineKind>,
) -> Result<RowReport, String> {
    run_row_traced(c, row, kind, cosim, None)
}

/// The system of one engine kind for `row`: engines, host configurations, the fault,
/// the traffic and the read-back of the configuration.
fn build(c: &PlanConfig, row: Row, kind: EngineKind) -> Result<DualBusSystem, String> {
    let engines = (0..c.nodes())
        .map(|_| drcc_engine(kind))
        .collect::<Result<Vec<_>, _>>()?;
    let mut configs: Vec<_> = (0..DEVICES.len()).map(|d| c.host_config(d)).collect();
    if c.monitor {
        configs.push(c.monitor_config());
    }
    let mut sys = DualBusSystem::new(engines, configs)?;
    let start = c.onset_clock(&row);
    let cycles = c.fault_end_clock() - start;
    match row.marker.map(|m| m.fault()) {
        None => {}
        Some(PlanFault::Detach { device, line }) => sys.detach(
            line,
            Detach {
                node: device,
                start,
                cycles,
            },
        )?,
        Some(PlanFault::Short { line }) => sys.short_circuit(line, start, cycles)?,
    }
    for (d, subs) in schedule(c).into_iter().enumerate() {
        let host = &mut sys.node_mut(d).host;
        for s in subs {
            host.submit(s.due, s.frame, 0);
        }
        // Served right after the start-up configuration (explicit reads go first).
        host.read(reg::CTRL);
        host.read(reg::DMR_CFG);
    }
    Ok(sys)
}

/// The four devices of the plan (without the monitor node, `PlanConfig::monitor`).
fn devices(sys: &DualBusSystem) -> &[DrccNode] {
    &sys.nodes()[..DEVICES.len()]
}

/// Refuses an engine that did not take the DMR configuration (e.g. an RTL without
/// DMR mode): `CTRL.dmr` must read 1 and `DMR_CFG` as written.
fn check_readback(c: &PlanConfig, sys: &DualBusSystem, row: Row) -> Result<(), String> {
    for (d, n) in devices(sys).iter().enumerate() {
        let (ctrl, cfg) = (n.host.reads[0].value, n.host.reads[1].value);
        let want = c.dmr_config(d).dmr_cfg();
        if MAP.field("CTRL", "dmr").get(ctrl) != 1 || cfg != want {
            return Err(format!(
                "{}: the {} engine did not take the DMR configuration on {}: CTRL reads \
                 {ctrl:#010x} (dmr = {}), DMR_CFG reads {cfg:#010x} (written {want:#010x}); \
                 this engine does not implement DMR mode (DMR contract §2){}",
                row.name(),
                n.engine.name(),
                DEVICES[d],
                MAP.field("CTRL", "dmr").get(ctrl),
                if n.engine.name() == "model" {
                    ""
                } else {
                    ": run the plan on --engine model"
                }
            ));
        }
    }
    Ok(())
}

/// [`run_row`], also writing the VCD of the main engine's system into `vcd`.
pub fn run_row_traced(
    c: &PlanConfig,
    row: Row,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    vcd: Option<&mut Vec<u8>>,
) -> Result<RowReport, String> {
    let wall = Instant::now();
    // The reference model is the plan's oracle: another engine alone always runs with
    // it in lock step, so an engine without (or with a wrong) DMR mode fails at its
    // first divergence instead of printing a row of its own.
    let cosim = cosim.or((kind != EngineKind::Model).then_some(EngineKind::Model));
    let mut main = build(c, row, kind)?;
    let mut other = cosim.map(|k| build(c, row, k)).transpose()?;
    let mut writer = match vcd {
        Some(buf) => Some(
            DrccVcdWriter::with_dmr(
                buf,
                CLOCK_HZ,
                c.nodes(),
                &format!(
                    "DRCC CiA 701 DMR test plan, {} (nodes 0..3 = COS1, COS2, COS3, COM1; \
                     line_a = DCL, line_b = RCL; node 4 = the monitor)",
                    row.name()
                ),
            )
            .map_err(|e| e.to_string())?,
        ),
        None => None,
    };
    let onset = c.onset_clock(&row);
    let fault_end = c.fault_end_clock();
    let total = c.run_clocks();
    let read_during = fault_end - CLOCKS_PER_MS;
    // Detection and ACL switch count inside the fault window (the whole run for the
    // baseline, where any fault flag is a finding).
    let window_end = if row.marker.is_none() {
        u64::MAX
    } else {
        fault_end
    };
    let mut r = RowReport {
        row,
        engine: kind.name().to_string(),
        first_copy: c.first_copy,
        onset,
        fault_end,
        ..RowReport::default()
    };
    let mut acl_at_onset = vec![false; DEVICES.len()];
    let mut checked = false;
    // Debugging aid: DRCC_DEBUG_RTL_TRACE=NODE:CYCLE:FILE opens the RTL trace
    // of one device at that cycle (read once: not a lookup at every clock).
    let debug_trace = std::env::var("DRCC_DEBUG_RTL_TRACE").ok();
    loop {
        let cycle = main.cycle();
        if cycle >= total && devices(&main).iter().all(|n| n.host.reads.len() >= READS) {
            break;
        }
        if cycle > total + READ_GRACE {
            return Err(format!(
                "{}: the hosts did not finish their register reads",
                row.name()
            ));
        }
        let mut regs: &[u8] = &[];
        if cycle == read_during {
            regs = &[reg::DMR_STATUS];
        } else if cycle == total {
            regs = &[reg::DMR_STATUS, reg::DMR_RX_STATS, reg::DMR_CS_COUNT];
        }
        for d in 0..DEVICES.len() {
            for &x in regs {
                main.node_mut(d).host.read(x);
                if let Some(o) = other.as_mut() {
                    o.node_mut(d).host.read(x);
                }
            }
        }
        if let Some(spec) = &debug_trace {
            let p: Vec<&str> = spec.splitn(3, ':').collect();
            if p.len() == 3 && p[1].parse::<u64>().ok() == Some(cycle) {
                let n: usize = p[0].parse().unwrap_or(0);
                main.node_mut(n)
                    .engine
                    .open_rtl_trace(std::path::Path::new(p[2]))?;
            }
        }
        main.step();
        if let Some(w) = writer.as_mut() {
            w.write_cycle(&main).map_err(|e| e.to_string())?;
        }
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&main, o) {
                return Err(format!(
                    "{}: {d} ({:.3} ms into the run)",
                    row.name(),
                    ms(d.cycle)
                ));
            }
        }
        if !checked && devices(&main).iter().all(|n| n.host.reads.len() >= 2) {
            check_readback(c, &main, row)?;
            if let Some(o) = other.as_ref() {
                check_readback(c, o, row)?;
            }
            checked = true;
        }
        let mut first_inactive = None;
        for (d, n) in devices(&main).iter().enumerate() {
            let p = probe(&n.outputs);
            if cycle == onset {
                acl_at_onset[d] = p.acl;
            }
            if cycle >= onset && cycle < window_end {
                if p.fault && r.detection.is_none() {
                    r.detection = Some(cycle - onset);
                }
                if p.acl != acl_at_onset[d] && r.acl_switch.is_none() {
                    r.acl_switch = Some(cycle - onset);
                }
            }
            if p.state != 0 {
                r.last_not_active = Some(cycle);
                first_inactive.get_or_insert(d);
            }
        }
        if cycle >= fault_end {
            match (r.recovered, first_inactive) {
                (None, None) => r.recovered = Some(cycle),
                (Some(_), Some(d)) if r.relapse.is_none() => r.relapse = Some((cycle, d)),
                _ => {}
            }
        }
    }
    if let Some(w) = writer.as_mut() {
        w.finish(main.cycle()).map_err(|e| e.to_string())?;
    }
    r.cycles = main.cycle();
    r.all_active_at_end = devices(&main).iter().all(|n| probe(&n.outputs).state == 0);
    tally(c, &main, &mut r);
    r.wall = wall.elapsed();
    Ok(r)
}

/// Deliveries (every pushed frame popped exactly once by every other host) and the
/// register reads.
fn tally(c: &PlanConfig, sys: &DualBusSystem, r: &mut RowReport) {
    let submitted: usize = schedule(c).iter().map(Vec::len).sum();
    let mut pushed: Vec<Vec<u16>> = vec![Vec::new(); DEVICES.len()];
    for (d, n) in devices(sys).iter().enumerate() {
        pushed[d] = n
            .host
            .sent
            .iter()
            .filter_map(|t| decode(&t.frame))
            .map(|x| x.1)
            .collect();
    }
    r.pushed = pushed.iter().map(Vec::len).sum();
    r.unpushed = submitted - r.pushed;
    for (rx, n) in devices(sys).iter().enumerate() {
        let mut pops: HashMap<(usize, u16), u64> = HashMap::new();
        let mut count: HashMap<(usize, u16), usize> = HashMap::new();
        for got in &n.host.received {
            match decode(&got.frame) {
                // A device never receives its own frames: one is as foreign as garbage.
                Some(key) if key.0 != rx => {
                    pops.entry(key).or_insert(got.cycle);
                    *count.entry(key).or_insert(0) += 1;
                }
                _ => r.foreign += 1,
            }
        }
        r.deliveries += n.host.received.len();
        for (tx, seqs) in pushed.iter().enumerate() {
            if tx == rx {
                continue;
            }
            for &seq in seqs {
                match count.get(&(tx, seq)).copied().unwrap_or(0) {
                    0 => r.lost.push((rx, tx, seq)),
                    1 => {}
                    _ => r.duplicated.push((rx, tx, seq)),
                }
            }
        }
        r.pops.push(pops);
        let read = |i: usize| n.host.reads.get(i).map_or(0, |x: &HostRead| x.value);
        r.during.push(DeviceStatus { word: read(2) });
        r.end.push(DeviceStatus { word: read(3) });
        r.rx_stats_end.push(read(4));
        r.cs_count_end.push(read(5));
    }
}
