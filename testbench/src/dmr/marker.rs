//! The fault markers F1..F10 of the seed's test setup (Figure 9) and the rows of the
//! test plan.
//!
//! Figure 9 is not in the seed's text; the markers follow from its tables (DMR
//! contract §10):
//!
//! - Table 2: F1..F8 turn "CAN bus connected" into "CAN bus disconnected", F9..F10
//!   "Termination available" into "CAN lines short-circuited". So F1..F8 disconnect
//!   one device from one line (8 = 4 devices x 2 lines) and F9/F10 short one line each.
//! - Table 3 ("RCL startup failure"): rows F2, F4, F6, F8 each make exactly one device
//!   "disabled" (a line it cannot transmit on), in the order COS1, COS2, COS3, COM1,
//!   and keep the DCL as ACL everywhere: the even markers are the RCL stubs of the
//!   devices in that order, so the odd ones are their DCL stubs. Row F10 makes all
//!   four disabled with the DCL still the ACL: F10 is the RCL, so F9 is the DCL.

use drcc_cosim::dual::Line;

/// The devices of Table 3, node `i` = `DEVICES[i]`.
pub const DEVICES: [&str; 4] = ["COS1", "COS2", "COS3", "COM1"];

/// A fault marker of Figure 9.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Marker {
    F1,
    F2,
    F3,
    F4,
    F5,
    F6,
    F7,
    F8,
    F9,
    F10,
}

/// What a marker does to the network.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlanFault {
    /// Device `device` disconnected from `line` (it hears only itself).
    Detach { device: usize, line: Line },
    /// The whole line short-circuited (every device reads recessive).
    Short { line: Line },
}

/// The seed's name of a line.
pub fn line_name(line: Line) -> &'static str {
    match line {
        Line::A => "DCL",
        Line::B => "RCL",
    }
}

impl Marker {
    /// Every marker in order.
    pub const ALL: [Marker; 10] = [
        Marker::F1,
        Marker::F2,
        Marker::F3,
        Marker::F4,
        Marker::F5,
        Marker::F6,
        Marker::F7,
        Marker::F8,
        Marker::F9,
        Marker::F10,
    ];

    /// `1..=10`.
    pub fn number(self) -> usize {
        Marker::ALL.iter().position(|&m| m == self).unwrap_or(0) + 1
    }

    /// "F1" .. "F10".
    pub fn name(self) -> String {
        format!("F{}", self.number())
    }

    /// The marker named `s` ("F2" or "f2").
    pub fn parse(s: &str) -> Option<Marker> {
        let n: usize = s.strip_prefix(['F', 'f'])?.parse().ok()?;
        Marker::ALL.get(n.checked_sub(1)?).copied()
    }

    /// The fault (module docs: odd = DCL, even = RCL of COS1, COS2, COS3, COM1; F9
    /// the DCL short circuit, F10 the RCL one).
    pub fn fault(self) -> PlanFault {
        let n = self.number();
        let line = if n % 2 == 1 { Line::A } else { Line::B };
        if n <= 8 {
            PlanFault::Detach {
                device: (n - 1) / 2,
                line,
            }
        } else {
            PlanFault::Short { line }
        }
    }

    /// In words, as the table prints it.
    pub fn describe(self) -> String {
        match self.fault() {
            PlanFault::Detach { device, line } => {
                format!(
                    "{} disconnected from the {}",
                    DEVICES[device],
                    line_name(line)
                )
            }
            PlanFault::Short { line } => format!("{} short-circuited", line_name(line)),
        }
    }
}

/// When the fault is there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Onset {
    /// Present at power-on (the seed's "startup failure").
    Startup,
    /// Arising while the network runs.
    Runtime,
}

impl Onset {
    /// As the table and the CLI spell it.
    pub fn name(self) -> &'static str {
        match self {
            Onset::Startup => "startup",
            Onset::Runtime => "runtime",
        }
    }
}

/// One row of the test plan: a fault and its onset, or the fault-free baseline.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Row {
    pub marker: Option<Marker>,
    pub onset: Onset,
}

impl Default for Row {
    /// The baseline.
    fn default() -> Self {
        Row::BASELINE
    }
}

impl Row {
    /// The fault-free baseline.
    pub const BASELINE: Row = Row {
        marker: None,
        onset: Onset::Startup,
    };

    /// The rows of the table: the baseline, then F1..F10 each at startup and at run time.
    pub fn all() -> Vec<Row> {
        let mut rows = vec![Row::BASELINE];
        for m in Marker::ALL {
            for onset in [Onset::Startup, Onset::Runtime] {
                rows.push(Row {
                    marker: Some(m),
                    onset,
                });
            }
        }
        rows
    }

    /// "F2 startup", or "baseline".
    pub fn name(&self) -> String {
        match self.marker {
            Some(m) => format!("{} {}", m.name(), self.onset.name()),
            None => "baseline".to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markers_follow_tables_2_and_3() {
        // Table 3: F2, F4, F6, F8 disable COS1, COS2, COS3, COM1 with the DCL as
        // ACL, so they are the RCL stubs of these devices in that order.
        for (i, m) in [Marker::F2, Marker::F4, Marker::F6, Marker::F8]
            .into_iter()
            .enumerate()
        {
            assert_eq!(
                m.fault(),
                PlanFault::Detach {
                    device: i,
                    line: Line::B
                }
            );
        }
        assert_eq!(
            Marker::F1.fault(),
            PlanFault::Detach {
                device: 0,
                line: Line::A
            }
        );
        assert_eq!(
            Marker::F7.fault(),
            PlanFault::Detach {
                device: 3,
                line: Line::A
            }
        );
        assert_eq!(Marker::F9.fault(), PlanFault::Short { line: Line::A });
        assert_eq!(Marker::F10.fault(), PlanFault::Short { line: Line::B });
        assert_eq!(Marker::F4.describe(), "COS2 disconnected from the RCL");
        assert_eq!(Marker::F9.describe(), "DCL short-circuited");
    }

    #[test]
    fn names_parse_back_and_bad_ones_are_refused() {
        for m in Marker::ALL {
            assert_eq!(Marker::parse(&m.name()), Some(m));
        }
        assert_eq!(Marker::parse("f10"), Some(Marker::F10));
        for bad in ["F0", "F11", "F", "G2", "2", "F-1", ""] {
            assert_eq!(Marker::parse(bad), None, "{bad}");
        }
    }

    #[test]
    fn the_table_has_a_baseline_and_every_marker_twice() {
        let rows = Row::all();
        assert_eq!(rows.len(), 21);
        assert_eq!(rows[0], Row::BASELINE);
        assert_eq!(rows[1].name(), "F1 startup");
        assert_eq!(rows[20].name(), "F10 runtime");
    }
}
