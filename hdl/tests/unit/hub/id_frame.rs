//! Tests of `drcc_hdl::hub::id_frame`.

use drcc_hdl::hub::id_frame::*;
use rust_hdl::prelude::*;

#[test]
fn id_frame_synthesizes() {
    let mut uut = IdFrame::<0>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_id_frame", &generate_verilog(&uut));
}

mod tests {
    use super::*;

    fn text(bits: &[bool]) -> String {
        bits.iter().map(|&b| if b { '1' } else { '0' }).collect()
    }

    /// Contract §9.1 and §9.5: hub A's frame is 41 bits (its CRC is 0), hub B's 38.
    #[test]
    fn the_roms_are_the_stuffed_identification_frames() {
        let a = id_frame(0x000);
        assert_eq!(a.len(), 41);
        assert_eq!(text(&a), "00000100000100000100000100000100000100001");
        let b = id_frame(0x001);
        assert_eq!(b.len(), 38);
        assert_eq!(text(&b), "00000100000101000001000100010000100111");
        let (word, len) = id_rom(0x001);
        assert_eq!(len, 38);
        for (k, &bit) in b.iter().enumerate() {
            assert_eq!((word >> k) & 1 == 1, bit, "bit {k}");
        }
        assert_eq!(word >> len, 0);
    }

    /// The stuffing and CRC of the builder, against a frame worked by hand: base
    /// identifier 0x7FF has 11 recessive bits, so it is stuffed after the fifth
    /// and the tenth.
    #[test]
    fn stuffing_counts_the_stuff_bit_in_the_next_run() {
        let f = id_frame(0x7FF);
        assert_eq!(text(&f[..15]), "011111011111010");
        assert!(*f.last().unwrap(), "ends with the recessive CRC delimiter");
    }

    type Uut = IdFrame<1>;

    fn clock(u: &mut Uut) {
        u.clk.next = Clock::from(false);
        assert!(simulate(u, 100));
        u.clk.next = Clock::from(true);
        assert!(simulate(u, 100));
        u.bit_start.next = false;
        u.sample.next = false;
        u.ev_sof.next = false;
        u.ev_frame.next = false;
    }

    /// One bit on an ideal bus: a bit start (the transmitter drives), then a SAMPLE
    /// edge with `bus` AND the transmitter's bit, as the tracker would report it.
    fn bit(u: &mut Uut, bus: bool, sof: bool, frame: bool) -> bool {
        u.bit_start.next = true;
        clock(u);
        let driven = u.tx.val();
        u.sample.next = true;
        u.b.next = bus & driven;
        u.ev_sof.next = sof;
        u.ev_frame.next = frame;
        clock(u);
        driven
    }

    /// Hub B sends its frame from the ROM when nobody else sends, recognises it as
    /// its own and sends nothing after the CRC delimiter; then it recognises hub
    /// A's frame, loses arbitration to it and acknowledges it in its ACK slot.
    #[test]
    fn sends_its_own_frame_and_acknowledges_the_twins() {
        let mut u = Box::<Uut>::default();
        u.connect_all();
        u.rst.next = true;
        clock(&mut u);
        u.rst.next = false;
        u.hush.next = false;
        u.ack_en.next = true;
        // 11 recessive bits, then the own frame: SOF and the ROM
        for _ in 0..11 {
            assert!(bit(&mut u, true, false, false));
        }
        u.send.next = true;
        let own = id_frame(1);
        let mut sent = Vec::new();
        sent.push(bit(&mut u, true, true, false));
        for _ in 1..own.len() {
            sent.push(bit(&mut u, true, false, true));
        }
        assert_eq!(sent, own);
        assert!(u.own_frame.val() && !u.twin_frame.val());
        u.send.next = false;
        assert!(bit(&mut u, false, false, false), "ACK slot: listening");
        // ACK delimiter, EOF, intermission: the SOF waits for 11 recessive bits
        u.send.next = true;
        for _ in 0..11 {
            assert!(bit(&mut u, true, false, false));
        }
        // the twin's frame (hub A's) while B tries to send: B loses at the
        // identifier's LSB (bus bit 13, after the stuff bit at 11)
        let twin = id_frame(0);
        let mut drove = Vec::new();
        drove.push(bit(&mut u, twin[0], true, false));
        for &t in &twin[1..] {
            drove.push(bit(&mut u, t, false, true));
        }
        let lost = own.iter().zip(&twin).position(|(o, t)| o != t).unwrap();
        assert_eq!(lost, 13);
        assert_eq!(&drove[..=lost], &own[..=lost], "sends until it loses");
        assert!(
            drove[lost..].iter().all(|&d| d),
            "then listens: {}",
            text(&drove)
        );
        assert!(u.twin_frame.val() && !u.own_frame.val());
        u.send.next = false;
        assert!(!bit(&mut u, true, false, false), "ACK of the twin's frame");
        assert!(bit(&mut u, true, false, false), "recessive again after it");
        // hush: nothing is sent
        for _ in 0..11 {
            bit(&mut u, true, false, false);
        }
        u.hush.next = true;
        u.send.next = true;
        assert!(bit(&mut u, true, false, false));
    }
}
