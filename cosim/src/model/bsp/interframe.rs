//! States between frames: bus integration after reset, bus idle, intermission,
//! suspend transmission and bus-off recovery (ISO 11898-1:2015 clause 10.4.6,
//! interframe space; clause 12, bus integration and bus-off, 12.1.4.2 rule l).

use super::frame::ErrorKind;
use super::Bsp;
use crate::model::field;

impl Bsp {
    /// INTEGRATING: 11 consecutive recessive bits, then IDLE.
    pub(super) fn integrating(&mut self, b: bool) {
        if b {
            self.cnt += 1;
            if self.cnt == 11 {
                self.next_field(field::IDLE);
            }
        } else {
            self.cnt = 0;
        }
    }

    /// IDLE: a dominant bit is a start of frame.
    pub(super) fn idle(&mut self, b: bool) {
        if !b {
            self.sof();
        } else if !self.tx {
            // Its own SOF read back recessive: the node sent a frame bit, so it is
            // transmitter and has a bit error (ISO 11898-1 12.1.3.1; contract §4.4).
            self.transmitter = true;
            self.attempt = true;
            self.error(ErrorKind::Bit);
        }
    }

    /// INTERMISSION: a dominant bit 1 or 2 starts an overload frame (ISO 16845-1
    /// 7.4.1, 8.4.1); a dominant bit 3 is a SOF (7.3.2, 8.1.8, 8.4.3). After 3
    /// recessive bits an error-passive transmitter suspends transmission, others go
    /// to IDLE. The transmitter role ends here (decision 1).
    pub(super) fn intermission(&mut self, b: bool) {
        if !b {
            if self.cnt < 2 {
                self.start_overload();
            } else {
                self.sof();
            }
            return;
        }
        self.cnt += 1;
        if self.cnt == 3 {
            let suspend = self.counters.is_passive() && self.transmitter;
            self.transmitter = false;
            self.next_field(if suspend { field::SUSPEND } else { field::IDLE });
        }
    }

    /// SUSPEND: 8 recessive bits before the node may start a frame; a dominant bit
    /// is another node's SOF, received (ISO 16845-1 8.5.4 to 8.5.7).
    pub(super) fn suspend(&mut self, b: bool) {
        if !b {
            self.sof();
            return;
        }
        self.cnt += 1;
        if self.cnt == 8 {
            self.next_field(field::IDLE);
        }
    }

    /// Enters bus-off (rule j): no transmission, no flag, the frame stays pending.
    pub(super) fn enter_bus_off(&mut self) {
        self.next_field(field::BUS_OFF);
        self.busoff_occ = 0;
        self.transmitter = false;
        self.attempt = false;
        self.ack_exception = false;
    }

    /// BUS_OFF: count occurrences of 11 consecutive recessive bits; after 128 the
    /// node is error active with both counters 0 and idle (rule l, decision 9).
    pub(super) fn bus_off(&mut self, b: bool) {
        if !b {
            self.cnt = 0;
            return;
        }
        self.cnt += 1;
        if self.cnt == 11 {
            self.cnt = 0;
            self.busoff_occ += 1;
            if self.busoff_occ == 128 {
                self.counters.recover();
                self.next_field(field::IDLE);
            }
        }
    }
}
