//! The hub's configuration registers (hub contract §8 "RW cfg" registers and the
//! NRAP registers of §9.5): `BTR`, `GUARD_CFG`, `BF_CFG`, `RESTORE_CFG`,
//! `NRAP_CFG`, `NRAP_TIME`, `NRAP_DDSP`. They share one write rule: a write taken
//! in reset mode (`reset_mode`, the value before the edge) is stored with the
//! clamps of §8 and §9.5 (reads show the stored value); outside reset mode it is
//! refused, and the register block (`super::registers`, which owns the Wishbone
//! slave and decodes every other address) sets `INT_STATUS.illegal`.
//!
//! Clamps: `sd_run_up`, `sd_run_sub` below 14 store 14; `bf_up`, `bf_sub` below 8
//! store 8; `force_bits` below 64 stores 64; `srp_pairs`, `nrp_pairs`,
//! `ddsp_frames` 0 stores 1; `srp_bits`, `nrp_bits`, `ddsp_bits` below 256 store
//! 256; `block_frames` 1..3 store 4 (0 stays: off). Word indices, field positions, reset values and clamps come from the
//! table (`crate::host::hub_registers`).

use crate::channel::BRP_BITS;
use crate::host::hub_registers::{
    self as map, BF_MIN, BLOCK_MIN, FORCE_MIN, MAP, NRAP_BITS_MIN, NRAP_COUNT_MIN, SD_MIN,
};
use crate::host::map::lsb;
use rust_hdl::prelude::*;

fn adr(index: u32) -> Constant<Bits<6>> {
    Constant::new((index as u64).into())
}

/// Reset value of `reg.field` as an RTL constant.
fn reset<const B: usize>(reg: &str, field: &str) -> Constant<Bits<B>> {
    Constant::new((MAP.field(reg, field).reset as u64).into())
}

/// A clamp minimum as an RTL constant.
fn min<const B: usize>(value: u32) -> Constant<Bits<B>> {
    Constant::new((value as u64).into())
}

/// The hub's configuration registers.
#[derive(LogicBlock)]
pub struct HubConfig {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register to its table reset value.
    pub rst: Signal<In, Bit>,
    // ---- from the register block ----
    /// A Wishbone write is taken at this edge.
    pub wr: Signal<In, Bit>,
    /// Word index.
    pub adr: Signal<In, Bits<6>>,
    /// Write data.
    pub wdat: Signal<In, Bits<32>>,
    /// `CTRL.reset_mode` (value before the edge): writes are stored only then.
    pub reset_mode: Signal<In, Bit>,
    // ---- to the register block ----
    /// `adr` is one of these registers (a write outside reset mode is refused).
    pub hit: Signal<Out, Bit>,
    /// Value of the addressed register (0 when `hit` is 0).
    pub rdata: Signal<Out, Bits<32>>,
    // ---- configuration out ----
    /// The prescaler BRP, `{BTR.brp_ext, BTR.brp}` (0..1023).
    pub brp: Signal<Out, Bits<BRP_BITS>>,
    /// `BTR.tseg1`.
    pub tseg1: Signal<Out, Bits<4>>,
    /// `BTR.tseg2`.
    pub tseg2: Signal<Out, Bits<3>>,
    /// `BTR.sjw`.
    pub sjw: Signal<Out, Bits<2>>,
    /// `GUARD_CFG.sd_run_up`.
    pub sd_run_up: Signal<Out, Bits<6>>,
    /// `GUARD_CFG.sd_run_sub`.
    pub sd_run_sub: Signal<Out, Bits<6>>,
    /// `GUARD_CFG.sr_frames`.
    pub sr_frames: Signal<Out, Bits<4>>,
    /// `BF_CFG.bf_up`.
    pub bf_up: Signal<Out, Bits<8>>,
    /// `BF_CFG.bf_sub`.
    pub bf_sub: Signal<Out, Bits<8>>,
    /// `RESTORE_CFG.restore_bits`.
    pub restore_bits: Signal<Out, Bits<16>>,
    /// `RESTORE_CFG.decouple_bits`.
    pub decouple_bits: Signal<Out, Bits<16>>,
    /// `NRAP_CFG.force_bits`.
    pub force_bits: Signal<Out, Bits<10>>,
    /// `NRAP_CFG.srp_pairs`.
    pub srp_pairs: Signal<Out, Bits<4>>,
    /// `NRAP_CFG.nrp_pairs`.
    pub nrp_pairs: Signal<Out, Bits<4>>,
    /// `NRAP_CFG.ddsp_frames`.
    pub ddsp_frames: Signal<Out, Bits<4>>,
    /// `NRAP_TIME.srp_bits`.
    pub srp_bits: Signal<Out, Bits<16>>,
    /// `NRAP_TIME.nrp_bits`.
    pub nrp_bits: Signal<Out, Bits<16>>,
    /// `NRAP_DDSP.ddsp_bits`.
    pub ddsp_bits: Signal<Out, Bits<16>>,
    /// `NRAP_DDSP.block_frames`.
    pub block_frames: Signal<Out, Bits<5>>,
    // ---- registers ----
    btr_q: DFF<Bits<15>>,
    brp_ext_q: DFF<Bits<4>>,
    sd_up_q: DFF<Bits<6>>,
    sd_sub_q: DFF<Bits<6>>,
    sr_q: DFF<Bits<4>>,
    bf_up_q: DFF<Bits<8>>,
    bf_sub_q: DFF<Bits<8>>,
    restore_q: DFF<Bits<16>>,
    decouple_q: DFF<Bits<16>>,
    force_q: DFF<Bits<10>>,
    srp_pairs_q: DFF<Bits<4>>,
    nrp_pairs_q: DFF<Bits<4>>,
    ddsp_frames_q: DFF<Bits<4>>,
    srp_bits_q: DFF<Bits<16>>,
    nrp_bits_q: DFF<Bits<16>>,
    ddsp_bits_q: DFF<Bits<16>>,
    block_q: DFF<Bits<5>>,
    // ---- decode ----
    store: Signal<Local, Bit>,
    w6a: Signal<Local, Bits<6>>,
    w6b: Signal<Local, Bits<6>>,
    w8a: Signal<Local, Bits<8>>,
    w8b: Signal<Local, Bits<8>>,
    w10: Signal<Local, Bits<10>>,
    w4a: Signal<Local, Bits<4>>,
    w4b: Signal<Local, Bits<4>>,
    w4c: Signal<Local, Bits<4>>,
    w16a: Signal<Local, Bits<16>>,
    w16b: Signal<Local, Bits<16>>,
    w16c: Signal<Local, Bits<16>>,
    w5: Signal<Local, Bits<5>>,
    // ---- word indices ----
    a_btr: Constant<Bits<6>>,
    a_guard: Constant<Bits<6>>,
    a_bf: Constant<Bits<6>>,
    a_restore: Constant<Bits<6>>,
    a_ncfg: Constant<Bits<6>>,
    a_ntime: Constant<Bits<6>>,
    a_nddsp: Constant<Bits<6>>,
    // ---- field positions (BTR's index the 15-bit register) ----
    b_brp: Constant<Bits<4>>,
    /// `BTR.brp_ext`'s position in the word (it is held in `brp_ext_q`).
    b_brp_ext: Constant<Bits<5>>,
    brp_ext_shift: Constant<Bits<4>>,
    b_tseg1: Constant<Bits<4>>,
    b_tseg2: Constant<Bits<4>>,
    b_sjw: Constant<Bits<4>>,
    g_sd_up: Constant<Bits<5>>,
    g_sd_sub: Constant<Bits<5>>,
    g_sr: Constant<Bits<5>>,
    f_bf_up: Constant<Bits<5>>,
    f_bf_sub: Constant<Bits<5>>,
    r_restore: Constant<Bits<5>>,
    r_decouple: Constant<Bits<5>>,
    n_force: Constant<Bits<5>>,
    n_srp_pairs: Constant<Bits<5>>,
    n_nrp_pairs: Constant<Bits<5>>,
    n_ddsp_frames: Constant<Bits<5>>,
    n_srp_bits: Constant<Bits<5>>,
    n_nrp_bits: Constant<Bits<5>>,
    n_ddsp_bits: Constant<Bits<5>>,
    n_block: Constant<Bits<5>>,
    // ---- reset values and clamps ----
    btr_reset: Constant<Bits<15>>,
    zero4: Constant<Bits<4>>,
    sd_up_reset: Constant<Bits<6>>,
    sd_sub_reset: Constant<Bits<6>>,
    sd_min: Constant<Bits<6>>,
    sr_reset: Constant<Bits<4>>,
    bf_up_reset: Constant<Bits<8>>,
    bf_sub_reset: Constant<Bits<8>>,
    bf_min: Constant<Bits<8>>,
    restore_reset: Constant<Bits<16>>,
    decouple_reset: Constant<Bits<16>>,
    force_reset: Constant<Bits<10>>,
    force_min: Constant<Bits<10>>,
    srp_pairs_reset: Constant<Bits<4>>,
    nrp_pairs_reset: Constant<Bits<4>>,
    ddsp_frames_reset: Constant<Bits<4>>,
    frames_min: Constant<Bits<4>>,
    srp_bits_reset: Constant<Bits<16>>,
    nrp_bits_reset: Constant<Bits<16>>,
    ddsp_bits_reset: Constant<Bits<16>>,
    bits_min: Constant<Bits<16>>,
    block_reset: Constant<Bits<5>>,
    block_min: Constant<Bits<5>>,
    zero5: Constant<Bits<5>>,
    zero32: Constant<Bits<32>>,
}

impl Default for HubConfig {
    fn default() -> Self {
        let btr = map::register("BTR").unwrap();
        assert!(
            btr.defined() & !0x7FFF == 0xF << 24,
            "register map HUB: BTR has fields above bit 14 other than brp_ext [27:24]"
        );
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            adr: Default::default(),
            wdat: Default::default(),
            reset_mode: Default::default(),
            hit: Default::default(),
            rdata: Default::default(),
            brp: Default::default(),
            tseg1: Default::default(),
            tseg2: Default::default(),
            sjw: Default::default(),
            sd_run_up: Default::default(),
            sd_run_sub: Default::default(),
            sr_frames: Default::default(),
            bf_up: Default::default(),
            bf_sub: Default::default(),
            restore_bits: Default::default(),
            decouple_bits: Default::default(),
            force_bits: Default::default(),
            srp_pairs: Default::default(),
            nrp_pairs: Default::default(),
            ddsp_frames: Default::default(),
            srp_bits: Default::default(),
            nrp_bits: Default::default(),
            ddsp_bits: Default::default(),
            block_frames: Default::default(),
            btr_q: Default::default(),
            brp_ext_q: Default::default(),
            sd_up_q: Default::default(),
            sd_sub_q: Default::default(),
            sr_q: Default::default(),
            bf_up_q: Default::default(),
            bf_sub_q: Default::default(),
            restore_q: Default::default(),
            decouple_q: Default::default(),
            force_q: Default::default(),
            srp_pairs_q: Default::default(),
            nrp_pairs_q: Default::default(),
            ddsp_frames_q: Default::default(),
            srp_bits_q: Default::default(),
            nrp_bits_q: Default::default(),
            ddsp_bits_q: Default::default(),
            block_q: Default::default(),
            store: Default::default(),
            w6a: Default::default(),
            w6b: Default::default(),
            w8a: Default::default(),
            w8b: Default::default(),
            w10: Default::default(),
            w4a: Default::default(),
            w4b: Default::default(),
            w4c: Default::default(),
            w16a: Default::default(),
            w16b: Default::default(),
            w16c: Default::default(),
            w5: Default::default(),
            a_btr: adr(map::BTR),
            a_guard: adr(map::GUARD_CFG),
            a_bf: adr(map::BF_CFG),
            a_restore: adr(map::RESTORE_CFG),
            a_ncfg: adr(map::NRAP_CFG),
            a_ntime: adr(map::NRAP_TIME),
            a_nddsp: adr(map::NRAP_DDSP),
            b_brp: lsb(&MAP, "BTR", "brp", 6),
            b_brp_ext: lsb(&MAP, "BTR", "brp_ext", 4),
            brp_ext_shift: Constant::new(6.into()),
            b_tseg1: lsb(&MAP, "BTR", "tseg1", 4),
            b_tseg2: lsb(&MAP, "BTR", "tseg2", 3),
            b_sjw: lsb(&MAP, "BTR", "sjw", 2),
            g_sd_up: lsb(&MAP, "GUARD_CFG", "sd_run_up", 6),
            g_sd_sub: lsb(&MAP, "GUARD_CFG", "sd_run_sub", 6),
            g_sr: lsb(&MAP, "GUARD_CFG", "sr_frames", 4),
            f_bf_up: lsb(&MAP, "BF_CFG", "bf_up", 8),
            f_bf_sub: lsb(&MAP, "BF_CFG", "bf_sub", 8),
            r_restore: lsb(&MAP, "RESTORE_CFG", "restore_bits", 16),
            r_decouple: lsb(&MAP, "RESTORE_CFG", "decouple_bits", 16),
            n_force: lsb(&MAP, "NRAP_CFG", "force_bits", 10),
            n_srp_pairs: lsb(&MAP, "NRAP_CFG", "srp_pairs", 4),
            n_nrp_pairs: lsb(&MAP, "NRAP_CFG", "nrp_pairs", 4),
            n_ddsp_frames: lsb(&MAP, "NRAP_CFG", "ddsp_frames", 4),
            n_srp_bits: lsb(&MAP, "NRAP_TIME", "srp_bits", 16),
            n_nrp_bits: lsb(&MAP, "NRAP_TIME", "nrp_bits", 16),
            n_ddsp_bits: lsb(&MAP, "NRAP_DDSP", "ddsp_bits", 16),
            n_block: lsb(&MAP, "NRAP_DDSP", "block_frames", 5),
            btr_reset: Constant::new((btr.reset_value() as u64).into()),
            zero4: Constant::new(0.into()),
            sd_up_reset: reset("GUARD_CFG", "sd_run_up"),
            sd_sub_reset: reset("GUARD_CFG", "sd_run_sub"),
            sd_min: min(SD_MIN),
            sr_reset: reset("GUARD_CFG", "sr_frames"),
            bf_up_reset: reset("BF_CFG", "bf_up"),
            bf_sub_reset: reset("BF_CFG", "bf_sub"),
            bf_min: min(BF_MIN),
            restore_reset: reset("RESTORE_CFG", "restore_bits"),
            decouple_reset: reset("RESTORE_CFG", "decouple_bits"),
            force_reset: reset("NRAP_CFG", "force_bits"),
            force_min: min(FORCE_MIN),
            srp_pairs_reset: reset("NRAP_CFG", "srp_pairs"),
            nrp_pairs_reset: reset("NRAP_CFG", "nrp_pairs"),
            ddsp_frames_reset: reset("NRAP_CFG", "ddsp_frames"),
            frames_min: min(NRAP_COUNT_MIN),
            srp_bits_reset: reset("NRAP_TIME", "srp_bits"),
            nrp_bits_reset: reset("NRAP_TIME", "nrp_bits"),
            ddsp_bits_reset: reset("NRAP_DDSP", "ddsp_bits"),
            bits_min: min(NRAP_BITS_MIN),
            block_reset: reset("NRAP_DDSP", "block_frames"),
            block_min: min(BLOCK_MIN),
            zero5: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl Logic for HubConfig {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            btr_q,
            brp_ext_q,
            sd_up_q,
            sd_sub_q,
            sr_q,
            bf_up_q,
            bf_sub_q,
            restore_q,
            decouple_q,
            force_q,
            srp_pairs_q,
            nrp_pairs_q,
            ddsp_frames_q,
            srp_bits_q,
            nrp_bits_q,
            ddsp_bits_q,
            block_q
        );
        // ---- decode and read values ----
        self.hit.next = false;
        self.rdata.next = self.zero32.val();
        if self.adr.val() == self.a_btr.val() {
            self.hit.next = true;
            self.rdata.next = bit_cast::<32, 15>(self.btr_q.q.val())
                | (bit_cast::<32, 4>(self.brp_ext_q.q.val()) << self.b_brp_ext.val());
        } else if self.adr.val() == self.a_guard.val() {
            self.hit.next = true;
            self.rdata.next = (bit_cast::<32, 6>(self.sd_up_q.q.val()) << self.g_sd_up.val())
                | (bit_cast::<32, 6>(self.sd_sub_q.q.val()) << self.g_sd_sub.val())
                | (bit_cast::<32, 4>(self.sr_q.q.val()) << self.g_sr.val());
        } else if self.adr.val() == self.a_bf.val() {
            self.hit.next = true;
            self.rdata.next = (bit_cast::<32, 8>(self.bf_up_q.q.val()) << self.f_bf_up.val())
                | (bit_cast::<32, 8>(self.bf_sub_q.q.val()) << self.f_bf_sub.val());
        } else if self.adr.val() == self.a_restore.val() {
            self.hit.next = true;
            self.rdata.next = (bit_cast::<32, 16>(self.restore_q.q.val()) << self.r_restore.val())
                | (bit_cast::<32, 16>(self.decouple_q.q.val()) << self.r_decouple.val());
        } else if self.adr.val() == self.a_ncfg.val() {
            self.hit.next = true;
            self.rdata.next = (bit_cast::<32, 10>(self.force_q.q.val()) << self.n_force.val())
                | (bit_cast::<32, 4>(self.srp_pairs_q.q.val()) << self.n_srp_pairs.val())
                | (bit_cast::<32, 4>(self.nrp_pairs_q.q.val()) << self.n_nrp_pairs.val())
                | (bit_cast::<32, 4>(self.ddsp_frames_q.q.val()) << self.n_ddsp_frames.val());
        } else if self.adr.val() == self.a_ntime.val() {
            self.hit.next = true;
            self.rdata.next = (bit_cast::<32, 16>(self.srp_bits_q.q.val())
                << self.n_srp_bits.val())
                | (bit_cast::<32, 16>(self.nrp_bits_q.q.val()) << self.n_nrp_bits.val());
        } else if self.adr.val() == self.a_nddsp.val() {
            self.hit.next = true;
            self.rdata.next = (bit_cast::<32, 16>(self.ddsp_bits_q.q.val())
                << self.n_ddsp_bits.val())
                | (bit_cast::<32, 5>(self.block_q.q.val()) << self.n_block.val());
        }

        // ---- the written fields ----
        self.w6a.next = self.wdat.val().get_bits::<6>(self.g_sd_up.val().index());
        self.w6b.next = self.wdat.val().get_bits::<6>(self.g_sd_sub.val().index());
        self.w8a.next = self.wdat.val().get_bits::<8>(self.f_bf_up.val().index());
        self.w8b.next = self.wdat.val().get_bits::<8>(self.f_bf_sub.val().index());
        self.w10.next = self.wdat.val().get_bits::<10>(self.n_force.val().index());
        self.w4a.next = self
            .wdat
            .val()
            .get_bits::<4>(self.n_srp_pairs.val().index());
        self.w4b.next = self
            .wdat
            .val()
            .get_bits::<4>(self.n_nrp_pairs.val().index());
        self.w4c.next = self
            .wdat
            .val()
            .get_bits::<4>(self.n_ddsp_frames.val().index());
        self.w16a.next = self
            .wdat
            .val()
            .get_bits::<16>(self.n_srp_bits.val().index());
        self.w16b.next = self
            .wdat
            .val()
            .get_bits::<16>(self.n_nrp_bits.val().index());
        self.w16c.next = self
            .wdat
            .val()
            .get_bits::<16>(self.n_ddsp_bits.val().index());
        self.w5.next = self.wdat.val().get_bits::<5>(self.n_block.val().index());

        // ---- writes: stored in reset mode, with the clamps ----
        self.store.next = self.wr.val() & self.reset_mode.val();
        if self.store.val() {
            if self.adr.val() == self.a_btr.val() {
                self.btr_q.d.next = self.wdat.val().get_bits::<15>(0);
                self.brp_ext_q.d.next = self.wdat.val().get_bits::<4>(self.b_brp_ext.val().index());
            } else if self.adr.val() == self.a_guard.val() {
                if self.w6a.val() < self.sd_min.val() {
                    self.sd_up_q.d.next = self.sd_min.val();
                } else {
                    self.sd_up_q.d.next = self.w6a.val();
                }
                if self.w6b.val() < self.sd_min.val() {
                    self.sd_sub_q.d.next = self.sd_min.val();
                } else {
                    self.sd_sub_q.d.next = self.w6b.val();
                }
                self.sr_q.d.next = self.wdat.val().get_bits::<4>(self.g_sr.val().index());
            } else if self.adr.val() == self.a_bf.val() {
                if self.w8a.val() < self.bf_min.val() {
                    self.bf_up_q.d.next = self.bf_min.val();
                } else {
                    self.bf_up_q.d.next = self.w8a.val();
                }
                if self.w8b.val() < self.bf_min.val() {
                    self.bf_sub_q.d.next = self.bf_min.val();
                } else {
                    self.bf_sub_q.d.next = self.w8b.val();
                }
            } else if self.adr.val() == self.a_restore.val() {
                self.restore_q.d.next =
                    self.wdat.val().get_bits::<16>(self.r_restore.val().index());
                self.decouple_q.d.next = self
                    .wdat
                    .val()
                    .get_bits::<16>(self.r_decouple.val().index());
            } else if self.adr.val() == self.a_ncfg.val() {
                if self.w10.val() < self.force_min.val() {
                    self.force_q.d.next = self.force_min.val();
                } else {
                    self.force_q.d.next = self.w10.val();
                }
                if self.w4a.val() < self.frames_min.val() {
                    self.srp_pairs_q.d.next = self.frames_min.val();
                } else {
                    self.srp_pairs_q.d.next = self.w4a.val();
                }
                if self.w4b.val() < self.frames_min.val() {
                    self.nrp_pairs_q.d.next = self.frames_min.val();
                } else {
                    self.nrp_pairs_q.d.next = self.w4b.val();
                }
                if self.w4c.val() < self.frames_min.val() {
                    self.ddsp_frames_q.d.next = self.frames_min.val();
                } else {
                    self.ddsp_frames_q.d.next = self.w4c.val();
                }
            } else if self.adr.val() == self.a_ntime.val() {
                if self.w16a.val() < self.bits_min.val() {
                    self.srp_bits_q.d.next = self.bits_min.val();
                } else {
                    self.srp_bits_q.d.next = self.w16a.val();
                }
                if self.w16b.val() < self.bits_min.val() {
                    self.nrp_bits_q.d.next = self.bits_min.val();
                } else {
                    self.nrp_bits_q.d.next = self.w16b.val();
                }
            } else if self.adr.val() == self.a_nddsp.val() {
                if self.w16c.val() < self.bits_min.val() {
                    self.ddsp_bits_q.d.next = self.bits_min.val();
                } else {
                    self.ddsp_bits_q.d.next = self.w16c.val();
                }
                if (self.w5.val() != self.zero5.val()) & (self.w5.val() < self.block_min.val()) {
                    self.block_q.d.next = self.block_min.val();
                } else {
                    self.block_q.d.next = self.w5.val();
                }
            }
        }

        if self.rst.val() {
            self.btr_q.d.next = self.btr_reset.val();
            self.brp_ext_q.d.next = self.zero4.val();
            self.sd_up_q.d.next = self.sd_up_reset.val();
            self.sd_sub_q.d.next = self.sd_sub_reset.val();
            self.sr_q.d.next = self.sr_reset.val();
            self.bf_up_q.d.next = self.bf_up_reset.val();
            self.bf_sub_q.d.next = self.bf_sub_reset.val();
            self.restore_q.d.next = self.restore_reset.val();
            self.decouple_q.d.next = self.decouple_reset.val();
            self.force_q.d.next = self.force_reset.val();
            self.srp_pairs_q.d.next = self.srp_pairs_reset.val();
            self.nrp_pairs_q.d.next = self.nrp_pairs_reset.val();
            self.ddsp_frames_q.d.next = self.ddsp_frames_reset.val();
            self.srp_bits_q.d.next = self.srp_bits_reset.val();
            self.nrp_bits_q.d.next = self.nrp_bits_reset.val();
            self.ddsp_bits_q.d.next = self.ddsp_bits_reset.val();
            self.block_q.d.next = self.block_reset.val();
        }

        // ---- outputs ----
        self.brp.next =
            bit_cast::<BRP_BITS, 6>(self.btr_q.q.val().get_bits::<6>(self.b_brp.val().index()))
                | (bit_cast::<BRP_BITS, 4>(self.brp_ext_q.q.val()) << self.brp_ext_shift.val());
        self.tseg1.next = self.btr_q.q.val().get_bits::<4>(self.b_tseg1.val().index());
        self.tseg2.next = self.btr_q.q.val().get_bits::<3>(self.b_tseg2.val().index());
        self.sjw.next = self.btr_q.q.val().get_bits::<2>(self.b_sjw.val().index());
        self.sd_run_up.next = self.sd_up_q.q.val();
        self.sd_run_sub.next = self.sd_sub_q.q.val();
        self.sr_frames.next = self.sr_q.q.val();
        self.bf_up.next = self.bf_up_q.q.val();
        self.bf_sub.next = self.bf_sub_q.q.val();
        self.restore_bits.next = self.restore_q.q.val();
        self.decouple_bits.next = self.decouple_q.q.val();
        self.force_bits.next = self.force_q.q.val();
        self.srp_pairs.next = self.srp_pairs_q.q.val();
        self.nrp_pairs.next = self.nrp_pairs_q.q.val();
        self.ddsp_frames.next = self.ddsp_frames_q.q.val();
        self.srp_bits.next = self.srp_bits_q.q.val();
        self.nrp_bits.next = self.nrp_bits_q.q.val();
        self.ddsp_bits.next = self.ddsp_bits_q.q.val();
        self.block_frames.next = self.block_q.q.val();
    }
}
