//! Tests of `drcc_hdl::hub::ack_unit`.

use drcc_hdl::hub::ack_unit::*;
use rust_hdl::prelude::*;

#[test]
fn ack_unit_synthesizes() {
    let mut uut = AckUnit::<4, 2, 6>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_ack_unit", &generate_verilog(&uut));
}

mod tests {
    use super::*;

    type Uut = AckUnit<4, 2, 6>;

    /// Clocks per bit: BRP 0, TSEG1 5, TSEG2 2 (the hub's `BTR` reset value).
    const BIT: usize = 8;

    /// The test bench: the unit and a correct or leaking coupler's `dl_next`
    /// (the AND of the pins two edges late, as the coupler's synchronizers).
    struct Bench {
        u: Box<Uut>,
        /// Pins one and two edges ago (node ports, sublinks).
        hist: [(u64, u64); 2],
        /// Leak the own nodes' ACK inside the window (`CTRL.fi_ack_leak`).
        leak: bool,
        /// Clocks where the unit made a dominant `dl_next` recessive.
        forced: usize,
        events: usize,
        window_seen: bool,
    }

    impl Bench {
        fn new() -> Self {
            let mut u = Box::<Uut>::default();
            u.connect_all();
            u.cfg_brp_next.next = 0.into();
            u.cfg_tseg1_len.next = 5.into();
            u.cfg_tseg2_len.next = 2.into();
            u.cfg_sjw_len.next = 1.into();
            u.ack_interdep.next = true;
            // the NRAP transmitter idle (recessive), not forcing
            u.own_gate.next = true;
            u.enabled.next = 0x3F.into();
            u.uplink.next = 0xF.into();
            u.sublink_in.next = 0x3.into();
            let mut b = Bench {
                u,
                hist: [(0xF, 0x3); 2],
                leak: false,
                forced: 0,
                events: 0,
                window_seen: false,
            };
            b.u.rst.next = true;
            b.u.trk_rst.next = true;
            b.u.btl_rst.next = true;
            b.clock(0xF, 0x3);
            b.u.rst.next = false;
            b.u.trk_rst.next = false;
            b.u.btl_rst.next = false;
            b
        }

        /// One clock with these pins; checks the downlink rule against `dl_next`.
        fn clock(&mut self, up: u64, sub: u64) {
            let (own_d, sub_d) = self.hist[1];
            let own = own_d == 0xF;
            let twin = sub_d == 0x3;
            let window = self.u.u_window.val();
            // the coupler: only the twin inside the window, unless it leaks
            let dl_next = if window && !self.leak {
                twin
            } else {
                own && twin
            };
            self.u.uplink.next = up.into();
            self.u.sublink_in.next = sub.into();
            self.u.dl_next.next = dl_next;
            self.u.clk.next = Clock::from(false);
            assert!(simulate(&mut *self.u, 100));
            if self.u.ev_block.val() {
                self.events += 1;
            }
            self.window_seen |= window;
            self.u.clk.next = Clock::from(true);
            assert!(simulate(&mut *self.u, 100));
            let down = self.u.downlink.val().to_u64();
            assert!(
                down == 0 || down == 0xF,
                "every downlink bit carries one value"
            );
            if down == 0xF && !dl_next {
                assert!(
                    window && twin,
                    "the unit forces recessive only in its window"
                );
                self.forced += 1;
            } else {
                assert_eq!(down == 0xF, dl_next, "outside an intervention: dl_next");
            }
            self.hist = [(up, sub), self.hist[0]];
        }

        /// One bit: `up` on the node ports, `sub` on the sublinks, BIT clocks.
        fn bit(&mut self, up: u64, sub: u64) {
            for _ in 0..BIT {
                self.clock(up, sub);
            }
        }

        /// A frame from node 0 whose ACK slot carries `ack_up` / `ack_sub`.
        fn frame(&mut self, ack_up: u64, ack_sub: u64) {
            for _ in 0..12 {
                self.bit(0xF, 0x3);
            }
            for b in frame_bits() {
                self.bit(if b { 0xF } else { 0xE }, 0x3);
            }
            self.bit(0xF, 0x3); // CRC delimiter
            self.bit(ack_up, ack_sub); // ACK slot
            for _ in 0..8 {
                self.bit(0xF, 0x3); // ACK delimiter, EOF
            }
        }
    }

    /// Stuffed bits of a base data frame from SOF to the end of the CRC
    /// (identifier 0x123, DLC 1, data 0xA5, CRC field all recessive: the tracker
    /// does not check the CRC).
    fn frame_bits() -> Vec<bool> {
        let mut raw = vec![false];
        raw.extend((0..11).rev().map(|k| (0x123u16 >> k) & 1 == 1));
        raw.extend([false, false, false, false, false, false, true]);
        raw.extend((0..8).rev().map(|k| (0xA5u8 >> k) & 1 == 1));
        raw.extend([true; 15]);
        let mut out = Vec::new();
        let (mut last, mut run) = (true, 0);
        for b in raw {
            if run == 5 {
                out.push(!last);
                last = !last;
                run = 1;
            }
            if b == last {
                run += 1;
            } else {
                last = b;
                run = 1;
            }
            out.push(b);
        }
        if run == 5 {
            out.push(!last);
        }
        out
    }

    #[test]
    fn a_correct_coupler_is_never_touched() {
        let mut b = Bench::new();
        b.frame(0xD, 0x3); // own node 1 acknowledges
        b.frame(0xF, 0x2); // the twin acknowledges on interlink 0
        assert!(b.window_seen, "the unit's tracker found the ACK windows");
        assert_eq!((b.forced, b.events), (0, 0));
        assert_eq!(b.u.blocks.val().to_u64(), 0);
    }

    #[test]
    fn a_leaking_coupler_is_blocked_once_per_window() {
        let mut b = Bench::new();
        b.leak = true;
        b.frame(0xD, 0x3); // own ACK only: blocked
        assert!(b.forced > 0, "the own ACK did not reach the downlink");
        assert_eq!(b.events, 1);
        assert_eq!(b.u.blocks.val().to_u64(), 1);
        b.frame(0xF, 0x2); // the twin's ACK passes
        assert_eq!(b.events, 1);
        b.frame(0xD, 0x3);
        assert_eq!(b.events, 2);
        assert_eq!(b.u.blocks.val().to_u64(), 2);
        // decoupled: the hub is a star of its own, the unit does not judge
        b.u.decoupled.next = true;
        let forced = b.forced;
        b.frame(0xD, 0x3);
        assert_eq!((b.forced, b.events), (forced, 2));
    }
}
