//! What one row of the test plan shows, and the Markdown table of every row (`drcc dmr
//! table`).
//!
//! Columns: per device its DMR state and ACL at the end of the fault window (as its
//! host read `DMR_STATUS`; the cells of the seed's Table 3), the same at the end of
//! the run, application frames lost and duplicated (every frame a host pushed must be
//! popped exactly once by every other host), the times from the fault's onset (clock 0
//! for a startup failure) to the first fault flag of any device and to the first ACL
//! switch (inside the fault window), from the fault's removal to "redundancy active"
//! on every device (with the first relapse after it, if any), and the
//! worst extra delivery latency of any message against the fault-free baseline (same
//! traffic; a message is matched by sender and sequence number at each receiver).
//! Times in ms (bit times / 125).

use std::collections::HashMap;
use std::time::Duration;

use drcc_cosim::dual::Line;
use drcc_hdl::host::registers::{DmrState, MAP};

use super::marker::{line_name, Row, DEVICES};
use super::ms;
use super::run::run_row;
use super::setup::PlanConfig;
use crate::engines::EngineKind;

/// A device's `DMR_STATUS` word, decoded with the register table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DeviceStatus {
    pub word: u32,
}

impl DeviceStatus {
    /// `dmr_state`.
    pub fn state(&self) -> Option<DmrState> {
        DmrState::from_code(MAP.field("DMR_STATUS", "dmr_state").get(self.word))
    }

    /// `acl`.
    pub fn acl(&self) -> Line {
        if MAP.field("DMR_STATUS", "acl").get(self.word) == 0 {
            Line::A
        } else {
            Line::B
        }
    }

    /// The seed's short name of the state (Table 3: "DMR: passive").
    pub fn state_name(&self) -> &'static str {
        match self.state() {
            Some(DmrState::RedundancyActive) => "active",
            Some(DmrState::RedundancyPassive) => "passive",
            Some(DmrState::RedundancyDisabled) => "disabled",
            Some(DmrState::NetworkDisconnected) => "disconnected",
            None => "?",
        }
    }

    /// "passive / DCL".
    pub fn cell(&self) -> String {
        format!("{} / {}", self.state_name(), line_name(self.acl()))
    }
}

/// What one row showed.
#[derive(Clone, Debug, Default)]
pub struct RowReport {
    pub row: Row,
    pub engine: String,
    /// The devices delivered the first copy from either line (DMR contract §8.1).
    pub first_copy: bool,
    pub cycles: u64,
    /// Clocks at which the fault started (0 for a startup failure) and ended.
    pub onset: u64,
    pub fault_end: u64,
    /// Per device: `DMR_STATUS` 1 ms before the fault ended, and at the end.
    pub during: Vec<DeviceStatus>,
    pub end: Vec<DeviceStatus>,
    /// Per device at the end: `DMR_RX_STATS`, `DMR_CS_COUNT`.
    pub rx_stats_end: Vec<u32>,
    pub cs_count_end: Vec<u32>,
    /// Frames the hosts pushed, and submitted ones they could not push by the end.
    pub pushed: usize,
    pub unpushed: usize,
    /// Frames the hosts popped.
    pub deliveries: usize,
    /// (receiver, sender, sequence number) of pushed frames a host never popped, or
    /// popped more than once.
    pub lost: Vec<(usize, usize, u16)>,
    pub duplicated: Vec<(usize, usize, u16)>,
    /// Popped frames that no other host pushed.
    pub foreign: usize,
    /// Clocks from the onset to the first fault flag of any device, and to the first
    /// ACL switch, inside the fault window (the baseline: the whole run).
    pub detection: Option<u64>,
    pub acl_switch: Option<u64>,
    /// The last clock at which some device was not "redundancy active".
    pub last_not_active: Option<u64>,
    /// The first clock at or after the fault's end at which every device was
    /// "redundancy active".
    pub recovered: Option<u64>,
    /// The first clock after `recovered` at which a device was not active again, and
    /// that device (a relapse: a fault flag without a fault).
    pub relapse: Option<(u64, usize)>,
    /// Every device "redundancy active" at the end.
    pub all_active_at_end: bool,
    /// Per receiver: the clock of the first pop of each (sender, sequence number).
    pub pops: Vec<HashMap<(usize, u16), u64>>,
    /// Wall-clock time of the run.
    pub wall: Duration,
}

impl RowReport {
    /// Every pushed frame reached every other host exactly once, nothing else arrived.
    pub fn exactly_once(&self) -> bool {
        self.lost.is_empty() && self.duplicated.is_empty() && self.foreign == 0
    }

    /// Clocks from the fault's removal to "redundancy active" on every device (0 if
    /// they were all active already), `None` if that never happened.
    pub fn recovery(&self) -> Option<u64> {
        self.recovered.map(|c| c - self.fault_end)
    }

    /// The worst extra delivery latency, in clocks, of any message at any receiver
    /// against `base` (the same traffic without the fault); negative if every message
    /// came earlier. `None` if no message was delivered in both runs.
    pub fn extra_latency(&self, base: &RowReport) -> Option<i64> {
        self.pops
            .iter()
            .zip(&base.pops)
            .flat_map(|(mine, theirs)| {
                mine.iter()
                    .filter_map(|(k, &at)| theirs.get(k).map(|&b| at as i64 - b as i64))
            })
            .max()
    }

    /// "all active / DCL", or each device's cell when they differ.
    fn summary(states: &[DeviceStatus]) -> String {
        match states.first() {
            Some(first) if states.iter().all(|s| s.cell() == first.cell()) => {
                format!("all {}", first.cell())
            }
            _ => states
                .iter()
                .zip(DEVICES)
                .map(|(s, d)| format!("{d} {}", s.cell()))
                .collect::<Vec<_>>()
                .join(", "),
        }
    }
}

/// The columns after the devices' cells, for the rule a row ran with.
const RULE_COLUMNS: &str = " at the end | lost | duplicated | onset -> detection (ms) \
     | onset -> ACL switch (ms) | removal -> redundancy active (ms) | worst extra latency (ms) |";

/// The first-copy column set (DMR contract §8.1) of the whole table.
const FIRST_COPY_COLUMNS: &str = " first copy: Table 3 cells | first copy: lost \
     | first copy: duplicated | first copy: worst extra latency (ms) |";

fn header(first_copy_columns: bool) -> String {
    let mut h = String::from("| row | fault |");
    for d in DEVICES {
        h.push_str(&format!(" {d} |"));
    }
    h.push_str(RULE_COLUMNS);
    let mut align = String::from("|---|---|---|---|---|---|---|---:|---:|---:|---:|---:|---:|");
    if first_copy_columns {
        h.push_str(FIRST_COPY_COLUMNS);
        align.push_str("---|---:|---:|---:|");
    }
    format!("{h}\n{align}\n")
}

/// The header of one row's table (the rule it ran with).
pub fn table_header() -> String {
    header(false)
}

/// The header of the whole table: the seed's ACL rule, then the first-copy
/// column set (DMR contract §8.1).
pub fn table_header_both() -> String {
    header(true)
}

fn ms_cell(clocks: Option<u64>) -> String {
    clocks.map_or("-".to_string(), |c| format!("{:.1}", ms(c)))
}

/// One row of the table; `base` is the baseline run for the latency column.
pub fn row_line(r: &RowReport, base: Option<&RowReport>) -> String {
    let fault = r.row.marker.map_or("none".to_string(), |m| m.describe());
    let mut line = format!("| {} | {fault} |", r.row.name());
    for s in &r.during {
        line.push_str(&format!(" {} |", s.cell()));
    }
    let recovery = match (r.recovery(), r.relapse) {
        (Some(c), None) => format!("{:.1}", ms(c)),
        (Some(c), Some((at, d))) => format!(
            "{:.1}, relapse of {} {:.1} ms after the removal",
            ms(c),
            DEVICES[d],
            ms(at - r.fault_end)
        ),
        (None, _) => "not within the run".to_string(),
    };
    let latency = match base.and_then(|b| r.extra_latency(b)) {
        Some(c) => format!("{:.1}", c.max(0) as f64 / super::CLOCKS_PER_MS as f64),
        None => "-".to_string(),
    };
    let unpushed = if r.unpushed > 0 {
        format!(" ({} never pushed)", r.unpushed)
    } else {
        String::new()
    };
    line.push_str(&format!(
        " {} | {}{unpushed} | {} | {} | {} | {} | {latency} |\n",
        RowReport::summary(&r.end),
        r.lost.len(),
        r.duplicated.len() + r.foreign,
        ms_cell(r.detection),
        ms_cell(r.acl_switch),
        recovery,
    ));
    line
}

/// The first-copy column set of a row: `fc` is the row run with first-copy
/// delivery, `acl` the same row with the seed's ACL rule, `fc_base` the
/// first-copy baseline. The cells are "same" when every device's DMR state and
/// ACL at the end of the fault window are those of the ACL rule (the diagnosis
/// does not depend on the delivery rule), else the first-copy cells.
pub fn first_copy_cells(acl: &RowReport, fc: &RowReport, fc_base: &RowReport) -> String {
    let cells = if fc
        .during
        .iter()
        .map(DeviceStatus::cell)
        .eq(acl.during.iter().map(DeviceStatus::cell))
    {
        "same".to_string()
    } else {
        RowReport::summary(&fc.during)
    };
    let latency = match fc.extra_latency(fc_base) {
        Some(c) => format!("{:.1}", c.max(0) as f64 / super::CLOCKS_PER_MS as f64),
        None => "-".to_string(),
    };
    format!(
        " {cells} | {} | {} | {latency} |",
        fc.lost.len(),
        fc.duplicated.len() + fc.foreign
    )
}

/// Runs every row ([`Row::all`]) of `c`, each with the seed's ACL rule and with
/// first-copy delivery, and renders the table; `each` sees every report as it is
/// done (progress, run times).
pub fn dmr_table(
    c: &PlanConfig,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    mut each: impl FnMut(&RowReport),
) -> Result<String, String> {
    let acl_plan = PlanConfig {
        first_copy: false,
        ..*c
    };
    let fc_plan = c.first_copy();
    let mut t = table_header_both();
    let mut bases: Option<(RowReport, RowReport)> = None;
    for row in Row::all() {
        let r = run_row(&acl_plan, row, kind, cosim)?;
        each(&r);
        let f = run_row(&fc_plan, row, kind, cosim)?;
        each(&f);
        let (base, fc_base) = bases.as_ref().map_or((&r, &f), |(b, fb)| (b, fb));
        t.push_str(row_line(&r, Some(base)).trim_end());
        t.push_str(&first_copy_cells(&r, &f, fc_base));
        t.push('\n');
        if row == Row::BASELINE {
            bases = Some((r, f));
        }
    }
    Ok(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dmr::marker::{Marker, Onset};

    fn status(state: u32, acl: u32) -> DeviceStatus {
        DeviceStatus {
            word: MAP.field("DMR_STATUS", "dmr_state").put(state)
                | MAP.field("DMR_STATUS", "acl").put(acl),
        }
    }

    #[test]
    fn cells_name_state_and_line_as_table_3() {
        assert_eq!(status(1, 0).cell(), "passive / DCL");
        assert_eq!(status(2, 0).cell(), "disabled / DCL");
        assert_eq!(status(0, 1).cell(), "active / RCL");
        assert_eq!(status(3, 1).cell(), "disconnected / RCL");
    }

    #[test]
    fn a_row_renders_every_column() {
        let base = RowReport {
            pops: vec![HashMap::from([((1, 0), 1000)])],
            ..RowReport::default()
        };
        let r = RowReport {
            row: Row {
                marker: Some(Marker::F2),
                onset: Onset::Startup,
            },
            during: vec![status(2, 0), status(1, 0), status(1, 0), status(1, 0)],
            end: vec![status(0, 0); 4],
            detection: Some(20_500),
            acl_switch: None,
            fault_end: 400_000,
            last_not_active: Some(699_999),
            recovered: Some(700_000),
            all_active_at_end: true,
            pops: vec![HashMap::from([((1, 0), 3500)])],
            ..RowReport::default()
        };
        let line = row_line(&r, Some(&base));
        assert_eq!(
            line,
            "| F2 startup | COS1 disconnected from the RCL | disabled / DCL | passive / DCL \
             | passive / DCL | passive / DCL | all active / DCL | 0 | 0 | 20.5 | - | 300.0 \
             | 2.5 |\n"
        );
        assert_eq!(table_header().lines().count(), 2);
        assert_eq!(
            table_header().lines().next().unwrap().matches('|').count(),
            line.trim_end().matches('|').count()
        );
    }

    #[test]
    fn recovery_is_missing_or_relapses() {
        let mut r = RowReport {
            fault_end: 400_000,
            ..RowReport::default()
        };
        assert_eq!(r.recovery(), None);
        assert!(row_line(&r, None).contains("not within the run"));
        r.recovered = Some(500_000);
        r.relapse = Some((650_000, 2));
        assert_eq!(r.recovery(), Some(100_000));
        assert!(row_line(&r, None).contains("100.0, relapse of COS3 250.0 ms after the removal"));
    }
}
