//! Tests of `drcc_hdl::hub::tracker`.

use drcc_hdl::hub::tracker::*;
use rust_hdl::prelude::*;

#[test]
fn tracker_synthesizes() {
    let mut uut = FrameTracker::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_tracker", &generate_verilog(&uut));
}

mod tests {
    use super::*;

    fn clock(u: &mut FrameTracker) {
        u.clk.next = Clock::from(false);
        assert!(simulate(u, 100));
        u.clk.next = Clock::from(true);
        assert!(simulate(u, 100));
    }

    /// One SAMPLE edge with bus value `b` (and one idle clock after it).
    fn bit(u: &mut FrameTracker, b: bool) {
        u.sample.next = true;
        u.b.next = b;
        clock(u);
        u.sample.next = false;
        clock(u);
    }

    /// Stuffed bits of a base data frame from SOF to the end of the CRC
    /// (identifier `id`, DLC 1, data 0xA5, CRC field all recessive: the tracker
    /// does not check the CRC).
    fn frame(id: u16) -> Vec<bool> {
        let mut raw = vec![false];
        raw.extend((0..11).rev().map(|k| (id >> k) & 1 == 1));
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
    fn follows_a_frame_to_its_ack_slot_and_counts_it() {
        let mut u = Box::<FrameTracker>::default();
        u.connect_all();
        u.rst.next = true;
        clock(&mut u);
        u.rst.next = false;
        // a dominant bit before 10 recessive ones is no start of frame
        for _ in 0..9 {
            bit(&mut u, true);
        }
        bit(&mut u, false);
        assert_eq!(u.trk.val().to_u64(), IDLE_WAIT);
        for _ in 0..10 {
            bit(&mut u, true);
        }
        let bits = frame(0x123);
        for (k, &b) in bits.iter().enumerate() {
            bit(&mut u, b);
            assert_eq!(u.trk.val().to_u64(), FRAME, "bit {k}");
        }
        bit(&mut u, true); // CRC delimiter
        assert_eq!(u.trk.val().to_u64(), ACK_SLOT);
        bit(&mut u, false); // ACK slot
        assert_eq!(u.trk.val().to_u64(), ACK_DELIM);
        bit(&mut u, true); // ACK delimiter
        assert_eq!(u.trk.val().to_u64(), IDLE_WAIT);
        assert_eq!(u.frames.val().to_u64(), 1);
        assert_eq!(u.errors.val().to_u64(), 0);
        // six equal bits inside a frame: stuff error
        for _ in 0..10 {
            bit(&mut u, true);
        }
        for _ in 0..6 {
            bit(&mut u, false);
        }
        assert_eq!(u.trk.val().to_u64(), IDLE_WAIT);
        assert_eq!(u.errors.val().to_u64(), 1);
    }
}
