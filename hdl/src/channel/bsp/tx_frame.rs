//! The transmit frame (ISO 11898-1:2015, 10.4.2): the frame the host asked to
//! send, latched once, and the bit of it that belongs to a field position.
//!
//! The latched frame stays unchanged while the frame is pending (automatic
//! retransmission after lost arbitration or an error, 10.4.2.1 / 12.1.4). The
//! serialiser is a multiplexer, not a shift register: the protocol controller's
//! bit counter indexes the latched fields directly, so a retransmission needs no
//! reload. Stuff bits, flags and the ACK slot are chosen by the protocol
//! controller; this block gives the frame's own bit only.

use super::field::Field;
use rust_hdl::prelude::*;

/// The latched transmit frame and its bit selector.
#[derive(LogicBlock, Default)]
pub struct TxFrame {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Latch the host's frame (one clock; only while nothing is pending).
    pub load: Signal<In, Bit>,
    /// Identifier (base frame: ID[10:0]; extended: ID[28:0]).
    pub id: Signal<In, Bits<29>>,
    /// Extended frame (IDE recessive).
    pub ide: Signal<In, Bit>,
    /// Remote frame (RTR recessive).
    pub rtr: Signal<In, Bit>,
    /// Data length code.
    pub dlc: Signal<In, Bits<4>>,
    /// Data bytes, byte 0 in bits 63..56.
    pub data: Signal<In, Bits<64>>,
    /// The field the next bit belongs to.
    pub field: Signal<In, Field>,
    /// Position of the next bit in its field.
    pub bit_cnt: Signal<In, Bits<6>>,
    /// The CRC register (the CRC sequence to send once the CRC field starts).
    pub crc: Signal<In, Bits<15>>,
    /// The latched frame's bit at `field`/`bit_cnt` (recessive outside the
    /// fields of a frame).
    pub frame_bit: Signal<Out, Bit>,
    /// The latched frame is extended (its IDE bit is part of arbitration).
    pub frame_ide: Signal<Out, Bit>,
    // The identifier, aligned so the bit counter indexes it without an adder:
    // ID_A (ID[28:18] extended, ID[10:0] base) in bits 15..5 (bit 15 - n is ID_A
    // bit n), ID[17:0] in bits 31..14 (bit 31 - n is ID_B bit n).
    ida: DFF<Bits<16>>,
    idb: DFF<Bits<32>>,
    ide_q: DFF<Bit>,
    rtr_q: DFF<Bit>,
    dlc_q: DFF<Bits<4>>,
    data_q: DFF<Bits<64>>,
    // 15 - n, 31 - n, 3 - n, 63 - n: the complement of the bit counter.
    id_a_idx: Signal<Local, Bits<4>>,
    id_b_idx: Signal<Local, Bits<5>>,
    dlc_idx: Signal<Local, Bits<2>>,
    data_idx: Signal<Local, Bits<6>>,
    // CRC aligned one bit up: bit 15 - n is CRC bit 14 - n
    crc_idx: Signal<Local, Bits<4>>,
    crc_tx: Signal<Local, Bits<16>>,
}

impl Logic for TxFrame {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ida, idb, ide_q, rtr_q, dlc_q, data_q);
        if self.load.val() {
            if self.ide.val() {
                self.ida.d.next = bit_cast::<16, 11>(self.id.val().get_bits::<11>(18)) << 5;
            } else {
                self.ida.d.next = bit_cast::<16, 11>(self.id.val().get_bits::<11>(0)) << 5;
            }
            self.idb.d.next = bit_cast::<32, 18>(self.id.val().get_bits::<18>(0)) << 14;
            self.ide_q.d.next = self.ide.val();
            self.rtr_q.d.next = self.rtr.val();
            self.dlc_q.d.next = self.dlc.val();
            self.data_q.d.next = self.data.val();
        }
        self.frame_ide.next = self.ide_q.q.val();
        self.id_a_idx.next = !self.bit_cnt.val().get_bits::<4>(0);
        self.id_b_idx.next = !self.bit_cnt.val().get_bits::<5>(0);
        self.dlc_idx.next = !self.bit_cnt.val().get_bits::<2>(0);
        self.data_idx.next = !self.bit_cnt.val();
        self.crc_idx.next = !self.bit_cnt.val().get_bits::<4>(0);
        self.crc_tx.next = bit_cast::<16, 15>(self.crc.val()) << 1;
        self.frame_bit.next = true;
        match self.field.val() {
            Field::IdA => {
                self.frame_bit.next = self.ida.q.val().get_bit(self.id_a_idx.val().index());
            }
            Field::SrrRtr => {
                // SRR (recessive) in an extended frame, RTR in a base frame.
                self.frame_bit.next = self.ide_q.q.val() || self.rtr_q.q.val();
            }
            Field::Ide => {
                self.frame_bit.next = self.ide_q.q.val();
            }
            Field::IdB => {
                self.frame_bit.next = self.idb.q.val().get_bit(self.id_b_idx.val().index());
            }
            Field::RtrExt => {
                self.frame_bit.next = self.rtr_q.q.val();
            }
            Field::R1 => {
                self.frame_bit.next = false;
            }
            Field::R0 => {
                self.frame_bit.next = false;
            }
            Field::Dlc => {
                self.frame_bit.next = self.dlc_q.q.val().get_bit(self.dlc_idx.val().index());
            }
            Field::Data => {
                self.frame_bit.next = self.data_q.q.val().get_bit(self.data_idx.val().index());
            }
            Field::Crc => {
                self.frame_bit.next = self.crc_tx.val().get_bit(self.crc_idx.val().index());
            }
            _ => {}
        }
    }
}
