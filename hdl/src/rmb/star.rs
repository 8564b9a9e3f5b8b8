//! Following the hubs' decision in a replicated star node (DRCC contract §4.5,
//! `CTRL.star`; ReCANcentrate seed §5). The hubs say with their identification
//! frames (base data frames, DLC 0, identifier 0x000 = hub A = the hub of channel
//! A, 0x001 = hub B = channel B) whether they form one domain or have split for
//! good. Per channel x, combinational on registered values:
//!
//! `hubf_x = on && rx_valid_x && rtr_x == 0 && ide_x == 0 && dlc_x == 0 && id_x[10:1] == 0`
//!
//! with `on` = `CTRL.star` in redundancy mode outside reset mode, and `h_x =
//! id_x[0]` the hub whose frame it is. A base frame's `id[28:11]` read 0 (§C.5),
//! so the block sees only `key_x = {rtr, ide, id[10:0], dlc}` of the received
//! frame, and the compare is its 16 bits other than `id[0]`. The RX path takes an edge with `hubf_x` as one without
//! `rx_valid_x` (as an echo, §4.4; `super::echo` hands the RX writer the
//! remaining receptions). At each `hubf_x`: `last_x <= h_x + 1`, `hub_frames_x`
//! += 1 (8 bits, saturating), and `split` gets channel x's verdict: 0 if the frame
//! is the other hub's (hub B's on A, hub A's on B), else 1 if `last_x` already was
//! the own hub's; channel A's verdict wins over B's at the same edge. `ev_domain`
//! (`INT_STATUS.domain`) is set at every change of `split`.
//!
//! `clear` (`rst`, reset mode, or normal mode: the main FSM's hold) holds every
//! field at 0 and suppresses the event: entering reset mode clears them all
//! (§4.5), and in normal mode nothing sets them (`CTRL.redundancy` changes only
//! in reset mode). `word` is `STAR_STATUS` with the fields at their table
//! positions (`crate::host::registers`).

use crate::host::map::lsb;
use crate::host::registers::{StarLast, MAP};
use rust_hdl::prelude::*;

/// The identification frames of the hubs and the domain they tell (§4.5).
#[derive(LogicBlock)]
pub struct StarFollow {
    // ---- clock and hold ----
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// Holds every field at 0 (`rst`, reset mode, normal mode).
    pub clear: Signal<In, Bit>,
    /// `CTRL.star` in redundancy mode outside reset mode.
    pub on: Signal<In, Bit>,
    // ---- receptions (the channels' outputs, laid out as the TX RAM) ----
    /// Channel A `rx_valid`.
    pub rx_valid_a: Signal<In, Bit>,
    /// Channel A's received frame, `{rtr, ide, id[10:0], dlc}`: [16] rtr, [15]
    /// ide, [14:4] id[10:0], [3:0] dlc.
    pub key_a: Signal<In, Bits<17>>,
    /// Channel B `rx_valid`.
    pub rx_valid_b: Signal<In, Bit>,
    /// Channel B's received frame, laid out as `key_a`.
    pub key_b: Signal<In, Bits<17>>,
    // ---- out ----
    /// Channel A's reception at this edge is an identification frame (`hubf_a`).
    pub hubf_a: Signal<Out, Bit>,
    /// Channel B's reception at this edge is an identification frame (`hubf_b`).
    pub hubf_b: Signal<Out, Bit>,
    /// `split` changes at this edge (`INT_STATUS.domain`).
    pub ev_domain: Signal<Out, Bit>,
    /// `STAR_STATUS`.
    pub word: Signal<Out, Bits<32>>,
    /// `split` (the register): the hubs split, so a `dual_tx` copy goes out (§4.4).
    pub split_q: Signal<Out, Bit>,
    // ---- registers ----
    split: DFF<Bit>,
    last_a: DFF<Bits<2>>,
    last_b: DFF<Bits<2>>,
    frames_a: DFF<Bits<8>>,
    frames_b: DFF<Bits<8>>,
    // ---- combinational ----
    h_a: Signal<Local, Bit>,
    h_b: Signal<Local, Bit>,
    split_new: Signal<Local, Bit>,
    // ---- constants ----
    last_hub_a: Constant<Bits<2>>,
    last_hub_b: Constant<Bits<2>>,
    zero2: Constant<Bits<2>>,
    zero8: Constant<Bits<8>>,
    zero17: Constant<Bits<17>>,
    /// Every bit of a key but `id[0]`.
    not_hub: Constant<Bits<17>>,
    one8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    s_split: Constant<Bits<5>>,
    s_last_a: Constant<Bits<5>>,
    s_last_b: Constant<Bits<5>>,
    s_frames_a: Constant<Bits<5>>,
    s_frames_b: Constant<Bits<5>>,
}

impl Default for StarFollow {
    fn default() -> Self {
        // last_x = h + 1: hub A's frame 1, hub B's 2
        assert_eq!(StarLast::HubA.code(), 1);
        assert_eq!(StarLast::HubB.code(), 2);
        Self {
            clk: Default::default(),
            clear: Default::default(),
            on: Default::default(),
            rx_valid_a: Default::default(),
            key_a: Default::default(),
            rx_valid_b: Default::default(),
            key_b: Default::default(),
            hubf_a: Default::default(),
            hubf_b: Default::default(),
            ev_domain: Default::default(),
            word: Default::default(),
            split_q: Default::default(),
            split: Default::default(),
            last_a: Default::default(),
            last_b: Default::default(),
            frames_a: Default::default(),
            frames_b: Default::default(),
            h_a: Default::default(),
            h_b: Default::default(),
            split_new: Default::default(),
            last_hub_a: Constant::new((StarLast::HubA.code() as u64).into()),
            last_hub_b: Constant::new((StarLast::HubB.code() as u64).into()),
            zero2: Constant::new(0.into()),
            zero8: Constant::new(0.into()),
            zero17: Constant::new(0.into()),
            not_hub: Constant::new(0x1_FFEF.into()),
            one8: Constant::new(1.into()),
            max8: Constant::new(0xFF.into()),
            s_split: lsb(&MAP, "STAR_STATUS", "split", 1),
            s_last_a: lsb(&MAP, "STAR_STATUS", "last_a", 2),
            s_last_b: lsb(&MAP, "STAR_STATUS", "last_b", 2),
            s_frames_a: lsb(&MAP, "STAR_STATUS", "hub_frames_a", 8),
            s_frames_b: lsb(&MAP, "STAR_STATUS", "hub_frames_b", 8),
        }
    }
}

impl Logic for StarFollow {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, split, last_a, last_b, frames_a, frames_b);
        // an identification frame: base data frame, DLC 0, id[10:1] = 0
        self.hubf_a.next = self.on.val()
            & self.rx_valid_a.val()
            & ((self.key_a.val() & self.not_hub.val()) == self.zero17.val());
        self.hubf_b.next = self.on.val()
            & self.rx_valid_b.val()
            & ((self.key_b.val() & self.not_hub.val()) == self.zero17.val());
        // whose frame: id[0] (0 hub A, 1 hub B)
        self.h_a.next = self.key_a.val().get_bit(4);
        self.h_b.next = self.key_b.val().get_bit(4);

        // split: channel B's verdict, then channel A's (A wins at one edge); a
        // channel hangs on its own hub (A on hub A, B on hub B)
        self.split_new.next = self.split.q.val();
        if self.hubf_b.val() {
            if !self.h_b.val() {
                // hub A's frame on channel B: only one domain carries it here
                self.split_new.next = false;
            } else if self.last_b.q.val() == self.last_hub_b.val() {
                // two of hub B's frames in a row
                self.split_new.next = true;
            }
        }
        if self.hubf_a.val() {
            if self.h_a.val() {
                self.split_new.next = false;
            } else if self.last_a.q.val() == self.last_hub_a.val() {
                self.split_new.next = true;
            }
        }
        self.split.d.next = self.split_new.val();
        self.ev_domain.next = self.split_new.val() != self.split.q.val();

        // last_x = h + 1 and the saturating count, at each hubf_x
        self.last_a.d.next = self.last_a.q.val();
        self.frames_a.d.next = self.frames_a.q.val();
        if self.hubf_a.val() {
            if self.h_a.val() {
                self.last_a.d.next = self.last_hub_b.val();
            } else {
                self.last_a.d.next = self.last_hub_a.val();
            }
            if self.frames_a.q.val() != self.max8.val() {
                self.frames_a.d.next = self.frames_a.q.val() + self.one8.val();
            }
        }
        self.last_b.d.next = self.last_b.q.val();
        self.frames_b.d.next = self.frames_b.q.val();
        if self.hubf_b.val() {
            if self.h_b.val() {
                self.last_b.d.next = self.last_hub_b.val();
            } else {
                self.last_b.d.next = self.last_hub_a.val();
            }
            if self.frames_b.q.val() != self.max8.val() {
                self.frames_b.d.next = self.frames_b.q.val() + self.one8.val();
            }
        }

        if self.clear.val() {
            self.split.d.next = false;
            self.last_a.d.next = self.zero2.val();
            self.last_b.d.next = self.zero2.val();
            self.frames_a.d.next = self.zero8.val();
            self.frames_b.d.next = self.zero8.val();
            self.ev_domain.next = false;
        }

        self.split_q.next = self.split.q.val();
        self.word.next = (bit_cast::<32, 1>(self.split.q.val().into()) << self.s_split.val())
            | (bit_cast::<32, 2>(self.last_a.q.val()) << self.s_last_a.val())
            | (bit_cast::<32, 2>(self.last_b.q.val()) << self.s_last_b.val())
            | (bit_cast::<32, 8>(self.frames_a.q.val()) << self.s_frames_a.val())
            | (bit_cast::<32, 8>(self.frames_b.q.val()) << self.s_frames_b.val());
    }
}
