//! VCD of a dual-bus DRCC system with the DRCC paper's signal names (`docs/design.md`,
//! "Redundancy management"): per node `state[3:0]`, `tx_channel`,
//! `transmission_ack`, `chan_a_transmission_req`, ..., plus the CAN pins and the
//! two line values. Values change at the rising edge of the clock that produced
//! them (one VCD time unit per the [`crate::trace::TimeBase`] of the clock); no
//! `clk` toggles are written, so the file stays small enough to be a golden
//! snapshot and to be diffed with `drcc wave-diff`.

use super::DualBusSystem;
use crate::system::DrccNode;
use crate::trace::TimeBase;
use std::io::{self, Write};
use vcd::{IdCode, ReferenceIndex, Value, VarType};

/// One traced signal of a node: name, width, getter.
pub struct DrccSignal {
    pub name: &'static str,
    pub width: u32,
    pub get: fn(&DrccNode) -> u64,
}

macro_rules! probe {
    ($name:ident, $w:expr) => {
        DrccSignal {
            name: stringify!($name),
            width: $w,
            get: |n| n.outputs.probes.$name as u64,
        }
    };
}

/// The signals of every node, in the order the paper's Fig. 7 lists them, then the
/// pins and the auxiliary FSMs.
pub const DRCC_SIGNALS: &[DrccSignal] = &[
    probe!(chan_a_bsp_tx_err_cnt, 9),
    probe!(chan_a_bsp_node_error_passive, 1),
    probe!(chan_b_bsp_tx_err_cnt, 9),
    probe!(chan_b_bsp_node_error_passive, 1),
    probe!(tx_channel, 1),
    probe!(transmission_ack, 1),
    probe!(chan_a_transmission_req, 1),
    probe!(chan_b_transmission_req, 1),
    probe!(tx_success, 1),
    probe!(tx_ok_channel, 2),
    probe!(tx_failure, 1),
    probe!(tx_failure_channel, 2),
    probe!(tx_going_on, 1),
    probe!(state, 4),
    probe!(aux_a_state, 2),
    probe!(aux_b_state, 2),
    DrccSignal {
        name: "chan_a_tx",
        width: 1,
        get: |n| n.outputs.chan_a_tx as u64,
    },
    DrccSignal {
        name: "chan_b_tx",
        width: 1,
        get: |n| n.outputs.chan_b_tx as u64,
    },
    DrccSignal {
        name: "irq",
        width: 1,
        get: |n| n.outputs.irq as u64,
    },
];

/// The DMR probes (DMR contract §9), traced by [`DrccVcdWriter::with_dmr`] after
/// [`DRCC_SIGNALS`] and named by the lock-step comparison: the CiA 701 names.
pub const DMR_SIGNALS: &[DrccSignal] = &[
    probe!(dmr_state, 2),
    probe!(acl, 1),
    probe!(dcl_tx_fault, 1),
    probe!(dcl_rx_fault, 1),
    probe!(rcl_tx_fault, 1),
    probe!(rcl_rx_fault, 1),
    probe!(dmr_tick, 1),
];

struct Var {
    id: IdCode,
    width: u32,
    prev: Option<u64>,
}

/// Streams a [`DualBusSystem`] into a VCD, one call per clock.
pub struct DrccVcdWriter<W: Write> {
    w: vcd::Writer<W>,
    tb: TimeBase,
    lines: [Var; 2],
    nodes: Vec<Vec<Var>>,
    signals: Vec<&'static DrccSignal>,
    last_time: Option<u64>,
}

fn add<W: Write>(w: &mut vcd::Writer<W>, name: &str, width: u32) -> io::Result<Var> {
    let index = (width > 1).then(|| ReferenceIndex::Range(width - 1, 0));
    Ok(Var {
        id: w.add_var(VarType::Wire, width, name, index)?,
        width,
        prev: None,
    })
}

impl<W: Write> DrccVcdWriter<W> {
    /// Header for `nodes` nodes at `clock_hz`, tracing [`DRCC_SIGNALS`].
    pub fn new(out: W, clock_hz: u64, nodes: usize, comment: &str) -> io::Result<Self> {
        Self::with_signals(out, clock_hz, nodes, comment, DRCC_SIGNALS.iter().collect())
    }

    /// As [`DrccVcdWriter::new`], also tracing the DMR probes ([`DMR_SIGNALS`]).
    pub fn with_dmr(out: W, clock_hz: u64, nodes: usize, comment: &str) -> io::Result<Self> {
        let signals = DRCC_SIGNALS.iter().chain(DMR_SIGNALS).collect();
        Self::with_signals(out, clock_hz, nodes, comment, signals)
    }

    fn with_signals(
        out: W,
        clock_hz: u64,
        nodes: usize,
        comment: &str,
        signals: Vec<&'static DrccSignal>,
    ) -> io::Result<Self> {
        let tb = TimeBase::new(clock_hz);
        let mut w = vcd::Writer::new(out);
        w.comment(comment)?;
        w.timescale(1, tb.unit())?;
        w.add_module("dual_bus")?;
        let lines = [add(&mut w, "line_a", 1)?, add(&mut w, "line_b", 1)?];
        let mut nv = Vec::new();
        for i in 0..nodes {
            w.add_module(&format!("node{i}"))?;
            nv.push(
                signals
                    .iter()
                    .map(|s| add(&mut w, s.name, s.width))
                    .collect::<io::Result<Vec<_>>>()?,
            );
            w.upscope()?;
        }
        w.upscope()?;
        w.enddefinitions()?;
        Ok(DrccVcdWriter {
            w,
            tb,
            lines,
            nodes: nv,
            signals,
            last_time: None,
        })
    }

    fn change(
        w: &mut vcd::Writer<W>,
        var: &mut Var,
        v: u64,
        time: u64,
        last: &mut Option<u64>,
    ) -> io::Result<()> {
        let v = if var.width >= 64 {
            v
        } else {
            v & ((1u64 << var.width) - 1)
        };
        if var.prev == Some(v) {
            return Ok(());
        }
        var.prev = Some(v);
        if *last != Some(time) {
            w.timestamp(time)?;
            *last = Some(time);
        }
        if var.width == 1 {
            w.change_scalar(var.id, v != 0)
        } else {
            let n = var.width as usize;
            let bits: Vec<Value> = (0..n)
                .map(|i| Value::from((v >> (n - 1 - i)) & 1 == 1))
                .collect();
            w.change_vector(var.id, &bits)
        }
    }

    /// Records the state after the last step of `sys`.
    pub fn write_cycle(&mut self, sys: &DualBusSystem) -> io::Result<()> {
        let time = self.tb.edge(sys.cycle().saturating_sub(1));
        let (a, b) = sys.lines();
        for (var, v) in self.lines.iter_mut().zip([a, b]) {
            Self::change(&mut self.w, var, v as u64, time, &mut self.last_time)?;
        }
        for (vars, node) in self.nodes.iter_mut().zip(sys.nodes()) {
            for (var, s) in vars.iter_mut().zip(&self.signals) {
                Self::change(&mut self.w, var, (s.get)(node), time, &mut self.last_time)?;
            }
        }
        Ok(())
    }

    /// Ends the trace one clock after the last recorded edge, so that a viewer
    /// shows the last values for a full clock. Pass `&mut` output to keep it.
    pub fn finish(&mut self, cycles: u64) -> io::Result<()> {
        self.w.timestamp(self.tb.edge(cycles))
    }
}

/// Every DRCC output, for clock-by-clock comparison: [`DRCC_SIGNALS`] plus the bus
/// interface and the channel probes that the paper trace leaves out.
pub const EXTRA_SIGNALS: &[DrccSignal] = &[
    DrccSignal {
        name: "wb_ack_o",
        width: 1,
        get: |n| n.outputs.wb_ack as u64,
    },
    DrccSignal {
        name: "wb_err_o",
        width: 1,
        get: |n| n.outputs.wb_err as u64,
    },
    DrccSignal {
        name: "wb_dat_o",
        width: 32,
        get: |n| n.outputs.wb_dat_r as u64,
    },
    probe!(chan_a_sample_point, 1),
    probe!(chan_b_sample_point, 1),
    probe!(chan_a_field, 5),
    probe!(chan_b_field, 5),
    probe!(chan_a_rec, 8),
    probe!(chan_b_rec, 8),
    probe!(chan_a_err_state, 2),
    probe!(chan_b_err_state, 2),
];
