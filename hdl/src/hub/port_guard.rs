//! Guard of one hub port (ReCANcentrate paper section 2, "per-port fault
//! treatment" and "restoration policy"; hub contract §6). Instantiated once per
//! node port (uplink) and once per incoming sublink. At every SAMPLE edge it
//! judges `pb` (the port's `port_q`) against `b` (`coupled_q`) and the frame
//! events of the tracker:
//! - rule SD: `dom_run >= sd_limit` isolates (kind 1, stuck-at-dominant);
//! - rule RID: a node port that is still a candidate transmitter at data bit 10
//!   of identifier 0x000/0x001 is isolated (kind 4, reserved identifier);
//! - rule BF: BLAME (pec += 8) for a dominant bit from a port that is not the
//!   frame's transmitter, or for the transmitter at a stuff error on a recessive
//!   bit; `pec >= bf_limit` isolates (kind 3, bit-flipping);
//! - rule SR: `sr_frames` frames without a dominant bit isolate (kind 2, silent);
//! - a disabled port is restored after `restore_bits` SAMPLE edges without a
//!   symptom.
//!
//! Several isolations at one edge: the kind is the first of SD, RID, BF, SR. The
//! whole guard holds its reset values while `rst` (`rst | reset_mode`), holds every
//! field while `freeze` (a sublink guard while decoupled, every guard while NRAP is
//! active, §6), and the host's `recouple` command wins over a guard event at the
//! same edge (§8).
//!
//! Guard stage (§6.1): every input but `rst` comes one clock late through
//! `super::guard_stage`, so the guard applies at edge t + 1 what §6 decides at edge
//! t; its registers are §6's fields one clock late. The one exception is
//! `recouple`'s enable, which `enabled` and `word` show already in the clock after
//! the command's own edge (so NRAP never sees the recoupled sublinks disabled).
//!
//! Precomputed counters (structural, for Fmax): between two SAMPLE edges the
//! fields change only at the guard's own step (one clock after a SAMPLE edge),
//! at a reset or at a `recouple` (whose writes `*_eff` below anticipate), and two
//! SAMPLE edges are more than 2 clocks apart (§6.1); so in the clock before a step
//! the fields already hold the values the step reads. Every clock registers the
//! saturating increments and the threshold comparisons of those values (`pre_*`),
//! and the step uses them instead of computing them after the tracker's events.
//!
//! NRAP (§9.2) keeps the port's NRAP field here (`rrun`) and writes the guard's
//! fields through strobes from the phase machine (`super::nrap`; each implies a
//! SAMPLE edge; the top wires to a port only the strobes §9.2 gives its kind of
//! port). They come at edges where NRAP is active (the guard is frozen), except
//! `n_clr` at a Joining edge (`RUN` → `SRP_EXCHANGE`, sublinks), where §6 still
//! runs; `n_clr` writes only `rrun`, which §6 does not touch:
//! - `n_rrun` (sublinks, `SRP_EXCHANGE`): a disabled port counts recessive samples
//!   (`rrun`, saturating at 15, 0 at a dominant one) and is enabled at 11 with
//!   `pec = silent = restore_cnt = 0`;
//! - `n_watch` (node ports, `NRP`, `DDSP_SEND`, inside an identification frame):
//!   an enabled port that is dominant at a `FRAME_PORTS` bit after the arbitration
//!   field is disabled;
//! - `n_off`: `enabled = 0 ; rrun = 0`;
//! - `n_clr` (sublinks, Joining): `rrun = 0` (the port keeps its state);
//! - `n_enable` (node ports): enabled with `pec = silent = restore_cnt = 0`.
//!
//! Where two strobes meet at one edge the later in this list wins (only `n_rrun`
//! and `n_off` can: the entry to `DDSP_FORCE` disables the sublinks); `recouple`
//! wins over all of them.

use rust_hdl::prelude::*;

/// Port fault kinds (PORT_p.kind).
pub const KIND_STUCK_DOMINANT: u64 = 1;
pub const KIND_SILENT: u64 = 2;
pub const KIND_BIT_FLIPPING: u64 = 3;
pub const KIND_RESERVED_ID: u64 = 4;

/// One port's guard.
#[derive(LogicBlock)]
pub struct PortGuard {
    // clock and reset
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst | reset_mode`: the guard holds its reset values.
    pub rst: Signal<In, Bit>,
    /// Hold every field (a sublink guard while decoupled).
    pub freeze: Signal<In, Bit>,
    /// The reserved-identifier rule applies (node ports only).
    pub rid_en: Signal<In, Bit>,
    /// Host command `CTRL.recouple` for this port (sublinks only), one clock
    /// late like every input (§6.1); `enabled` shows it at once.
    pub recouple: Signal<In, Bit>,
    // SAMPLE edge, port value and bus value (before the edge)
    /// A SAMPLE edge of the hub's bit timing logic (one clock).
    pub sample: Signal<In, Bit>,
    /// `port_q` of this port: its value at the edge, 1 = recessive.
    pub pb: Signal<In, Bit>,
    /// `coupled_q`: the bus value at the edge, 1 = recessive.
    pub b: Signal<In, Bit>,
    // tracker events (each implies `sample`)
    /// Tracker `SOF_PORTS`: a start of frame (a dominant bit after at least 10 recessive ones).
    pub ev_sof: Signal<In, Bit>,
    /// Tracker `FRAME_PORTS`: a sampled bit of the frame, stuff bits and the CRC delimiter
    /// included.
    pub ev_frame: Signal<In, Bit>,
    /// Tracker: the bit is in the arbitration field (candidate transmitters are tracked).
    pub in_arb: Signal<In, Bit>,
    /// Tracker: a stuff error on a recessive bit (rule BF blames the transmitter).
    pub ev_stuff_rec: Signal<In, Bit>,
    /// Tracker: data bit 10 of identifier 0x000/0x001 (rule RID).
    pub ev_rid: Signal<In, Bit>,
    /// Tracker `ACK_PORTS`: the ACK slot (rule SR; a frame without blame decrements `pec`).
    pub ev_ack: Signal<In, Bit>,
    // NRAP strobes (§9.2; each implies `sample`)
    /// `SRP_EXCHANGE` (sublinks): count recessive samples while disabled, enable at 11.
    pub n_rrun: Signal<In, Bit>,
    /// `NRP`, `DDSP_SEND` (node ports): a dominant bit after the arbitration field
    /// disables.
    pub n_watch: Signal<In, Bit>,
    /// Disable: `enabled = 0 ; rrun = 0`.
    pub n_off: Signal<In, Bit>,
    /// `rrun = 0`, nothing else (sublinks, at the Joining edge).
    pub n_clr: Signal<In, Bit>,
    /// Enable with `pec = silent = restore_cnt = 0` (node ports).
    pub n_enable: Signal<In, Bit>,
    // limits (§8)
    /// Rule SD: the dominant run, in bits, that isolates the port as stuck-at-dominant.
    pub sd_limit: Signal<In, Bits<6>>,
    /// Rule BF: the `pec` that isolates the port as bit-flipping (BLAME adds 8).
    pub bf_limit: Signal<In, Bits<8>>,
    /// Rule SR: frames without a dominant bit from the port that isolate it as silent (0 = off).
    pub sr_frames: Signal<In, Bits<4>>,
    /// SAMPLE edges without a symptom after which a disabled port is restored (0 = never).
    pub restore_bits: Signal<In, Bits<16>>,
    // outputs
    /// The port takes part in the coupling (`PORT_p.enabled`); a `recouple` shows here at once.
    pub enabled: Signal<Out, Bit>,
    /// PORT_p register value: [0] enabled, [3:1] kind, [15:8] pec,
    /// [23:16] isolations, [31:24] restorations.
    pub word: Signal<Out, Bits<32>>,
    /// One-clock events for INT_STATUS (valid in the clock of the edge).
    pub iso_evt: Signal<Out, Bit>,
    /// The port was restored at this edge (INT_STATUS; one clock, like `iso_evt`).
    pub rest_evt: Signal<Out, Bit>,
    // registers
    enabled_q: DFF<Bit>,
    kind: DFF<Bits<3>>,
    pec: DFF<Bits<8>>,
    dom_run: DFF<Bits<6>>,
    silent: DFF<Bits<4>>,
    restore_cnt: DFF<Bits<16>>,
    isolations: DFF<Bits<8>>,
    restorations: DFF<Bits<8>>,
    cand: DFF<Bit>,
    lost: DFF<Bit>,
    blamed: DFF<Bit>,
    active: DFF<Bit>,
    // NRAP field (§9.2)
    rrun: DFF<Bits<4>>,
    // precomputed for the next step (see the header)
    pre_dom: DFF<Bits<6>>,
    pre_sd: DFF<Bit>,
    pre_pec_b: DFF<Bits<8>>,
    pre_bf: DFF<Bit>,
    pre_pec_dec: DFF<Bits<8>>,
    pre_sil: DFF<Bits<4>>,
    pre_sr: DFF<Bit>,
    pre_rc: DFF<Bits<16>>,
    pre_rest: DFF<Bit>,
    pre_rrun: DFF<Bits<4>>,
    pre_rrun11: DFF<Bit>,
    pec_eff: Signal<Local, Bits<8>>,
    sil_eff: Signal<Local, Bits<4>>,
    rc_eff: Signal<Local, Bits<16>>,
    dom_inc: Signal<Local, Bits<6>>,
    pec_inc: Signal<Local, Bits<8>>,
    sil_inc: Signal<Local, Bits<4>>,
    rc_inc: Signal<Local, Bits<16>>,
    rrun_inc: Signal<Local, Bits<4>>,
    // combinational
    run: Signal<Local, Bit>,
    dom_new: Signal<Local, Bits<6>>,
    sd_hit: Signal<Local, Bit>,
    cand_n: Signal<Local, Bit>,
    lost_n: Signal<Local, Bit>,
    active_n: Signal<Local, Bit>,
    blame: Signal<Local, Bit>,
    pec_blamed: Signal<Local, Bits<8>>,
    bf_hit: Signal<Local, Bit>,
    rid_hit: Signal<Local, Bit>,
    silent_new: Signal<Local, Bits<4>>,
    sr_hit: Signal<Local, Bit>,
    symptom: Signal<Local, Bit>,
    rc_new: Signal<Local, Bits<16>>,
    rrun_new: Signal<Local, Bits<4>>,
    en_out: Signal<Local, Bit>,
    // constants
    k_sd: Constant<Bits<3>>,
    k_sr: Constant<Bits<3>>,
    k_bf: Constant<Bits<3>>,
    k_rid: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    max4: Constant<Bits<4>>,
    eleven4: Constant<Bits<4>>,
    zero6: Constant<Bits<6>>,
    one6: Constant<Bits<6>>,
    max6: Constant<Bits<6>>,
    zero8: Constant<Bits<8>>,
    one8: Constant<Bits<8>>,
    eight8: Constant<Bits<8>>,
    sat8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl Default for PortGuard {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            freeze: Default::default(),
            rid_en: Default::default(),
            recouple: Default::default(),
            sample: Default::default(),
            pb: Default::default(),
            b: Default::default(),
            ev_sof: Default::default(),
            ev_frame: Default::default(),
            in_arb: Default::default(),
            ev_stuff_rec: Default::default(),
            ev_rid: Default::default(),
            ev_ack: Default::default(),
            n_rrun: Default::default(),
            n_watch: Default::default(),
            n_off: Default::default(),
            n_clr: Default::default(),
            n_enable: Default::default(),
            sd_limit: Default::default(),
            bf_limit: Default::default(),
            sr_frames: Default::default(),
            restore_bits: Default::default(),
            enabled: Default::default(),
            word: Default::default(),
            iso_evt: Default::default(),
            rest_evt: Default::default(),
            enabled_q: Default::default(),
            kind: Default::default(),
            pec: Default::default(),
            dom_run: Default::default(),
            silent: Default::default(),
            restore_cnt: Default::default(),
            isolations: Default::default(),
            restorations: Default::default(),
            cand: Default::default(),
            lost: Default::default(),
            blamed: Default::default(),
            active: Default::default(),
            rrun: Default::default(),
            pre_dom: Default::default(),
            pre_sd: Default::default(),
            pre_pec_b: Default::default(),
            pre_bf: Default::default(),
            pre_pec_dec: Default::default(),
            pre_sil: Default::default(),
            pre_sr: Default::default(),
            pre_rc: Default::default(),
            pre_rest: Default::default(),
            pre_rrun: Default::default(),
            pre_rrun11: Default::default(),
            pec_eff: Default::default(),
            sil_eff: Default::default(),
            rc_eff: Default::default(),
            dom_inc: Default::default(),
            pec_inc: Default::default(),
            sil_inc: Default::default(),
            rc_inc: Default::default(),
            rrun_inc: Default::default(),
            run: Default::default(),
            dom_new: Default::default(),
            sd_hit: Default::default(),
            cand_n: Default::default(),
            lost_n: Default::default(),
            active_n: Default::default(),
            blame: Default::default(),
            pec_blamed: Default::default(),
            bf_hit: Default::default(),
            rid_hit: Default::default(),
            silent_new: Default::default(),
            sr_hit: Default::default(),
            symptom: Default::default(),
            rc_new: Default::default(),
            rrun_new: Default::default(),
            en_out: Default::default(),
            k_sd: Constant::new(KIND_STUCK_DOMINANT.into()),
            k_sr: Constant::new(KIND_SILENT.into()),
            k_bf: Constant::new(KIND_BIT_FLIPPING.into()),
            k_rid: Constant::new(KIND_RESERVED_ID.into()),
            zero3: Constant::new(0.into()),
            zero4: Constant::new(0.into()),
            one4: Constant::new(1.into()),
            max4: Constant::new(15.into()),
            eleven4: Constant::new(11.into()),
            zero6: Constant::new(0.into()),
            one6: Constant::new(1.into()),
            max6: Constant::new(63.into()),
            zero8: Constant::new(0.into()),
            one8: Constant::new(1.into()),
            eight8: Constant::new(8.into()),
            sat8: Constant::new(248.into()),
            max8: Constant::new(255.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

impl Logic for PortGuard {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            enabled_q,
            kind,
            pec,
            dom_run,
            silent,
            restore_cnt,
            isolations,
            restorations,
            cand,
            lost,
            blamed,
            active,
            rrun,
            pre_dom,
            pre_sd,
            pre_pec_b,
            pre_bf,
            pre_pec_dec,
            pre_sil,
            pre_sr,
            pre_rc,
            pre_rest,
            pre_rrun,
            pre_rrun11
        );
        self.iso_evt.next = false;
        self.rest_evt.next = false;
        self.run.next = self.sample.val() & !self.freeze.val();

        // ---- precomputed for the next step (header): the fields as they will be
        // at it (a pending `recouple` clears pec, silent and restore_cnt first) ----
        self.pec_eff.next = self.pec.q.val();
        self.sil_eff.next = self.silent.q.val();
        self.rc_eff.next = self.restore_cnt.q.val();
        if self.recouple.val() {
            self.pec_eff.next = self.zero8.val();
            self.sil_eff.next = self.zero4.val();
            self.rc_eff.next = self.zero16.val();
        }
        if self.dom_run.q.val() == self.max6.val() {
            self.dom_inc.next = self.max6.val();
        } else {
            self.dom_inc.next = self.dom_run.q.val() + self.one6.val();
        }
        self.pre_dom.d.next = self.dom_inc.val();
        self.pre_sd.d.next = self.dom_inc.val() >= self.sd_limit.val();
        if self.pec_eff.val() >= self.sat8.val() {
            self.pec_inc.next = self.max8.val();
        } else {
            self.pec_inc.next = self.pec_eff.val() + self.eight8.val();
        }
        self.pre_pec_b.d.next = self.pec_inc.val();
        self.pre_bf.d.next = self.pec_inc.val() >= self.bf_limit.val();
        self.pre_pec_dec.d.next = self.pec_eff.val() - self.one8.val();
        if self.sil_eff.val() == self.max4.val() {
            self.sil_inc.next = self.max4.val();
        } else {
            self.sil_inc.next = self.sil_eff.val() + self.one4.val();
        }
        self.pre_sil.d.next = self.sil_inc.val();
        self.pre_sr.d.next = (self.sr_frames.val() != self.zero4.val())
            & (self.sil_inc.val() >= self.sr_frames.val());
        if self.rc_eff.val() == self.max16.val() {
            self.rc_inc.next = self.max16.val();
        } else {
            self.rc_inc.next = self.rc_eff.val() + self.one16.val();
        }
        self.pre_rc.d.next = self.rc_inc.val();
        self.pre_rest.d.next = (self.restore_bits.val() != self.zero16.val())
            & (self.rc_inc.val() >= self.restore_bits.val());
        if self.rrun.q.val() == self.max4.val() {
            self.rrun_inc.next = self.max4.val();
        } else {
            self.rrun_inc.next = self.rrun.q.val() + self.one4.val();
        }
        self.pre_rrun.d.next = self.rrun_inc.val();
        self.pre_rrun11.d.next = self.rrun_inc.val() >= self.eleven4.val();

        // every SAMPLE, every port: dom_run = pb ? 0 : min(dom_run + 1, 63)
        if self.pb.val() {
            self.dom_new.next = self.zero6.val();
        } else {
            self.dom_new.next = self.pre_dom.q.val();
        }
        // dom_new >= sd_limit
        if self.pb.val() {
            self.sd_hit.next = self.sd_limit.val() == self.zero6.val();
        } else {
            self.sd_hit.next = self.pre_sd.q.val();
        }

        // per-frame flags, tracked for every port
        self.cand_n.next = self.cand.q.val();
        self.lost_n.next = self.lost.q.val();
        self.active_n.next = self.active.q.val();
        if self.ev_sof.val() {
            self.cand_n.next = !self.pb.val();
            self.lost_n.next = false;
            self.active_n.next = !self.pb.val();
        }
        if self.ev_frame.val() | self.ev_ack.val() {
            self.active_n.next = self.active.q.val() | !self.pb.val();
        }
        if self.ev_frame.val() & self.in_arb.val() {
            if !self.pb.val() & !self.lost.q.val() {
                self.cand_n.next = true;
            }
            if self.pb.val() & !self.b.val() {
                self.cand_n.next = false;
                self.lost_n.next = true;
            }
        }

        // rule BF: BLAME (once per frame) and its pec
        self.blame.next = self.ev_frame.val()
            & !self.blamed.q.val()
            & ((!self.in_arb.val() & !self.pb.val() & !self.cand_n.val())
                | (self.ev_stuff_rec.val() & self.cand_n.val()));
        self.pec_blamed.next = self.pre_pec_b.q.val();
        self.bf_hit.next = self.blame.val() & self.pre_bf.q.val();
        // rule RID
        self.rid_hit.next = self.ev_rid.val() & self.rid_en.val() & self.cand_n.val();
        // rule SR
        self.silent_new.next = self.pre_sil.q.val();
        self.sr_hit.next = self.ev_ack.val() & !self.active_n.val() & self.pre_sr.q.val();
        // restoration
        self.symptom.next = (!self.pb.val() & self.b.val())
            | self.sd_hit.val()
            | (self.ev_ack.val() & !self.active_n.val());
        if self.symptom.val() {
            self.rc_new.next = self.zero16.val();
        } else {
            self.rc_new.next = self.pre_rc.q.val();
        }

        if self.run.val() {
            self.dom_run.d.next = self.dom_new.val();
            self.cand.d.next = self.cand_n.val();
            self.lost.d.next = self.lost_n.val();
            self.active.d.next = self.active_n.val();
            if self.ev_sof.val() {
                self.blamed.d.next = false;
            }
            if self.enabled_q.q.val() {
                if self.blame.val() {
                    self.blamed.d.next = true;
                    self.pec.d.next = self.pec_blamed.val();
                }
                if self.ev_ack.val() {
                    if !self.blamed.q.val() & (self.pec.q.val() != self.zero8.val()) {
                        self.pec.d.next = self.pre_pec_dec.q.val();
                    }
                    if self.active_n.val() {
                        self.silent.d.next = self.zero4.val();
                    } else {
                        self.silent.d.next = self.silent_new.val();
                    }
                }
                if self.sd_hit.val() | self.rid_hit.val() | self.bf_hit.val() | self.sr_hit.val() {
                    // ISOLATE(p, kind): first of SD, RID, BF, SR
                    self.iso_evt.next = true;
                    self.enabled_q.d.next = false;
                    if self.sd_hit.val() {
                        self.kind.d.next = self.k_sd.val();
                    } else if self.rid_hit.val() {
                        self.kind.d.next = self.k_rid.val();
                    } else if self.bf_hit.val() {
                        self.kind.d.next = self.k_bf.val();
                    } else {
                        self.kind.d.next = self.k_sr.val();
                    }
                    if self.isolations.q.val() != self.max8.val() {
                        self.isolations.d.next = self.isolations.q.val() + self.one8.val();
                    }
                    self.restore_cnt.d.next = self.zero16.val();
                    self.silent.d.next = self.zero4.val();
                }
            } else if !self.symptom.val() & self.pre_rest.q.val() {
                // new restore_cnt >= restore_bits != 0 (a symptom makes it 0)
                // restoration
                self.rest_evt.next = true;
                self.enabled_q.d.next = true;
                if self.restorations.q.val() != self.max8.val() {
                    self.restorations.d.next = self.restorations.q.val() + self.one8.val();
                }
                self.pec.d.next = self.zero8.val();
                self.silent.d.next = self.zero4.val();
                self.restore_cnt.d.next = self.zero16.val();
            } else {
                self.restore_cnt.d.next = self.rc_new.val();
            }
        }

        // ---- NRAP (§9.2) ----
        if self.pb.val() {
            self.rrun_new.next = self.pre_rrun.q.val();
        } else {
            self.rrun_new.next = self.zero4.val();
        }
        if self.n_rrun.val() & !self.enabled_q.q.val() {
            // a silent sublink: 11 recessive bits, an idle twin
            self.rrun.d.next = self.rrun_new.val();
            if self.pb.val() & self.pre_rrun11.q.val() {
                self.enabled_q.d.next = true;
                self.pec.d.next = self.zero8.val();
                self.silent.d.next = self.zero4.val();
                self.restore_cnt.d.next = self.zero16.val();
            }
        }
        if self.n_watch.val()
            & self.ev_frame.val()
            & !self.in_arb.val()
            & self.enabled_q.q.val()
            & !self.pb.val()
        {
            // only the frame's transmitter drives these bits: the node erred
            self.enabled_q.d.next = false;
        }
        if self.n_clr.val() {
            self.rrun.d.next = self.zero4.val();
        }
        if self.n_off.val() {
            self.enabled_q.d.next = false;
            self.rrun.d.next = self.zero4.val();
        }
        if self.n_enable.val() {
            self.enabled_q.d.next = true;
            self.pec.d.next = self.zero8.val();
            self.silent.d.next = self.zero4.val();
            self.restore_cnt.d.next = self.zero16.val();
        }

        if self.recouple.val() {
            // CTRL.recouple: kind and the counts are kept
            self.enabled_q.d.next = true;
            self.restore_cnt.d.next = self.zero16.val();
            self.silent.d.next = self.zero4.val();
            self.pec.d.next = self.zero8.val();
        }
        if self.rst.val() {
            self.enabled_q.d.next = true;
            self.kind.d.next = self.zero3.val();
            self.pec.d.next = self.zero8.val();
            self.dom_run.d.next = self.zero6.val();
            self.silent.d.next = self.zero4.val();
            self.restore_cnt.d.next = self.zero16.val();
            self.isolations.d.next = self.zero8.val();
            self.restorations.d.next = self.zero8.val();
            self.cand.d.next = false;
            self.lost.d.next = false;
            self.blamed.d.next = false;
            self.active.d.next = false;
            self.rrun.d.next = self.zero4.val();
            self.iso_evt.next = false;
            self.rest_evt.next = false;
        }
        // §6.1: the command's enable shows at its own edge (`recouple` is the
        // command one clock late, whose writes land now)
        self.en_out.next = self.enabled_q.q.val() | self.recouple.val();
        self.enabled.next = self.en_out.val();
        self.word.next = bit_cast::<32, 1>(self.en_out.val().into())
            | (bit_cast::<32, 3>(self.kind.q.val()) << 1)
            | (bit_cast::<32, 8>(self.pec.q.val()) << 8)
            | (bit_cast::<32, 8>(self.isolations.q.val()) << 16)
            | (bit_cast::<32, 8>(self.restorations.q.val()) << 24);
    }
}
