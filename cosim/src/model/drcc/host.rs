//! The core's host interface (PeliCAN contract §14): what a host view other than
//! the native register file drives into the core at an edge, and what the core
//! reports back. With no drive set ([`DrccModel::step`] alone) the native
//! register file is the host and nothing here acts.

use super::DrccModel;
use crate::engine::drcc::DrccInputs;
use crate::engine::ChannelOutputs;
use crate::frame::Frame;
use crate::model::pelican::acf::Acf;

/// One edge's drive of the core by a host view, computed from the view's
/// registers before the edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HostDrive {
    /// The native `CTRL` word the view composes (P-CFG-3); its `reset_mode`
    /// bit is the core's hold (P-CORE-3).
    pub ctrl: u32,
    /// The native `BTR` word (P-CFG-2).
    pub btr: u32,
    /// The channels' reset (P-CORE-3): host reset mode and one clock after
    /// it, or a channel the mode leaves unused (P-CFG-3).
    pub chan_reset: [bool; 2],
    /// A push at this edge: target queue and normalized frame (P-TX-2).
    pub push: Option<(usize, Frame)>,
    /// An RX FIFO pop at this edge (P-CMR-4).
    pub pop: bool,
    /// Per-request single shot (P-CORE-1, P-TX-4).
    pub tx_single: bool,
    /// Per-channel abort (P-TX-3, P-BO-3).
    pub tx_abort: [bool; 2],
    /// Per-channel bus-off hold (P-CORE-2, P-BO-3).
    pub boff_hold: [bool; 2],
    /// A self-received frame offered to the RX writer (source `S`, P-TX-5).
    pub self_frame: Option<Frame>,
    /// The acceptance gate at the RX FIFO's write port (P-CORE-4).
    pub gate: Option<Acf>,
    /// A full-word access of the native register port at this edge (the view's
    /// window, P-X-3, P-X-4); its answer is the core's Wishbone outputs after it.
    pub native: Option<NativeAccess>,
    /// The window's load of `CAP_A` / `CAP_B` re-arms that channel's captures.
    pub cap_rearm: [bool; 2],
}

/// One full-word access of the native register port (DRCC contract §D2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NativeAccess {
    /// A write (else a read).
    pub we: bool,
    /// The native word index.
    pub adr: u8,
    /// The word written.
    pub dat: u32,
}

/// The core's events at the last edge, for the host view.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HostEvents {
    /// The native `INT_STATUS` events of the edge (§D8).
    pub ints: u32,
    /// The main FSM's `tx_success` pulse (§D4.1).
    pub tx_success: bool,
    /// The RX writer stored a frame.
    pub stored: bool,
    /// The RX writer dropped an accepted frame on a full FIFO.
    pub overrun: bool,
    /// The DMR function's host `tx_done` (§M5).
    pub dmr_tx_done: bool,
}

/// The core state a host view reads (combinational or registered).
#[derive(Clone, Copy, Debug)]
pub struct CoreView<'a> {
    /// The channels' output registers.
    pub chan: [&'a ChannelOutputs; 2],
    /// The RX FIFO's `rx_ready`, head frame and its channel, count.
    pub rx_ready: bool,
    pub head: Frame,
    pub head_ch: u8,
    pub rx_count: u8,
    /// Main FSM state, `tx_channel`, `failover`.
    pub fsm_state: u8,
    pub tx_channel: u8,
    pub failover: bool,
    /// Auxiliary FSM states.
    pub aux: [u8; 2],
    /// DMR state and active CAN line.
    pub dmr_state: u8,
    pub acl: u8,
    /// Replicated star: the hubs have split (§4.5).
    pub split: bool,
}

impl DrccModel {
    /// One clock with `drive` as the host; the native register port makes the
    /// drive's window access, if any.
    pub fn step_host(&mut self, rst: bool, rx: [bool; 2], drive: HostDrive) -> HostEvents {
        self.host = Some(drive);
        if !rst {
            self.r.ctrl = drive.ctrl;
            self.r.btr = drive.btr;
            self.r.filt.gate = drive.gate;
            self.rx.offer_s = drive.self_frame;
        }
        self.host_ev = HostEvents::default();
        let nat = drive.native.unwrap_or_default();
        let on = drive.native.is_some();
        self.step(&DrccInputs {
            rst,
            chan_a_rx: rx[0],
            chan_b_rx: rx[1],
            wb_cyc: on,
            wb_stb: on,
            wb_we: nat.we,
            wb_adr: nat.adr,
            wb_dat_w: nat.dat,
            wb_sel: 0xF,
        });
        self.host_ev
    }

    /// The core as the host view sees it after the last edge.
    pub fn core_view(&self) -> CoreView<'_> {
        CoreView {
            chan: [&self.out[0], &self.out[1]],
            rx_ready: self.rx.rx_ready,
            head: self.rx.rd.0,
            head_ch: self.rx.rd.1,
            rx_count: self.rx.count,
            fsm_state: self.fsm.state,
            tx_channel: self.fsm.tx_channel() as u8,
            failover: self.fsm.failover,
            aux: [self.aux[0].state, self.aux[1].state],
            dmr_state: self.dmr.dmr_state,
            acl: self.dmr.acl,
            split: self.star.split,
        }
    }
}
