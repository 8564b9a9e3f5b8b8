//! The fields of a data or remote frame, SOF to EOF, for transmitter and receivers
//! (ISO 11898-1:2015 clause 10: frame formats 10.4.2 / 10.4.3, bit stuffing,
//! arbitration, ACK, frame validity; error detection of bit, stuff, CRC, form and
//! ACK errors). Contract §4.3 and §4.4.

use super::Bsp;
use crate::frame::Frame;
use crate::model::crc::crc15_step;
use crate::model::field;

/// The kinds of error a node detects (ISO 11898-1 error detection).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ErrorKind {
    /// Bit sent differs from bit read (outside arbitration and the ACK slot).
    Bit,
    /// Six equal bits in the stuffed region.
    Stuff,
    /// Recessive stuff bit of the transmitter read dominant during arbitration
    /// (rule c exception 2).
    StuffInArbitration,
    /// Received CRC differs from the computed one (signalled after the ACK delimiter).
    Crc,
    /// Dominant bit in a fixed-form field.
    Form,
    /// Transmitter reads a recessive ACK slot.
    Ack,
}

impl Bsp {
    /// Start of frame: a dominant sample in IDLE or SUSPEND or at intermission
    /// bit 3. The node becomes transmitter iff `start_ok` (contract §4.4).
    pub(super) fn sof(&mut self) {
        // A node whose own SOF is on `tx` has begun its attempt: it stays
        // transmitter even if an abort arrived during the SOF bit (§8, decision 15).
        self.transmitter = self.starts();
        self.attempt = self.transmitter;
        self.field = field::ID_A;
        self.cnt = 0;
        self.pos = 1;
        // The stuffed region starts with SOF, a dominant bit (contract §4.3).
        self.stuff_last = false;
        self.stuff_cnt = 1;
        self.last_arb = false;
        // CRC-15 of the SOF bit from the initial value 0.
        self.crc = crc15_step(0, false);
        self.id = 0;
        self.srr_rtr = false;
        self.ide = false;
        self.rtr = false;
        self.dlc = 0;
        self.data = 0;
        self.data_bits = 0;
        self.rx_crc = 0;
        self.crc_ok = false;
        self.ack_exception = false;
    }

    /// A bit of the stuffed region (ID_A up to the CRC delimiter): destuffing,
    /// stuff errors, arbitration and bit errors of the transmitter.
    pub(super) fn stuffed_bit(&mut self, b: bool) {
        let sent = self.tx;
        if self.stuff_cnt == 5 {
            // Five equal bits precede: this is a stuff bit.
            if self.transmitter && b != sent {
                let kind = if sent && self.last_arb {
                    ErrorKind::StuffInArbitration
                } else {
                    ErrorKind::Bit
                };
                return self.error(kind);
            }
            if b == self.stuff_last {
                return self.error(ErrorKind::Stuff);
            }
            self.stuff_last = b;
            self.stuff_cnt = 1;
            return;
        }
        if b == self.stuff_last {
            self.stuff_cnt += 1;
        } else {
            self.stuff_last = b;
            self.stuff_cnt = 1;
        }
        // IDE is arbitration only in an extended frame (the transmitter sent it
        // recessive); a base frame's IDE is control field (ISO 11898-1 10.4.2.2),
        // so a stuff bit after it is not "in arbitration" (contract §4.4, §4.5).
        let arb = field::is_arbitration(self.field) && (self.field != field::IDE || sent);
        if self.transmitter && b != sent {
            if arb && sent {
                // Sent recessive, read dominant: arbitration lost; receive the rest.
                self.lose_arbitration();
            } else {
                return self.error(ErrorKind::Bit);
            }
        }
        self.last_arb = arb;
        self.field_bit(b);
    }

    /// A destuffed bit of the frame: collect it and advance the field.
    fn field_bit(&mut self, b: bool) {
        let bit = b as u32;
        match self.field {
            field::ID_A => {
                self.id = (self.id << 1) | bit;
                self.frame_bit(b);
                self.cnt += 1;
                if self.cnt == 11 {
                    self.next_field(field::SRR_RTR);
                }
            }
            field::SRR_RTR => {
                self.srr_rtr = b;
                self.frame_bit(b);
                self.next_field(field::IDE);
            }
            field::IDE => {
                self.ide = b;
                self.frame_bit(b);
                if b {
                    self.next_field(field::ID_B);
                } else {
                    self.rtr = self.srr_rtr;
                    self.next_field(field::R0);
                }
            }
            field::ID_B => {
                self.id = (self.id << 1) | bit;
                self.frame_bit(b);
                self.cnt += 1;
                if self.cnt == 18 {
                    self.next_field(field::RTR_EXT);
                }
            }
            field::RTR_EXT => {
                self.rtr = b;
                self.frame_bit(b);
                self.next_field(field::R1);
            }
            field::R1 => {
                // Either value is accepted (ISO 16845-1 7.1.4 / 7.1.5).
                self.frame_bit(b);
                self.next_field(field::R0);
            }
            field::R0 => {
                self.frame_bit(b);
                self.next_field(field::DLC);
            }
            field::DLC => {
                self.dlc = (self.dlc << 1) | b as u8;
                self.frame_bit(b);
                self.cnt += 1;
                if self.cnt == 4 {
                    self.data_bits = if self.rtr { 0 } else { self.dlc.min(8) * 8 };
                    if self.data_bits == 0 {
                        self.next_field(field::CRC);
                    } else {
                        self.next_field(field::DATA);
                    }
                }
            }
            field::DATA => {
                self.data = (self.data << 1) | bit as u64;
                self.frame_bit(b);
                self.cnt += 1;
                if self.cnt == self.data_bits {
                    self.next_field(field::CRC);
                }
            }
            field::CRC => {
                self.rx_crc = (self.rx_crc << 1) | bit as u16;
                self.pos += 1;
                self.cnt += 1;
                if self.cnt == 15 {
                    self.crc_ok = self.rx_crc == self.crc;
                    self.next_field(field::CRC_DELIM);
                }
            }
            field::CRC_DELIM => {
                // End of the stuffed region.
                if !b {
                    return self.error(ErrorKind::Form);
                }
                self.next_field(field::ACK_SLOT);
            }
            other => unreachable!("field code {other} in the stuffed region"),
        }
    }

    /// A bit covered by the CRC (SOF to end of data).
    #[inline]
    fn frame_bit(&mut self, b: bool) {
        self.crc = crc15_step(self.crc, b);
        self.pos += 1;
    }

    #[inline]
    pub(super) fn next_field(&mut self, f: u8) {
        self.field = f;
        self.cnt = 0;
    }

    /// ACK slot: the transmitter needs a dominant bit (else ACK error; not in
    /// SELF_TEST and LOOPBACK, §7); a receiver that sent its ACK must read it back
    /// (else bit error, ISO 16845-1 7.2.1) and then counts a successful reception
    /// (rule h, decision 8).
    pub(super) fn ack_slot(&mut self, b: bool) {
        if self.transmitter {
            if b && !self.ack_optional {
                return self.error(ErrorKind::Ack);
            }
        } else if !self.tx {
            if b {
                return self.error(ErrorKind::Bit);
            }
            self.counters.rx_success();
        }
        self.next_field(field::ACK_DELIM);
    }

    /// ACK delimiter: must be recessive; a receiver's CRC error is signalled from
    /// the next bit on, unless a form error here already starts the flag.
    pub(super) fn ack_delim(&mut self, b: bool) {
        if !b {
            let kind = if self.transmitter {
                ErrorKind::Bit
            } else {
                ErrorKind::Form
            };
            return self.error(kind);
        }
        if !self.transmitter && !self.crc_ok {
            return self.error(ErrorKind::Crc);
        }
        self.next_field(field::EOF);
    }

    /// End of frame: 7 recessive bits. A receiver takes the frame at bit 6 and
    /// answers a dominant bit 7 with an overload frame; the transmitter's frame is
    /// valid at the end of bit 7 (ISO 16845-1 7.1.12, 8.1.5).
    pub(super) fn eof(&mut self, b: bool) {
        if self.transmitter {
            if !b {
                return self.error(ErrorKind::Bit);
            }
            self.cnt += 1;
            if self.cnt == 6 && self.loopback {
                // LOOPBACK: the node delivers its own frame too (§7).
                self.rx_valid = true;
                self.rx_frame = self.received_frame();
            } else if self.cnt == 7 {
                self.tx_done = true;
                self.tx_pending = false;
                self.attempt_done();
                self.counters.tx_success();
                self.next_field(field::INTERMISSION);
            }
            return;
        }
        if !b {
            if self.cnt == 6 {
                return self.start_overload();
            }
            return self.error(ErrorKind::Form);
        }
        self.cnt += 1;
        if self.cnt == 6 {
            self.rx_valid = true;
            self.rx_frame = self.received_frame();
        } else if self.cnt == 7 {
            self.next_field(field::INTERMISSION);
        }
    }

    /// The frame as received: identifier in the low bits, data bytes left-aligned,
    /// bytes past min(DLC, 8) and all bytes of a remote frame zero, DLC as received.
    fn received_frame(&self) -> Frame {
        let n = self.data_bits as u32;
        let word = if n == 0 { 0 } else { self.data << (64 - n) };
        Frame {
            id: self.id,
            ide: self.ide,
            rtr: self.rtr,
            dlc: self.dlc,
            data: word.to_be_bytes(),
        }
    }
}
