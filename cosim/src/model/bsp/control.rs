//! Transmit control and diagnostics (timing contract §8 and §9): single-shot
//! transmission, `tx_abort`, `tx_failed`; the error code capture (`err_valid`,
//! `err_kind`, `err_field`, `err_tx`), the arbitration lost capture (`alc`) and the
//! error counters by kind. ISO 11898-1:2015 leaves these host-side services to the
//! implementation (clause 10 names the error kinds: bit, stuff, CRC, form, ACK).

use super::Bsp;
use crate::model::field;

/// `err_kind` code of a bit error.
pub const KIND_BIT: u8 = 1;
/// `err_kind` code of a stuff error.
pub const KIND_STUFF: u8 = 2;
/// `err_kind` code of a CRC error.
pub const KIND_CRC: u8 = 3;
/// `err_kind` code of a form error.
pub const KIND_FORM: u8 = 4;
/// `err_kind` code of an ACK error.
pub const KIND_ACK: u8 = 5;

/// The §9 registers kept by the bit stream processor.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Diag {
    /// One-clock pulse: an error was captured at this edge.
    pub err_valid: bool,
    /// Kind of the last error (`KIND_*`), 0 before the first.
    pub err_kind: u8,
    /// `field` probe at the last error, before the update.
    pub err_field: u8,
    /// The node was transmitter at the last error.
    pub err_tx: bool,
    /// Arbitration lost capture.
    pub alc: u8,
    /// Errors by kind (index `kind - 1`), saturating at 255.
    pub counts: [u8; 5],
}

impl Bsp {
    /// An error that starts an error flag was detected at this SAMPLE edge: load
    /// the capture registers and count it by kind (§9). Called before any state
    /// of the edge changes, so `field` and the role are those at detection.
    pub(super) fn capture(&mut self, kind: u8) {
        let d = &mut self.diag;
        d.err_valid = true;
        d.err_kind = kind;
        d.err_field = self.field;
        d.err_tx = self.transmitter;
        let c = &mut d.counts[(kind - 1) as usize];
        *c = c.saturating_add(1);
    }

    /// Arbitration lost at the bit of `field`/`cnt` (before the update): load `alc`
    /// (§9) and end the attempt (§8).
    pub(super) fn lose_arbitration(&mut self) {
        self.diag.alc = match self.field {
            field::ID_A => self.cnt,
            field::SRR_RTR => 11,
            field::IDE => 12,
            field::ID_B => 13 + self.cnt,
            _ => 31, // RTR_EXT
        };
        self.transmitter = false;
        self.arb_lost = true;
        self.attempt_failed();
    }

    /// The attempt ended without success (lost arbitration, or an error detected
    /// as transmitter): in single-shot mode (`cfg_single_shot`, or `tx_single`
    /// latched with this frame), or with an abort remembered before
    /// this edge, the frame is dropped at this edge (§8); otherwise it stays
    /// pending (an abort that arrived at this very edge is carried out at the next
    /// edge where the node is no transmitter and its `tx` recessive).
    pub(super) fn attempt_failed(&mut self) {
        self.attempt = false;
        if self.single_shot || self.tx_single || (self.abort_pending && !self.abort_new) {
            self.drop_frame();
        }
    }

    /// The attempt succeeded (`tx_done`): a remembered abort is forgotten.
    pub(super) fn attempt_done(&mut self) {
        self.attempt = false;
        self.abort_pending = false;
    }

    /// Drops the pending frame: `tx_pending` clears, `tx_failed` pulses.
    fn drop_frame(&mut self) {
        self.tx_pending = false;
        self.abort_pending = false;
        self.tx_failed = true;
    }

    /// A remembered abort is waiting (checked at every edge).
    #[inline]
    pub fn abort_pending(&self) -> bool {
        self.abort_pending
    }

    /// `tx_abort` at this edge, or a remembered abort (§8), judged on the state
    /// before the edge: with a frame pending, the node not transmitter and its `tx`
    /// register recessive, the frame is dropped now; otherwise the abort is
    /// remembered and carried out at the first edge where that holds, unless the
    /// attempt in progress ends first (success: forgotten; failure: dropped). An
    /// abort with nothing pending does nothing.
    pub fn abort(&mut self) {
        if !self.tx_pending {
            return;
        }
        if !self.transmitter && self.tx {
            self.drop_frame();
        } else if !self.abort_pending {
            self.abort_pending = true;
            self.abort_new = true;
        }
    }
}
