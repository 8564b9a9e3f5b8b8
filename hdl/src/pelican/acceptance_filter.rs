//! The SJA1000 acceptance filter (pelican_contract.md P-ACF-1, SJA1000 data
//! sheet 6.4.15): the verdict on one frame from the four acceptance code bytes
//! `ACR0..3`, the four mask bytes `AMR0..3` and the filter mode `MOD.AFM`.
//!
//! A byte compares as `m(c, k, x) = ((c ^ x) & ~k) == 0`: a mask bit 1 is
//! "don't care". Single filter (`AFM = 1`): one long filter over the
//! identifier, RTR and, for a standard frame, the first two data bytes.
//! Dual filter (`AFM = 0`): two short filters, either may accept; for a
//! standard frame filter 1 also takes the first data byte (its high nibble in
//! `ACR1[3:0]`, its low nibble in `ACR3[3:0]`). A data byte the frame does not
//! have (a remote frame, or a DLC that stops before it) matches whatever the
//! filter says (data sheet: "messages may also be accepted if there are no
//! data bytes").
//!
//! Combinational: the RX writer asks it about the frame at the RX FIFO's write
//! port (P-RX-5), so both copies of a redundant frame get the same verdict.

use rust_hdl::prelude::*;

/// The acceptance filter of the SJA1000 view (pure logic, no state).
#[derive(LogicBlock, Default)]
pub struct AcceptanceFilter {
    // ---- the filter registers (written in reset mode by the host) ----
    /// `ACR0`, acceptance code byte 0.
    pub acr0: Signal<In, Bits<8>>,
    /// `ACR1`.
    pub acr1: Signal<In, Bits<8>>,
    /// `ACR2`.
    pub acr2: Signal<In, Bits<8>>,
    /// `ACR3`.
    pub acr3: Signal<In, Bits<8>>,
    /// `AMR0`, acceptance mask byte 0: a bit 1 is not compared.
    pub amr0: Signal<In, Bits<8>>,
    /// `AMR1`.
    pub amr1: Signal<In, Bits<8>>,
    /// `AMR2`.
    pub amr2: Signal<In, Bits<8>>,
    /// `AMR3`.
    pub amr3: Signal<In, Bits<8>>,
    /// `MOD.AFM`: 1 = single filter, 0 = dual filter.
    pub afm: Signal<In, Bit>,
    // ---- the frame judged (the RX FIFO entry's layout) ----
    /// Identifier, right-aligned: a standard frame's 11 bits in `[10:0]`.
    pub id: Signal<In, Bits<29>>,
    /// Extended frame (IDE).
    pub ide: Signal<In, Bit>,
    /// Remote frame (RTR).
    pub rtr: Signal<In, Bit>,
    /// Data length code as received.
    pub dlc: Signal<In, Bits<4>>,
    /// First data byte (data byte 1 of the data sheet).
    pub data1: Signal<In, Bits<8>>,
    /// Second data byte.
    pub data2: Signal<In, Bits<8>>,
    // ---- verdict ----
    /// 1 = the frame is accepted (stored in the RX FIFO).
    pub accept: Signal<Out, Bit>,
    // ---- byte comparisons, named after the data sheet's figures ----
    /// Standard: `ID.28..21` (`id[10:3]`) against byte 0 / byte 2.
    std_id_0: Signal<Local, Bit>,
    std_id_2: Signal<Local, Bit>,
    /// Standard: `{ID.20..18, RTR}` against `ACR1[7:4]` / `ACR3[7:4]`.
    std_lo_1: Signal<Local, Bit>,
    std_lo_3: Signal<Local, Bit>,
    /// Standard, single filter: data bytes 1 and 2 against bytes 2 and 3.
    std_d1: Signal<Local, Bit>,
    std_d2: Signal<Local, Bit>,
    /// Standard, dual filter: data byte 1 against `{ACR1[3:0], ACR3[3:0]}`.
    std_d1_dual: Signal<Local, Bit>,
    /// The frame has no data byte 1 / no data byte 2.
    no_d1: Signal<Local, Bit>,
    no_d2: Signal<Local, Bit>,
    /// Extended: `ID.28..21`, `ID.20..13` against bytes 0..3 (single filter
    /// and both dual filters use them).
    ext_hi_0: Signal<Local, Bit>,
    ext_mid_1: Signal<Local, Bit>,
    ext_hi_2: Signal<Local, Bit>,
    ext_mid_3: Signal<Local, Bit>,
    /// Extended, single filter: `ID.12..5` against byte 2, `{ID.4..0, RTR}`
    /// against `ACR3[7:2]`.
    ext_lo_2: Signal<Local, Bit>,
    ext_lo_3: Signal<Local, Bit>,
    /// The single-filter verdict and the two dual-filter verdicts.
    single: Signal<Local, Bit>,
    dual1: Signal<Local, Bit>,
    dual2: Signal<Local, Bit>,
    /// The RTR bit against `ACR1[4]` (standard) / `ACR3[4]` / `ACR3[2]` (extended).
    rtr_1: Signal<Local, Bit>,
    rtr_3: Signal<Local, Bit>,
    rtr_3x: Signal<Local, Bit>,
}

impl Logic for AcceptanceFilter {
    #[hdl_gen]
    fn update(&mut self) {
        // The RTR bit below the identifier's low bits, as the data sheet lays
        // out ACR1 (standard, bit 4) and ACR3 (standard bit 4, extended bit 2).
        self.rtr_1.next =
            self.amr1.val().get_bit(4) || (self.acr1.val().get_bit(4) == self.rtr.val());
        self.rtr_3.next =
            self.amr3.val().get_bit(4) || (self.acr3.val().get_bit(4) == self.rtr.val());
        self.rtr_3x.next =
            self.amr3.val().get_bit(2) || (self.acr3.val().get_bit(2) == self.rtr.val());

        // m(c, k, x) = ((c ^ x) & ~k) == 0, byte by byte.
        self.std_id_0.next =
            !((self.acr0.val() ^ self.id.val().get_bits::<8>(3)) & !self.amr0.val()).any();
        self.std_id_2.next =
            !((self.acr2.val() ^ self.id.val().get_bits::<8>(3)) & !self.amr2.val()).any();
        self.std_lo_1.next = self.rtr_1.val()
            && !((self.acr1.val().get_bits::<3>(5) ^ self.id.val().get_bits::<3>(0))
                & !self.amr1.val().get_bits::<3>(5))
            .any();
        self.std_lo_3.next = self.rtr_3.val()
            && !((self.acr3.val().get_bits::<3>(5) ^ self.id.val().get_bits::<3>(0))
                & !self.amr3.val().get_bits::<3>(5))
            .any();
        self.std_d1.next = !((self.acr2.val() ^ self.data1.val()) & !self.amr2.val()).any();
        self.std_d2.next = !((self.acr3.val() ^ self.data2.val()) & !self.amr3.val()).any();
        // Dual filter 1: data byte 1's high nibble in ACR1[3:0], low in ACR3[3:0].
        self.std_d1_dual.next = !((self.acr1.val().get_bits::<4>(0)
            ^ self.data1.val().get_bits::<4>(4))
            & !self.amr1.val().get_bits::<4>(0))
        .any()
            && !((self.acr3.val().get_bits::<4>(0) ^ self.data1.val().get_bits::<4>(0))
                & !self.amr3.val().get_bits::<4>(0))
            .any();
        self.ext_hi_0.next =
            !((self.acr0.val() ^ self.id.val().get_bits::<8>(21)) & !self.amr0.val()).any();
        self.ext_mid_1.next =
            !((self.acr1.val() ^ self.id.val().get_bits::<8>(13)) & !self.amr1.val()).any();
        self.ext_hi_2.next =
            !((self.acr2.val() ^ self.id.val().get_bits::<8>(21)) & !self.amr2.val()).any();
        self.ext_mid_3.next =
            !((self.acr3.val() ^ self.id.val().get_bits::<8>(13)) & !self.amr3.val()).any();
        self.ext_lo_2.next =
            !((self.acr2.val() ^ self.id.val().get_bits::<8>(5)) & !self.amr2.val()).any();
        self.ext_lo_3.next = self.rtr_3x.val()
            && !((self.acr3.val().get_bits::<5>(3) ^ self.id.val().get_bits::<5>(0))
                & !self.amr3.val().get_bits::<5>(3))
            .any();

        // P-ACF-1: a data byte the frame does not carry matches.
        self.no_d1.next = self.rtr.val() || !self.dlc.val().any();
        self.no_d2.next = self.rtr.val() || !self.dlc.val().get_bits::<3>(1).any();

        if self.ide.val() {
            self.single.next = self.ext_hi_0.val()
                && self.ext_mid_1.val()
                && self.ext_lo_2.val()
                && self.ext_lo_3.val();
            self.dual1.next = self.ext_hi_0.val() && self.ext_mid_1.val();
            self.dual2.next = self.ext_hi_2.val() && self.ext_mid_3.val();
        } else {
            self.single.next = self.std_id_0.val()
                && self.std_lo_1.val()
                && (self.no_d1.val() || self.std_d1.val())
                && (self.no_d2.val() || self.std_d2.val());
            self.dual1.next = self.std_id_0.val()
                && self.std_lo_1.val()
                && (self.no_d1.val() || self.std_d1_dual.val());
            self.dual2.next = self.std_id_2.val() && self.std_lo_3.val();
        }
        if self.afm.val() {
            self.accept.next = self.single.val();
        } else {
            self.accept.next = self.dual1.val() || self.dual2.val();
        }
    }
}
