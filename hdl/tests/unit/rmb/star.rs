//! Tests of `drcc_hdl::rmb::star`.

use drcc_hdl::host::registers::{StarLast, MAP};
use drcc_hdl::rmb::star::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;
    use drcc_hdl::host::registers as map;

    /// The key of a received frame: `{rtr, ide, id[10:0], dlc}`.
    fn frame(id: u64, dlc: u64, ide: bool, rtr: bool) -> Bits<17> {
        ((rtr as u64) << 16 | (ide as u64) << 15 | (id & 0x7FF) << 4 | dlc).into()
    }

    struct Bench {
        u: StarFollow,
        domains: usize,
    }

    impl Bench {
        fn new() -> Self {
            let mut u = StarFollow::default();
            u.connect_all();
            u.on.next = true;
            let mut b = Bench { u, domains: 0 };
            b.u.clear.next = true;
            b.clock(None, None);
            b.u.clear.next = false;
            b
        }

        /// One edge with these receptions; returns (hubf_a, hubf_b) of the edge.
        fn clock(&mut self, a: Option<Bits<17>>, b: Option<Bits<17>>) -> (bool, bool) {
            let u = &mut self.u;
            u.rx_valid_a.next = a.is_some();
            u.key_a.next = a.unwrap_or_else(|| frame(0x7FF, 8, false, false));
            u.rx_valid_b.next = b.is_some();
            u.key_b.next = b.unwrap_or_else(|| frame(0x7FF, 8, false, false));
            u.clk.next = Clock::from(false);
            assert!(simulate(u, 20));
            let seen = (u.hubf_a.val(), u.hubf_b.val());
            self.domains += u.ev_domain.val() as usize;
            u.clk.next = Clock::from(true);
            assert!(simulate(u, 20));
            u.rx_valid_a.next = false;
            u.rx_valid_b.next = false;
            seen
        }

        fn status(&self) -> u32 {
            self.u.word.val().to_u64() as u32
        }
    }

    fn field(word: u32, name: &str) -> u32 {
        MAP.field("STAR_STATUS", name).get(word)
    }

    #[test]
    fn star_follow_synthesizes() {
        let mut uut = StarFollow::default();
        uut.connect_all();
        crate::synth_check::yosys_check("star_follow", &generate_verilog(&uut));
    }

    /// Only base data frames 0x000 / 0x001 with DLC 0 are the hubs' frames.
    #[test]
    fn identification_frames_are_recognised() {
        let mut b = Bench::new();
        assert_eq!(
            b.clock(Some(frame(0, 0, false, false)), None),
            (true, false)
        );
        assert_eq!(
            b.clock(None, Some(frame(1, 0, false, false))),
            (false, true)
        );
        for f in [
            frame(2, 0, false, false),
            frame(0x400, 0, false, false),
            frame(1, 1, false, false),
            frame(0, 0, false, true),
            frame(0, 0, true, false),
        ] {
            assert_eq!(b.clock(Some(f), Some(f)), (false, false));
        }
        // not running: nothing is taken
        b.u.on.next = false;
        let f = frame(0, 0, false, false);
        assert_eq!(b.clock(Some(f), Some(f)), (false, false));
        assert_eq!(field(b.status(), "hub_frames_a"), 1);
        assert_eq!(field(b.status(), "hub_frames_b"), 1);
    }

    /// §4.5: alternating frames are one domain; two of a channel's own hub's
    /// frames in a row split; the other hub's frame on a channel joins again;
    /// channel A's verdict wins at one edge; `clear` empties the register.
    #[test]
    fn the_domain_follows_the_hubs_frames() {
        let (fa, fb) = (frame(0, 0, false, false), frame(1, 0, false, false));
        let mut b = Bench::new();
        // recoupling: both hubs' frames alternate on both stars
        for _ in 0..2 {
            b.clock(Some(fa), Some(fa));
            b.clock(Some(fb), Some(fb));
        }
        let s = b.status();
        assert_eq!(field(s, "split"), 0);
        assert_eq!(field(s, "last_a"), StarLast::HubB.code());
        assert_eq!(field(s, "last_b"), StarLast::HubB.code());
        assert_eq!((field(s, "hub_frames_a"), field(s, "hub_frames_b")), (4, 4));
        assert_eq!(b.domains, 0);
        // definitive decoupling: each hub sends its own frame to its own star;
        // the first of hub A's after hub B's changes nothing on A
        b.clock(Some(fa), None);
        assert_eq!(field(b.status(), "split"), 0);
        b.clock(Some(fa), None);
        assert_eq!(field(b.status(), "split"), 1);
        assert_eq!(b.domains, 1);
        b.clock(None, Some(fb));
        assert_eq!(field(b.status(), "split"), 1);
        // hub A's frame on channel B: one domain again
        b.clock(None, Some(fa));
        assert_eq!(field(b.status(), "split"), 0);
        assert_eq!(b.domains, 2);
        // at one edge A says split (a second own frame: last_a is hub A's), B
        // says one domain (hub A's frame): A wins
        b.clock(Some(fa), Some(fa));
        assert_eq!(field(b.status(), "split"), 1);
        assert_eq!(field(b.status(), "last_b"), StarLast::HubA.code());
        // clear (reset mode) empties it, without an event
        b.u.clear.next = true;
        b.clock(None, None);
        b.u.clear.next = false;
        assert_eq!(b.status(), 0);
        assert_eq!(b.domains, 3);
        assert_eq!(map::STAR_STATUS, 36);
    }
}
