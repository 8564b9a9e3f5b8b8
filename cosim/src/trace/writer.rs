//! VCD writers: the full trace of one or more systems, and the bus-only trace of
//! 1-bit signals (for sigrok). Time base and signal timing: see `crate::trace`.
//!
//! Writers only emit value changes. They write into any `io::Write`; pass
//! `&mut BufWriter<File>` and flush it after the last cycle (the helpers
//! [`VcdWriter::write_file`] and [`BusVcdWriter::write_file`] do this).

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use vcd::{IdCode, ReferenceIndex, SimulationCommand, Value, VarType};

use super::{TimeBase, OUTPUT_SIGNALS};
use crate::system::Sample;

#[derive(Clone, Copy, Debug)]
struct Var {
    id: IdCode,
    width: u32,
    prev: Option<u64>,
}

fn mask(width: u32, v: u64) -> u64 {
    if width >= 64 {
        v
    } else {
        v & ((1u64 << width) - 1)
    }
}

/// Writes a change of `var` to `v` (masked to its width) if it changed.
fn change<W: Write>(w: &mut vcd::Writer<W>, var: &mut Var, v: u64) -> io::Result<()> {
    let v = mask(var.width, v);
    if var.prev == Some(v) {
        return Ok(());
    }
    var.prev = Some(v);
    if var.width == 1 {
        w.change_scalar(var.id, v != 0)
    } else {
        let mut bits = [Value::V0; 64];
        let n = var.width.min(64) as usize;
        for (i, b) in bits[..n].iter_mut().enumerate() {
            *b = Value::from((v >> (n - 1 - i)) & 1 == 1);
        }
        w.change_vector(var.id, &bits[..n])
    }
}

fn add_var<W: Write>(w: &mut vcd::Writer<W>, name: &str, width: u32) -> io::Result<Var> {
    let index = (width > 1).then(|| ReferenceIndex::Range(width - 1, 0));
    let id = w.add_var(VarType::Wire, width, name, index)?;
    Ok(Var {
        id,
        width,
        prev: None,
    })
}

struct NodeVars {
    rx: Var,
    tx_req: Var,
    tx_abort: Var,
    outputs: Vec<Var>,
}

struct Group {
    clk: Var,
    rst: Var,
    bus: Var,
    nodes: Vec<NodeVars>,
}

/// Tracks the current VCD time and writes a timestamp when time advances.
struct Clock {
    now: Option<u64>,
}

impl Clock {
    fn at<W: Write>(&mut self, w: &mut vcd::Writer<W>, t: u64) -> io::Result<()> {
        match self.now {
            Some(now) if t <= now => Ok(()),
            _ => {
                self.now = Some(t);
                w.timestamp(t)
            }
        }
    }
}

/// The full trace of one or more systems, cycle by cycle.
///
/// Each system is a top-level scope (e.g. `tb`, or the engine name when several
/// systems share one file) holding `clk`, `rst`, `bus` and one scope per node
/// (`node0`, ...) with `rx`, `tx_req`, `tx_abort` and every output, probe and
/// diagnostics register of [`OUTPUT_SIGNALS`] (`tx`, ..., `rx_frame_id[28:0]`,
/// ..., `field[4:0]`, `tec[8:0]`, ..., `err_kind[2:0]`, ...).
pub struct VcdWriter<W: Write> {
    w: vcd::Writer<W>,
    tb: TimeBase,
    groups: Vec<Group>,
    clock: Clock,
    last_cycle: Option<u64>,
}

impl<W: Write> VcdWriter<W> {
    /// Writes the header for systems given as `(scope name, number of nodes)`.
    pub fn new(
        out: W,
        clock_hz: u64,
        systems: &[(&str, usize)],
        comment: &str,
    ) -> io::Result<Self> {
        let tb = TimeBase::new(clock_hz);
        let mut w = vcd::Writer::new(out);
        w.comment(comment)?;
        w.timescale(1, tb.unit())?;
        let mut groups = Vec::new();
        for (scope, nodes) in systems {
            w.add_module(scope)?;
            let clk = add_var(&mut w, "clk", 1)?;
            let rst = add_var(&mut w, "rst", 1)?;
            let bus = add_var(&mut w, "bus", 1)?;
            let mut nv = Vec::new();
            for i in 0..*nodes {
                w.add_module(&format!("node{i}"))?;
                let rx = add_var(&mut w, "rx", 1)?;
                let tx_req = add_var(&mut w, "tx_req", 1)?;
                let tx_abort = add_var(&mut w, "tx_abort", 1)?;
                let outputs = OUTPUT_SIGNALS
                    .iter()
                    .map(|s| add_var(&mut w, s.name, s.width))
                    .collect::<io::Result<Vec<_>>>()?;
                w.upscope()?;
                nv.push(NodeVars {
                    rx,
                    tx_req,
                    tx_abort,
                    outputs,
                });
            }
            w.upscope()?;
            groups.push(Group {
                clk,
                rst,
                bus,
                nodes: nv,
            });
        }
        w.enddefinitions()?;
        Ok(VcdWriter {
            w,
            tb,
            groups,
            clock: Clock { now: None },
            last_cycle: None,
        })
    }

    /// Writes one clock cycle: one sample per system, all of the same cycle, cycles
    /// increasing.
    pub fn write_cycle(&mut self, samples: &[&Sample]) -> io::Result<()> {
        if samples.len() != self.groups.len() {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!(
                    "VCD writer has {} systems, got {} samples",
                    self.groups.len(),
                    samples.len()
                ),
            ));
        }
        let Some(first) = samples.first() else {
            return Ok(());
        };
        let n = first.cycle;
        for (s, g) in samples.iter().zip(&self.groups) {
            if s.cycle != n || s.outputs.len() != g.nodes.len() {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    "VCD writer: samples of different cycles or node counts",
                ));
            }
        }
        let w = &mut self.w;
        match self.last_cycle {
            Some(last) if n <= last => {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    "VCD writer: cycles must increase",
                ))
            }
            None => {
                // Initial values of everything at the first edge.
                self.clock.at(w, self.tb.edge(n))?;
                w.begin(SimulationCommand::Dumpvars)?;
                for (s, g) in samples.iter().zip(self.groups.iter_mut()) {
                    change(w, &mut g.clk, 1)?;
                    write_inputs(w, g, s)?;
                    write_outputs(w, g, s)?;
                }
                w.end()?;
            }
            Some(_) => {
                // Line and rx: together with the tx of cycle n-1 (edge n-1).
                self.clock.at(w, self.tb.edge(n - 1))?;
                for (s, g) in samples.iter().zip(self.groups.iter_mut()) {
                    change(w, &mut g.bus, s.bus as u64)?;
                    for (nv, &rx) in g.nodes.iter_mut().zip(&s.rx) {
                        change(w, &mut nv.rx, rx as u64)?;
                    }
                }
                // Inputs of cycle n: at the falling edge before edge n.
                self.clock.at(w, self.tb.falling(n - 1))?;
                for (s, g) in samples.iter().zip(self.groups.iter_mut()) {
                    change(w, &mut g.clk, 0)?;
                    change(w, &mut g.rst, s.rst as u64)?;
                    for (i, nv) in g.nodes.iter_mut().enumerate() {
                        change(w, &mut nv.tx_req, flag(&s.tx_req, i))?;
                        change(w, &mut nv.tx_abort, flag(&s.tx_abort, i))?;
                    }
                }
                // Outputs of cycle n: at edge n.
                self.clock.at(w, self.tb.edge(n))?;
                for (s, g) in samples.iter().zip(self.groups.iter_mut()) {
                    change(w, &mut g.clk, 1)?;
                    write_outputs(w, g, s)?;
                }
            }
        }
        self.last_cycle = Some(n);
        Ok(())
    }

    /// Writes the falling edge after the last cycle, so viewers show it whole.
    pub fn finish(&mut self) -> io::Result<()> {
        if let Some(n) = self.last_cycle {
            self.clock.at(&mut self.w, self.tb.falling(n))?;
            for g in self.groups.iter_mut() {
                change(&mut self.w, &mut g.clk, 0)?;
            }
        }
        Ok(())
    }
}

impl VcdWriter<&mut BufWriter<File>> {
    /// Writes a whole trace of systems given as `(scope name, number of nodes)` to
    /// `path`; `cycles` yields one sample per system for each cycle.
    pub fn write_file<'a, I>(
        path: &Path,
        clock_hz: u64,
        systems: &[(&str, usize)],
        comment: &str,
        cycles: I,
    ) -> Result<(), String>
    where
        I: IntoIterator<Item = Vec<&'a Sample>>,
    {
        drcc_tools::atomic::write_with(path, |buf| {
            let mut w = VcdWriter::new(buf, clock_hz, systems, comment)?;
            for samples in cycles {
                w.write_cycle(&samples)?;
            }
            w.finish()
        })
        .map_err(|e| format!("VCD trace: {e}"))
    }
}

fn write_inputs<W: Write>(w: &mut vcd::Writer<W>, g: &mut Group, s: &Sample) -> io::Result<()> {
    change(w, &mut g.rst, s.rst as u64)?;
    change(w, &mut g.bus, s.bus as u64)?;
    for (i, nv) in g.nodes.iter_mut().enumerate() {
        change(w, &mut nv.rx, s.rx.get(i).copied().unwrap_or(true) as u64)?;
        change(w, &mut nv.tx_req, flag(&s.tx_req, i))?;
        change(w, &mut nv.tx_abort, flag(&s.tx_abort, i))?;
    }
    Ok(())
}

/// A per-node input flag of a sample (0 when the sample has no entry for the node).
fn flag(v: &[bool], node: usize) -> u64 {
    v.get(node).copied().unwrap_or(false) as u64
}

fn write_outputs<W: Write>(w: &mut vcd::Writer<W>, g: &mut Group, s: &Sample) -> io::Result<()> {
    for (nv, o) in g.nodes.iter_mut().zip(&s.outputs) {
        for (var, sig) in nv.outputs.iter_mut().zip(OUTPUT_SIGNALS) {
            change(w, var, (sig.get)(o))?;
        }
    }
    Ok(())
}

/// The bus-only trace: 1-bit signals only, flat names, no clock.
///
/// Scope `can` holds `bus` (the line) and `node0_tx`, `node1_tx`, ... Decode it
/// with sigrok: `sigrok-cli -I vcd -i FILE -P can:can_rx=bus:nominal_bitrate=RATE`.
pub struct BusVcdWriter<W: Write> {
    w: vcd::Writer<W>,
    tb: TimeBase,
    bus: Var,
    tx: Vec<Var>,
    clock: Clock,
    last_cycle: Option<u64>,
}

impl<W: Write> BusVcdWriter<W> {
    /// Writes the header for `nodes` nodes.
    pub fn new(out: W, clock_hz: u64, nodes: usize, comment: &str) -> io::Result<Self> {
        let tb = TimeBase::new(clock_hz);
        let mut w = vcd::Writer::new(out);
        w.comment(comment)?;
        w.timescale(1, tb.unit())?;
        w.add_module("can")?;
        let bus = add_var(&mut w, "bus", 1)?;
        let tx = (0..nodes)
            .map(|i| add_var(&mut w, &format!("node{i}_tx"), 1))
            .collect::<io::Result<Vec<_>>>()?;
        w.upscope()?;
        w.enddefinitions()?;
        Ok(BusVcdWriter {
            w,
            tb,
            bus,
            tx,
            clock: Clock { now: None },
            last_cycle: None,
        })
    }

    /// Writes one clock cycle (cycles increasing).
    pub fn write_cycle(&mut self, s: &Sample) -> io::Result<()> {
        if s.outputs.len() != self.tx.len() {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "bus VCD writer: wrong node count",
            ));
        }
        let n = s.cycle;
        if matches!(self.last_cycle, Some(last) if n <= last) {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "bus VCD writer: cycles must increase",
            ));
        }
        let w = &mut self.w;
        let first = self.last_cycle.is_none();
        // The line of cycle n is the AND of the tx of cycle n-1: same time.
        self.clock
            .at(w, self.tb.edge(if first { n } else { n - 1 }))?;
        if first {
            w.begin(SimulationCommand::Dumpvars)?;
        }
        change(w, &mut self.bus, s.bus as u64)?;
        if first {
            for (var, o) in self.tx.iter_mut().zip(&s.outputs) {
                change(w, var, o.tx as u64)?;
            }
            w.end()?;
        } else {
            self.clock.at(w, self.tb.edge(n))?;
            for (var, o) in self.tx.iter_mut().zip(&s.outputs) {
                change(w, var, o.tx as u64)?;
            }
        }
        self.last_cycle = Some(n);
        Ok(())
    }

    /// Writes a final timestamp one clock after the last cycle.
    pub fn finish(&mut self) -> io::Result<()> {
        if let Some(n) = self.last_cycle {
            self.clock.at(&mut self.w, self.tb.edge(n + 1))?;
        }
        Ok(())
    }
}

impl BusVcdWriter<&mut BufWriter<File>> {
    /// Writes a whole bus-only trace to `path`.
    pub fn write_file<'a, I>(
        path: &Path,
        clock_hz: u64,
        nodes: usize,
        comment: &str,
        samples: I,
    ) -> Result<(), String>
    where
        I: IntoIterator<Item = &'a Sample>,
    {
        drcc_tools::atomic::write_with(path, |buf| {
            let mut w = BusVcdWriter::new(buf, clock_hz, nodes, comment)?;
            for s in samples {
                w.write_cycle(s)?;
            }
            w.finish()
        })
        .map_err(|e| format!("VCD trace: {e}"))
    }
}
