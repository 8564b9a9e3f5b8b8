//! The `rust-hdl` engine of the DRCC core under a host view (PeliCAN contract
//! §14): the `drcc_hdl::drcc_core::DrccCore<M>` block with its `view_*` inputs
//! driven from a [`HostDrive`], the drive the view's reference model gives its
//! model core. Running it beside that model checks the core's side of the seam
//! clock by clock before the view's RTL exists. The native register port is
//! idle (a view's window onto it is the view's, P-X-3).
//!
//! One `step`: with `clk` low, apply the inputs and settle, read the writer's
//! events of this edge (combinational); raise `clk` and settle; read the
//! registered outputs.

use super::drcc::{DrccOutputs, DrccProbes};
use super::drcc_rusthdl::drcc_probes;
use super::rusthdl::{field_code, settle};
use crate::frame::Frame;
use crate::model::drcc::HostDrive;
use drcc_hdl::config::DrccConfig;
use drcc_hdl::drcc_core::DrccCore;
use rust_hdl::prelude::*;

/// Settling budget per half clock.
const MAX_SETTLE_ITERS: usize = 400;

/// A channel's outputs a view reads (the core's `chan_x_*` view outputs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ViewChannel {
    pub tx_done: bool,
    pub tx_failed: bool,
    pub tx_pending: bool,
    pub is_tx: bool,
    pub boff_runs: u8,
    pub err_warning: bool,
    pub tec: u16,
    pub err_valid: bool,
    pub err_kind: u8,
    pub err_field: u8,
    pub err_tx: bool,
    pub arb_lost: bool,
    pub alc: u8,
}

/// The core's outputs of one step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CoreViewOutputs {
    /// The CAN pins and the DRCC probes (the Wishbone fields are the idle port's).
    pub top: DrccOutputs,
    /// Channels A and B.
    pub chan: [ViewChannel; 2],
    /// The RX writer stored a frame at this edge.
    pub stored: bool,
    /// The RX writer dropped a frame on a full FIFO at this edge.
    pub overrun: bool,
    /// The RX FIFO after the edge: `rx_ready`, count, head frame and channel.
    pub rx_ready: bool,
    pub rx_count: u8,
    pub head: Frame,
    pub head_ch: u8,
}

/// The TX RAM's 99-bit layout of `f` (`crate::memory::tx_buffer` of drcc-hdl:
/// [98] rtr, [97] ide, [96:68] id, [67:64] dlc, [63:0] data, byte 1 on top).
pub fn frame_word(f: &Frame) -> Bits<99> {
    let data = u64::from_be_bytes(f.data);
    let hi = ((f.rtr as u64) << 34)
        | ((f.ide as u64) << 33)
        | ((f.id as u64 & 0x1FFF_FFFF) << 4)
        | (f.dlc as u64 & 0xF);
    (Bits::<99>::from(hi) << 64) | Bits::<99>::from(data)
}

/// The frame of a 99-bit TX RAM word.
pub fn word_frame(w: Bits<99>) -> Frame {
    let data = w.get_bits::<64>(0).to_u64();
    Frame {
        rtr: w.get_bit(98),
        ide: w.get_bit(97),
        id: w.get_bits::<29>(68).to_u64() as u32,
        dlc: w.get_bits::<4>(64).to_u64() as u8,
        data: data.to_be_bytes(),
    }
}

/// The DRCC core with `M` DMR mailboxes, driven by a host view.
pub struct DrccCoreViewEngine<const M: usize> {
    uut: Box<DrccCore<M>>,
}

impl<const M: usize> std::fmt::Debug for DrccCoreViewEngine<M> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DrccCoreViewEngine").finish_non_exhaustive()
    }
}

impl<const M: usize> DrccCoreViewEngine<M> {
    /// A fresh core generated with the sizes of `cfg`, clock low, not yet reset.
    pub fn with_config(cfg: &DrccConfig) -> Self {
        let mut uut = Box::new(DrccCore::<M>::with_config(cfg));
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        let mut e = DrccCoreViewEngine { uut };
        e.settle();
        e
    }

    fn settle(&mut self) {
        settle(self.uut.as_mut(), MAX_SETTLE_ITERS, "drcc core");
    }

    /// One clock: `rst`, the CAN receive pins and the view's drive.
    pub fn step(&mut self, rst: bool, rx: [bool; 2], d: &HostDrive) -> CoreViewOutputs {
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.rst.next = rst;
        u.wb_cyc_i.next = false;
        u.wb_stb_i.next = false;
        u.wb_we_i.next = false;
        u.wb_adr_i.next = 0.into();
        u.wb_dat_i.next = 0.into();
        u.wb_sel_i.next = 0.into();
        u.chan_a_rx.next = rx[0];
        u.chan_b_rx.next = rx[1];
        u.view_on.next = true;
        u.view_ctrl.next = (d.ctrl as u64).into();
        u.view_btr.next = ((d.btr & 0x0FFF_FFFF) as u64).into();
        u.view_chan_reset.next = ((d.chan_reset[0] as u64) | (d.chan_reset[1] as u64) << 1).into();
        u.view_push.next = d.push.is_some();
        u.view_push_q.next = d.push.is_some_and(|(q, _)| q == 1);
        u.view_push_frame.next = d.push.map(|(_, f)| frame_word(&f)).unwrap_or_default();
        u.view_pop.next = d.pop;
        u.view_tx_single.next = d.tx_single;
        u.view_tx_abort.next = ((d.tx_abort[0] as u64) | (d.tx_abort[1] as u64) << 1).into();
        u.view_boff_hold.next = ((d.boff_hold[0] as u64) | (d.boff_hold[1] as u64) << 1).into();
        u.view_offer_s.next = d.self_frame.is_some();
        u.view_frame_s.next = d.self_frame.map(|f| frame_word(&f)).unwrap_or_default();
        u.view_gate_on.next = d.gate.is_some();
        let g = d.gate.unwrap_or_default();
        u.view_afm.next = g.single;
        u.view_acr.next = (u32::from_le_bytes(g.acr) as u64).into();
        u.view_amr.next = (u32::from_le_bytes(g.amr) as u64).into();
        self.settle();
        let (stored, overrun) = (self.uut.rx_stored.val(), self.uut.rx_overrun.val());
        self.uut.clk.next = Clock::from(true);
        self.settle();
        let u = &self.uut;
        let head = u.rx_head.val();
        CoreViewOutputs {
            top: DrccOutputs {
                wb_ack: u.wb_ack_o.val(),
                wb_err: u.wb_err_o.val(),
                wb_dat_r: u.wb_dat_o.val().to_u64() as u32,
                irq: u.irq.val(),
                chan_a_tx: u.chan_a_tx.val(),
                chan_b_tx: u.chan_b_tx.val(),
                probes: drcc_probes!(u),
            },
            chan: [
                ViewChannel {
                    tx_done: u.chan_a_tx_done.val(),
                    tx_failed: u.chan_a_tx_failed.val(),
                    tx_pending: u.chan_a_tx_pending.val(),
                    is_tx: u.chan_a_is_tx.val(),
                    boff_runs: u.chan_a_boff_runs.val().to_u64() as u8,
                    err_warning: u.chan_a_err_warning.val(),
                    tec: u.chan_a_tec.val().to_u64() as u16,
                    err_valid: u.chan_a_err_valid.val(),
                    err_kind: u.chan_a_err_kind.val().to_u64() as u8,
                    err_field: field_code(&u.chan_a_err_field.val()),
                    err_tx: u.chan_a_err_tx.val(),
                    arb_lost: u.chan_a_arb_lost.val(),
                    alc: u.chan_a_alc.val().to_u64() as u8,
                },
                ViewChannel {
                    tx_done: u.chan_b_tx_done.val(),
                    tx_failed: u.chan_b_tx_failed.val(),
                    tx_pending: u.chan_b_tx_pending.val(),
                    is_tx: u.chan_b_is_tx.val(),
                    boff_runs: u.chan_b_boff_runs.val().to_u64() as u8,
                    err_warning: u.chan_b_err_warning.val(),
                    tec: u.chan_b_tec.val().to_u64() as u16,
                    err_valid: u.chan_b_err_valid.val(),
                    err_kind: u.chan_b_err_kind.val().to_u64() as u8,
                    err_field: field_code(&u.chan_b_err_field.val()),
                    err_tx: u.chan_b_err_tx.val(),
                    arb_lost: u.chan_b_arb_lost.val(),
                    alc: u.chan_b_alc.val().to_u64() as u8,
                },
            ],
            stored,
            overrun,
            rx_ready: u.rx_ready.val(),
            rx_count: u.rx_count.val().to_u64() as u8,
            head: word_frame(head.get_bits::<99>(0)),
            head_ch: head.get_bit(99) as u8,
        }
    }
}
