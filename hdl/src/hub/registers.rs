//! Wishbone slave and register block of the hub (hub contract §8, with the
//! Wishbone conventions of the DRCC contract §D.1/§D.2) and the decoupling state
//! of §7 (ReCANcentrate paper section 5: definitive decoupling).
//!
//! - A transaction is taken at an edge where `cyc & stb & !ack`: `ack <= 1` and,
//!   for a read, `dat_o <=` the register value before the edge; a write takes
//!   effect at that edge. Otherwise `ack <= 0`, `dat_o <= 0`. Unmapped reads are 0.
//! - cfg fields (`CTRL.ack_interdep`, `BTR`, `GUARD_CFG`, `BF_CFG`, `RESTORE_CFG`)
//!   are writable only in reset mode, with the clamps of §8; refused writes,
//!   writes to RO/unmapped registers, a CTRL write whose `ack_interdep` differs
//!   outside reset mode and a CTRL write carrying both commands set
//!   `INT_STATUS.illegal`.
//! - `CTRL.force_decouple` / `CTRL.recouple` act only with `reset_mode` 0 before
//!   the write and in the written value. The sublink guards get the `recouple`
//!   pulse from the top (decoded there so that no always block both reads the
//!   guard events and drives the command: no combinational cycle for Verilator).
//! - §7: `no_twin` counts SAMPLE edges without an enabled sublink; it decouples
//!   after `decouple_bits` of them. A command wins over that at the same edge.
//! - `INT_STATUS` is W1C, an event at the same edge wins; `irq <=
//!   |(INT_STATUS & INT_ENABLE)`.
//! - Reset mode (`reset_mode` before the edge) holds `no_twin` and `decoupled` at
//!   0; `INT_STATUS`/`INT_ENABLE` are kept.
//!
//! N node ports, M interlinks, P = N + M ports; the `PORT_p` word for the addressed
//! port is selected by the top (`port_rd`).

use rust_hdl::prelude::*;

/// Word indices of the hub register map (contract §8).
pub const ID: u32 = 0;
pub const CTRL: u32 = 1;
pub const BTR: u32 = 2;
pub const GUARD_CFG: u32 = 3;
pub const BF_CFG: u32 = 4;
pub const RESTORE_CFG: u32 = 5;
pub const STATUS: u32 = 6;
pub const INT_STATUS: u32 = 7;
pub const INT_ENABLE: u32 = 8;
pub const STATS: u32 = 9;
/// `PORT_p` is at word index `PORT0 + p`.
pub const PORT0: u32 = 16;
/// Reset values (contract §8).
pub const BTR_RESET: u32 = (4 << 6) | (1 << 10);
pub const GUARD_CFG_RESET: u32 = 14 | (16 << 8) | (8 << 16);
pub const BF_CFG_RESET: u32 = 32 | (64 << 8);
pub const RESTORE_CFG_RESET: u32 = 1408 | (4096 << 16);

/// The ID register value of a hub with N node ports and M interlinks.
pub fn id_value(n: usize, m: usize) -> u32 {
    0x4855_0000 | ((n as u32) << 8) | m as u32
}

fn adr(index: u32) -> Constant<Bits<6>> {
    Constant::new((index as u64).into())
}

/// The hub's Wishbone register block.
#[derive(LogicBlock)]
pub struct HubRegs<const N: usize, const M: usize, const P: usize> {
    // clock and reset
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Wishbone B4 classic slave
    pub wb_cyc_i: Signal<In, Bit>,
    pub wb_stb_i: Signal<In, Bit>,
    pub wb_we_i: Signal<In, Bit>,
    pub wb_adr_i: Signal<In, Bits<6>>,
    pub wb_dat_i: Signal<In, Bits<32>>,
    pub wb_dat_o: Signal<Out, Bits<32>>,
    pub wb_ack_o: Signal<Out, Bit>,
    pub irq: Signal<Out, Bit>,
    // status inputs
    pub sample: Signal<In, Bit>,
    pub any_sub_en: Signal<In, Bit>,
    pub trk: Signal<In, Bits<2>>,
    pub ack_window: Signal<In, Bit>,
    pub port_en: Signal<In, Bits<P>>,
    pub frames: Signal<In, Bits<16>>,
    pub errors: Signal<In, Bits<16>>,
    /// PORT_p word of the addressed port (0 when the address is no port).
    pub port_rd: Signal<In, Bits<32>>,
    // events
    pub ev_iso: Signal<In, Bit>,
    pub ev_rest: Signal<In, Bit>,
    // configuration and state outputs
    pub reset_mode: Signal<Out, Bit>,
    /// `reset_mode` one edge earlier (1 after `rst`).
    pub reset_mode_d: Signal<Out, Bit>,
    pub ack_interdep: Signal<Out, Bit>,
    pub decoupled: Signal<Out, Bit>,
    pub brp: Signal<Out, Bits<6>>,
    pub tseg1: Signal<Out, Bits<4>>,
    pub tseg2: Signal<Out, Bits<3>>,
    pub sjw: Signal<Out, Bits<2>>,
    pub sd_run_up: Signal<Out, Bits<6>>,
    pub sd_run_sub: Signal<Out, Bits<6>>,
    pub sr_frames: Signal<Out, Bits<4>>,
    pub bf_up: Signal<Out, Bits<8>>,
    pub bf_sub: Signal<Out, Bits<8>>,
    pub restore_bits: Signal<Out, Bits<16>>,
    // registers
    ack_q: DFF<Bit>,
    dat_q: DFF<Bits<32>>,
    irq_q: DFF<Bit>,
    reset_mode_q: DFF<Bit>,
    reset_mode_dq: DFF<Bit>,
    ack_interdep_q: DFF<Bit>,
    btr_q: DFF<Bits<15>>,
    sd_up_q: DFF<Bits<6>>,
    sd_sub_q: DFF<Bits<6>>,
    sr_q: DFF<Bits<4>>,
    bf_up_q: DFF<Bits<8>>,
    bf_sub_q: DFF<Bits<8>>,
    restore_q: DFF<Bits<16>>,
    decouple_q: DFF<Bits<16>>,
    int_status: DFF<Bits<4>>,
    int_enable: DFF<Bits<4>>,
    decoupled_q: DFF<Bit>,
    no_twin: DFF<Bits<16>>,
    // decode
    taken: Signal<Local, Bit>,
    wr: Signal<Local, Bit>,
    wdat: Signal<Local, Bits<32>>,
    rdata: Signal<Local, Bits<32>>,
    is_port: Signal<Local, Bit>,
    illegal: Signal<Local, Bit>,
    w1c: Signal<Local, Bits<4>>,
    dec_evt: Signal<Local, Bit>,
    no_twin_new: Signal<Local, Bits<16>>,
    events: Signal<Local, Bits<4>>,
    // register indices
    a_id: Constant<Bits<6>>,
    a_ctrl: Constant<Bits<6>>,
    a_btr: Constant<Bits<6>>,
    a_guard: Constant<Bits<6>>,
    a_bf: Constant<Bits<6>>,
    a_restore: Constant<Bits<6>>,
    a_status: Constant<Bits<6>>,
    a_int_status: Constant<Bits<6>>,
    a_int_enable: Constant<Bits<6>>,
    a_stats: Constant<Bits<6>>,
    a_port0: Constant<Bits<6>>,
    a_port_end: Constant<Bits<6>>,
    // constants
    id_val: Constant<Bits<32>>,
    btr_reset: Constant<Bits<15>>,
    sd_up_reset: Constant<Bits<6>>,
    sd_sub_reset: Constant<Bits<6>>,
    sd_min: Constant<Bits<6>>,
    sr_reset: Constant<Bits<4>>,
    bf_up_reset: Constant<Bits<8>>,
    bf_sub_reset: Constant<Bits<8>>,
    bf_min: Constant<Bits<8>>,
    restore_reset: Constant<Bits<16>>,
    decouple_reset: Constant<Bits<16>>,
    zero4: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
    zero32: Constant<Bits<32>>,
}

impl<const N: usize, const M: usize, const P: usize> Default for HubRegs<N, M, P> {
    fn default() -> Self {
        assert!((2..=8).contains(&N), "hub: N node ports must be 2..=8");
        assert!((1..=4).contains(&M), "hub: M interlinks must be 1..=4");
        assert_eq!(P, N + M, "hub: P must be N + M");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            sample: Default::default(),
            any_sub_en: Default::default(),
            trk: Default::default(),
            ack_window: Default::default(),
            port_en: Default::default(),
            frames: Default::default(),
            errors: Default::default(),
            port_rd: Default::default(),
            ev_iso: Default::default(),
            ev_rest: Default::default(),
            reset_mode: Default::default(),
            reset_mode_d: Default::default(),
            ack_interdep: Default::default(),
            decoupled: Default::default(),
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
            ack_q: Default::default(),
            dat_q: Default::default(),
            irq_q: Default::default(),
            reset_mode_q: Default::default(),
            reset_mode_dq: Default::default(),
            ack_interdep_q: Default::default(),
            btr_q: Default::default(),
            sd_up_q: Default::default(),
            sd_sub_q: Default::default(),
            sr_q: Default::default(),
            bf_up_q: Default::default(),
            bf_sub_q: Default::default(),
            restore_q: Default::default(),
            decouple_q: Default::default(),
            int_status: Default::default(),
            int_enable: Default::default(),
            decoupled_q: Default::default(),
            no_twin: Default::default(),
            taken: Default::default(),
            wr: Default::default(),
            wdat: Default::default(),
            rdata: Default::default(),
            is_port: Default::default(),
            illegal: Default::default(),
            w1c: Default::default(),
            dec_evt: Default::default(),
            no_twin_new: Default::default(),
            events: Default::default(),
            a_id: adr(ID),
            a_ctrl: adr(CTRL),
            a_btr: adr(BTR),
            a_guard: adr(GUARD_CFG),
            a_bf: adr(BF_CFG),
            a_restore: adr(RESTORE_CFG),
            a_status: adr(STATUS),
            a_int_status: adr(INT_STATUS),
            a_int_enable: adr(INT_ENABLE),
            a_stats: adr(STATS),
            a_port0: adr(PORT0),
            a_port_end: adr(PORT0 + P as u32),
            id_val: Constant::new((id_value(N, M) as u64).into()),
            btr_reset: Constant::new((BTR_RESET as u64).into()),
            sd_up_reset: Constant::new(14.into()),
            sd_sub_reset: Constant::new(16.into()),
            sd_min: Constant::new(14.into()),
            sr_reset: Constant::new(8.into()),
            bf_up_reset: Constant::new(32.into()),
            bf_sub_reset: Constant::new(64.into()),
            bf_min: Constant::new(8.into()),
            restore_reset: Constant::new(1408.into()),
            decouple_reset: Constant::new(4096.into()),
            zero4: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const M: usize, const P: usize> Logic for HubRegs<N, M, P> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            ack_q,
            dat_q,
            irq_q,
            reset_mode_q,
            reset_mode_dq,
            ack_interdep_q,
            btr_q,
            sd_up_q,
            sd_sub_q,
            sr_q,
            bf_up_q,
            bf_sub_q,
            restore_q,
            decouple_q,
            int_status,
            int_enable,
            decoupled_q,
            no_twin
        );
        self.taken.next = self.wb_cyc_i.val() & self.wb_stb_i.val() & !self.ack_q.q.val();
        self.wr.next = self.taken.val() & self.wb_we_i.val();
        self.wdat.next = self.wb_dat_i.val();
        self.is_port.next = (self.wb_adr_i.val() >= self.a_port0.val())
            & (self.wb_adr_i.val() < self.a_port_end.val());

        // ---- read values ----
        self.rdata.next = self.zero32.val();
        if self.wb_adr_i.val() == self.a_id.val() {
            self.rdata.next = self.id_val.val();
        } else if self.wb_adr_i.val() == self.a_ctrl.val() {
            self.rdata.next = bit_cast::<32, 1>(self.reset_mode_q.q.val().into())
                | (bit_cast::<32, 1>(self.ack_interdep_q.q.val().into()) << 8);
        } else if self.wb_adr_i.val() == self.a_btr.val() {
            self.rdata.next = bit_cast::<32, 15>(self.btr_q.q.val());
        } else if self.wb_adr_i.val() == self.a_guard.val() {
            self.rdata.next = bit_cast::<32, 6>(self.sd_up_q.q.val())
                | (bit_cast::<32, 6>(self.sd_sub_q.q.val()) << 8)
                | (bit_cast::<32, 4>(self.sr_q.q.val()) << 16);
        } else if self.wb_adr_i.val() == self.a_bf.val() {
            self.rdata.next = bit_cast::<32, 8>(self.bf_up_q.q.val())
                | (bit_cast::<32, 8>(self.bf_sub_q.q.val()) << 8);
        } else if self.wb_adr_i.val() == self.a_restore.val() {
            self.rdata.next = bit_cast::<32, 16>(self.restore_q.q.val())
                | (bit_cast::<32, 16>(self.decouple_q.q.val()) << 16);
        } else if self.wb_adr_i.val() == self.a_status.val() {
            self.rdata.next = bit_cast::<32, 1>(self.reset_mode_q.q.val().into())
                | (bit_cast::<32, 1>(self.decoupled_q.q.val().into()) << 1)
                | (bit_cast::<32, 1>(self.ack_window.val().into()) << 2)
                | (bit_cast::<32, 2>(self.trk.val()) << 4)
                | (bit_cast::<32, P>(self.port_en.val()) << 16);
        } else if self.wb_adr_i.val() == self.a_int_status.val() {
            self.rdata.next = bit_cast::<32, 4>(self.int_status.q.val());
        } else if self.wb_adr_i.val() == self.a_int_enable.val() {
            self.rdata.next = bit_cast::<32, 4>(self.int_enable.q.val());
        } else if self.wb_adr_i.val() == self.a_stats.val() {
            self.rdata.next = bit_cast::<32, 16>(self.frames.val())
                | (bit_cast::<32, 16>(self.errors.val()) << 16);
        } else if self.is_port.val() {
            self.rdata.next = self.port_rd.val();
        }

        // ---- Wishbone handshake ----
        self.ack_q.d.next = self.taken.val();
        self.dat_q.d.next = self.zero32.val();
        if self.taken.val() & !self.wb_we_i.val() {
            self.dat_q.d.next = self.rdata.val();
        }
        self.reset_mode_dq.d.next = self.reset_mode_q.q.val();

        // ---- §7 decoupling (at SAMPLE edges) ----
        self.dec_evt.next = false;
        if self.any_sub_en.val() {
            self.no_twin_new.next = self.zero16.val();
        } else if self.no_twin.q.val() == self.max16.val() {
            self.no_twin_new.next = self.max16.val();
        } else {
            self.no_twin_new.next = self.no_twin.q.val() + self.one16.val();
        }
        if self.sample.val() {
            self.no_twin.d.next = self.no_twin_new.val();
            if !self.decoupled_q.q.val()
                & (self.decouple_q.q.val() != self.zero16.val())
                & (self.no_twin_new.val() >= self.decouple_q.q.val())
            {
                self.decoupled_q.d.next = true;
                self.dec_evt.next = true;
            }
        }

        // ---- writes ----
        self.illegal.next = false;
        self.w1c.next = self.zero4.val();
        if self.wr.val() {
            if self.wb_adr_i.val() == self.a_ctrl.val() {
                if self.wdat.val().get_bit(1) & self.wdat.val().get_bit(2) {
                    // both commands in one write: refused
                    self.illegal.next = true;
                } else {
                    self.reset_mode_q.d.next = self.wdat.val().get_bit(0);
                    if self.reset_mode_q.q.val() {
                        self.ack_interdep_q.d.next = self.wdat.val().get_bit(8);
                    } else {
                        self.illegal.next =
                            self.wdat.val().get_bit(8) != self.ack_interdep_q.q.val();
                        if !self.wdat.val().get_bit(0) {
                            if self.wdat.val().get_bit(1) {
                                // force_decouple
                                self.decoupled_q.d.next = true;
                                self.dec_evt.next = true;
                            }
                            if self.wdat.val().get_bit(2) {
                                // recouple
                                self.decoupled_q.d.next = false;
                                self.no_twin.d.next = self.zero16.val();
                                self.dec_evt.next = false;
                            }
                        }
                    }
                }
            } else if self.wb_adr_i.val() == self.a_btr.val() {
                if self.reset_mode_q.q.val() {
                    self.btr_q.d.next = self.wdat.val().get_bits::<15>(0);
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_guard.val() {
                if self.reset_mode_q.q.val() {
                    if self.wdat.val().get_bits::<6>(0) < self.sd_min.val() {
                        self.sd_up_q.d.next = self.sd_min.val();
                    } else {
                        self.sd_up_q.d.next = self.wdat.val().get_bits::<6>(0);
                    }
                    if self.wdat.val().get_bits::<6>(8) < self.sd_min.val() {
                        self.sd_sub_q.d.next = self.sd_min.val();
                    } else {
                        self.sd_sub_q.d.next = self.wdat.val().get_bits::<6>(8);
                    }
                    self.sr_q.d.next = self.wdat.val().get_bits::<4>(16);
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_bf.val() {
                if self.reset_mode_q.q.val() {
                    if self.wdat.val().get_bits::<8>(0) < self.bf_min.val() {
                        self.bf_up_q.d.next = self.bf_min.val();
                    } else {
                        self.bf_up_q.d.next = self.wdat.val().get_bits::<8>(0);
                    }
                    if self.wdat.val().get_bits::<8>(8) < self.bf_min.val() {
                        self.bf_sub_q.d.next = self.bf_min.val();
                    } else {
                        self.bf_sub_q.d.next = self.wdat.val().get_bits::<8>(8);
                    }
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_restore.val() {
                if self.reset_mode_q.q.val() {
                    self.restore_q.d.next = self.wdat.val().get_bits::<16>(0);
                    self.decouple_q.d.next = self.wdat.val().get_bits::<16>(16);
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_int_status.val() {
                self.w1c.next = self.wdat.val().get_bits::<4>(0);
            } else if self.wb_adr_i.val() == self.a_int_enable.val() {
                self.int_enable.d.next = self.wdat.val().get_bits::<4>(0);
            } else {
                // read-only or unmapped
                self.illegal.next = true;
            }
        }

        // reset mode holds no_twin and decoupled (value before the edge)
        if self.reset_mode_q.q.val() {
            self.no_twin.d.next = self.zero16.val();
            self.decoupled_q.d.next = false;
            self.dec_evt.next = false;
        }

        // ---- interrupts ----
        self.events.next = bit_cast::<4, 1>(self.ev_iso.val().into())
            | (bit_cast::<4, 1>(self.ev_rest.val().into()) << 1)
            | (bit_cast::<4, 1>(self.dec_evt.val().into()) << 2)
            | (bit_cast::<4, 1>(self.illegal.val().into()) << 3);
        self.int_status.d.next = (self.int_status.q.val() & !self.w1c.val()) | self.events.val();
        self.irq_q.d.next = (self.int_status.q.val() & self.int_enable.q.val()) != self.zero4.val();

        if self.rst.val() {
            self.ack_q.d.next = false;
            self.dat_q.d.next = self.zero32.val();
            self.irq_q.d.next = false;
            self.reset_mode_q.d.next = true;
            self.reset_mode_dq.d.next = true;
            self.ack_interdep_q.d.next = true;
            self.btr_q.d.next = self.btr_reset.val();
            self.sd_up_q.d.next = self.sd_up_reset.val();
            self.sd_sub_q.d.next = self.sd_sub_reset.val();
            self.sr_q.d.next = self.sr_reset.val();
            self.bf_up_q.d.next = self.bf_up_reset.val();
            self.bf_sub_q.d.next = self.bf_sub_reset.val();
            self.restore_q.d.next = self.restore_reset.val();
            self.decouple_q.d.next = self.decouple_reset.val();
            self.int_status.d.next = self.zero4.val();
            self.int_enable.d.next = self.zero4.val();
            self.decoupled_q.d.next = false;
            self.no_twin.d.next = self.zero16.val();
        }

        // ---- outputs ----
        self.wb_ack_o.next = self.ack_q.q.val();
        self.wb_dat_o.next = self.dat_q.q.val();
        self.irq.next = self.irq_q.q.val();
        self.reset_mode.next = self.reset_mode_q.q.val();
        self.reset_mode_d.next = self.reset_mode_dq.q.val();
        self.ack_interdep.next = self.ack_interdep_q.q.val();
        self.decoupled.next = self.decoupled_q.q.val();
        self.brp.next = self.btr_q.q.val().get_bits::<6>(0);
        self.tseg1.next = self.btr_q.q.val().get_bits::<4>(6);
        self.tseg2.next = self.btr_q.q.val().get_bits::<3>(10);
        self.sjw.next = self.btr_q.q.val().get_bits::<2>(13);
        self.sd_run_up.next = self.sd_up_q.q.val();
        self.sd_run_sub.next = self.sd_sub_q.q.val();
        self.sr_frames.next = self.sr_q.q.val();
        self.bf_up.next = self.bf_up_q.q.val();
        self.bf_sub.next = self.bf_sub_q.q.val();
        self.restore_bits.next = self.restore_q.q.val();
    }
}

#[test]
fn hub_regs_synthesizes() {
    let mut uut = HubRegs::<4, 2, 6>::default();
    uut.connect_all();
    yosys_validate("hub_regs", &generate_verilog(&uut)).unwrap();
}
