//! Tests of `drcc_hdl::channel::bsp::tx_request`.

use drcc_hdl::channel::bsp::tx_request::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn clock(uut: &mut TxRequest) {
        assert!(simulate(uut, 100), "settles");
        uut.clk.next = Clock { clk: true };
        simulate(uut, 100);
        uut.clk.next = Clock { clk: false };
        simulate(uut, 100);
    }

    /// Idle node, reset, nothing pending, `tx` recessive.
    fn idle() -> TxRequest {
        let mut uut = TxRequest::default();
        uut.connect_all();
        uut.tx_pin.next = true;
        uut.rst.next = true;
        clock(&mut uut);
        uut.rst.next = false;
        clock(&mut uut);
        uut
    }

    /// A one-clock `tx_req`: returns whether it loaded the frame.
    fn request(uut: &mut TxRequest) -> bool {
        uut.tx_req.next = true;
        assert!(simulate(uut, 100));
        let load = uut.tx_load.val();
        clock(uut);
        uut.tx_req.next = false;
        assert!(simulate(uut, 100));
        load
    }

    /// One sample point with the strobes `f` sets, then all strobes off.
    fn at_sample(uut: &mut TxRequest, f: impl Fn(&mut TxRequest)) {
        uut.sample.next = true;
        f(uut);
        clock(uut);
        uut.sample.next = false;
        uut.sof.next = false;
        uut.sof_as_tx.next = false;
        uut.sent.next = false;
        uut.lost.next = false;
        uut.error.next = false;
        assert!(simulate(uut, 100));
    }

    /// Contract §7: listen-only refuses a request with `tx_failed`, nothing pends.
    #[test]
    fn listen_only_refuses_the_request() {
        let mut uut = idle();
        uut.listen_only.next = true;
        assert!(!request(&mut uut));
        assert!(uut.tx_failed.val() && !uut.tx_pending.val());
        clock(&mut uut);
        assert!(!uut.tx_failed.val(), "one clock");
    }

    /// Contract §8: lost arbitration and errors keep the frame pending (automatic
    /// retransmission); it is done once valid for the transmitter (10.7).
    #[test]
    fn retransmits_until_sent() {
        let mut uut = idle();
        assert!(request(&mut uut));
        assert!(uut.tx_pending.val() && uut.starts.val() && uut.joins.val());
        at_sample(&mut uut, |u| {
            u.sof.next = true;
            u.sof_as_tx.next = true;
        });
        uut.is_tx.next = true;
        at_sample(&mut uut, |u| u.lost.next = true);
        assert!(uut.arb_lost.val() && uut.tx_pending.val() && !uut.tx_failed.val());
        at_sample(&mut uut, |u| {
            u.sof.next = true;
            u.sof_as_tx.next = true;
        });
        at_sample(&mut uut, |u| u.error.next = true);
        assert!(uut.tx_pending.val() && !uut.tx_failed.val());
        assert!(!request(&mut uut), "one frame at a time");
        at_sample(&mut uut, |u| u.sent.next = true);
        assert!(uut.tx_done.val() && !uut.tx_pending.val());
        // 10.4.5: an error-passive transmitter does not join at intermission bit 3.
        assert!(request(&mut uut));
        uut.suspend_due.next = true;
        assert!(simulate(&mut uut, 100));
        assert!(uut.starts.val() && !uut.joins.val());
        // Bus-off: nothing starts.
        uut.bus_off.next = true;
        assert!(simulate(&mut uut, 100));
        assert!(!uut.starts.val());
    }

    /// Contract §8: single shot drops the frame at the attempt's first error.
    #[test]
    fn single_shot_drops_a_failed_attempt() {
        let mut uut = idle();
        uut.single_shot.next = true;
        assert!(request(&mut uut));
        at_sample(&mut uut, |u| {
            u.sof.next = true;
            u.sof_as_tx.next = true;
        });
        uut.is_tx.next = true;
        at_sample(&mut uut, |u| u.error.next = true);
        assert!(uut.tx_failed.val() && !uut.tx_pending.val());
    }

    /// Contract §8: an abort waits while the frame is on the bus, blocks a new
    /// start, and is carried out once the node is no longer transmitter.
    #[test]
    fn abort_waits_for_the_frame_to_leave_the_bus() {
        let mut uut = idle();
        assert!(request(&mut uut));
        uut.is_tx.next = true;
        uut.tx_abort.next = true;
        clock(&mut uut);
        uut.tx_abort.next = false;
        clock(&mut uut);
        assert!(uut.tx_pending.val() && !uut.tx_failed.val() && !uut.starts.val());
        uut.is_tx.next = false;
        clock(&mut uut);
        assert!(uut.tx_failed.val() && !uut.tx_pending.val());
    }

    #[test]
    fn tx_request_synthesizes() {
        let mut uut = TxRequest::default();
        uut.connect_all();
        crate::synth_check::yosys_check("tx_request", &generate_verilog(&uut));
    }
}
