//! What a star run reports (deliveries, omissions, port isolations and
//! restorations) and the markdown table of every fault scenario.

use super::*;

/// One isolation or restoration seen on a hub's `port_enabled` probe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PortEvent {
    pub cycle: u64,
    /// 0 = hub 1.
    pub hub: usize,
    pub port: usize,
    /// true = restored, false = isolated.
    pub enabled: bool,
}

/// A change of a hub's NRAP phase (`nrap_phase` probe, hub contract §9.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NrapEvent {
    pub cycle: u64,
    /// 0 = hub 1.
    pub hub: usize,
    pub phase: u8,
}

/// NRAP phase names as the table prints them.
pub fn phase_name(p: u8) -> &'static str {
    match p {
        0 => "RUN",
        1 => "SRP_FORCE",
        2 => "SRP_EXCHANGE",
        3 => "NRP",
        4 => "DDSP_FORCE",
        5 => "DDSP_SEND",
        6 => "SPLIT",
        _ => "?",
    }
}

/// What one run showed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StarReport {
    pub scenario: String,
    pub cycles: u64,
    pub fault_start: u64,
    pub fault_end: u64,
    /// (receiver, sender, k) of frames a host never got / got twice.
    pub missing: Vec<(usize, usize, usize)>,
    pub duplicates: Vec<(usize, usize, usize)>,
    pub foreign: usize,
    pub delivered: usize,
    pub submitted: usize,
    /// Per node: frames from others delivered, and second copies the DRCC dropped;
    /// their difference is the omissions the node saw (a frame that came through one
    /// hub only).
    pub from_others: Vec<usize>,
    pub dups_dropped: Vec<u32>,
    /// Per node: its own frames its host got back. A star node takes the other
    /// channel's echo of its frame as the notice of its transmission, not as a
    /// reception (DRCC contract §4.4), so this stays 0.
    pub own: Vec<usize>,
    /// Per node: the clocks at which its host took each frame from its RX FIFO.
    pub received_at: Vec<Vec<u64>>,
    /// Every change of a hub's `port_enabled`.
    pub events: Vec<PortEvent>,
    /// Clocks at which each hub became decoupled.
    pub decoupled_at: [Option<u64>; 2],
    /// Per hub: `STATS` and every `PORT_p` register at the end.
    pub hub_stats: [u32; 2],
    pub hub_ports: [Vec<u32>; 2],
    /// Per hub: `ACK_UNIT` at the end (hub contract §4.1).
    pub hub_ack_unit: [u32; 2],
    /// Per hub: `NRAP_STATUS` at the end (hub contract §9.5).
    pub hub_nrap: [u32; 2],
    /// Every NRAP phase change of either hub.
    pub nrap_events: Vec<NrapEvent>,
    /// Per node: the hubs' identification frames its host received (not counted as
    /// application frames). A star node keeps them from its host (DRCC contract
    /// §4.5), so this stays 0.
    pub hub_frames: Vec<usize>,
    /// Per node: `STAR_STATUS` at the end (DRCC contract §4.5: [0] split).
    pub star_status: Vec<u32>,
}

impl StarReport {
    /// Every frame reached every other host exactly once.
    pub fn exactly_once(&self) -> bool {
        self.missing.is_empty() && self.duplicates.is_empty() && self.foreign == 0
    }

    /// Omissions detected by node `i` (frames that came through one hub only).
    pub fn omissions(&self, i: usize) -> usize {
        self.from_others[i].saturating_sub(self.dups_dropped[i] as usize)
    }

    /// First isolation of (hub, port) at or after `from`.
    pub fn isolated_at(&self, hub: usize, port: usize, from: u64) -> Option<u64> {
        self.events
            .iter()
            .find(|e| e.hub == hub && e.port == port && !e.enabled && e.cycle >= from)
            .map(|e| e.cycle)
    }

    /// Last restoration of (hub, port) at or after `from`.
    pub fn restored_at(&self, hub: usize, port: usize, from: u64) -> Option<u64> {
        self.events
            .iter()
            .rev()
            .find(|e| e.hub == hub && e.port == port && e.enabled && e.cycle >= from)
            .map(|e| e.cycle)
    }

    /// Per node, the domain it follows at the end: true = the hubs split.
    pub fn node_split(&self) -> Vec<bool> {
        self.star_status.iter().map(|s| s & 1 == 1).collect()
    }

    /// The NRAP phase hub `h` is in at the end of the run.
    pub fn final_phase(&self, h: usize) -> u8 {
        (self.hub_nrap[h] & 7) as u8
    }

    /// Clock of hub `h`'s first NRAP trigger at or after `from`, and of the end of
    /// that run (the next change to RUN or SPLIT), if any.
    pub fn nrap_run(&self, h: usize, from: u64) -> Option<(u64, Option<(u64, u8)>)> {
        let mut ev = self
            .nrap_events
            .iter()
            .filter(|e| e.hub == h && e.cycle >= from);
        let start = ev.find(|e| e.phase == 1)?;
        let end = ev
            .find(|e| e.phase == 0 || e.phase == 6)
            .map(|e| (e.cycle, e.phase));
        Some((start.cycle, end))
    }

    /// Isolations of ports other than `targets`.
    pub fn false_isolations(&self, targets: &[(usize, usize)]) -> Vec<PortEvent> {
        self.events
            .iter()
            .filter(|e| !e.enabled && !targets.contains(&(e.hub, e.port)))
            .copied()
            .collect()
    }
}

/// Bit times between two clocks, or "-".
fn bits(from: u64, to: Option<u64>) -> String {
    match to {
        Some(c) if c >= from => format!("{}", (c - from) / CLOCKS_PER_BIT),
        Some(c) => format!("-{}", (from - c) / CLOCKS_PER_BIT),
        None => "never".to_string(),
    }
}

/// The star fault scenarios as a Markdown table (`drcc star table`).
pub fn star_table(kind: EngineKind, cosim: Option<EngineKind>) -> Result<String, String> {
    let mut t = String::from(
        "| fault | onset -> isolation (bit times) | frames lost (of 288) | duplicated | omissions seen per node | fault end -> restoration (bit times) | other isolations | NRAP: phases (bit times after onset) |\n\
         |---|---|---:|---:|---|---|---|---|\n",
    );
    for f in StarFault::ALL {
        let s = StarScenario::standard(f);
        let r = run_star(&s, kind, cosim)?;
        t.push_str(&table_row(&s, &r));
    }
    // The same double fault with NRAP off (`CTRL.nrap_on = 0`): each hub decouples
    // on its own after `decouple_bits` (contract §7), what the hubs did before NRAP.
    let s = StarScenario::without_nrap(StarFault::AllInterlinksLost);
    let r = run_star(&s, kind, cosim)?;
    let row = table_row(&s, &r).replacen(
        "| all_interlinks_lost (",
        "| all_interlinks_lost, NRAP off (CTRL.nrap_on = 0, the hosts recouple 200 bit times after the fault; ",
        1,
    );
    t.push_str(&row);
    Ok(t)
}

/// One row of [`star_table`].
pub fn table_row(s: &StarScenario, r: &StarReport) -> String {
    let targets = s.fault.target_ports();
    let port_name = |hub: usize, port: usize| {
        if port < HUB_N {
            format!("hub {} port {port}", hub + 1)
        } else {
            format!("hub {} sublink {}", hub + 1, port - HUB_N)
        }
    };
    let iso: Vec<String> = targets
        .iter()
        .map(|&(h, p)| {
            format!(
                "{}: {}",
                port_name(h, p),
                bits(r.fault_start, r.isolated_at(h, p, r.fault_start))
            )
        })
        .collect();
    let mut iso = if iso.is_empty() {
        "-".to_string()
    } else {
        iso.join("; ")
    };
    for (h, at) in r.decoupled_at.iter().enumerate() {
        if let Some(c) = at {
            iso.push_str(&format!(
                "; hub {} decoupled: {}",
                h + 1,
                bits(r.fault_start, Some(*c))
            ));
        }
    }
    let restore: Vec<String> = targets
        .iter()
        .filter(|&&(h, p)| r.isolated_at(h, p, r.fault_start).is_some())
        .map(|&(h, p)| {
            let back = r.restored_at(h, p, r.fault_end);
            format!("{}: {}", port_name(h, p), bits(r.fault_end, back))
        })
        .collect();
    let others: Vec<String> = r
        .false_isolations(&targets)
        .iter()
        .map(|e| {
            format!(
                "{} at {}",
                port_name(e.hub, e.port),
                bits(r.fault_start, Some(e.cycle))
            )
        })
        .collect();
    let omissions: Vec<String> = (0..s.nodes).map(|i| r.omissions(i).to_string()).collect();
    format!(
        "| {} ({}) | {} | {} | {} | {} | {} | {} | {} |\n",
        s.fault.name(),
        s.fault.describe(),
        iso,
        r.missing.len(),
        r.duplicates.len(),
        omissions.join(" / "),
        if restore.is_empty() {
            "-".to_string()
        } else {
            restore.join("; ")
        },
        if others.is_empty() {
            "none".to_string()
        } else {
            others.join("; ")
        },
        nrap_cell(r)
    )
}

/// Each hub's NRAP phases with the bit time (after the fault's onset) at which each
/// began, then its final phase; "-" when NRAP never ran.
pub fn nrap_cell(r: &StarReport) -> String {
    let mut hubs = Vec::new();
    for h in 0..2 {
        let ev: Vec<String> = r
            .nrap_events
            .iter()
            .filter(|e| e.hub == h)
            .map(|e| {
                format!(
                    "{} {}",
                    phase_name(e.phase),
                    bits(r.fault_start, Some(e.cycle))
                )
            })
            .collect();
        if !ev.is_empty() {
            hubs.push(format!("hub {}: {}", h + 1, ev.join(", ")));
        }
    }
    if hubs.is_empty() {
        return "-".to_string();
    }
    let domains: Vec<&str> = r
        .node_split()
        .iter()
        .map(|&s| if s { "split" } else { "one" })
        .collect();
    format!(
        "{}; nodes' STAR_STATUS: {}",
        hubs.join("; "),
        domains.join(" / ")
    )
}
