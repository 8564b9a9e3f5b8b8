//! NRAP counters computed one clock ahead (structural, for Fmax on the
//! iCE40UP5K; hub contract §9.2 unchanged). At a SAMPLE edge the phase machine
//! (`super::nrap`) compares the new `nt`, `ncnt` and `unacked` with its limits;
//! behind the bit timing's sample decision and the tracker's events those adders
//! and comparators made the hub's longest path. The counters change only at
//! SAMPLE edges, at a command that changes the phase (it clears `nt` and `ncnt`)
//! and in reset mode (then no SAMPLE edge follows, the bit timing is held one
//! edge longer), and two SAMPLE edges are more than 2 clocks apart (§6.1); so
//! every clock this block registers, from the counters before the edge, the
//! saturating increments and each comparison for both outcomes (`0`: the counter
//! stays, `1`: it counts). At a SAMPLE edge the registers hold exactly what the
//! phase machine's rules need, unless a command cleared `nt` and `ncnt` at the
//! edge before (`clear_q`): then the outputs are the comparisons of the cleared
//! counters (1 and 0/1) with the limits. (The command is not folded into the
//! registered values: that put the Wishbone decode in front of the adders.)

use rust_hdl::prelude::*;

/// The counter increments and limit comparisons of the next SAMPLE edge.
#[derive(LogicBlock)]
pub struct NrapAhead {
    /// Clock; every output is a register of it.
    pub clk: Signal<In, Clock>,
    // the counters before the edge
    /// `nt` (SAMPLE edges in this phase).
    pub nt: Signal<In, Bits<16>>,
    /// `ncnt` (pairs or own frames in this phase).
    pub ncnt: Signal<In, Bits<4>>,
    /// `unacked` (frames in a row with an error flag at the ACK delimiter).
    pub unacked: Signal<In, Bits<5>>,
    /// A command changes the phase at this edge: `nt` and `ncnt` become 0.
    pub clear: Signal<In, Bit>,
    // limits (§9.5; written only in reset mode)
    /// `force_bits` (§9.5).
    pub force_bits: Signal<In, Bits<10>>,
    /// `srp_bits` (§9.5).
    pub srp_bits: Signal<In, Bits<16>>,
    /// `nrp_bits` (§9.5).
    pub nrp_bits: Signal<In, Bits<16>>,
    /// `ddsp_bits` (§9.5).
    pub ddsp_bits: Signal<In, Bits<16>>,
    /// `srp_pairs` (§9.5).
    pub srp_pairs: Signal<In, Bits<4>>,
    /// `nrp_pairs` (§9.5).
    pub nrp_pairs: Signal<In, Bits<4>>,
    /// `ddsp_frames` (§9.5).
    pub ddsp_frames: Signal<In, Bits<4>>,
    /// `block_frames` (§9.5, 0 = off).
    pub block_frames: Signal<In, Bits<5>>,
    // registered for the next edge
    /// `min(nt + 1, 65535)`: the new `nt` of a SAMPLE edge.
    pub nt_inc: Signal<Out, Bits<16>>,
    /// New `nt >= force_bits`.
    pub nt_force: Signal<Out, Bit>,
    /// New `nt >= srp_bits`.
    pub nt_srp: Signal<Out, Bit>,
    /// New `nt >= nrp_bits`.
    pub nt_nrp: Signal<Out, Bit>,
    /// New `nt >= ddsp_bits`.
    pub nt_ddsp: Signal<Out, Bit>,
    /// `min(ncnt + 1, 15)`: the new `ncnt` when it counts.
    pub ncnt_inc: Signal<Out, Bits<4>>,
    /// `ncnt >= srp_pairs` (it stays).
    pub srp0: Signal<Out, Bit>,
    /// `min(ncnt + 1, 15) >= srp_pairs` (it counts).
    pub srp1: Signal<Out, Bit>,
    /// `ncnt >= nrp_pairs` (it stays).
    pub nrp0: Signal<Out, Bit>,
    /// `min(ncnt + 1, 15) >= nrp_pairs` (it counts).
    pub nrp1: Signal<Out, Bit>,
    /// `ncnt >= ddsp_frames` (it stays).
    pub ddsp0: Signal<Out, Bit>,
    /// `min(ncnt + 1, 15) >= ddsp_frames` (it counts).
    pub ddsp1: Signal<Out, Bit>,
    /// `min(unacked + 1, 31)`: the new `unacked` after an error flag.
    pub un_inc: Signal<Out, Bits<5>>,
    /// `block_frames != 0` and `unacked >= block_frames` (it stays).
    pub blk0: Signal<Out, Bit>,
    /// `block_frames != 0` and `min(unacked + 1, 31) >= block_frames` (it counts).
    pub blk1: Signal<Out, Bit>,
    // registers
    nt_inc_q: DFF<Bits<16>>,
    nt_force_q: DFF<Bit>,
    nt_srp_q: DFF<Bit>,
    nt_nrp_q: DFF<Bit>,
    nt_ddsp_q: DFF<Bit>,
    ncnt_inc_q: DFF<Bits<4>>,
    srp0_q: DFF<Bit>,
    srp1_q: DFF<Bit>,
    nrp0_q: DFF<Bit>,
    nrp1_q: DFF<Bit>,
    ddsp0_q: DFF<Bit>,
    ddsp1_q: DFF<Bit>,
    un_inc_q: DFF<Bits<5>>,
    blk0_q: DFF<Bit>,
    blk1_q: DFF<Bit>,
    clear_q: DFF<Bit>,
    /// The comparisons of the cleared counters (new nt = 1, new ncnt = 0 / 1) with
    /// the limits, registered too (the limits change only in reset mode).
    c_force: DFF<Bit>,
    c_srp: DFF<Bit>,
    c_nrp: DFF<Bit>,
    c_ddsp: DFF<Bit>,
    c_srp0: DFF<Bit>,
    c_srp1: DFF<Bit>,
    c_nrp0: DFF<Bit>,
    c_nrp1: DFF<Bit>,
    c_ddsp0: DFF<Bit>,
    c_ddsp1: DFF<Bit>,
    // combinational
    nt_n: Signal<Local, Bits<16>>,
    ncnt_n: Signal<Local, Bits<4>>,
    un_n: Signal<Local, Bits<5>>,
    blk_on: Signal<Local, Bit>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    max4: Constant<Bits<4>>,
    zero5: Constant<Bits<5>>,
    one5: Constant<Bits<5>>,
    max5: Constant<Bits<5>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl Default for NrapAhead {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            nt: Default::default(),
            ncnt: Default::default(),
            unacked: Default::default(),
            clear: Default::default(),
            force_bits: Default::default(),
            srp_bits: Default::default(),
            nrp_bits: Default::default(),
            ddsp_bits: Default::default(),
            srp_pairs: Default::default(),
            nrp_pairs: Default::default(),
            ddsp_frames: Default::default(),
            block_frames: Default::default(),
            nt_inc: Default::default(),
            nt_force: Default::default(),
            nt_srp: Default::default(),
            nt_nrp: Default::default(),
            nt_ddsp: Default::default(),
            ncnt_inc: Default::default(),
            srp0: Default::default(),
            srp1: Default::default(),
            nrp0: Default::default(),
            nrp1: Default::default(),
            ddsp0: Default::default(),
            ddsp1: Default::default(),
            un_inc: Default::default(),
            blk0: Default::default(),
            blk1: Default::default(),
            nt_inc_q: Default::default(),
            nt_force_q: Default::default(),
            nt_srp_q: Default::default(),
            nt_nrp_q: Default::default(),
            nt_ddsp_q: Default::default(),
            ncnt_inc_q: Default::default(),
            srp0_q: Default::default(),
            srp1_q: Default::default(),
            nrp0_q: Default::default(),
            nrp1_q: Default::default(),
            ddsp0_q: Default::default(),
            ddsp1_q: Default::default(),
            un_inc_q: Default::default(),
            blk0_q: Default::default(),
            blk1_q: Default::default(),
            clear_q: Default::default(),
            c_force: Default::default(),
            c_srp: Default::default(),
            c_nrp: Default::default(),
            c_ddsp: Default::default(),
            c_srp0: Default::default(),
            c_srp1: Default::default(),
            c_nrp0: Default::default(),
            c_nrp1: Default::default(),
            c_ddsp0: Default::default(),
            c_ddsp1: Default::default(),
            nt_n: Default::default(),
            ncnt_n: Default::default(),
            un_n: Default::default(),
            blk_on: Default::default(),
            zero4: Constant::new(0.into()),
            one4: Constant::new(1.into()),
            max4: Constant::new(15.into()),
            zero5: Constant::new(0.into()),
            one5: Constant::new(1.into()),
            max5: Constant::new(31.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

impl Logic for NrapAhead {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, nt_inc_q, nt_force_q, nt_srp_q, nt_nrp_q, nt_ddsp_q, ncnt_inc_q, srp0_q,
            srp1_q, nrp0_q, nrp1_q, ddsp0_q, ddsp1_q, un_inc_q, blk0_q, blk1_q, clear_q, c_force,
            c_srp, c_nrp, c_ddsp, c_srp0, c_srp1, c_nrp0, c_nrp1, c_ddsp0, c_ddsp1
        );
        self.clear_q.d.next = self.clear.val();
        self.c_force.d.next = self.one16.val() >= bit_cast::<16, 10>(self.force_bits.val());
        self.c_srp.d.next = self.one16.val() >= self.srp_bits.val();
        self.c_nrp.d.next = self.one16.val() >= self.nrp_bits.val();
        self.c_ddsp.d.next = self.one16.val() >= self.ddsp_bits.val();
        self.c_srp0.d.next = self.srp_pairs.val() == self.zero4.val();
        self.c_srp1.d.next = self.one4.val() >= self.srp_pairs.val();
        self.c_nrp0.d.next = self.nrp_pairs.val() == self.zero4.val();
        self.c_nrp1.d.next = self.one4.val() >= self.nrp_pairs.val();
        self.c_ddsp0.d.next = self.ddsp_frames.val() == self.zero4.val();
        self.c_ddsp1.d.next = self.one4.val() >= self.ddsp_frames.val();
        // nt: every SAMPLE edge counts
        if self.nt.val() == self.max16.val() {
            self.nt_n.next = self.max16.val();
        } else {
            self.nt_n.next = self.nt.val() + self.one16.val();
        }
        self.nt_inc_q.d.next = self.nt_n.val();
        self.nt_force_q.d.next = self.nt_n.val() >= bit_cast::<16, 10>(self.force_bits.val());
        self.nt_srp_q.d.next = self.nt_n.val() >= self.srp_bits.val();
        self.nt_nrp_q.d.next = self.nt_n.val() >= self.nrp_bits.val();
        self.nt_ddsp_q.d.next = self.nt_n.val() >= self.ddsp_bits.val();
        // ncnt: stays or counts
        if self.ncnt.val() == self.max4.val() {
            self.ncnt_n.next = self.max4.val();
        } else {
            self.ncnt_n.next = self.ncnt.val() + self.one4.val();
        }
        self.ncnt_inc_q.d.next = self.ncnt_n.val();
        self.srp0_q.d.next = self.ncnt.val() >= self.srp_pairs.val();
        self.srp1_q.d.next = self.ncnt_n.val() >= self.srp_pairs.val();
        self.nrp0_q.d.next = self.ncnt.val() >= self.nrp_pairs.val();
        self.nrp1_q.d.next = self.ncnt_n.val() >= self.nrp_pairs.val();
        self.ddsp0_q.d.next = self.ncnt.val() >= self.ddsp_frames.val();
        self.ddsp1_q.d.next = self.ncnt_n.val() >= self.ddsp_frames.val();
        // unacked: stays or counts (a phase change does not clear it)
        if self.unacked.val() == self.max5.val() {
            self.un_n.next = self.max5.val();
        } else {
            self.un_n.next = self.unacked.val() + self.one5.val();
        }
        self.un_inc_q.d.next = self.un_n.val();
        self.blk_on.next = self.block_frames.val() != self.zero5.val();
        self.blk0_q.d.next = self.blk_on.val() & (self.unacked.val() >= self.block_frames.val());
        self.blk1_q.d.next = self.blk_on.val() & (self.un_n.val() >= self.block_frames.val());

        if self.clear_q.q.val() {
            // a command cleared nt and ncnt: new nt = 1, new ncnt = 0 or 1
            self.nt_inc.next = self.one16.val();
            self.nt_force.next = self.c_force.q.val();
            self.nt_srp.next = self.c_srp.q.val();
            self.nt_nrp.next = self.c_nrp.q.val();
            self.nt_ddsp.next = self.c_ddsp.q.val();
            self.ncnt_inc.next = self.one4.val();
            self.srp0.next = self.c_srp0.q.val();
            self.srp1.next = self.c_srp1.q.val();
            self.nrp0.next = self.c_nrp0.q.val();
            self.nrp1.next = self.c_nrp1.q.val();
            self.ddsp0.next = self.c_ddsp0.q.val();
            self.ddsp1.next = self.c_ddsp1.q.val();
        } else {
            self.nt_inc.next = self.nt_inc_q.q.val();
            self.nt_force.next = self.nt_force_q.q.val();
            self.nt_srp.next = self.nt_srp_q.q.val();
            self.nt_nrp.next = self.nt_nrp_q.q.val();
            self.nt_ddsp.next = self.nt_ddsp_q.q.val();
            self.ncnt_inc.next = self.ncnt_inc_q.q.val();
            self.srp0.next = self.srp0_q.q.val();
            self.srp1.next = self.srp1_q.q.val();
            self.nrp0.next = self.nrp0_q.q.val();
            self.nrp1.next = self.nrp1_q.q.val();
            self.ddsp0.next = self.ddsp0_q.q.val();
            self.ddsp1.next = self.ddsp1_q.q.val();
        }
        self.un_inc.next = self.un_inc_q.q.val();
        self.blk0.next = self.blk0_q.q.val();
        self.blk1.next = self.blk1_q.q.val();
    }
}
