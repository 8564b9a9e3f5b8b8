//! Traces: VCD writing and reading (with the `vcd` crate) and waveform comparison.
//!
//! - [`VcdWriter`]: the full trace of one or more systems (`clk`, `rst`, `bus`,
//!   and per node its inputs, outputs, probes and diagnostics: `node0.tx`,
//!   `node0.field[4:0]`, `node0.err_kind[2:0]`).
//! - [`BusVcdWriter`]: the bus-only variant, 1-bit signals only (`bus`,
//!   `node0_tx`, ...), for tools such as sigrok whose VCD input stops at the first
//!   multi-bit signal and ignores scopes.
//! - [`History`]: a ring buffer of the last samples, dumped around a divergence.
//! - [`read_vcd`] / [`Trace`]: a VCD reader; [`first_difference`]: `wave-diff`.
//!
//! # Time base
//!
//! Times are real time derived from the scenario clock frequency ([`TimeBase`]):
//! the timescale is `1 ns` (or `1 ps` above 250 MHz), and the rising clock edge
//! of cycle n is at `round(n * 1e9 / clock_hz)` ns. Clocks that divide 1 GHz
//! (8 MHz: 125 ns) are exact; others are rounded to the nearest time unit
//! (24 MHz: edges 41 or 42 ns apart), which no viewer or decoder notices.
//! Inputs of cycle n (`rst`, `tx_req`) change at the falling clock edge half a
//! period before edge n; `bus` and every `rx` change together with the `tx`
//! outputs of cycle n-1 that produce them (the wired AND is combinational), i.e.
//! at edge n-1; outputs of cycle n change at edge n.

mod diff;
mod history;
mod reader;
mod writer;

pub use diff::{first_difference, WaveDiffReport, WaveDifference};
pub use history::History;
pub use reader::{read_vcd, read_vcd_from, Trace, TraceSignal};
pub use writer::{BusVcdWriter, VcdWriter};

use crate::engine::ChannelOutputs;
use vcd::TimescaleUnit;

/// One output (or probe) of a channel: its name in traces and reports, its width in
/// traces, and how to read it.
#[derive(Clone, Copy)]
pub struct OutputSignal {
    /// Name, as in `node0.<name>`.
    pub name: &'static str,
    /// Width in traces (values are masked to it there; comparisons use the full value).
    pub width: u32,
    /// Reads the value.
    pub get: fn(&ChannelOutputs) -> u64,
}

impl std::fmt::Debug for OutputSignal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}[{}]", self.name, self.width)
    }
}

/// Every output, probe and diagnostics register of a channel, in the order they
/// are compared and traced: the pins and host events, the received frame, the
/// probes, then the diagnostics (timing contract §9).
pub const OUTPUT_SIGNALS: &[OutputSignal] = &[
    OutputSignal {
        name: "tx",
        width: 1,
        get: |o| o.tx as u64,
    },
    OutputSignal {
        name: "tx_pending",
        width: 1,
        get: |o| o.tx_pending as u64,
    },
    OutputSignal {
        name: "tx_done",
        width: 1,
        get: |o| o.tx_done as u64,
    },
    OutputSignal {
        name: "arb_lost",
        width: 1,
        get: |o| o.arb_lost as u64,
    },
    OutputSignal {
        name: "tx_failed",
        width: 1,
        get: |o| o.tx_failed as u64,
    },
    OutputSignal {
        name: "rx_valid",
        width: 1,
        get: |o| o.rx_valid as u64,
    },
    OutputSignal {
        name: "rx_frame_id",
        width: 29,
        get: |o| o.rx_frame.id as u64,
    },
    OutputSignal {
        name: "rx_frame_ide",
        width: 1,
        get: |o| o.rx_frame.ide as u64,
    },
    OutputSignal {
        name: "rx_frame_rtr",
        width: 1,
        get: |o| o.rx_frame.rtr as u64,
    },
    OutputSignal {
        name: "rx_frame_dlc",
        width: 4,
        get: |o| o.rx_frame.dlc as u64,
    },
    OutputSignal {
        name: "rx_frame_data",
        width: 64,
        get: |o| o.rx_frame.data_word(),
    },
    OutputSignal {
        name: "sample_point",
        width: 1,
        get: |o| o.probes.sample_point as u64,
    },
    OutputSignal {
        name: "sampled_bit",
        width: 1,
        get: |o| o.probes.sampled_bit as u64,
    },
    OutputSignal {
        name: "field",
        width: 5,
        get: |o| o.probes.field as u64,
    },
    OutputSignal {
        name: "tec",
        width: 9,
        get: |o| o.probes.tec as u64,
    },
    OutputSignal {
        name: "rec",
        width: 8,
        get: |o| o.probes.rec as u64,
    },
    OutputSignal {
        name: "err_state",
        width: 2,
        get: |o| o.probes.err_state as u64,
    },
    OutputSignal {
        name: "is_tx",
        width: 1,
        get: |o| o.probes.is_tx as u64,
    },
    OutputSignal {
        name: "boff_runs",
        width: 7,
        get: |o| o.probes.boff_runs as u64,
    },
    OutputSignal {
        name: "err_warning",
        width: 1,
        get: |o| o.diag.err_warning as u64,
    },
    OutputSignal {
        name: "err_valid",
        width: 1,
        get: |o| o.diag.err_valid as u64,
    },
    OutputSignal {
        name: "err_kind",
        width: 3,
        get: |o| o.diag.err_kind as u64,
    },
    OutputSignal {
        name: "err_field",
        width: 5,
        get: |o| o.diag.err_field as u64,
    },
    OutputSignal {
        name: "err_tx",
        width: 1,
        get: |o| o.diag.err_tx as u64,
    },
    OutputSignal {
        name: "alc",
        width: 5,
        get: |o| o.diag.alc as u64,
    },
    OutputSignal {
        name: "cnt_bit",
        width: 8,
        get: |o| o.diag.cnt_bit as u64,
    },
    OutputSignal {
        name: "cnt_stuff",
        width: 8,
        get: |o| o.diag.cnt_stuff as u64,
    },
    OutputSignal {
        name: "cnt_crc",
        width: 8,
        get: |o| o.diag.cnt_crc as u64,
    },
    OutputSignal {
        name: "cnt_form",
        width: 8,
        get: |o| o.diag.cnt_form as u64,
    },
    OutputSignal {
        name: "cnt_ack",
        width: 8,
        get: |o| o.diag.cnt_ack as u64,
    },
];

/// Formats a value of the given width for reports: `0`/`1` for one bit, else
/// hexadecimal and decimal.
pub fn format_value(width: u32, v: u64) -> String {
    if width == 1 {
        format!("{v}")
    } else {
        format!("0x{v:X} ({v})")
    }
}

/// Maps clock cycles to VCD times (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TimeBase {
    clock_hz: u64,
    unit: TimescaleUnit,
}

impl TimeBase {
    /// The time base for a clock of `clock_hz` (clamped to at least 1 Hz).
    pub fn new(clock_hz: u64) -> Self {
        let clock_hz = clock_hz.max(1);
        let unit = if clock_hz <= 250_000_000 {
            TimescaleUnit::NS
        } else {
            TimescaleUnit::PS
        };
        TimeBase { clock_hz, unit }
    }

    /// Clock frequency.
    pub fn clock_hz(&self) -> u64 {
        self.clock_hz
    }

    /// The VCD timescale unit (the timescale is 1 of it).
    pub fn unit(&self) -> TimescaleUnit {
        self.unit
    }

    /// Time of `half_periods` half clock periods, rounded to the nearest unit.
    fn halves(&self, half_periods: u128) -> u64 {
        let per_s = self.unit.divisor() as u128;
        let den = 2 * self.clock_hz as u128;
        let t = (half_periods * per_s + den / 2) / den;
        u64::try_from(t).unwrap_or(u64::MAX)
    }

    /// Time of the rising clock edge of cycle `n`.
    pub fn edge(&self, n: u64) -> u64 {
        self.halves(2 * n as u128)
    }

    /// Time of the falling clock edge after the rising edge of cycle `n`.
    pub fn falling(&self, n: u64) -> u64 {
        self.halves(2 * n as u128 + 1)
    }

    /// The cycle whose rising edge is nearest to `time` (from below).
    pub fn cycle_at(&self, time: u64) -> u64 {
        let per_s = self.unit.divisor() as u128;
        let c = (time as u128 * self.clock_hz as u128 + per_s / 4) / per_s;
        u64::try_from(c).unwrap_or(u64::MAX)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_base_is_exact_or_rounded() {
        let tb = TimeBase::new(8_000_000);
        assert_eq!(tb.edge(3), 375);
        assert_eq!(tb.falling(3), 438);
        assert_eq!(tb.cycle_at(375), 3);
        let tb = TimeBase::new(24_000_000);
        assert_eq!(tb.edge(3), 125);
        assert_eq!(tb.edge(1), 42);
        for n in [0u64, 1, 2, 5, 1234, 99_999_999] {
            assert_eq!(tb.cycle_at(tb.edge(n)), n);
            assert!(tb.falling(n) > tb.edge(n) && tb.falling(n) < tb.edge(n + 1));
        }
        let fast = TimeBase::new(400_000_000);
        assert_eq!(fast.unit(), TimescaleUnit::PS);
        assert_eq!(fast.edge(1), 2500);
    }

    #[test]
    fn output_signal_names_are_unique() {
        let mut names: Vec<&str> = OUTPUT_SIGNALS.iter().map(|s| s.name).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), OUTPUT_SIGNALS.len());
    }
}

#[cfg(test)]
mod roundtrip_tests {
    use super::*;
    use crate::engine::BitTiming;
    use crate::frame::Frame;
    use crate::system::tests::Ideal;
    use crate::system::{Sample, System};

    fn run() -> Vec<Sample> {
        let mut s = System::new(
            (0..3).map(|_| Ideal::boxed()).collect(),
            BitTiming::default(),
        )
        .unwrap();
        s.submit(
            1,
            0,
            Frame {
                dlc: 5,
                ..Default::default()
            },
        )
        .unwrap();
        let mut v = Vec::new();
        s.run_until_idle_with(10_000, |x| {
            v.push(x.clone());
            Ok::<(), ()>(())
        })
        .unwrap();
        v
    }

    fn full_vcd(samples: &[Sample], tamper: Option<u64>) -> Vec<u8> {
        let mut buf = Vec::new();
        {
            let mut w = VcdWriter::new(
                &mut buf,
                24_000_000,
                &[("tb", 3)],
                "test; clock_hz=24000000",
            )
            .unwrap();
            for s in samples {
                let mut s = s.clone();
                if Some(s.cycle) == tamper {
                    s.outputs[2].probes.field = 7;
                }
                w.write_cycle(&[&s]).unwrap();
            }
            w.finish().unwrap();
        }
        buf
    }

    #[test]
    fn full_vcd_reads_back() {
        let samples = run();
        let buf = full_vcd(&samples, None);
        let t = read_vcd_from(&buf[..], "mem").unwrap();
        assert_eq!(t.clock_hz(), Some(24_000_000));
        let tb = TimeBase::new(24_000_000);
        let tx = t.signal("tb.node1.tx").unwrap();
        let bus = t.signal("tb.bus").unwrap();
        assert!(t.signal("tb.node0.field[4:0]").is_some());
        for name in [
            "tb.node0.tx_abort",
            "tb.node0.tx_failed",
            "tb.node2.err_warning",
            "tb.node2.err_valid",
            "tb.node2.err_kind[2:0]",
            "tb.node2.err_field[4:0]",
            "tb.node2.err_tx",
            "tb.node2.alc[4:0]",
            "tb.node2.cnt_bit[7:0]",
            "tb.node2.cnt_stuff[7:0]",
            "tb.node2.cnt_crc[7:0]",
            "tb.node2.cnt_form[7:0]",
            "tb.node2.cnt_ack[7:0]",
        ] {
            assert!(t.signal(name).is_some(), "{name} is traced");
        }
        assert_eq!(t.find("node2.rx_frame_dlc").len(), 1);
        for s in &samples {
            let v = tx.value_at(tb.edge(s.cycle)).unwrap();
            assert_eq!(v == "1", s.outputs[1].tx, "cycle {}", s.cycle);
            if s.cycle > 0 {
                let b = bus.value_at(tb.edge(s.cycle - 1)).unwrap();
                assert_eq!(b == "1", s.bus, "cycle {}", s.cycle);
            }
        }
        let dlc = t.signal("tb.node0.rx_frame_dlc[3:0]").unwrap();
        assert_eq!(dlc.changes.last().unwrap().1, "0101");
    }

    #[test]
    fn wave_diff_finds_the_first_difference() {
        let samples = run();
        let a = read_vcd_from(&full_vcd(&samples, None)[..], "a").unwrap();
        let b = read_vcd_from(&full_vcd(&samples, Some(30))[..], "b").unwrap();
        let same = first_difference(&a, &a, &[]).unwrap();
        assert!(!same.differs(), "{same}");
        let d = first_difference(&a, &b, &[]).unwrap();
        let first = d.first.clone().unwrap();
        assert_eq!(first.signal, "tb.node2.field[4:0]");
        assert_eq!(first.cycle, Some(30));
        assert_eq!(first.time, TimeBase::new(24_000_000).edge(30));
        assert!(first.b.contains("0x7"), "{}", first.b);
        // Filtered to other signals: no difference.
        let f = first_difference(&a, &b, &["node2.tx".to_string()]).unwrap();
        assert!(!f.differs());
        assert!(first_difference(&a, &b, &["nope".to_string()]).is_err());
    }

    #[test]
    fn bus_vcd_is_one_bit_only() {
        let samples = run();
        let mut buf = Vec::new();
        {
            let mut w = BusVcdWriter::new(&mut buf, 8_000_000, 3, "bus").unwrap();
            for s in &samples {
                w.write_cycle(s).unwrap();
            }
            w.finish().unwrap();
        }
        let t = read_vcd_from(&buf[..], "bus").unwrap();
        assert!(t.signals.iter().all(|s| s.width == 1));
        let names: Vec<&str> = t.signals.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(
            names,
            ["can.bus", "can.node0_tx", "can.node1_tx", "can.node2_tx"]
        );
        let tb = TimeBase::new(8_000_000);
        let bus = t.signal("can.bus").unwrap();
        for s in samples.iter().skip(1) {
            let b = bus.value_at(tb.edge(s.cycle - 1)).unwrap();
            assert_eq!(b == "1", s.bus);
        }
    }
}
