//! The emitted tops: the one registry every tool reads (`drcc generate`, the
//! FPGA flow, the Verilator shims).
//!
//! For each top it gives the Verilog (`drcc generate` writes it to
//! `rtl-out/<name>.v`) and the port list, taken from the rust-hdl block itself
//! through its [`Probe`] walk, never by parsing Verilog, with each port's meaning
//! taken from the `///` comment on its field in the block's source
//! ([`port_docs`]). From those, `drcc generate` writes the header and the port
//! comments of `rtl-out/<name>.v` ([`verilog`]) and the Verilator port table
//! `cosim/verilator-sys/shim/<name>_ports.h` ([`shim_table`]).
//!
//! # Adding a top
//! 1. Write its block, with a `///` comment on every `pub` port (the test
//!    `every_port_is_documented` fails otherwise).
//! 2. Add one [`Top`] entry to [`TOPS`].
//! 3. Run `cargo run --release -- generate` and commit `rtl-out/` and
//!    `cosim/verilator-sys/shim/`.
//!
//! That is all: `drcc generate --check`, the lint and FPGA flows read [`TOPS`];
//! verilator-sys's build script finds the new `<name>_ports.h`, verilates
//! `rtl-out/<name>.v` and generates the C shim, the Rust port structs
//! `<Name>In` / `<Name>Out` and the wrapper `verilator_sys::<Name>`. Only an
//! engine that drives the top (`cosim/src/engine/`) is written by hand.

mod configured;
pub mod fusesoc;
pub mod params;
pub mod port_docs;
pub mod readable;
pub mod shim_table;
pub mod verilog;

use configured::raw_verilog_small;
pub use configured::{
    drcc_with_config, drcc_with_config_on, finish_shaped_hub, pelican_with_config,
};

use crate::bus::drcc_tops::{DrccApb, DrccAxi};
use crate::channel::can_channel::CanChannel;

use crate::drcc::{Drcc, DrccM0};
use crate::hub::hub::{Hub4x2, HubB4x2};
use crate::pelican::bus_tops::{DrccPelicanApb, DrccPelicanAxi};
use crate::pelican::top::DrccPelican;
use crate::redcan::rcm::Rcm;
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
    /// What the port means and how it is encoded: the `///` comment on its field
    /// (empty when the field has none).
    pub doc: String,
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
    /// The rust-hdl struct of the top (its port docs are read from its source).
    pub block: &'static str,
    /// Repository path of the file declaring [`Top::block`].
    pub source_path: &'static str,
    /// The text of that file (`include_str!`), for the port docs.
    source: &'static str,
    /// Extra lines for the header of the emitted file (layouts, pointers).
    pub notes: &'static str,
    /// The CAN transmit pins (1 = recessive): recessive from configuration on.
    pub can_tx: &'static [&'static str],
    /// The CAN receive pins (1 = recessive), asynchronous, synchronized inside.
    pub can_rx: &'static [&'static str],
    /// The raw rust-hdl Verilog of the block (before [`finish_verilog`]).
    raw_verilog: fn() -> String,
    /// The ports of the block, from its probe walk.
    ports: fn() -> Vec<Port>,
}

impl Top {
    /// The finished Verilog of this top, as `drcc generate` writes it.
    pub fn verilog(&self) -> String {
        verilog::finish(self, &(self.raw_verilog)(), &self.ports())
    }

    /// The Verilog of this top without the readable step of [`readable`]: rust-hdl's
    /// text with its modules renamed and no `initial` blocks, a module per
    /// flip-flop and per block instance, and no header or parameters. The same
    /// logic as [`Top::verilog`]; `examples/emit.rs --unreadable` prints it, to
    /// compare the two texts' area and Fmax.
    pub fn unreadable_verilog(&self) -> String {
        verilog::strip_initial_blocks(&verilog::rename_modules(self.name, &(self.raw_verilog)()))
    }

    /// The top-level ports, in declaration order, with their docs.
    pub fn ports(&self) -> Vec<Port> {
        let docs = port_docs::port_docs(self.source, self.block);
        let mut ports = (self.ports)();
        for p in &mut ports {
            if let Some((_, doc)) = docs.iter().find(|(n, _)| *n == p.name) {
                p.doc = doc.clone();
            }
        }
        ports
    }

    /// The text of `cosim/verilator-sys/shim/<name>_ports.h`.
    pub fn shim_table(&self) -> String {
        shim_table::ports_header(self, &self.ports())
    }
}

/// A top block built and connected as `drcc generate` emits it.
fn connected<B: Block + Default>() -> B {
    let mut uut = B::default();
    uut.connect_all();
    uut
}

/// The Verilog rust-hdl writes for top block `B`, before `drcc generate`'s header.
pub fn raw_verilog_of<B: Block + Default>() -> String {
    generate_verilog(&connected::<B>())
}

/// The ports of top block `B`, from its probe walk (their docs still empty).
pub fn ports_of<B: Block + Default>() -> Vec<Port> {
    let uut = connected::<B>();
    let mut probe = PortProbe::default();
    uut.accept("top", &mut probe);
    probe.ports
}

/// The frame layout on `can_channel`'s ports, once, and how the DRCC's registers
/// differ (timing contract §4.4, `cosim/src/frame.rs`, drcc_contract.md §3).
const CHANNEL_NOTES: &str = "\
Frame layout: the can_channel ports versus the DRCC registers (drcc.v)
  item                  can_channel ports                DRCC registers
  data byte 0 (first)   tx_data/rx_data[63:56]           TX_DATA0/RX_DATA0[7:0]
  data byte 3           tx_data/rx_data[39:32]           TX_DATA0/RX_DATA0[31:24]
  data byte 4           tx_data/rx_data[31:24]           TX_DATA1/RX_DATA1[7:0]
  data byte 7           tx_data/rx_data[7:0]             TX_DATA1/RX_DATA1[31:24]
  first data bit sent   bit 63 (MSB of byte 0)           bit 7 of DATA0
  base identifier       tx_id/rx_id[10:0], [28:11] = 0   TX_ID/RX_ID[10:0]
  extended identifier   tx_id/rx_id[28:0], base [28:18]  TX_ID/RX_ID[28:0], base [28:18]
  ide, rtr              tx_ide/rx_ide, tx_rtr/rx_rtr     TX_ID/RX_ID[29], [30]
  dlc                   tx_dlc/rx_dlc[3:0]               TX_CTRL/RX_CTRL[3:0]
Bit-timing ports: cfg_brp is BRP itself (tq = cfg_brp + 1 clocks); cfg_tseg1, cfg_tseg2
and cfg_sjw are minus-one codes; every cfg_* input is captured only while rst = 1.";

/// Every emitted top, in the order `drcc generate` writes them.
pub static TOPS: &[Top] = &[
    Top {
        name: "can_channel",
        summary: "one ISO 11898-1 classical CAN channel (bit timing, bit stream processor, fault confinement)",
        contract: "cosim/src/model/timing_contract.md",
        params: &[],
        block: "CanChannel",
        source_path: "hdl/src/channel/can_channel.rs",
        source: include_str!("channel/can_channel.rs"),
        notes: CHANNEL_NOTES,
        can_tx: &["tx"],
        can_rx: &["rx"],
        raw_verilog: raw_verilog_of::<CanChannel>,
        ports: ports_of::<CanChannel>,
    },
    Top {
        name: "drcc",
        summary: "the dual-redundancy CAN controller: two channels, redundancy management, TX buffer, RX FIFO, Wishbone",
        contract: "cosim/src/model/drcc_contract.md",
        params: &[
            ("M", "16"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
        ],
        block: "DrccTop",
        source_path: "hdl/src/drcc.rs",
        source: include_str!("drcc.rs"),
        notes: "M DMR mailboxes (cosim/src/model/dmr_contract.md section 2). Registers:\n\
                docs/registers.md, C header rtl-out/drcc_regs.h. In TX_DATA0/1 and\n\
                RX_DATA0/1 byte 0 (the first on the bus) is in [7:0]; on can_channel's ports it\n\
                is in [63:56] (see the table in can_channel.v).",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<Drcc>,
        ports: ports_of::<Drcc>,
    },
    Top {
        name: "drcc_m0",
        summary: "the DRCC without DMR mailboxes (M = 0): DMR faults found by bus-off and the connection service only",
        contract: "cosim/src/model/drcc_contract.md",
        params: &[
            ("M", "0"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
        ],
        block: "DrccTop",
        source_path: "hdl/src/drcc.rs",
        source: include_str!("drcc.rs"),
        notes: "The drcc with M = 0 DMR mailboxes (cosim/src/model/dmr_contract.md section 2):\n\
                the same ports and registers; MB_SEL and the mailbox window refuse every\n\
                write and read 0. Registers: docs/registers.md, rtl-out/drcc_regs.h.",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<DrccM0>,
        ports: ports_of::<DrccM0>,
    },
    Top {
        name: "drcc_small",
        summary: "the DRCC for a small FPGA: the dual-bus controller of the DRCC paper without the CiA 701 DMR function and the replicated-star node; RX FIFO 8, TX queues 4, history 16",
        contract: "cosim/src/model/drcc_contract.md",
        params: &[
            ("M", "0"),
            ("RX_FIFO_DEPTH", "8"),
            ("TX_QUEUE_DEPTH", "4"),
            ("HISTORY", "16"),
            ("DMR", "0"),
            ("STAR", "0"),
        ],
        block: "DrccTop",
        source_path: "hdl/src/drcc.rs",
        source: include_str!("drcc.rs"),
        notes: "The small configuration (hdl/src/config.rs, drcc_contract.md section 1.1): the\n\
                same ports and registers as drcc; a CTRL write with dmr or star is refused\n\
                (INT_STATUS.illegal), a push to a TX queue holding 4 frames is refused, the RX\n\
                FIFO overruns at 8 frames, duplicate removal remembers 16 frames. Registers:\n\
                docs/registers.md, rtl-out/drcc_regs.h.",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_small,
        ports: ports_of::<DrccM0>,
    },
    Top {
        name: "drcc_apb",
        summary: "the drcc on an AMBA APB4 slave (PSTRB, PREADY, PSLVERR): the same registers, interrupt and CAN pins",
        contract: "cosim/src/model/bus_contract.md",
        params: &[
            ("M", "16"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
            ("BUS", "apb"),
        ],
        block: "DrccApb",
        source_path: "hdl/src/bus/drcc_tops.rs",
        source: include_str!("bus/drcc_tops.rs"),
        notes: "The drcc (M = 16) behind the APB front end of cosim/src/model/bus_contract.md\n\
                section 2: every access phase lasts two clocks, a refused access ends with\n\
                PSLVERR. Registers: docs/registers.md, rtl-out/drcc_regs.h (byte offsets).",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<DrccApb<16>>,
        ports: ports_of::<DrccApb<16>>,
    },
    Top {
        name: "drcc_axi",
        summary: "the drcc on an AXI4-Lite slave: the same registers, interrupt and CAN pins",
        contract: "cosim/src/model/bus_contract.md",
        params: &[
            ("M", "16"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
            ("BUS", "axi4-lite"),
        ],
        block: "DrccAxi",
        source_path: "hdl/src/bus/drcc_tops.rs",
        source: include_str!("bus/drcc_tops.rs"),
        notes: "The drcc (M = 16) behind the AXI4-Lite front end of cosim/src/model/bus_contract.md\n\
                section 3: one access at a time, writes and reads alternating; a refused\n\
                write answers SLVERR. Registers: docs/registers.md, rtl-out/drcc_regs.h.",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<DrccAxi<16>>,
        ports: ports_of::<DrccAxi<16>>,
    },
    Top {
        name: "drcc_pelican",
        summary: "the DRCC behind the SJA1000 (PeliCAN) register view: an unmodified SJA1000 driver runs the dual-redundant controller as one CAN controller",
        contract: "cosim/src/model/pelican_contract.md",
        params: &[
            ("M", "16"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
            ("HOST", "pelican"),
            ("PELICAN_STRIDE", "4"),
            ("PELICAN_DEFAULT_MODE", "redundancy"),
            ("PELICAN_POLICY", "error-passive"),
            ("PELICAN_K", "1"),
            ("PELICAN_DUAL_TX", "0"),
            ("PELICAN_STAR", "0"),
            ("PELICAN_BUSOFF", "sja1000"),
            ("PELICAN_REPORT", "best"),
        ],
        block: "DrccPelican",
        source_path: "hdl/src/pelican/top.rs",
        source: include_str!("pelican/top.rs"),
        notes: "Registers: the SJA1000 data sheet's PeliCAN mode at stride 4 (register r at\n\
                byte 4r, Linux reg-io-width = <4>), the DRCC's extension window at 112..127;\n\
                docs/pelican.md, cosim/src/model/pelican_contract.md. clk is the SJA1000's\n\
                oscillator (fosc = clk).",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<DrccPelican<16>>,
        ports: ports_of::<DrccPelican<16>>,
    },
    Top {
        name: "drcc_pelican_apb",
        summary: "the drcc_pelican on an AMBA APB4 slave (PSTRB, PREADY, PSLVERR): the same SJA1000 registers at stride 4, interrupt and CAN pins",
        contract: "cosim/src/model/pelican_contract.md",
        params: &[
            ("M", "16"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
            ("HOST", "pelican"),
            ("PELICAN_STRIDE", "4"),
            ("PELICAN_DEFAULT_MODE", "redundancy"),
            ("PELICAN_POLICY", "error-passive"),
            ("PELICAN_K", "1"),
            ("PELICAN_DUAL_TX", "0"),
            ("PELICAN_STAR", "0"),
            ("PELICAN_BUSOFF", "sja1000"),
            ("PELICAN_REPORT", "best"),
            ("BUS", "apb"),
        ],
        block: "DrccPelicanApb",
        source_path: "hdl/src/pelican/bus_tops.rs",
        source: include_str!("pelican/bus_tops.rs"),
        notes: "The drcc_pelican behind the APB front end of cosim/src/model/bus_contract.md\n\
                section 2: every access phase lasts two clocks, a refused write ends with\n\
                PSLVERR. Registers: the SJA1000 data sheet's PeliCAN mode at stride 4\n\
                (register r at byte 4r, Linux reg-io-width = <4>), the extension window at\n\
                112..127; docs/pelican.md. clk is the SJA1000's oscillator (fosc = clk).",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<DrccPelicanApb<16>>,
        ports: ports_of::<DrccPelicanApb<16>>,
    },
    Top {
        name: "drcc_pelican_axi",
        summary: "the drcc_pelican on an AXI4-Lite slave: the same SJA1000 registers at stride 4, interrupt and CAN pins",
        contract: "cosim/src/model/pelican_contract.md",
        params: &[
            ("M", "16"),
            ("RX_FIFO_DEPTH", "32"),
            ("TX_QUEUE_DEPTH", "8"),
            ("HISTORY", "32"),
            ("DMR", "1"),
            ("STAR", "1"),
            ("HOST", "pelican"),
            ("PELICAN_STRIDE", "4"),
            ("PELICAN_DEFAULT_MODE", "redundancy"),
            ("PELICAN_POLICY", "error-passive"),
            ("PELICAN_K", "1"),
            ("PELICAN_DUAL_TX", "0"),
            ("PELICAN_STAR", "0"),
            ("PELICAN_BUSOFF", "sja1000"),
            ("PELICAN_REPORT", "best"),
            ("BUS", "axi4-lite"),
        ],
        block: "DrccPelicanAxi",
        source_path: "hdl/src/pelican/bus_tops.rs",
        source: include_str!("pelican/bus_tops.rs"),
        notes: "The drcc_pelican behind the AXI4-Lite front end of cosim/src/model/bus_contract.md\n\
                section 3: one access at a time; a refused write answers SLVERR. Registers:\n\
                the SJA1000 data sheet's PeliCAN mode at stride 4 (register r at byte 4r,\n\
                Linux reg-io-width = <4>), the extension window at 112..127;\n\
                docs/pelican.md. clk is the SJA1000's oscillator (fosc = clk).",
        can_tx: &["chan_a_tx", "chan_b_tx"],
        can_rx: &["chan_a_rx", "chan_b_rx"],
        raw_verilog: raw_verilog_of::<DrccPelicanAxi<16>>,
        ports: ports_of::<DrccPelicanAxi<16>>,
    },
    Top {
        name: "hub",
        summary: "the ReCANcentrate star hub: coupling, fault treatment, ACK interdependence, NRAP; hub A of the replicated star: identification frame 0x000",
        contract: "cosim/src/model/hub_contract.md",
        params: &[("HUB_ID", "0"), ("N", "4"), ("M", "2")],
        block: "Hub",
        source_path: "hdl/src/hub/hub.rs",
        source: include_str!("hub/hub.rs"),
        notes: HUB_NOTES,
        can_tx: &["downlink", "sublink_out", "hub_tx"],
        can_rx: &["uplink", "sublink_in"],
        raw_verilog: raw_verilog_of::<Hub4x2>,
        ports: ports_of::<Hub4x2>,
    },
    Top {
        name: "hub_b",
        summary: "hub B of the replicated star: identification frame 0x001",
        contract: "cosim/src/model/hub_contract.md",
        params: &[("HUB_ID", "1"), ("N", "4"), ("M", "2")],
        block: "Hub",
        source_path: "hdl/src/hub/hub.rs",
        source: include_str!("hub/hub.rs"),
        notes: HUB_NOTES,
        can_tx: &["downlink", "sublink_out", "hub_tx"],
        can_rx: &["uplink", "sublink_in"],
        raw_verilog: raw_verilog_of::<HubB4x2>,
        ports: ports_of::<HubB4x2>,
    },
    Top {
        name: "rcm",
        summary: "the REDCAN relay module: the host's two control bits to the relay, transceiver and termination drivers of a ring node",
        contract: "cosim/src/model/ring_contract.md",
        params: &[],
        block: "Rcm",
        source_path: "hdl/src/redcan/rcm.rs",
        source: include_str!("redcan/rcm.rs"),
        notes: "ctl = {connect right, connect left}: 11 transparent (reset), 01 left, 10 right,\n\
                00 refused (illegal). The driver outputs are the coil and switch drives; the\n\
                ring simulator applies them after the relay's operate time (section 1).",
        can_tx: &[],
        can_rx: &[],
        raw_verilog: raw_verilog_of::<Rcm>,
        ports: ports_of::<Rcm>,
    },
];

/// The notes of both hubs (they differ only in `HUB_ID`, hub contract §9).
const HUB_NOTES: &str = "\
N node ports, M interlinks, P = N + M guarded ports (node ports 0..N-1, then
the incoming sublinks N..N+M-1). Registers: hub_contract.md section 8 and 9.5,
C header rtl-out/hub_regs.h (one map for both hubs; ID.hub_id reads HUB_ID).
hub.v (HUB_ID 0, hub A) and hub_b.v (HUB_ID 1, hub B) differ only in the
identification frame each sends and recognises (section 9.1): wire each one's
sublink_out to the other's sublink_in.";

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
            doc: String::new(),
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

/// The Verilog of one top by name, or `None` for an unknown name.
pub fn emit(name: &str) -> Option<String> {
    top(name).map(Top::verilog)
}

/// Every top and its Verilog.
pub fn emit_all() -> Vec<(&'static str, String)> {
    TOPS.iter().map(|t| (t.name, t.verilog())).collect()
}
