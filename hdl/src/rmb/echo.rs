//! The receive side of a replicated star node (DRCC contract §4.4, §4.5,
//! `CTRL.star`): the echo, and the hubs' identification frames
//! (`super::star::StarFollow`, instantiated here). The echo: on a
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
//!
//! The RX writer gets `rxv_x = rx_valid_x && !echo_x && !hubf_x`: neither the
//! node's own frame nor a hub's identification frame is a reception (§4.4, §4.5).
//! `clear` is the main FSM's hold (`rst`, reset mode, normal mode): it empties
//! `STAR_STATUS`, and `run = !clear`.

use super::star::StarFollow;
use rust_hdl::prelude::*;

/// Echo detection and identification frames of a replicated star node (contract
/// §4.4, §4.5).
#[derive(LogicBlock, Default)]
pub struct Echo {
    /// Clock (`STAR_STATUS`).
    pub clk: Signal<In, Clock>,
    // ---- configuration and the main FSM ----
    /// `CTRL.star`: replicated star node.
    pub star: Signal<In, Bit>,
    /// `rst`, reset mode or normal mode (the main FSM is held): the echo is off
    /// and `STAR_STATUS` is held at 0.
    pub clear: Signal<In, Bit>,
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
    // ---- to the RX writer and the registers ----
    /// Channel A's reception for the RX writer: neither an echo nor a hub's frame.
    pub rxv_a: Signal<Out, Bit>,
    /// Channel B's reception for the RX writer.
    pub rxv_b: Signal<Out, Bit>,
    /// `STAR_STATUS.split` changes at this edge (`INT_STATUS.domain`).
    pub ev_domain: Signal<Out, Bit>,
    /// `STAR_STATUS`.
    pub star_word: Signal<Out, Bits<32>>,
    /// `STAR_STATUS.split` (§4.5): gates the `dual_tx` copy in star mode (§4.4).
    pub star_split: Signal<Out, Bit>,
    // ---- internals ----
    follow: StarFollow,
    armed: Signal<Local, Bit>,
}

impl Logic for Echo {
    #[hdl_gen]
    fn update(&mut self) {
        self.armed.next = self.star.val() & !self.clear.val() & self.attempted.val();
        self.echo_a.next =
            self.armed.val() & self.rx_valid_a.val() & (self.frame_a.val() == self.head.val());
        self.echo_b.next =
            self.armed.val() & self.rx_valid_b.val() & (self.frame_b.val() == self.head.val());
        // §4.5: the hubs' identification frames
        self.follow.clk.next = self.clk.val();
        self.follow.clear.next = self.clear.val();
        self.follow.on.next = self.star.val() & !self.clear.val();
        // {rtr, ide, id[10:0], dlc}: frame bits [98:97] and [78:64]
        self.follow.rx_valid_a.next = self.rx_valid_a.val();
        self.follow.key_a.next = (bit_cast::<17, 2>(self.frame_a.val().get_bits::<2>(97)) << 15)
            | bit_cast::<17, 15>(self.frame_a.val().get_bits::<15>(64));
        self.follow.rx_valid_b.next = self.rx_valid_b.val();
        self.follow.key_b.next = (bit_cast::<17, 2>(self.frame_b.val().get_bits::<2>(97)) << 15)
            | bit_cast::<17, 15>(self.frame_b.val().get_bits::<15>(64));
        self.rxv_a.next = self.rx_valid_a.val() & !self.echo_a.val() & !self.follow.hubf_a.val();
        self.rxv_b.next = self.rx_valid_b.val() & !self.echo_b.val() & !self.follow.hubf_b.val();
        self.ev_domain.next = self.follow.ev_domain.val();
        self.star_word.next = self.follow.word.val();
        self.star_split.next = self.follow.split_q.val();
    }
}
