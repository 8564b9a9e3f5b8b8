//! Error and overload frames and the error counting they trigger (ISO 11898-1:2015
//! clause 10: error frame 10.4.4, overload frame 10.4.5, error signalling;
//! clause 12: error counting 12.1.4.2 rules a to f). Contract §4.5.
//!
//! Error flag: active = 6 dominant bits, passive = recessive until 6 equal
//! consecutive bits have been sampled. Delimiter (error and overload alike): the
//! node sends recessive, waits for the first recessive bit, then 7 more recessive
//! bits, 8 in total; a dominant bit among bits 2..7 is a form error, a dominant
//! 8th bit starts an overload frame. Overload flag: 6 dominant bits.

use super::control::{KIND_ACK, KIND_BIT, KIND_CRC, KIND_FORM, KIND_STUFF};
use super::frame::ErrorKind;
use super::Bsp;
use crate::model::{coverage, field};

impl Bsp {
    /// An error was detected at this SAMPLE edge: count it, then start the error
    /// flag at the next bit (a CRC error arrives here only at the ACK delimiter).
    pub(super) fn error(&mut self, kind: ErrorKind) {
        coverage::hit_with(|| {
            let k = match kind {
                ErrorKind::Bit => "bit",
                ErrorKind::Stuff => "stuff",
                ErrorKind::StuffInArbitration => "stuff in arbitration",
                ErrorKind::Crc => "crc",
                ErrorKind::Form => "form",
                ErrorKind::Ack => "ack",
            };
            coverage::error_bin(self.transmitter, k, self.field)
        });
        self.capture(match kind {
            ErrorKind::Bit => KIND_BIT,
            ErrorKind::Stuff | ErrorKind::StuffInArbitration => KIND_STUFF,
            ErrorKind::Crc => KIND_CRC,
            ErrorKind::Form => KIND_FORM,
            ErrorKind::Ack => KIND_ACK,
        });
        let mut ack_exception = false;
        if self.transmitter {
            if self.attempt {
                // The attempt ends without success (§8).
                self.attempt_failed();
            }
            match kind {
                // ISO 11898-1 12.1.4.2 rule c exception 2: no change.
                ErrorKind::StuffInArbitration => {
                    coverage::hit("rule c exception 2: stuff error in arbitration, TEC unchanged")
                }
                // Rule c exception 1: decided during the passive flag (decision 5).
                ErrorKind::Ack if self.counters.is_passive() => ack_exception = true,
                // Rule c: a transmitter sending an error flag, TEC + 8.
                _ => {
                    coverage::hit("rule c: TEC + 8");
                    self.counters.tec_add(8)
                }
            }
        } else {
            // Rule a: a receiver detecting an error, REC + 1.
            coverage::hit("rule a: REC + 1");
            self.counters.rec_add(1);
        }
        self.start_error_flag();
        self.ack_exception = ack_exception;
    }

    /// Starts an error flag at the next bit, active or passive by the error state.
    fn start_error_flag(&mut self) {
        self.next_field(field::ERROR_FLAG);
        // LISTEN_ONLY: every flag the node takes part in is passive (§7).
        self.flag_active = self.counters.is_active() && !self.listen_only;
        self.flag_eq = 0;
        self.ack_exception = false;
    }

    /// Bit error while sending an active error flag or an overload flag: rule d
    /// (transmitter) or rule e (receiver) +8, and a new error flag (decision 3).
    fn flag_bit_error(&mut self) {
        coverage::hit_with(|| coverage::error_bin(self.transmitter, "bit", self.field));
        self.capture(KIND_BIT);
        if self.transmitter {
            coverage::hit("rule d: TEC + 8 (bit error in its flag)");
            self.counters.tec_add(8);
        } else {
            coverage::hit("rule e: REC + 8 (bit error in its flag)");
            self.counters.rec_add(8);
        }
        self.start_error_flag();
    }

    /// Starts an overload flag at the next bit.
    pub(super) fn start_overload(&mut self) {
        self.next_field(field::OVERLOAD_FLAG);
    }

    /// ERROR_FLAG.
    pub(super) fn error_flag(&mut self, b: bool) {
        if self.flag_active {
            if b {
                return self.flag_bit_error();
            }
            self.cnt += 1;
            if self.cnt == 6 {
                self.start_delimiter(field::ERROR_DELIM);
            }
            return;
        }
        // Passive flag: a dominant bit is no bit error (ISO 16845-1 8.5.1), but it
        // ends rule c exception 1 for an error-passive transmitter's ACK error.
        if !b && self.ack_exception {
            coverage::hit("rule c exception 1 ended: dominant bit in the passive flag, TEC + 8");
            self.ack_exception = false;
            self.counters.tec_add(8);
        }
        if self.flag_eq == 0 || b != self.flag_last {
            self.flag_last = b;
            self.flag_eq = 1;
        } else {
            self.flag_eq += 1;
        }
        if self.flag_eq == 6 {
            self.start_delimiter(field::ERROR_DELIM);
        }
    }

    /// OVERLOAD_FLAG.
    pub(super) fn overload_flag(&mut self, b: bool) {
        // LISTEN_ONLY follows the 6 flag bits without checking them (§7).
        if b && !self.listen_only {
            return self.flag_bit_error();
        }
        self.cnt += 1;
        if self.cnt == 6 {
            self.start_delimiter(field::OVERLOAD_DELIM);
        }
    }

    fn start_delimiter(&mut self, f: u8) {
        if self.ack_exception {
            coverage::hit("rule c exception 1: passive ACK error, TEC unchanged");
        }
        self.next_field(f);
        self.first_after_flag = f == field::ERROR_DELIM;
        self.dom_cnt = 0;
        self.ack_exception = false;
    }

    /// ERROR_DELIM and OVERLOAD_DELIM; `cnt` counts the recessive delimiter bits.
    pub(super) fn delimiter(&mut self, b: bool) {
        let first_after_error_flag = self.first_after_flag;
        self.first_after_flag = false;
        if self.cnt == 0 {
            if b {
                self.cnt = 1;
                return;
            }
            // Still waiting for the first recessive bit (up to 7 dominant bits are
            // tolerated, ISO 16845-1 7.3.1 / 8.3.1).
            if first_after_error_flag && !self.transmitter {
                // Rule b: a receiver reads dominant as the first bit after its
                // error flag, REC + 8.
                coverage::hit("rule b: REC + 8 (dominant first bit after its error flag)");
                self.counters.rec_add(8);
            }
            self.dom_cnt += 1;
            if self.dom_cnt == 8 {
                // Rule f: 14th dominant bit after an active/overload flag start, 8th
                // after a passive flag, and each further 8.
                self.dom_cnt = 0;
                if self.transmitter {
                    coverage::hit("rule f: TEC + 8 (8 dominant bits after its flag)");
                    self.counters.tec_add(8);
                } else {
                    coverage::hit("rule f: REC + 8 (8 dominant bits after its flag)");
                    self.counters.rec_add(8);
                }
            }
            return;
        }
        if b {
            self.cnt += 1;
            if self.cnt == 8 {
                self.next_field(field::INTERMISSION);
            }
        } else if self.cnt == 7 {
            // Dominant 8th delimiter bit: overload frame (ISO 16845-1 7.4.3, 8.4.2).
            self.start_overload();
        } else {
            self.error(ErrorKind::Form);
        }
    }
}
