//! Fault confinement: the transmit and receive error counters and the node's error
//! state (ISO 11898-1:2015 clause 12, fault confinement; the counting rules are
//! 12.1.4.2 rules a to l).
//!
//! This file holds the counters and the state transitions (rules g to l); the
//! places where rules a to f apply live with the error frames in `error.rs`.
//! Open points decided here (also listed in timing_contract.md §4.5):
//! - REC saturates at 255 (the `rec` probe is 8 bits wide); TEC stops moving once
//!   the node is bus-off (at most 255 + 8 = 263).
//! - Rule h, REC > 127: the standard allows any value 119..=127; the model sets 127.
//! - The error state follows the counters at the same clock edge as the change.
//! - In LISTEN_ONLY mode the counters are frozen (contract §7: no rule a to h
//!   applies), see [`Counters::freeze`].

use crate::model::coverage;

/// `err_state` value of an error-active node.
pub const ERROR_ACTIVE: u8 = 0;
/// `err_state` value of an error-passive node.
pub const ERROR_PASSIVE: u8 = 1;
/// `err_state` value of a bus-off node.
pub const BUS_OFF: u8 = 2;

/// Error counters and error state of one node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Counters {
    tec: u16,
    rec: u8,
    state: u8,
    /// LISTEN_ONLY: no counting rule applies (contract §7).
    frozen: bool,
}

impl Default for Counters {
    fn default() -> Self {
        Self::new()
    }
}

impl Counters {
    /// Reset: both counters 0, error active.
    pub fn new() -> Self {
        Counters {
            tec: 0,
            rec: 0,
            state: ERROR_ACTIVE,
            frozen: false,
        }
    }

    /// `err_reset` (contract §4.5): both counters 0 and error active, applied after
    /// the edge's counting rules; a bus-off node is left alone (it leaves bus-off
    /// only by the recovery of 12.1.4.4).
    pub fn err_reset(&mut self) {
        if self.state != BUS_OFF {
            self.tec = 0;
            self.rec = 0;
            self.state = ERROR_ACTIVE;
        }
    }

    /// LISTEN_ONLY mode (contract §7): TEC and REC never change.
    pub fn freeze(&mut self) {
        self.frozen = true;
    }

    /// Transmit error counter.
    #[inline]
    pub fn tec(&self) -> u16 {
        self.tec
    }

    /// Receive error counter.
    #[inline]
    pub fn rec(&self) -> u8 {
        self.rec
    }

    /// Error state (`ERROR_ACTIVE`, `ERROR_PASSIVE` or `BUS_OFF`).
    #[inline]
    pub fn state(&self) -> u8 {
        self.state
    }

    /// Error active: sends active error flags.
    #[inline]
    pub fn is_active(&self) -> bool {
        self.state == ERROR_ACTIVE
    }

    /// Error passive.
    #[inline]
    pub fn is_passive(&self) -> bool {
        self.state == ERROR_PASSIVE
    }

    /// Bus-off.
    #[inline]
    pub fn is_bus_off(&self) -> bool {
        self.state == BUS_OFF
    }

    /// Rules c, d, f (transmitter): TEC + `n`. No effect while bus-off.
    pub fn tec_add(&mut self, n: u16) {
        if self.is_bus_off() || self.frozen {
            return;
        }
        self.tec += n;
        self.update();
    }

    /// Rules a, b, e, f (receiver): REC + `n`, saturating at 255. No effect while bus-off.
    pub fn rec_add(&mut self, n: u8) {
        if self.is_bus_off() || self.frozen {
            return;
        }
        self.rec = self.rec.saturating_add(n);
        self.update();
    }

    /// ISO 11898-1 12.1.4.2 rule g: successful transmission, TEC - 1 unless 0.
    pub fn tx_success(&mut self) {
        if self.frozen {
            return;
        }
        if self.tec > 0 {
            coverage::hit("rule g: TEC - 1");
            self.tec -= 1;
        } else {
            coverage::hit("rule g: TEC stays 0");
        }
        self.update();
    }

    /// ISO 11898-1 12.1.4.2 rule h: successful reception (no error up to the ACK
    /// slot and the ACK bit sent successfully): REC - 1 when 1..=127; when above 127
    /// a value in 119..=127 (the model takes 127).
    pub fn rx_success(&mut self) {
        if self.frozen {
            return;
        }
        if self.rec > 127 {
            coverage::hit("rule h: REC above 127 back to 119..127");
            self.rec = 127;
        } else if self.rec > 0 {
            coverage::hit("rule h: REC - 1");
            self.rec -= 1;
        } else {
            coverage::hit("rule h: REC stays 0");
        }
        self.update();
    }

    /// ISO 11898-1 12.1.4.2 rule l: bus-off recovery after 128 occurrences of 11
    /// consecutive recessive bits: both counters 0, error active.
    pub fn recover(&mut self) {
        coverage::hit("rule l: bus-off recovery (128 x 11 recessive bits)");
        self.tec = 0;
        self.rec = 0;
        self.state = ERROR_ACTIVE;
    }

    /// Rules i, j, k: error passive at TEC >= 128 or REC >= 128, bus-off at TEC > 255,
    /// error active again when both are <= 127. Bus-off is left only by `recover`.
    fn update(&mut self) {
        if self.is_bus_off() {
            return;
        }
        let was = self.state;
        self.state = if self.tec > 255 {
            BUS_OFF
        } else if self.tec >= 128 || self.rec >= 128 {
            ERROR_PASSIVE
        } else {
            ERROR_ACTIVE
        };
        if self.state != was && coverage::enabled() {
            coverage::hit(match self.state {
                BUS_OFF => "rule j: bus-off (TEC > 255)",
                ERROR_PASSIVE if self.tec >= 128 => "rule i: error passive (TEC >= 128)",
                ERROR_PASSIVE => "rule i: error passive (REC >= 128)",
                _ => "rule k: error active again",
            });
        }
    }
}
