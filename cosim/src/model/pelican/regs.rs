//! The view's register map (§12, §13): decode of a bus access (P-BUS-1..4),
//! reads, writes, commands (§6), and the per-edge events of §7-§10.

use super::{mode, PelicanInputs, PelicanModel, View};
use crate::frame::Frame;
use crate::model::drcc::regs::int;
use crate::model::drcc::{HostDrive, NativeAccess};
use crate::model::field;

/// Register addresses (§12).
pub mod adr {
    pub const MOD: u8 = 0;
    pub const CMR: u8 = 1;
    pub const SR: u8 = 2;
    pub const IR: u8 = 3;
    pub const IER: u8 = 4;
    pub const BTR0: u8 = 6;
    pub const BTR1: u8 = 7;
    pub const OCR: u8 = 8;
    pub const ALC: u8 = 11;
    pub const ECC: u8 = 12;
    pub const EWLR: u8 = 13;
    pub const RXERR: u8 = 14;
    pub const TXERR: u8 = 15;
    pub const WIN: u8 = 16;
    pub const RMC: u8 = 29;
    pub const RBSA: u8 = 30;
    pub const CDR: u8 = 31;
    pub const TXB: u8 = 96;
    pub const SCR: u8 = 109;
    pub const XID0: u8 = 112;
    pub const XID1: u8 = 113;
    pub const XVER: u8 = 114;
    pub const XMODE: u8 = 115;
    pub const XK: u8 = 116;
    pub const XSTAT: u8 = 117;
    pub const XERR: u8 = 118;
    pub const XFSM: u8 = 119;
    pub const XIR: u8 = 120;
    pub const XIER: u8 = 121;
    pub const XWIN_IDX: u8 = 122;
    pub const XWIN_CMD: u8 = 123;
    pub const XWIN_D0: u8 = 124;
}

/// `IR` bits (P-IR-1).
pub mod ir {
    pub const RI: u8 = 1 << 0;
    pub const TI: u8 = 1 << 1;
    pub const EI: u8 = 1 << 2;
    pub const DOI: u8 = 1 << 3;
    pub const EPI: u8 = 1 << 5;
    pub const ALI: u8 = 1 << 6;
    pub const BEI: u8 = 1 << 7;
}

/// `IER` bits (P-IER-1).
pub mod ier {
    pub const RIE: u8 = 1 << 0;
    pub const TIE: u8 = 1 << 1;
    pub const EIE: u8 = 1 << 2;
    pub const DOIE: u8 = 1 << 3;
    pub const EPIE: u8 = 1 << 5;
    pub const ALIE: u8 = 1 << 6;
    pub const BEIE: u8 = 1 << 7;
}

/// `XIR` bits (§13).
pub mod xir {
    pub const SWITCH: u8 = 1 << 0;
    pub const AUX: u8 = 1 << 1;
    pub const DMR: u8 = 1 << 2;
    pub const DOMAIN: u8 = 1 << 3;
    pub const ERR_STATE: u8 = 1 << 4;
    pub const BUS: u8 = 1 << 5;
    pub const WIN: u8 = 1 << 6;
    pub const IGN: u8 = 1 << 7;
}

/// The `XIR` bits of the core's `INT_STATUS` events (P-X-2).
pub(super) fn xir_events(ints: u32) -> u8 {
    [
        (int::SWITCH, xir::SWITCH),
        (int::AUX, xir::AUX),
        (int::DMR, xir::DMR),
        (int::DOMAIN, xir::DOMAIN),
        (int::ERR_STATE, xir::ERR_STATE),
    ]
    .into_iter()
    .filter(|&(i, _)| ints & i != 0)
    .fold(0, |m, (_, x)| m | x)
}

/// Native indices a window commit may write (P-X-4).
const XWIN_OK: [u8; 9] = [3, 4, 25, 26, 27, 31, 32, 33, 34];

/// P-X-3: a window load of native word `idx` at this edge. The words the view
/// owns (`INT_STATUS` 6, `INT_ENABLE` 7, `TX_*` and `RX_*` 12..21) are not read
/// and load 0; a load of `CAP_A` (40) or `CAP_B` (41) re-arms that channel's
/// captures. The answer loads `XWIN_D0..3` at the next edge.
fn window_load(idx: u8, n: &mut View, d: &mut HostDrive) {
    n.xwin_load_q = true;
    if !matches!(idx, 6 | 7 | 12..=21) {
        d.native = Some(NativeAccess {
            we: false,
            adr: idx,
            dat: 0,
        });
    }
    match idx {
        40 => d.cap_rearm[0] = true,
        41 => d.cap_rearm[1] = true,
        _ => {}
    }
}

/// The frame of `TXB` (P-TX-1), normalized.
pub(super) fn txb_frame(t: &[u8; 13]) -> Frame {
    let ext = t[0] & 0x80 != 0;
    let (id, d0) = if ext {
        (
            (t[1] as u32) << 21 | (t[2] as u32) << 13 | (t[3] as u32) << 5 | (t[4] as u32) >> 3,
            5,
        )
    } else {
        ((t[1] as u32) << 3 | (t[2] as u32) >> 5, 3)
    };
    let mut data = [0u8; 8];
    data.copy_from_slice(&t[d0..d0 + 8]);
    Frame {
        id,
        ide: ext,
        rtr: t[0] & 0x40 != 0,
        dlc: t[0] & 0x0F,
        data,
    }
    .normalized()
}

/// The receive window byte `k` (0..12) of the FIFO head (P-RX-2).
fn window(f: &Frame, k: usize) -> u8 {
    let rtr = f.rtr as u8;
    let n = if f.rtr { 0 } else { f.dlc.min(8) as usize };
    let (hdr, d0): ([u8; 5], usize) = if f.ide {
        (
            [
                0x80 | rtr << 6 | f.dlc,
                (f.id >> 21) as u8,
                (f.id >> 13) as u8,
                (f.id >> 5) as u8,
                ((f.id as u8) << 3) | rtr << 2,
            ],
            5,
        )
    } else {
        (
            [
                rtr << 6 | f.dlc,
                (f.id >> 3) as u8,
                ((f.id as u8 & 7) << 5) | rtr << 4,
                0,
                0,
            ],
            3,
        )
    };
    if k < d0 {
        hdr[k]
    } else if k - d0 < n {
        f.data[k - d0]
    } else {
        0
    }
}

/// `len` of a popped frame for `RBSA` (P-RX-4).
pub(super) fn rbsa_len(f: &Frame) -> u8 {
    3 + 2 * f.ide as u8 + if f.rtr { 0 } else { f.dlc.min(8) }
}

impl PelicanModel {
    /// The register `r` as a read taken now returns it (P-MAP-1).
    pub fn read(&self, r: u8) -> u8 {
        let v = &self.v;
        let c = self.core.core_view();
        match r {
            adr::MOD => v.rm() as u8 | (v.lom as u8) << 1 | (v.stm as u8) << 2 | (v.afm as u8) << 3,
            adr::SR => self.sr(),
            adr::IR => v.ir | self.ri(v),
            adr::IER => v.ier,
            adr::BTR0 => v.btr0,
            adr::BTR1 => v.btr1,
            adr::OCR => v.ocr,
            adr::ALC => v.alc,
            adr::ECC => v.ecc,
            adr::EWLR => v.ewlr,
            adr::RXERR if !v.hrm => c.chan[self.r()].probes.rec,
            adr::TXERR if !v.hrm => {
                let rp = c.chan[self.r()].probes;
                if rp.err_state == 2 {
                    127u8.saturating_sub(rp.boff_runs)
                } else {
                    rp.tec.min(255) as u8
                }
            }
            16..=23 if v.rm() => {
                let k = (r - 16) as usize;
                if k < 4 {
                    v.acr[k]
                } else {
                    v.amr[k - 4]
                }
            }
            16..=28 if !v.rm() => window(&c.head, (r - 16) as usize),
            adr::RMC => c.rx_count,
            adr::RBSA => v.rbsa,
            adr::CDR => v.cdr,
            96..=108 => v.txb[(r - 96) as usize],
            109..=111 => v.scr[(r - 109) as usize],
            adr::XID0 => 0x44,
            adr::XID1 => 0x52,
            adr::XVER => 0x10,
            adr::XMODE => v.xmode,
            adr::XK => v.xk,
            adr::XSTAT => {
                (self.u() as u8)
                    | (c.failover as u8) << 1
                    | (c.aux[0] & 3) << 2
                    | (c.aux[1] & 3) << 4
                    | (v.boh as u8) << 6
                    | ((c.rx_ready && c.head_ch & 1 != 0) as u8) << 7
            }
            adr::XERR => {
                let [a, b] = c.chan;
                (a.probes.err_state & 3)
                    | (b.probes.err_state & 3) << 2
                    | (a.diag.err_warning as u8) << 4
                    | (b.diag.err_warning as u8) << 5
            }
            adr::XFSM => {
                (c.fsm_state & 0xF)
                    | (c.dmr_state & 3) << 4
                    | (c.acl & 1) << 6
                    | (c.split as u8) << 7
            }
            adr::XIR => v.xir,
            adr::XIER => v.xier,
            adr::XWIN_IDX => v.xwin_idx,
            adr::XWIN_CMD => v.xwin_refused as u8,
            124..=127 => v.xwin_d[(r - 124) as usize],
            _ => 0,
        }
    }

    /// The bus access of this edge (§2): reads, writes and commands go to `n`
    /// and `d`.
    pub(super) fn access(&self, i: &PelicanInputs, n: &mut View, d: &mut HostDrive) {
        let v = self.v;
        let take = i.cyc && i.stb && !(v.ack || v.err);
        n.ack = false;
        n.err = false;
        n.dat = 0;
        if !take {
            return;
        }
        let sel = i.sel & 0xF;
        // P-BUS-1, P-BUS-2: the register and the byte.
        let target = if self.params.stride == 4 {
            if i.we && sel & 1 == 0 {
                None
            } else {
                Some((i.adr & 0x7F, i.dat as u8))
            }
        } else if sel.count_ones() == 1 {
            let l = sel.trailing_zeros() as u8;
            Some(((i.adr & 0x1F) << 2 | l, (i.dat >> (8 * l)) as u8))
        } else {
            None
        };
        let Some((r, b)) = target else {
            n.err = true;
            n.xir |= xir::BUS;
            return;
        };
        n.ack = true;
        if !i.we {
            let x = self.read(r) as u32;
            n.dat = if self.params.stride == 4 {
                x
            } else {
                x * 0x0101_0101
            };
            self.read_side_effect(r, n);
        } else {
            self.write(r, b, n, d);
        }
    }

    /// P-BUS-4: the clear-on-read registers.
    fn read_side_effect(&self, r: u8, n: &mut View) {
        match r {
            adr::IR => n.ir &= !(ir::TI | ir::EI | ir::DOI | ir::EPI | ir::ALI | ir::BEI),
            adr::ALC => n.alc_armed = true,
            adr::ECC => n.ecc_armed = true,
            adr::XIR => n.xir = 0,
            _ => {}
        }
    }

    /// A register write taken at this edge (P-MAP-1, P-MAP-2).
    fn write(&self, r: u8, b: u8, n: &mut View, d: &mut HostDrive) {
        let v = self.v;
        let rm = v.rm();
        // P-BO-6: a changed channel configuration turns the hold into a reset.
        let reconfig = |n: &mut View, old: u8, new: u8| {
            if v.boh && old != new {
                n.boh = false;
                n.hrm = true;
            }
        };
        match r {
            adr::MOD => {
                if b & 0x10 != 0 {
                    n.xir |= xir::IGN;
                }
                if !rm {
                    n.hrm = b & 1 != 0;
                } else {
                    let cfg = |x: u8| x & 0x06;
                    n.lom = b & 2 != 0;
                    n.stm = b & 4 != 0;
                    n.afm = b & 8 != 0;
                    if b & 1 == 0 {
                        if v.boh {
                            n.boh = false;
                        } else {
                            n.hrm = false;
                        }
                    }
                    let old = (v.lom as u8) << 1 | (v.stm as u8) << 2;
                    reconfig(n, cfg(old), cfg(b));
                }
            }
            adr::CMR => self.command(b, n, d),
            adr::IER => n.ier = b,
            adr::BTR0 if rm => {
                reconfig(n, v.btr0, b);
                n.btr0 = b;
            }
            adr::BTR1 if rm => {
                reconfig(n, v.btr1, b);
                n.btr1 = b;
            }
            adr::OCR if rm => n.ocr = b,
            adr::EWLR if rm => {
                reconfig(n, v.ewlr, b);
                n.ewlr = b;
            }
            adr::RXERR | adr::TXERR if rm && (v.boh || b != 0) => n.xir |= xir::IGN,
            16..=23 if rm => {
                let k = (r - 16) as usize;
                if k < 4 {
                    n.acr[k] = b;
                } else {
                    n.amr[k - 4] = b;
                }
            }
            16..=28 if !rm && v.tbs => n.txb[(r - 16) as usize] = b,
            adr::RBSA if rm => n.rbsa = b & 0x3F,
            adr::CDR => n.cdr = if rm { b & 0xEF } else { (v.cdr & !7) | (b & 7) },
            32..=95 if rm => n.xir |= xir::IGN,
            96..=108 if rm => n.txb[(r - 96) as usize] = b,
            109..=111 if rm => n.scr[(r - 109) as usize] = b,
            adr::XMODE | adr::XK => {
                let md = b & 3;
                if !rm
                    || (r == adr::XMODE
                        && ((md == mode::DMR && !self.params.core.dmr)
                            || (b & 0x20 != 0 && !self.params.core.star)))
                {
                    n.xir |= xir::IGN;
                } else if r == adr::XMODE {
                    reconfig(n, v.xmode, b);
                    n.xmode = b;
                } else {
                    let k = (b & 0xF).max(1);
                    reconfig(n, v.xk, k);
                    n.xk = k;
                }
            }
            adr::XIER => n.xier = b,
            adr::XWIN_IDX => {
                n.xwin_idx = b & 0x3F;
                window_load(n.xwin_idx, n, d);
            }
            adr::XWIN_CMD => {
                if b == 1 {
                    let ok = v.hrm && XWIN_OK.contains(&v.xwin_idx);
                    n.xwin_refused = !ok;
                    if ok {
                        n.xwin_commit_q = true;
                        d.native = Some(NativeAccess {
                            we: true,
                            adr: v.xwin_idx,
                            dat: u32::from_le_bytes(v.xwin_d),
                        });
                    } else {
                        n.xir |= xir::WIN;
                    }
                } else if b == 2 {
                    window_load(v.xwin_idx, n, d);
                }
            }
            124..=127 => n.xwin_d[(r - 124) as usize] = b,
            _ => {}
        }
    }

    /// `CMR` (§6): CDO, RRB, then the transmit bits.
    fn command(&self, b: u8, n: &mut View, d: &mut HostDrive) {
        let v = self.v;
        let c = self.core.core_view();
        let (tr, at, rrb, cdo, srr) = (b & 1 != 0, b & 2 != 0, b & 4 != 0, b & 8 != 0, b & 16 != 0);
        if cdo {
            n.dos = false;
        }
        if rrb && !v.rm() && c.rx_count != 0 {
            d.pop = true;
            n.rbsa = (v.rbsa + rbsa_len(&c.head)) & 0x3F;
        }
        if v.rm() {
            return;
        }
        if (tr || srr) && v.tbs {
            n.tbs = false;
            n.tcs = false;
            if v.lom {
                n.lo_start = true;
                return;
            }
            let q = if v.mode() == mode::SINGLE_B { 1 } else { 0 };
            d.push = Some((q, txb_frame(&v.txb)));
            n.one_shot = at && v.single();
            if at && !v.single() {
                n.xir |= xir::IGN;
            }
            n.self_rx = srr;
        } else if at && !tr && !srr && !v.tbs {
            if v.single() {
                n.abort_req = true;
            } else {
                n.xir |= xir::IGN;
            }
        }
    }

    /// The events of this edge from the core's outputs before it (§7-§10).
    /// Returns the frame offered for self-reception (P-TX-5).
    pub(super) fn events(&self, n: &mut View) -> Option<Frame> {
        let v = self.v;
        let c = self.core.core_view();
        let o = self.core.outputs();
        let u = self.u();
        let ch = c.chan[u];
        let op = !v.rm();
        let en = |bit: u8| op && v.ier & bit != 0;
        // P-TX-7 completion.
        let (done, ok) = if v.lo_start {
            (true, false)
        } else if v.tbs {
            (false, false)
        } else {
            match v.mode() {
                mode::SINGLE_A | mode::SINGLE_B => {
                    let q = &c.chan[if v.mode() == mode::SINGLE_B { 1 } else { 0 }];
                    (q.tx_done || q.tx_failed, q.tx_done)
                }
                mode::REDUNDANCY => (o.probes.tx_success, true),
                _ => (self.ev.dmr_tx_done, true),
            }
        };
        let offer = (done && ok && v.self_rx && !v.lo_start).then(|| txb_frame(&v.txb));
        if done {
            n.lo_start = false;
            n.tbs = true;
            n.tcs = ok;
            n.abort_req = false;
            n.one_shot = false;
            n.self_rx = false;
            if en(ier::TIE) {
                n.ir |= ir::TI;
            }
        }
        if ch.diag.err_valid && en(ier::BEIE) {
            n.ir |= ir::BEI;
        }
        if ch.arb_lost && en(ier::ALIE) {
            n.ir |= ir::ALI;
        }
        // P-CAP-1, P-CAP-2.
        if ch.arb_lost && v.alc_armed {
            n.alc = ch.diag.alc & 0x1F;
            n.alc_armed = false;
        }
        if ch.diag.err_valid && v.ecc_armed {
            n.ecc = ecc_code(
                ch.diag.err_kind,
                ch.diag.err_field,
                !ch.diag.err_tx,
                ch.probes.err_state == 1,
            );
            n.ecc_armed = false;
        }
        // P-IR-5, P-IR-6, P-BO-1.
        let (es, bs) = (self.es(), self.lbo());
        let st = c.chan[self.r()].probes.err_state;
        if (es != v.es_q || bs != v.bs_q) && en(ier::EIE) {
            n.ir |= ir::EI;
        }
        // Passive -> active counts unless ES falls at the same edge (P-IR-6).
        // "Becomes ERROR_PASSIVE": from any other state of `r` (a switch from
        // a bus-off channel to a passive one included).
        let es_falls = v.es_q && !es;
        let epi = (v.st_q != 1 && st == 1) || (v.st_q == 1 && st == 0 && !es_falls);
        if epi && en(ier::EPIE) {
            n.ir |= ir::EPI;
        }
        // P-BO-1 in every mode (a logical bus-off of REDUNDANCY or DMR too);
        // a host reset taken at the same edge wins (one reset-mode cause).
        if op && bs && !v.bs_q && v.xmode & 0x40 != 0 && !n.hrm {
            n.boh = true;
        }
        n.es_q = es;
        n.bs_q = bs;
        n.st_q = st;
        offer
    }
}

/// `ECC` from the channel's error report (P-CAP-2).
fn ecc_code(kind: u8, fld: u8, rx: bool, passive: bool) -> u8 {
    let (errc, seg_override) = match kind {
        1 => (0, None),
        4 => (1, None),
        2 => (2, None),
        5 => (3, Some(0x19)),
        _ => (1, Some(0x1B)),
    };
    let seg = seg_override.unwrap_or(match fld {
        field::IDLE => 0x03,
        field::ID_A => 0x02,
        field::SRR_RTR => 0x04,
        field::IDE => 0x05,
        field::ID_B => 0x07,
        field::RTR_EXT => 0x0C,
        field::R1 => 0x0D,
        field::R0 => 0x09,
        field::DLC => 0x0B,
        field::DATA => 0x0A,
        field::CRC => 0x08,
        field::CRC_DELIM => 0x18,
        field::ACK_SLOT => 0x19,
        field::ACK_DELIM => 0x1B,
        field::EOF => 0x1A,
        field::INTERMISSION | field::SUSPEND => 0x12,
        field::ERROR_FLAG if passive => 0x16,
        field::ERROR_FLAG => 0x11,
        field::ERROR_DELIM | field::OVERLOAD_DELIM => 0x17,
        field::OVERLOAD_FLAG => 0x1C,
        _ => 0,
    });
    errc << 6 | (rx as u8) << 5 | seg
}
