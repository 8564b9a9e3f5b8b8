//! Tests of `drcc_hdl::rmb::echo`.

use drcc_hdl::rmb::echo::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// (echo_a, echo_b) for one input combination; channel A receives `fa`,
    /// channel B `fb` (both with `rx_valid` when `Some`).
    fn echo(
        star: bool,
        run: bool,
        attempted: bool,
        fa: Option<u64>,
        fb: Option<u64>,
    ) -> (bool, bool) {
        let head: Bits<99> = (bit_cast::<99, 29>(0x123.into()) << 68)
            | (bit_cast::<99, 4>(2.into()) << 64)
            | (bit_cast::<99, 64>(0xCDAB_u64.into()) << 48);
        let mut uut = Echo::default();
        uut.connect_all();
        uut.star.next = star;
        uut.clear.next = !run;
        uut.attempted.next = attempted;
        uut.head.next = head;
        uut.rx_valid_a.next = fa.is_some();
        uut.frame_a.next = head ^ bit_cast::<99, 64>(fa.unwrap_or(0).into());
        uut.rx_valid_b.next = fb.is_some();
        uut.frame_b.next = head ^ bit_cast::<99, 64>(fb.unwrap_or(0).into());
        assert!(simulate(&mut uut, 10));
        // an echo is not a reception
        assert_eq!(uut.rxv_a.val(), fa.is_some() && !uut.echo_a.val());
        assert_eq!(uut.rxv_b.val(), fb.is_some() && !uut.echo_b.val());
        (uut.echo_a.val(), uut.echo_b.val())
    }

    #[test]
    fn echo_synthesizes() {
        let mut uut = Echo::default();
        uut.connect_all();
        crate::synth_check::yosys_check("echo", &generate_verilog(&uut));
    }

    /// §4.4: the head message received on a channel while attempted, in a star
    /// node of a running redundancy mode; any differing bit is another frame.
    #[test]
    fn the_attempted_head_received_is_an_echo() {
        // frame_x = head ^ the given bits
        assert_eq!(echo(true, true, true, None, Some(0)), (false, true));
        assert_eq!(echo(true, true, true, Some(0), None), (true, false));
        assert_eq!(echo(true, true, true, Some(0), Some(0)), (true, true));
        assert_eq!(
            echo(true, true, true, Some(1), Some(1 << 63)),
            (false, false)
        );
        // not a star node, not running, not attempted, no rx_valid
        assert_eq!(echo(false, true, true, Some(0), Some(0)), (false, false));
        assert_eq!(echo(true, false, true, Some(0), Some(0)), (false, false));
        assert_eq!(echo(true, true, false, Some(0), Some(0)), (false, false));
        assert_eq!(echo(true, true, true, None, None), (false, false));
    }
}
