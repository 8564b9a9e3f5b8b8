//! Wishbone slave and register block of the hub (hub contract §8, with the
//! Wishbone conventions of the DRCC contract §D.1/§D.2) and the decoupling state
//! of §7 (ReCANcentrate paper section 5: definitive decoupling).
//!
//! - The bus handshake and `INT_STATUS`/`INT_ENABLE`/`irq` are the shared
//!   Wishbone slave (`crate::host::wb_slave`, 6 interrupt bits); word indices,
//!   field positions and reset values come from the table
//!   (`crate::host::hub_registers`). Unmapped reads are 0. `ID` carries the
//!   const generic `H` (`HUB_ID`: 0 = hub A, 1 = hub B) at bit 12.
//! - The "RW cfg" registers (`BTR`, `GUARD_CFG`, `BF_CFG`, `RESTORE_CFG` and the
//!   NRAP registers `NRAP_CFG`, `NRAP_TIME`, `NRAP_DDSP`) are the block
//!   `super::config`, beside this one in the top: it reports whether the address
//!   is one of them (`cfg_hit`) and their read value; this block refuses such a
//!   write outside reset mode. The cfg bits of `CTRL` (`ack_interdep`, `nrap_on`)
//!   are here. Refused writes, writes to RO/unmapped registers (`NRAP_STATUS`
//!   included), a CTRL write whose bit 8 or 9 differs outside reset mode and a
//!   CTRL write carrying both commands set `INT_STATUS.illegal`.
//! - `CTRL.force_decouple` / `CTRL.recouple` act only with `reset_mode` 0 before
//!   the write and in the written value. The sublink guards and the NRAP phase
//!   machine get the command pulses from the top (decoded there so that no always
//!   block both reads the guard events and drives the command: no combinational
//!   cycle for Verilator); this block takes `decoupled` and `no_twin`.
//! - NRAP (§9): `NRAP_STATUS` reads the phase machine's word (`nrap_status`);
//!   its phase changes set `INT_STATUS.nrap`; its entry to `DDSP_FORCE`
//!   (`nrap_decouple`) sets `decoupled` and `INT_STATUS.decoupled` (a command at
//!   the same edge wins).
//! - `CTRL.fi_ack_leak` (§4.1 fault injection) and `CTRL.fi_no_twin` (§9.6) are
//!   runtime bits taken at every CTRL write that is taken at all (like
//!   `reset_mode`); they go to the coupler.
//! - `ACK_UNIT` and `INT_STATUS.ack_unit` show the ACK unit (§4.1,
//!   `super::ack_unit`): its `blocks` counter, its window and its event.
//! - §7: `no_twin` counts SAMPLE edges without an enabled sublink; it decouples
//!   after `decouple_bits` of them. The rule runs only while `nrap_on` is 0. A
//!   command wins over that at the same edge.
//! - Reset mode (`reset_mode` before the edge) holds `no_twin` and `decoupled` at
//!   0; `INT_STATUS`/`INT_ENABLE` are kept.
//!
//! N node ports, M interlinks, P = N + M ports; the `PORT_p` word for the addressed
//! port is selected by the top (`port_rd`).

use crate::host::hub_registers::{self as map, MAP};
use crate::host::map::{lsb, placed};
use crate::host::wb_slave::WbSlave;
use rust_hdl::prelude::*;

/// The word indices, for the top's decode (the table is the one source).
pub use crate::host::hub_registers::{CTRL, PORT0};

fn adr(index: u32) -> Constant<Bits<6>> {
    Constant::new((index as u64).into())
}

/// The hub's Wishbone register block (hub `H`: 0 = A, 1 = B).
#[derive(LogicBlock)]
pub struct HubRegs<const N: usize, const M: usize, const P: usize, const H: usize> {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register to its table reset value.
    pub rst: Signal<In, Bit>,
    // ---- Wishbone B4 classic slave ----
    /// Cycle in progress.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Strobe.
    pub wb_stb_i: Signal<In, Bit>,
    /// Write enable.
    pub wb_we_i: Signal<In, Bit>,
    /// Word index.
    pub wb_adr_i: Signal<In, Bits<6>>,
    /// Write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Byte lanes of a write: every hub word is written whole, so a write with
    /// another select than `4'b1111` is refused (bus_contract.md §1).
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Read data (registered, with the ack).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Acknowledge (registered).
    pub wb_ack_o: Signal<Out, Bit>,
    /// Error: the access was refused (registered, instead of the ack).
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request (registered).
    pub irq: Signal<Out, Bit>,
    // ---- status in ----
    /// SAMPLE edge of the bit timing (§7 counts at these).
    pub sample: Signal<In, Bit>,
    /// Some sublink port is enabled.
    pub any_sub_en: Signal<In, Bit>,
    /// Frame tracker state (`STATUS.trk`).
    pub trk: Signal<In, Bits<2>>,
    /// The tracker is in the ACK slot or delimiter.
    pub ack_window: Signal<In, Bit>,
    /// Enabled ports, bit p = port p.
    pub port_en: Signal<In, Bits<P>>,
    /// Frames tracked to their ACK slot.
    pub frames: Signal<In, Bits<16>>,
    /// Tracker errors.
    pub errors: Signal<In, Bits<16>>,
    /// PORT_p word of the addressed port (0 when the address is no port).
    pub port_rd: Signal<In, Bits<32>>,
    /// The ACK unit's `blocks` counter (`ACK_UNIT.blocks`).
    pub blocks: Signal<In, Bits<16>>,
    /// The ACK unit's window (`ACK_UNIT.u_window`).
    pub u_window: Signal<In, Bit>,
    /// `RESTORE_CFG.decouple_bits` (from `super::config`).
    pub decouple_bits: Signal<In, Bits<16>>,
    /// The address is a cfg register of `super::config`.
    pub cfg_hit: Signal<In, Bit>,
    /// Read value of that cfg register.
    pub cfg_rdata: Signal<In, Bits<32>>,
    /// The `NRAP_STATUS` word (§9.5).
    pub nrap_status: Signal<In, Bits<32>>,
    // ---- events in ----
    /// A port was isolated.
    pub ev_iso: Signal<In, Bit>,
    /// A port was restored.
    pub ev_rest: Signal<In, Bit>,
    /// The ACK unit intervened (first time in an ACK window).
    pub ev_ack_unit: Signal<In, Bit>,
    /// The NRAP phase changed (`INT_STATUS.nrap`).
    pub ev_nrap: Signal<In, Bit>,
    /// NRAP enters `DDSP_FORCE`: `decoupled = 1` (§9.2).
    pub nrap_decouple: Signal<In, Bit>,
    // ---- configuration and state out ----
    /// A whole-word write is taken at this edge (for `super::config`).
    pub wr: Signal<Out, Bit>,
    /// `CTRL.reset_mode`.
    pub reset_mode: Signal<Out, Bit>,
    /// `reset_mode` one edge earlier (1 after `rst`).
    pub reset_mode_d: Signal<Out, Bit>,
    /// `CTRL.ack_interdep`.
    pub ack_interdep: Signal<Out, Bit>,
    /// `CTRL.nrap_on`.
    pub nrap_on: Signal<Out, Bit>,
    /// `CTRL.fi_ack_leak` (§4.1 fault injection).
    pub fi_ack_leak: Signal<Out, Bit>,
    /// `CTRL.fi_no_twin` (§9.6 fault injection).
    pub fi_no_twin: Signal<Out, Bit>,
    /// The hub is decoupled (§7).
    pub decoupled: Signal<Out, Bit>,
    // ---- blocks ----
    bus: WbSlave<6>,
    // ---- registers ----
    reset_mode_q: DFF<Bit>,
    reset_mode_dq: DFF<Bit>,
    ack_interdep_q: DFF<Bit>,
    nrap_on_q: DFF<Bit>,
    fi_ack_leak_q: DFF<Bit>,
    fi_no_twin_q: DFF<Bit>,
    decoupled_q: DFF<Bit>,
    no_twin: DFF<Bits<16>>,
    /// The access answered now was refused: its ack is `ERR` (bus_contract.md §1).
    err_q: DFF<Bit>,
    // ---- decode ----
    wdat: Signal<Local, Bits<32>>,
    rdata: Signal<Local, Bits<32>>,
    is_port: Signal<Local, Bit>,
    illegal: Signal<Local, Bit>,
    /// All four byte lanes are selected.
    full: Signal<Local, Bit>,
    w1c: Signal<Local, Bits<6>>,
    dec_evt: Signal<Local, Bit>,
    no_twin_new: Signal<Local, Bits<16>>,
    // ---- word indices (from the table) ----
    a_id: Constant<Bits<6>>,
    a_ctrl: Constant<Bits<6>>,
    a_status: Constant<Bits<6>>,
    a_int_status: Constant<Bits<6>>,
    a_int_enable: Constant<Bits<6>>,
    a_stats: Constant<Bits<6>>,
    a_ack_unit: Constant<Bits<6>>,
    a_nrap_status: Constant<Bits<6>>,
    a_port0: Constant<Bits<6>>,
    a_port_end: Constant<Bits<6>>,
    // ---- field positions (from the table) ----
    c_reset_mode: Constant<Bits<5>>,
    c_force: Constant<Bits<5>>,
    c_recouple: Constant<Bits<5>>,
    c_ack_interdep: Constant<Bits<5>>,
    c_fi_ack_leak: Constant<Bits<5>>,
    c_fi_no_twin: Constant<Bits<5>>,
    c_nrap_on: Constant<Bits<5>>,
    s_reset_mode: Constant<Bits<5>>,
    s_decoupled: Constant<Bits<5>>,
    s_ack_window: Constant<Bits<5>>,
    s_trk: Constant<Bits<5>>,
    s_enabled: Constant<Bits<5>>,
    i_isolation: Constant<Bits<5>>,
    i_restoration: Constant<Bits<5>>,
    i_decoupled: Constant<Bits<5>>,
    i_illegal: Constant<Bits<5>>,
    i_ack_unit: Constant<Bits<5>>,
    i_nrap: Constant<Bits<5>>,
    t_frames: Constant<Bits<5>>,
    t_errors: Constant<Bits<5>>,
    u_blocks: Constant<Bits<5>>,
    u_u_window: Constant<Bits<5>>,
    // ---- values ----
    id_val: Constant<Bits<32>>,
    zero6: Constant<Bits<6>>,
    all_lanes: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
    zero32: Constant<Bits<32>>,
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Default
    for HubRegs<N, M, P, H>
{
    fn default() -> Self {
        assert!((2..=8).contains(&N), "hub: N node ports must be 2..=8");
        assert!((1..=4).contains(&M), "hub: M interlinks must be 1..=4");
        assert_eq!(P, N + M, "hub: P must be N + M");
        assert!(H <= 1, "hub: HUB_ID is 0 (hub A) or 1 (hub B)");
        // fixed by structure: the ID word, the commands decoded by the top
        // (`super::hub`) from CTRL[2:0]
        placed(&MAP, "ID", "m", 0, 8);
        placed(&MAP, "ID", "n", 8, 4);
        placed(&MAP, "ID", "hub_id", 12, 4);
        placed(&MAP, "CTRL", "reset_mode", 0, 1);
        placed(&MAP, "CTRL", "force_decouple", 1, 1);
        placed(&MAP, "CTRL", "recouple", 2, 1);
        let ctrl = map::register("CTRL").unwrap();
        assert_eq!(
            ctrl.field("reset_mode").unwrap().reset,
            1,
            "CTRL resets into reset mode"
        );
        assert_eq!(ctrl.field("ack_interdep").unwrap().reset, 1);
        assert_eq!(ctrl.field("nrap_on").unwrap().reset, 1);
        assert_eq!(ctrl.field("fi_ack_leak").unwrap().reset, 0);
        assert_eq!(ctrl.field("fi_no_twin").unwrap().reset, 0);
        // INT_STATUS / INT_ENABLE are the 6 bits of the shared slave
        assert_eq!(map::register("INT_STATUS").unwrap().defined(), 0x3F);
        assert_eq!(map::register("INT_ENABLE").unwrap().defined(), 0x3F);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            wb_err_o: Default::default(),
            irq: Default::default(),
            sample: Default::default(),
            any_sub_en: Default::default(),
            trk: Default::default(),
            ack_window: Default::default(),
            port_en: Default::default(),
            frames: Default::default(),
            errors: Default::default(),
            port_rd: Default::default(),
            blocks: Default::default(),
            u_window: Default::default(),
            decouple_bits: Default::default(),
            cfg_hit: Default::default(),
            cfg_rdata: Default::default(),
            nrap_status: Default::default(),
            ev_iso: Default::default(),
            ev_rest: Default::default(),
            ev_ack_unit: Default::default(),
            ev_nrap: Default::default(),
            nrap_decouple: Default::default(),
            wr: Default::default(),
            reset_mode: Default::default(),
            reset_mode_d: Default::default(),
            ack_interdep: Default::default(),
            nrap_on: Default::default(),
            fi_ack_leak: Default::default(),
            fi_no_twin: Default::default(),
            decoupled: Default::default(),
            bus: Default::default(),
            reset_mode_q: Default::default(),
            reset_mode_dq: Default::default(),
            ack_interdep_q: Default::default(),
            nrap_on_q: Default::default(),
            fi_ack_leak_q: Default::default(),
            fi_no_twin_q: Default::default(),
            decoupled_q: Default::default(),
            no_twin: Default::default(),
            err_q: Default::default(),
            wdat: Default::default(),
            rdata: Default::default(),
            is_port: Default::default(),
            illegal: Default::default(),
            full: Default::default(),
            w1c: Default::default(),
            dec_evt: Default::default(),
            no_twin_new: Default::default(),
            a_id: adr(map::ID),
            a_ctrl: adr(map::CTRL),
            a_status: adr(map::STATUS),
            a_int_status: adr(map::INT_STATUS),
            a_int_enable: adr(map::INT_ENABLE),
            a_stats: adr(map::STATS),
            a_ack_unit: adr(map::ACK_UNIT),
            a_nrap_status: adr(map::NRAP_STATUS),
            a_port0: adr(map::PORT0),
            a_port_end: adr(map::PORT0 + P as u32),
            c_reset_mode: lsb(&MAP, "CTRL", "reset_mode", 1),
            c_force: lsb(&MAP, "CTRL", "force_decouple", 1),
            c_recouple: lsb(&MAP, "CTRL", "recouple", 1),
            c_ack_interdep: lsb(&MAP, "CTRL", "ack_interdep", 1),
            c_fi_ack_leak: lsb(&MAP, "CTRL", "fi_ack_leak", 1),
            c_fi_no_twin: lsb(&MAP, "CTRL", "fi_no_twin", 1),
            c_nrap_on: lsb(&MAP, "CTRL", "nrap_on", 1),
            s_reset_mode: lsb(&MAP, "STATUS", "reset_mode", 1),
            s_decoupled: lsb(&MAP, "STATUS", "decoupled", 1),
            s_ack_window: lsb(&MAP, "STATUS", "ack_window", 1),
            s_trk: lsb(&MAP, "STATUS", "trk", 2),
            s_enabled: lsb(&MAP, "STATUS", "enabled", 16),
            i_isolation: lsb(&MAP, "INT_STATUS", "isolation", 1),
            i_restoration: lsb(&MAP, "INT_STATUS", "restoration", 1),
            i_decoupled: lsb(&MAP, "INT_STATUS", "decoupled", 1),
            i_illegal: lsb(&MAP, "INT_STATUS", "illegal", 1),
            i_ack_unit: lsb(&MAP, "INT_STATUS", "ack_unit", 1),
            i_nrap: lsb(&MAP, "INT_STATUS", "nrap", 1),
            t_frames: lsb(&MAP, "STATS", "frames", 16),
            t_errors: lsb(&MAP, "STATS", "errors", 16),
            u_blocks: lsb(&MAP, "ACK_UNIT", "blocks", 16),
            u_u_window: lsb(&MAP, "ACK_UNIT", "u_window", 1),
            id_val: Constant::new((map::id_value(H as u32, N as u32, M as u32) as u64).into()),
            zero6: Constant::new(0.into()),
            all_lanes: Constant::new(0xF.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Logic for HubRegs<N, M, P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            reset_mode_q,
            reset_mode_dq,
            ack_interdep_q,
            nrap_on_q,
            fi_ack_leak_q,
            fi_no_twin_q,
            decoupled_q,
            no_twin,
            err_q
        );
        // ---- Wishbone slave ----
        self.bus.clk.next = self.clk.val();
        self.bus.rst.next = self.rst.val();
        self.bus.wb_cyc_i.next = self.wb_cyc_i.val();
        self.bus.wb_stb_i.next = self.wb_stb_i.val();
        self.bus.wb_we_i.next = self.wb_we_i.val();
        self.full.next = self.wb_sel_i.val() == self.all_lanes.val();
        self.wr.next = self.bus.wr.val() & self.full.val();
        self.wdat.next = self.wb_dat_i.val();
        self.is_port.next = (self.wb_adr_i.val() >= self.a_port0.val())
            & (self.wb_adr_i.val() < self.a_port_end.val());

        // ---- read values ----
        self.rdata.next = self.zero32.val();
        if self.wb_adr_i.val() == self.a_id.val() {
            self.rdata.next = self.id_val.val();
        } else if self.wb_adr_i.val() == self.a_ctrl.val() {
            // the commands read 0
            self.rdata.next = (bit_cast::<32, 1>(self.reset_mode_q.q.val().into())
                << self.c_reset_mode.val())
                | (bit_cast::<32, 1>(self.fi_ack_leak_q.q.val().into())
                    << self.c_fi_ack_leak.val())
                | (bit_cast::<32, 1>(self.fi_no_twin_q.q.val().into()) << self.c_fi_no_twin.val())
                | (bit_cast::<32, 1>(self.ack_interdep_q.q.val().into())
                    << self.c_ack_interdep.val())
                | (bit_cast::<32, 1>(self.nrap_on_q.q.val().into()) << self.c_nrap_on.val());
        } else if self.cfg_hit.val() {
            self.rdata.next = self.cfg_rdata.val();
        } else if self.wb_adr_i.val() == self.a_status.val() {
            self.rdata.next = (bit_cast::<32, 1>(self.reset_mode_q.q.val().into())
                << self.s_reset_mode.val())
                | (bit_cast::<32, 1>(self.decoupled_q.q.val().into()) << self.s_decoupled.val())
                | (bit_cast::<32, 1>(self.ack_window.val().into()) << self.s_ack_window.val())
                | (bit_cast::<32, 2>(self.trk.val()) << self.s_trk.val())
                | (bit_cast::<32, P>(self.port_en.val()) << self.s_enabled.val());
        } else if self.wb_adr_i.val() == self.a_int_status.val() {
            self.rdata.next = bit_cast::<32, 6>(self.bus.int_status.val());
        } else if self.wb_adr_i.val() == self.a_int_enable.val() {
            self.rdata.next = bit_cast::<32, 6>(self.bus.int_enable.val());
        } else if self.wb_adr_i.val() == self.a_stats.val() {
            self.rdata.next = (bit_cast::<32, 16>(self.frames.val()) << self.t_frames.val())
                | (bit_cast::<32, 16>(self.errors.val()) << self.t_errors.val());
        } else if self.wb_adr_i.val() == self.a_ack_unit.val() {
            self.rdata.next = (bit_cast::<32, 16>(self.blocks.val()) << self.u_blocks.val())
                | (bit_cast::<32, 1>(self.u_window.val().into()) << self.u_u_window.val());
        } else if self.wb_adr_i.val() == self.a_nrap_status.val() {
            self.rdata.next = self.nrap_status.val();
        } else if self.is_port.val() {
            self.rdata.next = self.port_rd.val();
        }
        self.bus.rdata.next = self.rdata.val();
        self.reset_mode_dq.d.next = self.reset_mode_q.q.val();

        // ---- §7 decoupling (at SAMPLE edges, only with NRAP off) ----
        self.dec_evt.next = false;
        if self.any_sub_en.val() {
            self.no_twin_new.next = self.zero16.val();
        } else if self.no_twin.q.val() == self.max16.val() {
            self.no_twin_new.next = self.max16.val();
        } else {
            self.no_twin_new.next = self.no_twin.q.val() + self.one16.val();
        }
        if self.sample.val() & !self.nrap_on_q.q.val() {
            self.no_twin.d.next = self.no_twin_new.val();
            if !self.decoupled_q.q.val()
                & (self.decouple_bits.val() != self.zero16.val())
                & (self.no_twin_new.val() >= self.decouple_bits.val())
            {
                self.decoupled_q.d.next = true;
                self.dec_evt.next = true;
            }
        }
        // ---- §9.2: NRAP enters DDSP_FORCE ----
        if self.nrap_decouple.val() {
            self.decoupled_q.d.next = true;
            self.dec_evt.next = true;
        }

        // ---- writes (§8) ----
        self.illegal.next = false;
        self.w1c.next = self.zero6.val();
        self.bus.int_enable_we.next = false;
        self.bus.int_enable_d.next = self.wdat.val().get_bits::<6>(0);
        if self.bus.wr.val() & !self.full.val() {
            // a partial write (bus_contract.md §1)
            self.illegal.next = true;
        } else if self.wr.val() {
            if self.wb_adr_i.val() == self.a_ctrl.val() {
                if self.wdat.val().get_bit(self.c_force.val().index())
                    & self.wdat.val().get_bit(self.c_recouple.val().index())
                {
                    // both commands in one write: refused
                    self.illegal.next = true;
                } else {
                    self.reset_mode_q.d.next =
                        self.wdat.val().get_bit(self.c_reset_mode.val().index());
                    self.fi_ack_leak_q.d.next =
                        self.wdat.val().get_bit(self.c_fi_ack_leak.val().index());
                    self.fi_no_twin_q.d.next =
                        self.wdat.val().get_bit(self.c_fi_no_twin.val().index());
                    if self.reset_mode_q.q.val() {
                        self.ack_interdep_q.d.next =
                            self.wdat.val().get_bit(self.c_ack_interdep.val().index());
                        self.nrap_on_q.d.next =
                            self.wdat.val().get_bit(self.c_nrap_on.val().index());
                    } else {
                        self.illegal.next =
                            (self.wdat.val().get_bit(self.c_ack_interdep.val().index())
                                != self.ack_interdep_q.q.val())
                                | (self.wdat.val().get_bit(self.c_nrap_on.val().index())
                                    != self.nrap_on_q.q.val());
                        if !self.wdat.val().get_bit(self.c_reset_mode.val().index()) {
                            if self.wdat.val().get_bit(self.c_force.val().index()) {
                                self.decoupled_q.d.next = true;
                                self.dec_evt.next = true;
                            }
                            if self.wdat.val().get_bit(self.c_recouple.val().index()) {
                                self.decoupled_q.d.next = false;
                                self.no_twin.d.next = self.zero16.val();
                                self.dec_evt.next = false;
                            }
                        }
                    }
                }
            } else if self.cfg_hit.val() {
                // a cfg register (super::config stores it in reset mode)
                self.illegal.next = !self.reset_mode_q.q.val();
            } else if self.wb_adr_i.val() == self.a_int_status.val() {
                self.w1c.next = self.wdat.val().get_bits::<6>(0);
            } else if self.wb_adr_i.val() == self.a_int_enable.val() {
                self.bus.int_enable_we.next = true;
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
        self.bus.events.next = (bit_cast::<6, 1>(self.ev_iso.val().into())
            << self.i_isolation.val())
            | (bit_cast::<6, 1>(self.ev_rest.val().into()) << self.i_restoration.val())
            | (bit_cast::<6, 1>(self.dec_evt.val().into()) << self.i_decoupled.val())
            | (bit_cast::<6, 1>(self.illegal.val().into()) << self.i_illegal.val())
            | (bit_cast::<6, 1>(self.ev_ack_unit.val().into()) << self.i_ack_unit.val())
            | (bit_cast::<6, 1>(self.ev_nrap.val().into()) << self.i_nrap.val());
        self.bus.w1c.next = self.w1c.val();
        // the refused write's answer is ERR (illegal comes only with a write)
        self.err_q.d.next = self.illegal.val();

        if self.rst.val() {
            self.reset_mode_q.d.next = true;
            self.reset_mode_dq.d.next = true;
            self.ack_interdep_q.d.next = true;
            self.nrap_on_q.d.next = true;
            self.fi_ack_leak_q.d.next = false;
            self.fi_no_twin_q.d.next = false;
            self.decoupled_q.d.next = false;
            self.no_twin.d.next = self.zero16.val();
            self.err_q.d.next = false;
        }

        // ---- outputs ----
        self.wb_ack_o.next = self.bus.wb_ack_o.val() & !self.err_q.q.val();
        self.wb_err_o.next = self.err_q.q.val();
        self.wb_dat_o.next = self.bus.wb_dat_o.val();
        self.irq.next = self.bus.irq.val();
        self.reset_mode.next = self.reset_mode_q.q.val();
        self.reset_mode_d.next = self.reset_mode_dq.q.val();
        self.ack_interdep.next = self.ack_interdep_q.q.val();
        self.nrap_on.next = self.nrap_on_q.q.val();
        self.fi_ack_leak.next = self.fi_ack_leak_q.q.val();
        self.fi_no_twin.next = self.fi_no_twin_q.q.val();
        self.decoupled.next = self.decoupled_q.q.val();
    }
}
