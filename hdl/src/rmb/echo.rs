//! The echo of a replicated star node (DRCC contract §4.4, `CTRL.star`): on a
//! replicated star the two hubs form one communication domain, so while one
//! channel transmits the node's frame the other receives it through the other
//! hub. A channel's reception of the head message of TX queue A, while that
//! message is attempted, is that echo: the message was exchanged on the network.
//! Combinational, on registered values:
//!
//! `echo_x = star && run && attempted && rx_valid_x && frame_x == head`
//!
//! with `run` = redundancy mode outside reset mode (the main FSM is not held),
//! `attempted` the main FSM's register (the head was handed to a channel and is
//! not finished), `frame_x` the channel's received frame and `head` the TX RAM
//! read data (the head message, stored normalized at its push, §6), compared on
//! all 99 bits (id, ide, rtr, dlc, data). The main FSM finishes the message at an
//! echo (its first row in every state) and the RX writer does not take the frame
//! (`rxp_x` is not set, §7).

use rust_hdl::prelude::*;

/// Echo detection of a replicated star node (contract §4.4).
#[derive(LogicBlock, Default)]
pub struct Echo {
    // ---- configuration and the main FSM ----
    /// `CTRL.star`: replicated star node.
    pub star: Signal<In, Bit>,
    /// Redundancy mode outside reset mode: the main FSM runs.
    pub run: Signal<In, Bit>,
    /// The main FSM's `attempted`: the head message was requested on a channel
    /// and is not finished.
    pub attempted: Signal<In, Bit>,
    // ---- the head message (TX RAM read data) ----
    /// The head of TX queue A: [98] rtr, [97] ide, [96:68] id, [67:64] dlc,
    /// [63:0] data (byte 0 in [63:56]).
    pub head: Signal<In, Bits<99>>,
    // ---- channel A reception ----
    /// Channel A `rx_valid`: a frame was received without error.
    pub rx_valid_a: Signal<In, Bit>,
    /// Channel A's received frame, laid out as `head`.
    pub frame_a: Signal<In, Bits<99>>,
    // ---- channel B reception ----
    /// Channel B `rx_valid`.
    pub rx_valid_b: Signal<In, Bit>,
    /// Channel B's received frame, laid out as `head`.
    pub frame_b: Signal<In, Bits<99>>,
    // ---- echoes ----
    /// Channel A received the attempted head message at this edge.
    pub echo_a: Signal<Out, Bit>,
    /// Channel B received the attempted head message at this edge.
    pub echo_b: Signal<Out, Bit>,
    // ---- internals ----
    armed: Signal<Local, Bit>,
}

impl Logic for Echo {
    #[hdl_gen]
    fn update(&mut self) {
        self.armed.next = self.star.val() & self.run.val() & self.attempted.val();
        self.echo_a.next =
            self.armed.val() & self.rx_valid_a.val() & (self.frame_a.val() == self.head.val());
        self.echo_b.next =
            self.armed.val() & self.rx_valid_b.val() & (self.frame_b.val() == self.head.val());
    }
}

#[cfg(test)]
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
        uut.run.next = run;
        uut.attempted.next = attempted;
        uut.head.next = head;
        uut.rx_valid_a.next = fa.is_some();
        uut.frame_a.next = head ^ bit_cast::<99, 64>(fa.unwrap_or(0).into());
        uut.rx_valid_b.next = fb.is_some();
        uut.frame_b.next = head ^ bit_cast::<99, 64>(fb.unwrap_or(0).into());
        assert!(simulate(&mut uut, 10));
        (uut.echo_a.val(), uut.echo_b.val())
    }

    #[test]
    fn echo_synthesizes() {
        let mut uut = Echo::default();
        uut.connect_all();
        yosys_validate("echo", &generate_verilog(&uut)).unwrap();
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
