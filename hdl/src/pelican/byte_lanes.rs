//! The SJA1000 view's byte registers on a 32-bit bus (pelican_contract.md
//! P-BUS-1..3): which register an access addresses, which byte lane carries
//! it, and which accesses an 8-bit SJA1000 bus could not carry (refused with
//! the bus error, as the native map refuses).
//!
//! Stride 4 (Linux `reg-io-width = <4>`): register `r` is the word at byte
//! offset `4r`, in byte lane 0. A write takes `dat[7:0]` and is refused without
//! `sel[0]`; a read ignores `sel` and returns the byte in `[7:0]`.
//! Stride 1 (`reg-io-width = <1>`): register `r` is at byte offset `r`; an
//! access must select exactly one lane `l` (read or write), the register is
//! `{word address, l}`, a write takes lane `l`, and a read returns the byte on
//! all four lanes. Any other lane pattern is refused.
//!
//! Combinational, between the bus slave and the register block. The stride is
//! a generation choice (`new`).

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// Register number, write byte and refusal of one bus access.
#[derive(LogicBlock)]
pub struct ByteLanes {
    // ---- the access on the bus (taken by the slave) ----
    /// Word address: stride 4 uses `[6:0]`, stride 1 `[4:0]`.
    pub adr: Signal<In, Bits<7>>,
    /// Byte lane select.
    pub sel: Signal<In, Bits<4>>,
    /// 1 = write.
    pub we: Signal<In, Bit>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// The addressed register's byte, for the read data.
    pub rbyte: Signal<In, Bits<8>>,
    // ---- to the register block ----
    /// The register number 0..127.
    pub reg_num: Signal<Out, Bits<7>>,
    /// The byte a write carries.
    pub wbyte: Signal<Out, Bits<8>>,
    /// The access is refused (P-BUS-3): no effect, the bus's error.
    pub refused: Signal<Out, Bit>,
    /// The read data on the bus.
    pub rdat: Signal<Out, Bits<32>>,
    // ---- generation parameter ----
    /// 1 = stride 1 (four registers a word), 0 = stride 4.
    pub stride1: Constant<Bit>,
    /// `sel` is one-hot, and its lane.
    one_hot: Signal<Local, Bit>,
    lane: Signal<Local, Bits<2>>,
    lane0: Const<4, 1>,
    lane1: Const<4, 2>,
    lane2: Const<4, 4>,
    lane3: Const<4, 8>,
    idx0: Const<2, 0>,
    idx1: Const<2, 1>,
    idx2: Const<2, 2>,
    idx3: Const<2, 3>,
}

impl ByteLanes {
    /// The lanes of stride 4 (`stride = 4`) or stride 1 (`stride = 1`).
    pub fn new(stride: usize) -> Self {
        assert!(stride == 1 || stride == 4, "pelican stride is 1 or 4");
        Self {
            adr: Default::default(),
            sel: Default::default(),
            we: Default::default(),
            wdat: Default::default(),
            rbyte: Default::default(),
            reg_num: Default::default(),
            wbyte: Default::default(),
            refused: Default::default(),
            rdat: Default::default(),
            stride1: Constant::new(stride == 1),
            one_hot: Default::default(),
            lane: Default::default(),
            lane0: Default::default(),
            lane1: Default::default(),
            lane2: Default::default(),
            lane3: Default::default(),
            idx0: Default::default(),
            idx1: Default::default(),
            idx2: Default::default(),
            idx3: Default::default(),
        }
    }
}

impl Default for ByteLanes {
    /// Stride 4, the generator's default.
    fn default() -> Self {
        Self::new(4)
    }
}

impl Logic for ByteLanes {
    #[hdl_gen]
    fn update(&mut self) {
        self.one_hot.next = true;
        self.lane.next = self.idx0.val();
        if self.sel.val() == self.lane1.val() {
            self.lane.next = self.idx1.val();
        } else if self.sel.val() == self.lane2.val() {
            self.lane.next = self.idx2.val();
        } else if self.sel.val() == self.lane3.val() {
            self.lane.next = self.idx3.val();
        } else if self.sel.val() != self.lane0.val() {
            self.one_hot.next = false;
        }
        if self.stride1.val() {
            // P-BUS-2: {word address, lane}; the byte from that lane; the read
            // byte on every lane.
            self.reg_num.next = (bit_cast::<7, 5>(self.adr.val().get_bits::<5>(0)) << 2)
                | bit_cast::<7, 2>(self.lane.val());
            self.wbyte.next = self.wdat.val().get_bits::<8>(0);
            match self.lane.val().index() {
                1 => self.wbyte.next = self.wdat.val().get_bits::<8>(8),
                2 => self.wbyte.next = self.wdat.val().get_bits::<8>(16),
                3 => self.wbyte.next = self.wdat.val().get_bits::<8>(24),
                _ => {}
            }
            self.refused.next = !self.one_hot.val();
            self.rdat.next = (bit_cast::<32, 8>(self.rbyte.val()) << 24)
                | (bit_cast::<32, 8>(self.rbyte.val()) << 16)
                | (bit_cast::<32, 8>(self.rbyte.val()) << 8)
                | bit_cast::<32, 8>(self.rbyte.val());
        } else {
            // P-BUS-1: the word is the register, lane 0 carries it.
            self.reg_num.next = self.adr.val();
            self.wbyte.next = self.wdat.val().get_bits::<8>(0);
            self.refused.next = self.we.val() && !self.sel.val().get_bit(0);
            self.rdat.next = bit_cast::<32, 8>(self.rbyte.val());
        }
    }
}
