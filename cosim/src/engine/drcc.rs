//! One `DrccEngine` trait for the DRCC top (two channels, redundancy management,
//! RAMs, Wishbone registers), with the same step contract as [`super::ChannelEngine`]:
//! apply `inputs` (stable for the whole clock period), produce one rising edge of
//! `clk`, return the outputs as they are right after that edge. Every engine starts in
//! reset. The clock-level behaviour is `crate::model::drcc` (`drcc_contract.md`).

/// Inputs of the DRCC top for one clock.
///
/// `Default` is an idle bus with every byte lane selected (`wb_sel = 0xF`) and
/// everything else 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DrccInputs {
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
    /// Channel A (the paper's channel 1) receive pin, 1 = recessive.
    pub chan_a_rx: bool,
    /// Channel B (channel 2) receive pin.
    pub chan_b_rx: bool,
}

impl Default for DrccInputs {
    fn default() -> Self {
        Self {
            rst: false,
            wb_cyc: false,
            wb_stb: false,
            wb_we: false,
            wb_adr: 0,
            wb_dat_w: 0,
            wb_sel: 0xF,
            chan_a_rx: false,
            chan_b_rx: false,
        }
    }
}

/// The DRCC probes: the paper's signal names (DRCC contract §1) and the channel probes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrccProbes {
    /// Main FSM state, Table 1 encoding (idle1 = 0 .. wait4 = 9).
    pub state: u8,
    pub tx_channel: bool,
    pub transmission_ack: bool,
    pub chan_a_transmission_req: bool,
    pub chan_b_transmission_req: bool,
    pub tx_success: bool,
    pub tx_ok_channel: u8,
    pub tx_failure: bool,
    pub tx_failure_channel: u8,
    pub tx_going_on: bool,
    pub chan_a_bsp_tx_err_cnt: u16,
    pub chan_a_bsp_node_error_passive: bool,
    pub chan_b_bsp_tx_err_cnt: u16,
    pub chan_b_bsp_node_error_passive: bool,
    /// Auxiliary FSM states (valid 0, failed 1, restart 2, probation 3).
    pub aux_a_state: u8,
    pub aux_b_state: u8,
    pub chan_a_sample_point: bool,
    pub chan_b_sample_point: bool,
    pub chan_a_field: u8,
    pub chan_b_field: u8,
    pub chan_a_rec: u8,
    pub chan_b_rec: u8,
    pub chan_a_err_state: u8,
    pub chan_b_err_state: u8,
    /// DMR mode (dmr_contract.md §9): `dmr_state` (0 redundancy active, 1 passive,
    /// 2 disabled, 3 network disconnected), the active line (false DCL, true RCL),
    /// the fault flags per line and the DMR time base pulse. All 0 outside DMR mode.
    pub dmr_state: u8,
    pub acl: bool,
    pub dcl_tx_fault: bool,
    pub dcl_rx_fault: bool,
    pub rcl_tx_fault: bool,
    pub rcl_rx_fault: bool,
    pub dmr_tick: bool,
}

/// Outputs of the DRCC top right after a clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrccOutputs {
    pub wb_ack: bool,
    /// The access was refused (Wishbone `ERR`, instead of the ack).
    pub wb_err: bool,
    pub wb_dat_r: u32,
    pub irq: bool,
    pub chan_a_tx: bool,
    pub chan_b_tx: bool,
    pub probes: DrccProbes,
}

/// A DRCC simulator: the reference model or the Verilated RTL.
pub trait DrccEngine {
    /// Engine name as the CLI spells it (`model`, `verilator`).
    fn name(&self) -> &'static str;
    /// One clock: see the module documentation.
    fn step(&mut self, inputs: &DrccInputs) -> DrccOutputs;
    /// Starts a VCD trace of every internal RTL signal from the next clock on (the
    /// Verilated engine; the others have none and say so).
    fn open_rtl_trace(&mut self, path: &std::path::Path) -> Result<(), String> {
        let _ = path;
        Err(format!("the {} engine has no RTL trace", self.name()))
    }
}
