//! The acceptance filters' registers (DRCC contract §11.1): `FILT_ID0`,
//! `FILT_MASK0`, `FILT_ID1`, `FILT_MASK1`. cfg registers: a whole-word write
//! is stored in reset mode and refused outside it (§9); `rst` clears them
//! (every filter disabled: every frame accepted), reset mode keeps them. The
//! verdict on a frame is taken where the frames are, at the RX FIFO's write
//! port (`crate::memory::dedup`), from the words stored here.
//!
//! The block answers the register block as the DMR registers do: `hit` for
//! its addresses, `word` for the read, `illegal` for a refused write.

use super::registers as map;
use rust_hdl::prelude::*;

/// The two identifier/mask pairs.
#[derive(LogicBlock)]
pub struct FilterRegs {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every filter 0, disabled.
    pub rst: Signal<In, Bit>,
    // ---- the register access ----
    /// A whole-word write is taken at this edge (any address).
    pub wr: Signal<In, Bit>,
    /// Word index on the bus.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// `CTRL.reset_mode`: the filters are writable only then.
    pub reset_mode: Signal<In, Bit>,
    /// `adr` is one of the filter registers.
    pub hit: Signal<Out, Bit>,
    /// The addressed filter register's value (0 when not `hit`).
    pub word: Signal<Out, Bits<32>>,
    /// A write to a filter register outside reset mode: refused (§9).
    pub illegal: Signal<Out, Bit>,
    // ---- the stored filters ----
    /// `FILT_ID0[30:0]`: {rtr, ide, id} to compare.
    pub id0: Signal<Out, Bits<31>>,
    /// `FILT_MASK0`: [30:0] the bits compared, [31] `enable`.
    pub mask0: Signal<Out, Bits<32>>,
    /// `FILT_ID1[30:0]`.
    pub id1: Signal<Out, Bits<31>>,
    /// `FILT_MASK1`.
    pub mask1: Signal<Out, Bits<32>>,
    // ---- registers ----
    id0_q: DFF<Bits<31>>,
    mask0_q: DFF<Bits<32>>,
    id1_q: DFF<Bits<31>>,
    mask1_q: DFF<Bits<32>>,
    // ---- word indices (from the table) ----
    a_id0: Constant<Bits<6>>,
    a_mask0: Constant<Bits<6>>,
    a_id1: Constant<Bits<6>>,
    a_mask1: Constant<Bits<6>>,
    zero31: Constant<Bits<31>>,
    zero32: Constant<Bits<32>>,
}

impl Default for FilterRegs {
    fn default() -> Self {
        let adr = |i: u32| Constant::new((i as u64).into());
        for r in ["FILT_ID0", "FILT_MASK0", "FILT_ID1", "FILT_MASK1"] {
            assert_eq!(
                map::register(r).map(|r| r.reset_value()),
                Some(0),
                "{r}: the filters reset to 0 (disabled)"
            );
        }
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            adr: Default::default(),
            wdat: Default::default(),
            reset_mode: Default::default(),
            hit: Default::default(),
            word: Default::default(),
            illegal: Default::default(),
            id0: Default::default(),
            mask0: Default::default(),
            id1: Default::default(),
            mask1: Default::default(),
            id0_q: Default::default(),
            mask0_q: Default::default(),
            id1_q: Default::default(),
            mask1_q: Default::default(),
            a_id0: adr(map::FILT_ID0),
            a_mask0: adr(map::FILT_MASK0),
            a_id1: adr(map::FILT_ID1),
            a_mask1: adr(map::FILT_MASK1),
            zero31: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl Logic for FilterRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, id0_q, mask0_q, id1_q, mask1_q);
        self.hit.next = (self.adr.val() == self.a_id0.val())
            | (self.adr.val() == self.a_mask0.val())
            | (self.adr.val() == self.a_id1.val())
            | (self.adr.val() == self.a_mask1.val());
        self.word.next = self.zero32.val();
        if self.adr.val() == self.a_id0.val() {
            self.word.next = bit_cast::<32, 31>(self.id0_q.q.val());
        } else if self.adr.val() == self.a_mask0.val() {
            self.word.next = self.mask0_q.q.val();
        } else if self.adr.val() == self.a_id1.val() {
            self.word.next = bit_cast::<32, 31>(self.id1_q.q.val());
        } else if self.adr.val() == self.a_mask1.val() {
            self.word.next = self.mask1_q.q.val();
        }
        // cfg registers (§9): stored in reset mode, refused outside it
        self.illegal.next = self.hit.val() & !self.reset_mode.val();
        if self.wr.val() & self.reset_mode.val() {
            if self.adr.val() == self.a_id0.val() {
                self.id0_q.d.next = self.wdat.val().get_bits::<31>(0);
            } else if self.adr.val() == self.a_mask0.val() {
                self.mask0_q.d.next = self.wdat.val();
            } else if self.adr.val() == self.a_id1.val() {
                self.id1_q.d.next = self.wdat.val().get_bits::<31>(0);
            } else if self.adr.val() == self.a_mask1.val() {
                self.mask1_q.d.next = self.wdat.val();
            }
        }
        if self.rst.val() {
            self.id0_q.d.next = self.zero31.val();
            self.mask0_q.d.next = self.zero32.val();
            self.id1_q.d.next = self.zero31.val();
            self.mask1_q.d.next = self.zero32.val();
        }
        self.id0.next = self.id0_q.q.val();
        self.mask0.next = self.mask0_q.q.val();
        self.id1.next = self.id1_q.q.val();
        self.mask1.next = self.mask1_q.q.val();
    }
}
