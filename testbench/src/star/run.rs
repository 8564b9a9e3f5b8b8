//! Running one star scenario: the DRCC nodes and hubs clock by clock, the faults
//! applied on their links, the port events and deliveries tallied into a
//! [`StarReport`].

use super::*;
use crate::delivery::Deliveries;

/// Runs `s` on `kind`, or on two engines in lock step (`cosim`): then the first
/// divergence is an error.
pub fn run_star(
    s: &StarScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
) -> Result<StarReport, String> {
    run_star_observed(s, kind, cosim, &mut |_| Ok(()))
}

/// [`run_star`], calling `observe` with the main system after every clock
/// (traffic taps); an error stops the run.
pub fn run_star_observed(
    s: &StarScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    observe: &mut dyn FnMut(&StarSystem) -> Result<(), String>,
) -> Result<StarReport, String> {
    let mut main = build_star(s, kind)?;
    let mut other = match cosim {
        Some(k) => Some(build_star(s, k)?),
        None => None,
    };
    let total = s.run_bits() * CLOCKS_PER_BIT;
    let mut report = StarReport {
        scenario: s.fault.name().to_string(),
        fault_start: s.fault_start_bits * CLOCKS_PER_BIT,
        fault_end: (s.fault_start_bits + s.fault_bits) * CLOCKS_PER_BIT,
        ..StarReport::default()
    };
    let ask = |sys: &mut StarSystem| {
        for n in 0..sys.len() {
            sys.node_mut(n).host.read(reg::STATS0);
            sys.node_mut(n).host.read(reg::STAR_STATUS);
        }
        for h in 0..2 {
            let hub = sys.hub_mut(h);
            hub.host.read(hub_reg::STATS);
            for p in 0..HUB_N + HUB_M {
                hub.host.read(hub_reg::PORT0 + p as u8);
            }
            hub.host.read(hub_reg::ACK_UNIT);
            hub.host.read(hub_reg::NRAP_STATUS);
        }
    };
    // Without NRAP, after a definitive decoupling only the hubs' host can re-couple
    // them: both supervisors write `CTRL.recouple` once the interlinks are back. With
    // NRAP (the default) the hubs decide themselves.
    let recouple_at = (s.fault == StarFault::AllInterlinksLost && !s.hub.nrap_on)
        .then_some(report.fault_end + RECOUPLE_AFTER_BITS * CLOCKS_PER_BIT);
    // A hub's own fault: its supervisor's CTRL write switches the fault injection on
    // at the onset and off at the end (every CTRL write takes both bits, §8).
    let injection = s.fault.hub_injection();
    let inject = |sys: &mut StarSystem, on: bool| {
        if let Some((h, fi)) = injection {
            let c = HubConfig {
                fi_no_twin: fi.fi_no_twin && on,
                fi_ack_leak: fi.fi_ack_leak && on,
                ..s.hub
            };
            sys.hub_mut(h).host.write(hub_reg::CTRL, c.ctrl(false));
        }
    };
    let recouple = |sys: &mut StarSystem| {
        for h in 0..2 {
            // The configured CTRL (ACK interdependence, fault injection) with the
            // command: every CTRL write takes `fi_ack_leak` (hub contract §8).
            sys.hub_mut(h)
                .host
                .write(hub_reg::CTRL, s.hub.ctrl(false) | hub_reg::CTRL_RECOUPLE);
        }
    };
    let mut prev_enabled = [0u16; 2];
    let mut prev_decoupled = [false; 2];
    let mut prev_phase = [0u8; 2];
    let mut cycle = 0u64;
    loop {
        for (at, on) in [(report.fault_start, true), (report.fault_end, false)] {
            if cycle == at {
                inject(&mut main, on);
                if let Some(o) = other.as_mut() {
                    inject(o, on);
                }
            }
        }
        if Some(cycle) == recouple_at {
            recouple(&mut main);
            if let Some(o) = other.as_mut() {
                recouple(o);
            }
        }
        if cycle == total {
            ask(&mut main);
            if let Some(o) = other.as_mut() {
                ask(o);
            }
        }
        main.step();
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&main, o) {
                return Err(format!(
                    "scenario {}: {d} (bit time {})",
                    s.fault.name(),
                    d.cycle / CLOCKS_PER_BIT
                ));
            }
        }
        observe(&main)?;
        for h in 0..2 {
            let p = main.hub(h).outputs.probes;
            let mask = ((1u32 << (HUB_N + HUB_M)) - 1) as u16;
            let en = p.port_enabled & mask;
            if main.hub(h).host.configured() && cycle > 0 {
                let changed = en ^ prev_enabled[h];
                for port in 0..HUB_N + HUB_M {
                    if changed >> port & 1 != 0 {
                        report.events.push(PortEvent {
                            cycle,
                            hub: h,
                            port,
                            enabled: en >> port & 1 != 0,
                        });
                    }
                }
                if p.decoupled && !prev_decoupled[h] && report.decoupled_at[h].is_none() {
                    report.decoupled_at[h] = Some(cycle);
                }
            }
            if p.nrap_phase != prev_phase[h] {
                report.nrap_events.push(NrapEvent {
                    cycle,
                    hub: h,
                    phase: p.nrap_phase,
                });
            }
            prev_enabled[h] = en;
            prev_decoupled[h] = p.decoupled;
            prev_phase[h] = p.nrap_phase;
        }
        cycle += 1;
        let done = cycle > total
            && main.nodes().iter().all(|n| n.host.reads.len() >= 2)
            && (0..2).all(|h| main.hub(h).host.reads.len() > HUB_N + HUB_M + 2);
        if done {
            break;
        }
        if cycle > total + 100_000 {
            return Err(format!(
                "{}: the hosts did not finish their register reads",
                s.fault.name()
            ));
        }
    }
    report.cycles = cycle;
    tally(s, &main, &mut report);
    Ok(report)
}

fn tally(s: &StarScenario, sys: &StarSystem, r: &mut StarReport) {
    r.submitted = s.nodes * s.frames_per_node;
    for (rx_node, n) in sys.nodes().iter().enumerate() {
        let received = n.host.received.iter().map(|got| got.frame);
        let d = Deliveries::count(
            received,
            s.nodes,
            s.frames_per_node,
            is_identification_frame,
            |sender, k| StarScenario::frame(sender, k).normalized(),
        );
        let own = d.of(rx_node);
        let from_others = d.total() - own;
        r.foreign += d.foreign;
        r.delivered += from_others;
        r.received_at
            .push(n.host.received.iter().map(|got| got.cycle).collect());
        r.from_others.push(from_others);
        r.hub_frames.push(d.skipped);
        r.own.push(own);
        d.judge(rx_node, |_, _| true, &mut r.missing, &mut r.duplicates);
        r.dups_dropped
            .push(n.host.reads.first().map(|x| x.value & 0xFFFF).unwrap_or(0));
        r.star_status
            .push(n.host.reads.get(1).map(|x| x.value).unwrap_or(0));
    }
    for h in 0..2 {
        let reads = &sys.hub(h).host.reads;
        r.hub_stats[h] = reads.first().map(|x| x.value).unwrap_or(0);
        r.hub_ports[h] = reads
            .iter()
            .skip(1)
            .take(HUB_N + HUB_M)
            .map(|x| x.value)
            .collect();
        r.hub_ack_unit[h] = reads.get(1 + HUB_N + HUB_M).map_or(0, |x| x.value);
        r.hub_nrap[h] = reads.get(2 + HUB_N + HUB_M).map_or(0, |x| x.value);
    }
}

/// A hub's identification frame (hub contract §9.1: base data frame, identifier
/// 0x000 or 0x001, DLC 0). Nodes receive them while NRAP runs; they are the hubs'
/// traffic, not the application's.
pub fn is_identification_frame(f: &Frame) -> bool {
    !f.ide && !f.rtr && f.id <= 1 && f.dlc == 0
}
