//! One `HubEngine` trait for the ReCANcentrate hub top (two-stage AND coupling, port
//! guards, frame tracker, ACK interdependence, Wishbone registers), with the same
//! step contract as [`super::ChannelEngine`]: apply `inputs` (stable for the whole
//! clock period), produce one rising edge of `clk`, return the outputs as they are
//! right after that edge. Every engine starts in reset. The clock-level behaviour is
//! `crate::model::hub` (`hub_contract.md`).
//!
//! Links are packed into integers: bit i of `uplink`/`downlink` is node port i, bit j
//! of `sublink_in`/`sublink_out` is interlink j; 1 = recessive.

/// Largest number of node ports a hub may have (contract §0: N in 2..=8).
pub const MAX_NODE_PORTS: usize = 8;
/// Largest number of interlinks (contract: M in 1..=4).
pub const MAX_INTERLINKS: usize = 4;

/// Inputs of the hub top for one clock.
///
/// `Default` is an idle bus with every byte lane selected (`wb_sel = 0xF`) and
/// everything else 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HubInputs {
    /// Synchronous reset.
    pub rst: bool,
    /// Wishbone B4 classic slave: cycle, strobe, write enable.
    pub wb_cyc: bool,
    pub wb_stb: bool,
    pub wb_we: bool,
    /// Word address (byte address / 4), 6 bits.
    pub wb_adr: u8,
    /// Write data.
    pub wb_dat_w: u32,
    /// Byte lanes of a write, 4 bits (bus_contract.md §1).
    pub wb_sel: u8,
    /// Node transmit values, bit i = node port i.
    pub uplink: u16,
    /// The twin hub's contribution, bit j = interlink j.
    pub sublink_in: u8,
}

impl Default for HubInputs {
    fn default() -> Self {
        Self {
            rst: false,
            wb_cyc: false,
            wb_stb: false,
            wb_we: false,
            wb_adr: 0,
            wb_dat_w: 0,
            wb_sel: 0xF,
            uplink: 0,
            sublink_in: 0,
        }
    }
}

/// Hub probes (contract §1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HubProbes {
    /// `coupled_q`: the signal the hub tracks.
    pub coupled: bool,
    /// The bit timing logic's sample point probe.
    pub sample_point: bool,
    /// Tracker state: IDLE_WAIT 0, FRAME 1, ACK_SLOT 2, ACK_DELIM 3.
    pub trk_state: u8,
    pub ack_window: bool,
    pub decoupled: bool,
    /// Bit p = port p enabled (node ports 0..N, then sublinks N..N+M).
    pub port_enabled: u16,
    /// NRAP phase (hub contract §9.2).
    pub nrap_phase: u8,
    /// The hub's NRAP transmitter `tx_q` (§9.3), 1 = recessive.
    pub hub_tx: bool,
}

/// Outputs of the hub top right after a clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HubOutputs {
    pub wb_ack: bool,
    /// The access was refused (Wishbone `ERR`, instead of the ack).
    pub wb_err: bool,
    pub wb_dat_r: u32,
    pub irq: bool,
    /// Bit i = downlink to node port i.
    pub downlink: u16,
    /// Bit j = outgoing sublink of interlink j.
    pub sublink_out: u8,
    pub probes: HubProbes,
}

/// A hub simulator: the reference model, rust-hdl's simulator or the Verilated RTL.
pub trait HubEngine {
    /// Engine name as the CLI spells it (`model`, `rust-hdl`, `verilator`).
    fn name(&self) -> &'static str;
    /// Node ports N and interlinks M of this hub.
    fn shape(&self) -> (usize, usize);
    /// One clock: see the module documentation.
    fn step(&mut self, inputs: &HubInputs) -> HubOutputs;
}
