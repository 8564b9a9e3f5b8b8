//! The emitted tops: the one registry every tool reads (`drcc generate`, the
//! FPGA flow, the Verilator shims). Adding a top is one entry in [`TOPS`].
//!
//! For each top it gives the Verilog (`drcc generate` writes it to
//! `rtl-out/<name>.v`) and the port list, taken from the rust-hdl block itself
//! through its [`Probe`] walk, never by parsing Verilog. rust-hdl names every top
//! `top` and every sub-module after its path (`top$bsp$fc`); the emitter renames
//! them to `<name>` and `<name>__bsp__fc` so the Verilog reads well and several
//! tops can be compiled together.

use crate::channel::can_channel::CanChannel;
use crate::drcc::Drcc;
use crate::hub::hub::Hub4x2;
use rust_hdl::prelude::*;

/// Direction of a top-level port.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// Driven from outside the top.
    Input,
    /// Driven by the top.
    Output,
}

/// One port of an emitted top, as the rust-hdl block declares it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    /// Verilog port name (rust-hdl's `$` separators already turned into `__`).
    pub name: String,
    /// Input or output.
    pub direction: Direction,
    /// Width in bits (1 for a single bit or the clock).
    pub width: usize,
    /// True for the clock input (`Signal<In, Clock>`).
    pub is_clock: bool,
}

/// One emitted top: everything the tools need to know about it.
pub struct Top {
    /// Module and file name: `rtl-out/<name>.v`, Verilator class `V<name>`.
    pub name: &'static str,
    /// One line saying what the top is.
    pub summary: &'static str,
    /// The clock-level contract the top follows, relative to the repository root.
    pub contract: &'static str,
    /// Generation parameters, as `name = value` pairs, for the file header.
    pub params: &'static [(&'static str, &'static str)],
    /// The raw rust-hdl Verilog of the block (before [`finish_verilog`]).
    raw_verilog: fn() -> String,
    /// The ports of the block, from its probe walk.
    ports: fn() -> Vec<Port>,
}

impl Top {
    /// The finished Verilog of this top, as `drcc generate` writes it.
    pub fn verilog(&self) -> String {
        finish_verilog(self.name, &(self.raw_verilog)())
    }

    /// The top-level ports, in declaration order.
    pub fn ports(&self) -> Vec<Port> {
        (self.ports)()
    }
}

/// A top block built and connected as `drcc generate` emits it.
fn connected<B: Block + Default>() -> B {
    let mut uut = B::default();
    uut.connect_all();
    uut
}

fn raw_verilog_of<B: Block + Default>() -> String {
    generate_verilog(&connected::<B>())
}

fn ports_of<B: Block + Default>() -> Vec<Port> {
    let uut = connected::<B>();
    let mut probe = PortProbe::default();
    uut.accept("top", &mut probe);
    probe.ports
}

/// Every emitted top, in the order `drcc generate` writes them.
pub static TOPS: &[Top] = &[
    Top {
        name: "can_channel",
        summary: "one ISO 11898-1 classical CAN channel (bit timing, bit stream processor, fault confinement)",
        contract: "cosim/src/model/timing_contract.md",
        params: &[],
        raw_verilog: raw_verilog_of::<CanChannel>,
        ports: ports_of::<CanChannel>,
    },
    Top {
        name: "drcc",
        summary: "the dual-redundancy CAN controller: two channels, redundancy management, TX buffer, RX FIFO, Wishbone",
        contract: "cosim/src/model/drcc_contract.md",
        params: &[],
        raw_verilog: raw_verilog_of::<Drcc>,
        ports: ports_of::<Drcc>,
    },
    Top {
        name: "hub",
        summary: "the ReCANcentrate star hub: coupling, fault treatment, ACK interdependence",
        contract: "cosim/src/model/hub_contract.md",
        params: &[("N", "4"), ("M", "2")],
        raw_verilog: raw_verilog_of::<Hub4x2>,
        ports: ports_of::<Hub4x2>,
    },
];

/// The top with this name.
pub fn top(name: &str) -> Option<&'static Top> {
    TOPS.iter().find(|t| t.name == name)
}

/// The names of every top, in [`TOPS`] order.
pub fn names() -> Vec<&'static str> {
    TOPS.iter().map(|t| t.name).collect()
}

/// Collects the parameters (ports) of the outermost scope of a probe walk.
#[derive(Default)]
struct PortProbe {
    depth: usize,
    namespace: Vec<String>,
    ports: Vec<Port>,
}

impl Probe for PortProbe {
    fn visit_start_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth += 1;
    }

    fn visit_start_namespace(&mut self, name: &str, _node: &dyn Block) {
        if self.depth == 1 {
            self.namespace.push(name.to_string());
        }
    }

    fn visit_atom(&mut self, name: &str, signal: &dyn Atom) {
        if self.depth != 1 {
            return;
        }
        let direction = match signal.kind() {
            AtomKind::InputParameter => Direction::Input,
            AtomKind::OutputParameter | AtomKind::OutputPassthrough => Direction::Output,
            _ => return,
        };
        let mut full = self.namespace.clone();
        full.push(name.to_string());
        let name = full.join("__");
        self.ports.push(Port {
            is_clock: signal.descriptor().name == "clock",
            name,
            direction,
            width: signal.bits(),
        });
    }

    fn visit_end_namespace(&mut self, _name: &str, _node: &dyn Block) {
        if self.depth == 1 {
            self.namespace.pop();
        }
    }

    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth -= 1;
    }
}

/// Renames rust-hdl's `top` / `top$a$b` module names to `<name>` / `<name>__a__b`
/// and prefixes the file with a header naming the generator.
pub fn finish_verilog(name: &str, raw: &str) -> String {
    let mut text = String::new();
    text.push_str(&format!(
        "// {name}.v: generated by `drcc generate` from the rust-hdl blocks of drcc-hdl.\n\
         // Do not edit: change the Rust source and regenerate.\n\n"
    ));
    let mut body = raw.replace("module top$", &format!("module {name}__"));
    body = body.replace("module top(", &format!("module {name}("));
    body = body.replace("module top (", &format!("module {name} ("));
    // Instantiations reference the module names too: `top$bsp$fc name(`.
    body = body.replace("top$", &format!("{name}__"));
    body = body.replace('$', "__");
    body = strip_initial_blocks(&body);
    text.push_str(body.trim_end());
    text.push('\n');
    text
}

/// Removes rust-hdl's `initial begin ... end` blocks (power-up values of each
/// flip-flop): the design never relies on them, every register that matters is
/// reset by `rst`, and they are not portable to every FPGA flow.
fn strip_initial_blocks(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut skipping = false;
    for line in text.lines() {
        let t = line.trim();
        if !skipping && t == "initial begin" {
            skipping = true;
            continue;
        }
        if skipping {
            if t == "end" {
                skipping = false;
            }
            continue;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// The Verilog of one top by name, or `None` for an unknown name.
pub fn emit(name: &str) -> Option<String> {
    top(name).map(Top::verilog)
}

/// Every top and its Verilog.
pub fn emit_all() -> Vec<(&'static str, String)> {
    TOPS.iter().map(|t| (t.name, t.verilog())).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The probe walk finds exactly the ports the Verilog module header declares.
    #[test]
    fn ports_match_the_emitted_module_header() {
        for t in TOPS {
            let text = t.verilog();
            let header_start = text
                .find(&format!("module {}(", t.name))
                .expect("module header");
            let header = &text[header_start..];
            let header = &header[..header.find(");").expect("end of port list")];
            let declared: Vec<&str> = header
                .split(['(', ','])
                .skip(1)
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .collect();
            let probed: Vec<String> = t.ports().into_iter().map(|p| p.name).collect();
            assert_eq!(declared, probed, "ports of {}", t.name);
        }
    }

    #[test]
    fn channel_ports_have_their_widths_and_directions() {
        let ports = top("can_channel").unwrap().ports();
        let find = |n: &str| ports.iter().find(|p| p.name == n).unwrap().clone();
        assert!(find("clk").is_clock);
        assert_eq!(find("tx_id").width, 29);
        assert_eq!(find("tx_id").direction, Direction::Input);
        assert_eq!(find("rx_data").width, 64);
        assert_eq!(find("rx_data").direction, Direction::Output);
        assert_eq!(find("tec").width, 9);
    }
}
