//! The `hub` and `hub_b` tops: the ReCANcentrate star hub (ReCANcentrate paper
//! sections 2-5), exactly as fixed clock by clock by
//! `cosim/src/model/hub_contract.md`. N node ports (uplink/downlink pairs, 2..=8)
//! and M interlinks to the twin hub (sublink_in/sublink_out pairs, 1..=4); P = N +
//! M guarded ports (node ports 0..N, then the incoming sublinks N..N+M). `H` is
//! `HUB_ID` (§9): 0 = hub A (`hub.v`), 1 = hub B (`hub_b.v`); the two differ only in
//! the identification frame they send (`ID.hub_id` and the ROMs of §9.1).
//!
//! Blocks: the Wishbone register block with the decoupling state (§7, §8) and the
//! cfg registers beside it (§8, §9.5), the coupler (§2-§4, §9.4: the NRAP
//! transmitter `tx_q & !forcing` joins the own contribution), the ACK unit (§4.1:
//! the bus guardian that owns the downlink register; it gets the pins, the
//! captured bit timing, `ack_interdep`, the enabled mask, `decoupled`, NRAP's
//! `tx_q & !forcing` and the coupler's `dl_next`, nothing else; it guards during
//! NRAP too, §4.1 as of commit 753312e), the channel's bit timing
//! logic and configuration capture on `coupled_q` (§5: `tx = tx_q`, `triple = 0`,
//! `hard_sync_enable = (trk == IDLE_WAIT)`, held in reset by `rst | reset_mode |
//! reset_mode_q` exactly as the DRCC holds its channels), the frame tracker (§5),
//! one guard per port (§6, with the per-port NRAP field `rrun`), the NRAP phase machine
//! (§9.2) and the identification-frame transmitter and recogniser (§9.1, §9.3) at
//! the BTL's bit-start and SAMPLE edges. The tracker, the guards, the phase
//! machine and the transmitter are held at their reset values by `rst |
//! reset_mode` (`reset_mode` is the register value, i.e. the value before the
//! edge); NRAP's `runs` and `outcome` clear with `rst` only.
//!
//! While NRAP is active no rule of §6 runs (every guard is frozen, as the sublink
//! guards are while decoupled).
//!
//! Guard stage (§6.1, for Fmax on the iCE40UP5K): every guard input (the SAMPLE
//! edge, `port_q`, `coupled_q`, the tracker's events, the freezes, NRAP's port
//! strobes, `recouple` and the reset-mode hold) passes one register
//! (`super::guard_stage`), so the guards apply at edge t + 1 what §6 decides at
//! edge t; `rst` itself is not delayed.
//!
//! Parametrisation: const generics `N`, `M`, `P` and `H` (stable Rust cannot write
//! `N + M` in a type, so `P` is passed and checked to equal `N + M`; `H` defaults
//! to 0, hub A); the guards are arrays of blocks and the per-port wiring is written
//! with rust-hdl `for` loops, which the Verilog generator unrolls.

use super::ack_unit::AckUnit;
use super::config::HubConfig;
use super::coupler::Coupler;
use super::guard_stage::GuardStage;
use super::id_frame::IdFrame;
use super::nrap::Nrap;
use super::port_guard::PortGuard;
use super::registers::HubRegs;
use super::tracker::FrameTracker;
use crate::channel::btl::BitTimingLogic;
use crate::channel::config::ChannelConfig;
use rust_hdl::prelude::*;

/// The hub top with N node ports, M interlinks and P = N + M ports; hub A (`H` =
/// 0) or hub B (`H` = 1).
#[derive(LogicBlock)]
pub struct Hub<const N: usize, const M: usize, const P: usize, const H: usize = 0> {
    // clock and reset
    /// Clock. Every register changes at its rising edge; the hub's bit timing
    /// (register `BTR`) is counted in its periods.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high: at an edge with `rst = 1`
    /// every register takes its reset value and every link output is recessive.
    pub rst: Signal<In, Bit>,
    // Wishbone B4 classic slave, as the DRCC's (hub_contract.md §1, §8)
    /// Wishbone cycle, active high. A transaction is taken at an edge where
    /// `wb_cyc_i & wb_stb_i & !(wb_ack_o | wb_err_o)`.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone strobe, active high.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone write enable: 1 = write, 0 = read.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone word address: register index 0..63, byte offset = 4 x `wb_adr_i`
    /// (hub contract §8).
    pub wb_adr_i: Signal<In, Bits<6>>,
    /// Wishbone write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone byte select of a write: every hub word is written whole, a
    /// write with another select than `4'b1111` is refused (`wb_err_o`).
    /// Ignored on reads.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone read data, valid while `wb_ack_o = 1`, else 0.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone acknowledge, 1 for the clock after the edge that took the
    /// transaction: every access takes 2 clocks.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Wishbone error, instead of the acknowledge, for a refused access (it
    /// also sets `INT_STATUS.illegal`): bus_contract.md §1.
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered: `|(INT_STATUS & INT_ENABLE)`.
    pub irq: Signal<Out, Bit>,
    // node links: bit i belongs to node port i (1 = recessive, 0 = dominant);
    // the downlink register belongs to the ACK unit (§4.1)
    /// Node transmit values, bit i = node i's `tx` (N bits), 1 = recessive; each is
    /// synchronized by two flip-flops.
    pub uplink: Signal<In, Bits<N>>,
    /// What node i receives, bit i (N bits), 1 = recessive; every bit carries the
    /// same value (registers; in the ACK window only the twin hub's contribution
    /// while ACK interdependence is on).
    pub downlink: Signal<Out, Bits<N>>,
    // interlinks to the twin hub: bit j belongs to interlink j
    /// This hub's contribution (the AND of its enabled node ports and of its NRAP
    /// transmitter), the same on each of the M interlinks, 1 = recessive. Wire it
    /// to the twin's `sublink_in`.
    pub sublink_out: Signal<Out, Bits<M>>,
    /// The twin hub's contribution, bit j = interlink j (M bits), 1 = recessive;
    /// each is synchronized by two flip-flops.
    pub sublink_in: Signal<In, Bits<M>>,
    // probes (hub_contract.md §3 - §7)
    /// `coupled_q`: the coupled bus value the hub tracks, 1 = recessive.
    pub coupled: Signal<Out, Bit>,
    /// One-clock pulse, the clock after each sample point of the hub's bit timing.
    pub sample_point: Signal<Out, Bit>,
    /// Frame tracker state: 0 IDLE_WAIT, 1 FRAME, 2 ACK_SLOT, 3 ACK_DELIM.
    pub trk_state: Signal<Out, Bits<2>>,
    /// 1 while the tracker is in the ACK slot or ACK delimiter (the ACK window).
    pub ack_window: Signal<Out, Bit>,
    /// 1 once the hub has decoupled from its twin (sticky until `CTRL.recouple` or
    /// reset mode).
    pub decoupled: Signal<Out, Bit>,
    /// Bit p = port p enabled (not isolated): node ports 0..N-1, then the incoming
    /// sublinks N..N+M-1 (P = N + M bits).
    pub port_enabled: Signal<Out, Bits<P>>,
    /// NRAP phase (§9.2): 0 RUN, 1 SRP_FORCE, 2 SRP_EXCHANGE, 3 NRP, 4 DDSP_FORCE,
    /// 5 DDSP_SEND, 6 SPLIT.
    pub nrap_phase: Signal<Out, Bits<3>>,
    /// The hub's NRAP transmitter `tx_q` (§9.3), 1 = recessive: 1 outside the
    /// identification frames and ACKs it sends.
    pub hub_tx: Signal<Out, Bit>,
    // blocks
    regs: HubRegs<N, M, P, H>,
    hub_cfg: HubConfig,
    coupler: Coupler<N, M>,
    ack_unit: AckUnit<N, M, P>,
    cfg_regs: ChannelConfig,
    btl: BitTimingLogic,
    tracker: FrameTracker,
    guard_stage: GuardStage<N, M>,
    node_guards: [PortGuard; N],
    sub_guards: [PortGuard; M],
    nrap: Nrap<H>,
    id_frame: IdFrame<H>,
    // glue
    guard_rst: Signal<Local, Bit>,
    guard_hold: Signal<Local, Bit>,
    btl_rst: Signal<Local, Bit>,
    ack_win: Signal<Local, Bit>,
    ctrl_cmd: Signal<Local, Bit>,
    recouple: Signal<Local, Bit>,
    force_cmd: Signal<Local, Bit>,
    node_en: Signal<Local, Bits<N>>,
    sub_en: Signal<Local, Bits<M>>,
    port_en: Signal<Local, Bits<P>>,
    port_rd: Signal<Local, Bits<32>>,
    ev_iso: Signal<Local, Bit>,
    ev_rest: Signal<Local, Bit>,
    a_node: [Constant<Bits<6>>; N],
    a_sub: [Constant<Bits<6>>; M],
    shift_n: Constant<Bits<4>>,
    a_ctrl: Constant<Bits<6>>,
    all_lanes: Constant<Bits<4>>,
    s_idle: Constant<Bits<2>>,
    s_ack: Constant<Bits<2>>,
    s_delim: Constant<Bits<2>>,
    zero_n: Constant<Bits<N>>,
    zero_m: Constant<Bits<M>>,
    zero2: Constant<Bits<2>>,
    zero8: Constant<Bits<8>>,
    zero32: Constant<Bits<32>>,
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Default for Hub<N, M, P, H> {
    fn default() -> Self {
        assert!((2..=8).contains(&N), "hub: N node ports must be 2..=8");
        assert!((1..=4).contains(&M), "hub: M interlinks must be 1..=4");
        assert_eq!(P, N + M, "hub: P must be N + M");
        let port0 = super::registers::PORT0 as u64;
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
            uplink: Default::default(),
            downlink: Default::default(),
            sublink_out: Default::default(),
            sublink_in: Default::default(),
            coupled: Default::default(),
            sample_point: Default::default(),
            trk_state: Default::default(),
            ack_window: Default::default(),
            decoupled: Default::default(),
            port_enabled: Default::default(),
            nrap_phase: Default::default(),
            hub_tx: Default::default(),
            regs: Default::default(),
            hub_cfg: Default::default(),
            coupler: Default::default(),
            ack_unit: Default::default(),
            cfg_regs: Default::default(),
            btl: Default::default(),
            tracker: Default::default(),
            guard_stage: Default::default(),
            node_guards: std::array::from_fn(|_| Default::default()),
            sub_guards: std::array::from_fn(|_| Default::default()),
            nrap: Default::default(),
            id_frame: Default::default(),
            guard_rst: Default::default(),
            guard_hold: Default::default(),
            btl_rst: Default::default(),
            ack_win: Default::default(),
            ctrl_cmd: Default::default(),
            recouple: Default::default(),
            force_cmd: Default::default(),
            node_en: Default::default(),
            sub_en: Default::default(),
            port_en: Default::default(),
            port_rd: Default::default(),
            ev_iso: Default::default(),
            ev_rest: Default::default(),
            a_node: std::array::from_fn(|i| Constant::new((port0 + i as u64).into())),
            a_sub: std::array::from_fn(|j| Constant::new((port0 + (N + j) as u64).into())),
            shift_n: Constant::new((N as u64).into()),
            a_ctrl: Constant::new((super::registers::CTRL as u64).into()),
            all_lanes: Constant::new(0xF.into()),
            s_idle: Constant::new(super::tracker::IDLE_WAIT.into()),
            s_ack: Constant::new(super::tracker::ACK_SLOT.into()),
            s_delim: Constant::new(super::tracker::ACK_DELIM.into()),
            zero_n: Constant::new(0.into()),
            zero_m: Constant::new(0.into()),
            zero2: Constant::new(0.into()),
            zero8: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Logic for Hub<N, M, P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        // reset mode holds the tracker and the guards (value before the edge); the
        // BTL and its configuration capture stay in reset one edge longer (§5).
        self.guard_rst.next = self.rst.val() | self.regs.reset_mode.val();
        self.btl_rst.next =
            self.rst.val() | self.regs.reset_mode.val() | self.regs.reset_mode_d.val();
        // §4: the ACK window from the registered tracker state
        self.ack_win.next = (self.tracker.trk.val() == self.s_ack.val())
            | (self.tracker.trk.val() == self.s_delim.val());

        // CTRL.recouple / CTRL.force_decouple (§8): a CTRL write with one of bits 2
        // and 1, and reset_mode 0 before the write and in the written value (the
        // register block takes the rest of the command)
        // (written out from the ports, not from the register block's `wr`, so
        // that Verilator orders it apart from that block: no UNOPTFLAT)
        self.ctrl_cmd.next = self.wb_cyc_i.val()
            & self.wb_stb_i.val()
            & !(self.regs.wb_ack_o.val() | self.regs.wb_err_o.val())
            & self.wb_we_i.val()
            & (self.wb_sel_i.val() == self.all_lanes.val())
            & (self.wb_adr_i.val() == self.a_ctrl.val())
            & !self.regs.reset_mode.val()
            & !self.wb_dat_i.val().get_bit(0);
        self.recouple.next =
            self.ctrl_cmd.val() & !self.wb_dat_i.val().get_bit(1) & self.wb_dat_i.val().get_bit(2);
        self.force_cmd.next =
            self.ctrl_cmd.val() & self.wb_dat_i.val().get_bit(1) & !self.wb_dat_i.val().get_bit(2);

        // ---- guard stage (§6.1): the guards' inputs one clock late ----
        self.guard_stage.clk.next = self.clk.val();
        self.guard_stage.rst.next = self.rst.val();
        self.guard_stage.reset_mode.next = self.regs.reset_mode.val();
        self.guard_stage.sample.next = self.btl.sample.val();
        self.guard_stage.node_q.next = self.coupler.node_q.val();
        self.guard_stage.sub_q.next = self.coupler.sub_q.val();
        self.guard_stage.b.next = self.coupler.coupled.val();
        self.guard_stage.ev_sof.next = self.tracker.ev_sof.val();
        self.guard_stage.ev_frame.next = self.tracker.ev_frame.val();
        self.guard_stage.in_arb.next = self.tracker.in_arb.val();
        self.guard_stage.ev_stuff_rec.next = self.tracker.ev_stuff_rec.val();
        self.guard_stage.ev_rid.next = self.tracker.ev_rid.val();
        self.guard_stage.ev_ack.next = self.tracker.ev_ack.val();
        self.guard_stage.nrap_active.next = self.nrap.active.val();
        self.guard_stage.decoupled.next = self.regs.decoupled.val();
        self.guard_stage.p_watch.next = self.nrap.p_watch.val();
        self.guard_stage.p_enable.next = self.nrap.p_enable.val();
        self.guard_stage.p_exchange.next = self.nrap.p_exchange.val();
        self.guard_stage.p_off_sub.next = self.nrap.p_off_sub.val();
        self.guard_stage.p_join.next = self.nrap.p_join.val();
        self.guard_stage.recouple.next = self.recouple.val();
        // §6.1: the guards reset at the `rst` edge and hold one clock after reset
        // mode
        self.guard_hold.next = self.rst.val() | self.guard_stage.hold_d.val();

        // ---- guards (§6, run one clock late, §6.1) ----
        self.node_en.next = self.zero_n.val();
        self.sub_en.next = self.zero_m.val();
        self.port_rd.next = self.zero32.val();
        self.ev_iso.next = false;
        self.ev_rest.next = false;
        for i in 0..N {
            self.node_guards[i].clk.next = self.clk.val();
            self.node_guards[i].rst.next = self.guard_hold.val();
            // §6: no rule runs while NRAP is active
            self.node_guards[i].freeze.next = self.guard_stage.node_freeze_d.val();
            self.node_guards[i].rid_en.next = true;
            self.node_guards[i].recouple.next = false;
            self.node_guards[i].sample.next = self.guard_stage.sample_d.val();
            self.node_guards[i].pb.next = self.guard_stage.node_q_d.val().get_bit(i);
            self.node_guards[i].b.next = self.guard_stage.b_d.val();
            self.node_guards[i].ev_sof.next = self.guard_stage.ev_sof_d.val();
            self.node_guards[i].ev_frame.next = self.guard_stage.ev_frame_d.val();
            self.node_guards[i].in_arb.next = self.guard_stage.in_arb_d.val();
            self.node_guards[i].ev_stuff_rec.next = self.guard_stage.ev_stuff_rec_d.val();
            self.node_guards[i].ev_rid.next = self.guard_stage.ev_rid_d.val();
            self.node_guards[i].ev_ack.next = self.guard_stage.ev_ack_d.val();
            // §9.2: the NRAP actions on node ports
            self.node_guards[i].n_rrun.next = false;
            self.node_guards[i].n_watch.next = self.guard_stage.p_watch_d.val();
            self.node_guards[i].n_off.next = false;
            self.node_guards[i].n_clr.next = false;
            self.node_guards[i].n_enable.next = self.guard_stage.p_enable_d.val();
            self.node_guards[i].sd_limit.next = self.hub_cfg.sd_run_up.val();
            self.node_guards[i].bf_limit.next = self.hub_cfg.bf_up.val();
            self.node_guards[i].sr_frames.next = self.hub_cfg.sr_frames.val();
            self.node_guards[i].restore_bits.next = self.hub_cfg.restore_bits.val();
            self.node_en.next = self
                .node_en
                .val()
                .replace_bit(i, self.node_guards[i].enabled.val());
            if self.wb_adr_i.val() == self.a_node[i].val() {
                self.port_rd.next = self.node_guards[i].word.val();
            }
            self.ev_iso.next = self.ev_iso.val() | self.node_guards[i].iso_evt.val();
            self.ev_rest.next = self.ev_rest.val() | self.node_guards[i].rest_evt.val();
        }
        for j in 0..M {
            self.sub_guards[j].clk.next = self.clk.val();
            self.sub_guards[j].rst.next = self.guard_hold.val();
            // §6: the sublink guards are frozen while decoupled and while NRAP is
            // active
            self.sub_guards[j].freeze.next = self.guard_stage.sub_freeze_d.val();
            self.sub_guards[j].rid_en.next = false;
            self.sub_guards[j].recouple.next = self.guard_stage.recouple_d.val();
            self.sub_guards[j].sample.next = self.guard_stage.sample_d.val();
            self.sub_guards[j].pb.next = self.guard_stage.sub_q_d.val().get_bit(j);
            self.sub_guards[j].b.next = self.guard_stage.b_d.val();
            self.sub_guards[j].ev_sof.next = self.guard_stage.ev_sof_d.val();
            self.sub_guards[j].ev_frame.next = self.guard_stage.ev_frame_d.val();
            self.sub_guards[j].in_arb.next = self.guard_stage.in_arb_d.val();
            self.sub_guards[j].ev_stuff_rec.next = self.guard_stage.ev_stuff_rec_d.val();
            self.sub_guards[j].ev_rid.next = self.guard_stage.ev_rid_d.val();
            self.sub_guards[j].ev_ack.next = self.guard_stage.ev_ack_d.val();
            // §9.2: the NRAP actions on sublinks
            self.sub_guards[j].n_rrun.next = self.guard_stage.p_exchange_d.val();
            self.sub_guards[j].n_watch.next = false;
            self.sub_guards[j].n_off.next = self.guard_stage.p_off_sub_d.val();
            self.sub_guards[j].n_clr.next = self.guard_stage.p_join_d.val();
            self.sub_guards[j].n_enable.next = false;
            self.sub_guards[j].sd_limit.next = self.hub_cfg.sd_run_sub.val();
            self.sub_guards[j].bf_limit.next = self.hub_cfg.bf_sub.val();
            self.sub_guards[j].sr_frames.next = self.hub_cfg.sr_frames.val();
            self.sub_guards[j].restore_bits.next = self.hub_cfg.restore_bits.val();
            self.sub_en.next = self
                .sub_en
                .val()
                .replace_bit(j, self.sub_guards[j].enabled.val());
            if self.wb_adr_i.val() == self.a_sub[j].val() {
                self.port_rd.next = self.sub_guards[j].word.val();
            }
            self.ev_iso.next = self.ev_iso.val() | self.sub_guards[j].iso_evt.val();
            self.ev_rest.next = self.ev_rest.val() | self.sub_guards[j].rest_evt.val();
        }

        self.port_en.next = bit_cast::<P, N>(self.node_en.val())
            | (bit_cast::<P, M>(self.sub_en.val()) << self.shift_n.val());

        // ---- register block (§7, §8) ----
        self.regs.clk.next = self.clk.val();
        self.regs.rst.next = self.rst.val();
        self.regs.wb_cyc_i.next = self.wb_cyc_i.val();
        self.regs.wb_stb_i.next = self.wb_stb_i.val();
        self.regs.wb_we_i.next = self.wb_we_i.val();
        self.regs.wb_adr_i.next = self.wb_adr_i.val();
        self.regs.wb_dat_i.next = self.wb_dat_i.val();
        self.regs.wb_sel_i.next = self.wb_sel_i.val();
        self.regs.sample.next = self.btl.sample.val();
        self.regs.any_sub_en.next = self.sub_en.val() != self.zero_m.val();
        self.regs.trk.next = self.tracker.trk.val();
        self.regs.ack_window.next = self.ack_win.val();
        self.regs.port_en.next = self.port_en.val();
        self.regs.frames.next = self.tracker.frames.val();
        self.regs.errors.next = self.tracker.errors.val();
        self.regs.port_rd.next = self.port_rd.val();
        self.regs.ev_iso.next = self.ev_iso.val();
        self.regs.ev_rest.next = self.ev_rest.val();
        self.regs.blocks.next = self.ack_unit.blocks.val();
        self.regs.u_window.next = self.ack_unit.u_window.val();
        self.regs.ev_ack_unit.next = self.ack_unit.ev_block.val();
        self.regs.decouple_bits.next = self.hub_cfg.decouple_bits.val();
        self.regs.cfg_hit.next = self.hub_cfg.hit.val();
        self.regs.cfg_rdata.next = self.hub_cfg.rdata.val();
        self.regs.nrap_status.next = self.nrap.status.val();
        self.regs.ev_nrap.next = self.nrap.ev_phase.val();
        self.regs.nrap_decouple.next = self.nrap.set_decoupled.val();
        // ---- cfg registers (§8, §9.5) ----
        self.hub_cfg.clk.next = self.clk.val();
        self.hub_cfg.rst.next = self.rst.val();
        self.hub_cfg.wr.next = self.regs.wr.val();
        self.hub_cfg.adr.next = self.wb_adr_i.val();
        self.hub_cfg.wdat.next = self.wb_dat_i.val();
        self.hub_cfg.reset_mode.next = self.regs.reset_mode.val();

        // ---- NRAP phase machine (§9.2) ----
        self.nrap.clk.next = self.clk.val();
        self.nrap.rst.next = self.rst.val();
        self.nrap.hold.next = self.guard_rst.val();
        self.nrap.nrap_on.next = self.regs.nrap_on.val();
        self.nrap.force_bits.next = self.hub_cfg.force_bits.val();
        self.nrap.srp_pairs.next = self.hub_cfg.srp_pairs.val();
        self.nrap.nrp_pairs.next = self.hub_cfg.nrp_pairs.val();
        self.nrap.ddsp_frames.next = self.hub_cfg.ddsp_frames.val();
        self.nrap.srp_bits.next = self.hub_cfg.srp_bits.val();
        self.nrap.nrp_bits.next = self.hub_cfg.nrp_bits.val();
        self.nrap.ddsp_bits.next = self.hub_cfg.ddsp_bits.val();
        self.nrap.block_frames.next = self.hub_cfg.block_frames.val();
        self.nrap.decoupled.next = self.regs.decoupled.val();
        self.nrap.any_sub_en.next = self.sub_en.val() != self.zero_m.val();
        // twin_b: AND over the enabled sublink ports of port_q (1 when none)
        self.nrap.twin_b.next = (self.coupler.sub_q.val() | !self.sub_en.val()).all();
        self.nrap.sample.next = self.btl.sample.val();
        self.nrap.b.next = self.coupler.coupled.val();
        self.nrap.at_ack.next = self.tracker.trk.val() == self.s_ack.val();
        self.nrap.at_delim.next = self.tracker.trk.val() == self.s_delim.val();
        self.nrap.own_frame.next = self.id_frame.own_frame.val();
        self.nrap.twin_frame.next = self.id_frame.twin_frame.val();
        self.nrap.in_id.next = self.id_frame.in_id.val();
        self.nrap.cmd_run.next = self.recouple.val();
        self.nrap.cmd_split.next = self.force_cmd.val();

        // ---- identification frames: transmitter and recogniser (§9.1, §9.3) ----
        self.id_frame.clk.next = self.clk.val();
        self.id_frame.rst.next = self.guard_rst.val();
        self.id_frame.bit_start.next = self.btl.bit_start.val();
        self.id_frame.hard.next = self.btl.hard_sync.val();
        self.id_frame.sample.next = self.btl.sample.val();
        self.id_frame.b.next = self.coupler.coupled.val();
        self.id_frame.ev_sof.next = self.tracker.ev_sof.val();
        self.id_frame.ev_frame.next = self.tracker.ev_frame.val();
        self.id_frame.send.next = self.nrap.send.val();
        self.id_frame.ack_en.next = self.nrap.ack_en.val();
        self.id_frame.hush.next = self.nrap.hush.val();

        // ---- coupler (§2-§4) ----
        self.coupler.clk.next = self.clk.val();
        self.coupler.rst.next = self.rst.val();
        self.coupler.uplink.next = self.uplink.val();
        self.coupler.sublink_in.next = self.sublink_in.val();
        self.coupler.node_en.next = self.node_en.val();
        self.coupler.sub_en.next = self.sub_en.val();
        self.coupler.decoupled.next = self.regs.decoupled.val();
        // §9.4: own = AND of the node ports & tx_q & !forcing
        self.coupler.tx_own.next = self.id_frame.tx.val() & !self.nrap.forcing.val();
        self.coupler.ack_mask.next =
            self.ack_win.val() & self.regs.ack_interdep.val() & !self.regs.decoupled.val();
        self.coupler.fi_ack_leak.next = self.regs.fi_ack_leak.val();
        self.coupler.fi_no_twin.next = self.regs.fi_no_twin.val();
        // §9.4: a hub that decided on definitive decoupling keeps its sublinks
        // recessive
        self.coupler.quiet_twin.next = self.nrap.quiet_twin.val();

        // ---- ACK unit (§4.1): its own synchronizers, bus copy, BTL and tracker ----
        self.ack_unit.clk.next = self.clk.val();
        self.ack_unit.rst.next = self.rst.val();
        self.ack_unit.trk_rst.next = self.guard_rst.val();
        self.ack_unit.btl_rst.next = self.btl_rst.val();
        self.ack_unit.uplink.next = self.uplink.val();
        self.ack_unit.sublink_in.next = self.sublink_in.val();
        self.ack_unit.cfg_brp_next.next = self.cfg_regs.brp_next.val();
        self.ack_unit.cfg_tseg1_len.next = self.cfg_regs.tseg1_len.val();
        self.ack_unit.cfg_tseg2_len.next = self.cfg_regs.tseg2_len.val();
        self.ack_unit.cfg_sjw_len.next = self.cfg_regs.sjw_len.val();
        self.ack_unit.ack_interdep.next = self.regs.ack_interdep.val();
        self.ack_unit.enabled.next = self.port_en.val();
        self.ack_unit.decoupled.next = self.regs.decoupled.val();
        // §4.1 / §9.4: the unit's own view includes the NRAP transmitter
        self.ack_unit.own_gate.next = self.id_frame.tx.val() & !self.nrap.forcing.val();
        self.ack_unit.dl_next.next = self.coupler.dl_next.val();

        // ---- bit timing on coupled_q (§5) ----
        self.cfg_regs.clk.next = self.clk.val();
        self.cfg_regs.rst.next = self.btl_rst.val();
        self.cfg_regs.cfg_brp.next = self.hub_cfg.brp.val();
        self.cfg_regs.cfg_tseg1.next = self.hub_cfg.tseg1.val();
        self.cfg_regs.cfg_tseg2.next = self.hub_cfg.tseg2.val();
        self.cfg_regs.cfg_sjw.next = self.hub_cfg.sjw.val();
        self.cfg_regs.cfg_triple.next = false;
        self.cfg_regs.cfg_mode.next = self.zero2.val();
        self.cfg_regs.cfg_ewl.next = self.zero8.val();
        self.cfg_regs.cfg_single_shot.next = false;
        self.btl.clk.next = self.clk.val();
        self.btl.rst.next = self.btl_rst.val();
        self.btl.cfg_brp_next.next = self.cfg_regs.brp_next.val();
        self.btl.cfg_tseg1_len.next = self.cfg_regs.tseg1_len.val();
        self.btl.cfg_tseg2_len.next = self.cfg_regs.tseg2_len.val();
        self.btl.cfg_sjw_len.next = self.cfg_regs.sjw_len.val();
        self.btl.cfg_triple.next = false;
        self.btl.rx_s.next = self.coupler.coupled.val();
        // §5 / §9.3: no resynchronisation on the hub's own dominant bits
        self.btl.tx.next = self.id_frame.tx.val();
        self.btl.hard_sync_enable.next = self.tracker.trk.val() == self.s_idle.val();

        // ---- frame tracker (§5) ----
        self.tracker.clk.next = self.clk.val();
        self.tracker.rst.next = self.guard_rst.val();
        self.tracker.sample.next = self.btl.sample.val();
        self.tracker.b.next = self.coupler.coupled.val();

        // ---- outputs ----
        self.wb_dat_o.next = self.regs.wb_dat_o.val();
        self.wb_ack_o.next = self.regs.wb_ack_o.val();
        self.wb_err_o.next = self.regs.wb_err_o.val();
        self.irq.next = self.regs.irq.val();
        self.downlink.next = self.ack_unit.downlink.val();
        self.sublink_out.next = self.coupler.sublink_out.val();
        self.coupled.next = self.coupler.coupled.val();
        self.sample_point.next = self.btl.sample_point.val();
        self.trk_state.next = self.tracker.trk.val();
        self.ack_window.next = self.ack_win.val();
        self.decoupled.next = self.regs.decoupled.val();
        self.port_enabled.next = self.port_en.val();
        self.nrap_phase.next = self.nrap.phase.val();
        self.hub_tx.next = self.id_frame.tx.val();
    }
}

/// The emitted hub A (`hub.v`): N = 4 node ports, M = 2 interlinks, HUB_ID 0.
pub type Hub4x2 = Hub<4, 2, 6>;

/// The emitted hub B (`hub_b.v`): N = 4 node ports, M = 2 interlinks, HUB_ID 1.
pub type HubB4x2 = Hub<4, 2, 6, 1>;
