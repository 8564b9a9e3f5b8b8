//! The SJA1000 (PeliCAN) register block (pelican_contract.md §2-§13): the view's
//! Wishbone slave, its registers, and its drive of the DRCC core (§14). It
//! replaces only the native register file: it composes the core's `CTRL` and
//! `BTR` words from `MOD`, `BTR0/1`, `EWLR`, `XMODE`, `XK` (P-CFG-2, P-CFG-3),
//! pushes the transmit buffer and pops the receive FIFO, and reads the core's
//! state back as the one logical controller of §5.
//!
//! The blocks, one concern each: `ByteLanes` (which register an access
//! addresses, P-BUS-1..3), `ModeControl` (`MOD`, `CMR`, `TBS`/`TCS`/`DOS`, the
//! bus-off hold), `Interrupts` (`IR`, `IER`, `irq`), `LogicalController` (`u`,
//! `SR` bits, the counters), `ConfigRegs` (bit timing, `OCR`, `CDR`, `ACR`,
//! `AMR`), `TxFrameBuffer`, `RxWindow`, `Rbsa`, the capture registers `ALC` and
//! `ECC`, `ExtensionRegs` (112..121) and `NativeWindow` (122..127, the
//! window onto the core's native registers). Each read returns the value before the
//! edge that takes it (§15); a register outside every block reads 0.
//!
//! Bus (P-BUS-1..4): Wishbone B4 classic, 32-bit data, one register per access.
//! An access is taken at an edge with `cyc & stb & !(ack | err)`; `ack` (or
//! `err` for a refused lane pattern, with `XIR.bus`) and the read data follow
//! in the next clock, so every access takes two clocks, as the native slave's.

use super::armed_capture::ArmedCapture;
use super::byte_lanes::ByteLanes;
use super::config_regs::ConfigRegs;
use super::ecc_code::EccCode;
use super::extension::ExtensionRegs;
use super::interrupts::Interrupts;
use super::logical::LogicalController;
use super::mode_control::ModeControl;
use super::native_window::NativeWindow;
use super::rbsa::Rbsa;
use super::rx_window::RxWindow;
use super::tx_frame_buffer::TxFrameBuffer;
use super::PelicanKeys;
use crate::channel::bsp::field::Field;
use crate::channel::sized::Const;
use crate::memory::tx_normalize::FrameNormalizer;
use rust_hdl::prelude::*;

/// The SJA1000 view's register block.
#[derive(LogicBlock, Default)]
pub struct PelicanView {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register its §16 value.
    pub rst: Signal<In, Bit>,
    // ---- Wishbone slave (P-BUS-1..4) ----
    /// Wishbone cycle.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone strobe.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone write enable.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone word address.
    pub wb_adr_i: Signal<In, Bits<7>>,
    /// Wishbone write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone byte select.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone read data with `wb_ack_o`, else 0.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone acknowledge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Wishbone error: a refused access (P-BUS-3).
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request, active-high level (P-IRQ-1).
    pub irq: Signal<Out, Bit>,
    // ---- the core's state (its probes and view outputs) ----
    /// Main FSM state.
    pub state: Signal<In, Bits<4>>,
    /// Main FSM `tx_channel`.
    pub tx_channel: Signal<In, Bit>,
    /// Main FSM `failover`.
    pub failover: Signal<In, Bit>,
    /// Main FSM `tx_success` (the completion in `REDUNDANCY`).
    pub tx_success: Signal<In, Bit>,
    /// Auxiliary FSM A's state.
    pub aux_a_state: Signal<In, Bits<2>>,
    /// Auxiliary FSM B's state.
    pub aux_b_state: Signal<In, Bits<2>>,
    /// DMR state.
    pub dmr_state: Signal<In, Bits<2>>,
    /// DMR active CAN line.
    pub acl: Signal<In, Bit>,
    /// DMR host `tx_done` (the completion in `DMR`, one edge later).
    pub dmr_tx_done: Signal<In, Bit>,
    /// Replicated star: the hubs have split.
    pub star_split: Signal<In, Bit>,
    /// The RX writer drops an accepted frame at this edge, the FIFO full.
    pub rx_overrun: Signal<In, Bit>,
    /// The RX FIFO is not empty (registered).
    pub rx_ready: Signal<In, Bit>,
    /// The RX FIFO's count.
    pub rx_count: Signal<In, Bits<6>>,
    /// The RX FIFO's head: [115:100] time, [99] channel, [98:0] frame.
    pub rx_head: Signal<In, Bits<116>>,
    /// Native `INT_STATUS.switch` event.
    pub ev_switch: Signal<In, Bit>,
    /// Native `INT_STATUS.aux` event.
    pub ev_aux: Signal<In, Bit>,
    /// Native `INT_STATUS.dmr` event.
    pub ev_dmr: Signal<In, Bit>,
    /// Native `INT_STATUS.domain` event.
    pub ev_domain: Signal<In, Bit>,
    // ---- channel A ----
    /// Channel A `err_state`.
    pub chan_a_err_state: Signal<In, Bits<2>>,
    /// Channel A error warning.
    pub chan_a_err_warning: Signal<In, Bit>,
    /// Channel A `tec`.
    pub chan_a_tec: Signal<In, Bits<9>>,
    /// Channel A `rec`.
    pub chan_a_rec: Signal<In, Bits<8>>,
    /// Channel A bus-off recovery runs.
    pub chan_a_boff_runs: Signal<In, Bits<7>>,
    /// Channel A `field`.
    pub chan_a_field: Signal<In, Field>,
    /// Channel A transmitter role.
    pub chan_a_is_tx: Signal<In, Bit>,
    /// Channel A `tx_done`.
    pub chan_a_tx_done: Signal<In, Bit>,
    /// Channel A `tx_failed`.
    pub chan_a_tx_failed: Signal<In, Bit>,
    /// Channel A `tx_pending`.
    pub chan_a_tx_pending: Signal<In, Bit>,
    /// Channel A `err_valid`.
    pub chan_a_err_valid: Signal<In, Bit>,
    /// Channel A `err_kind`.
    pub chan_a_err_kind: Signal<In, Bits<3>>,
    /// Channel A `err_field`.
    pub chan_a_err_field: Signal<In, Field>,
    /// Channel A `err_tx`.
    pub chan_a_err_tx: Signal<In, Bit>,
    /// Channel A `arb_lost`.
    pub chan_a_arb_lost: Signal<In, Bit>,
    /// Channel A `alc`.
    pub chan_a_alc: Signal<In, Bits<5>>,
    // ---- channel B ----
    /// Channel B `err_state`.
    pub chan_b_err_state: Signal<In, Bits<2>>,
    /// Channel B error warning.
    pub chan_b_err_warning: Signal<In, Bit>,
    /// Channel B `tec`.
    pub chan_b_tec: Signal<In, Bits<9>>,
    /// Channel B `rec`.
    pub chan_b_rec: Signal<In, Bits<8>>,
    /// Channel B bus-off recovery runs.
    pub chan_b_boff_runs: Signal<In, Bits<7>>,
    /// Channel B `field`.
    pub chan_b_field: Signal<In, Field>,
    /// Channel B transmitter role.
    pub chan_b_is_tx: Signal<In, Bit>,
    /// Channel B `tx_done`.
    pub chan_b_tx_done: Signal<In, Bit>,
    /// Channel B `tx_failed`.
    pub chan_b_tx_failed: Signal<In, Bit>,
    /// Channel B `tx_pending`.
    pub chan_b_tx_pending: Signal<In, Bit>,
    /// Channel B `err_valid`.
    pub chan_b_err_valid: Signal<In, Bit>,
    /// Channel B `err_kind`.
    pub chan_b_err_kind: Signal<In, Bits<3>>,
    /// Channel B `err_field`.
    pub chan_b_err_field: Signal<In, Field>,
    /// Channel B `err_tx`.
    pub chan_b_err_tx: Signal<In, Bit>,
    /// Channel B `arb_lost`.
    pub chan_b_arb_lost: Signal<In, Bit>,
    /// Channel B `alc`.
    pub chan_b_alc: Signal<In, Bits<5>>,
    // ---- the view's drive of the core (§14) ----
    /// The native `CTRL` word (P-CFG-3).
    pub view_ctrl: Signal<Out, Bits<32>>,
    /// The native `BTR` word (P-CFG-2).
    pub view_btr: Signal<Out, Bits<28>>,
    /// The channels' reset, bit 0 = A.
    pub view_chan_reset: Signal<Out, Bits<2>>,
    /// Push the transmit buffer's frame (P-TX-2).
    pub view_push: Signal<Out, Bit>,
    /// The queue of the push: 1 = B (`SINGLE_B`).
    pub view_push_q: Signal<Out, Bit>,
    /// The pushed frame.
    pub view_push_frame: Signal<Out, Bits<99>>,
    /// Pop the RX FIFO's head (`RRB`).
    pub view_pop: Signal<Out, Bit>,
    /// The message is one-shot (P-TX-4).
    pub view_tx_single: Signal<Out, Bit>,
    /// Per-channel transmit abort (P-TX-3, P-BO-3).
    pub view_tx_abort: Signal<Out, Bits<2>>,
    /// Per-channel bus-off hold (P-BO-3).
    pub view_boff_hold: Signal<Out, Bits<2>>,
    /// Offer the transmitted frame for self-reception (P-TX-5).
    pub view_offer_s: Signal<Out, Bit>,
    /// The offered frame, normalized.
    pub view_frame_s: Signal<Out, Bits<99>>,
    /// The acceptance filter gates the FIFO's write port (P-RX-5): always.
    pub view_gate_on: Signal<Out, Bit>,
    /// `MOD.AFM`.
    pub view_afm: Signal<Out, Bit>,
    /// `ACR0..3`.
    pub view_acr: Signal<Out, Bits<32>>,
    /// `AMR0..3`.
    pub view_amr: Signal<Out, Bits<32>>,
    /// The native window re-arms channel A's (bit 0) or B's (bit 1) captures.
    pub view_cap_rearm: Signal<Out, Bits<2>>,
    // ---- the core's native register port, for the window (P-X-3, P-X-4) ----
    /// Native access at this edge (`cyc` and `stb`).
    pub nat_cyc: Signal<Out, Bit>,
    /// The native access is a write.
    pub nat_we: Signal<Out, Bit>,
    /// Native word index.
    pub nat_adr: Signal<Out, Bits<6>>,
    /// Native write data.
    pub nat_wdat: Signal<Out, Bits<32>>,
    /// Native read data, valid in the answer clock.
    pub nat_rdat: Signal<In, Bits<32>>,
    /// Native error answer.
    pub nat_err: Signal<In, Bit>,
    // ---- blocks ----
    lanes: ByteLanes,
    mc: ModeControl,
    ints: Interrupts,
    logical: LogicalController,
    cfg: ConfigRegs,
    ext: ExtensionRegs,
    win: NativeWindow,
    txb: TxFrameBuffer,
    rxwin: RxWindow,
    rx_start: Rbsa,
    alc: ArmedCapture,
    ecc: ArmedCapture,
    ecc_code: EccCode,
    self_norm: FrameNormalizer,
    // ---- the bus response ----
    ack_q: DFF<Bit>,
    err_q: DFF<Bit>,
    dat_q: DFF<Bits<32>>,
    /// The DMR `tx_done` of the previous edge (P-TX-7 in `DMR`).
    dmr_done_q: DFF<Bit>,
    /// Both channels' error states one clock earlier (`XIR.err_state`).
    err_state_q: DFF<Bits<4>>,
    // ---- decode and glue ----
    take: Signal<Local, Bit>,
    wr: Signal<Local, Bit>,
    rd: Signal<Local, Bit>,
    rbyte: Signal<Local, Bits<8>>,
    single: Signal<Local, Bit>,
    single_b: Signal<Local, Bit>,
    err_state_u: Signal<Local, Bits<2>>,
    chan_mode: Signal<Local, Bits<2>>,
    ctrl: Signal<Local, Bits<32>>,
    ign: Signal<Local, Bit>,
    sr: Signal<Local, Bits<8>>,
    /// The per-channel abort and bus-off hold of this clock (P-TX-3, P-BO-3).
    tx_abort: Signal<Local, Bits<2>>,
    boff_hold: Signal<Local, Bits<2>>,
    a_mod: Const<7, 0>,
    a_cmr: Const<7, 1>,
    a_sr: Const<7, 2>,
    a_ir: Const<7, 3>,
    a_ier: Const<7, 4>,
    a_alc: Const<7, 11>,
    a_ecc: Const<7, 12>,
    a_rxerr: Const<7, 14>,
    a_txerr: Const<7, 15>,
    a_rmc: Const<7, 29>,
    a_rbsa: Const<7, 30>,
    mode_single_a: Const<2, 0>,
    mode_dmr: Const<2, 2>,
    mode_single_b: Const<2, 3>,
    bus_off: Const<2, 2>,
    passive: Const<2, 1>,
    m_listen_only: Const<2, 1>,
    m_self_test: Const<2, 2>,
    m_normal: Const<2, 0>,
    /// `CTRL.redundancy` (bit 1) and `CTRL.dmr` (bit 17).
    ctrl_redundancy: Const<32, 0x2>,
    ctrl_dmr: Const<32, 0x2_0000>,
    /// 32..63 and 64..95 (`addr[6:5]`): the SJA1000's RX FIFO RAM (P-MAP-3).
    page_ram_lo: Const<2, 1>,
    page_ram_hi: Const<2, 2>,
    /// Per-channel bits: A, B, both.
    bit_a: Const<2, 1>,
    bit_b: Const<2, 2>,
    both: Const<2, 3>,
    zero2: Const<2, 0>,
    zero4: Const<4, 0>,
    zero32: Const<32, 0>,
}

impl PelicanView {
    /// The register block of a top generated with the keys `k` (the derived
    /// `Default` is the generator's defaults, [`PelicanKeys::default`]).
    pub fn new(k: &PelicanKeys) -> Self {
        Self {
            lanes: ByteLanes::new(k.stride),
            ext: ExtensionRegs::new(k.xmode(), k.k, k.dmr, k.star),
            ..Default::default()
        }
    }
}

// The update (the blocks' wiring, the read mux, the core's drive) lives beside
// this file.
mod wiring;
