//! Hub Wishbone register file (hub contract §8, Wishbone timing as DRCC contract
//! §D.2): word indices, field positions, reset values and clamps, the register
//! values a host can read or write, and the decoding of one write (which fields are
//! taken, which writes are refused and set `INT_STATUS.illegal`, which commands
//! act). The registers that only mirror guard or tracker state (`STATUS`, `STATS`,
//! `PORT_p`) are assembled by the hub (`super::HubModel`) from that state.

/// `ID` register without the shape: "HU" in the two upper bytes; `N << 8 | M` is
/// or-ed in.
pub const ID_BASE: u32 = 0x4855_0000;

/// `ID` register value of hub `hub_id` (0 = A, 1 = B) with `n` node ports and `m`
/// interlinks.
pub fn id_value(hub_id: u8, n: usize, m: usize) -> u32 {
    ID_BASE | (hub_id as u32 & 1) << 12 | (n as u32) << 8 | m as u32
}

/// Word indices (`wb_adr_i`, byte offset / 4).
pub mod idx {
    pub const ID: u8 = 0;
    pub const CTRL: u8 = 1;
    pub const BTR: u8 = 2;
    pub const GUARD_CFG: u8 = 3;
    pub const BF_CFG: u8 = 4;
    pub const RESTORE_CFG: u8 = 5;
    pub const STATUS: u8 = 6;
    pub const INT_STATUS: u8 = 7;
    pub const INT_ENABLE: u8 = 8;
    pub const STATS: u8 = 9;
    /// ACK unit (§4.1): [15:0] interventions, [16] its ACK window.
    pub const ACK_UNIT: u8 = 10;
    /// NRAP (§9.5).
    pub const NRAP_CFG: u8 = 11;
    pub const NRAP_TIME: u8 = 12;
    pub const NRAP_DDSP: u8 = 13;
    pub const NRAP_STATUS: u8 = 14;
    /// `PORT_p` is word `PORT0 + p` (p < N + M).
    pub const PORT0: u8 = 16;
}

/// `CTRL` bits.
pub mod ctrl {
    pub const RESET_MODE: u32 = 1 << 0;
    /// Command (write 1), reads 0.
    pub const FORCE_DECOUPLE: u32 = 1 << 1;
    /// Command (write 1), reads 0.
    pub const RECOUPLE: u32 = 1 << 2;
    /// Fault injection (§4.1): the coupler passes its own nodes' ACK.
    pub const FI_ACK_LEAK: u32 = 1 << 3;
    /// Fault injection (§9.6): the coupler ignores the twin's contribution.
    pub const FI_NO_TWIN: u32 = 1 << 4;
    /// cfg.
    pub const ACK_INTERDEP: u32 = 1 << 8;
    /// cfg: NRAP (§9).
    pub const NRAP_ON: u32 = 1 << 9;
}

/// `NRAP_CFG`: [9:0] `force_bits`, [15:12] `srp_pairs`, [19:16] `nrp_pairs`,
/// [23:20] `ddsp_frames`; `NRAP_TIME`: [15:0] `srp_bits`, [31:16] `nrp_bits`;
/// `NRAP_DDSP`: [15:0] `ddsp_bits`, [20:16] `block_frames` (§9.5).
pub mod nrap_cfg {
    pub const FORCE_MIN: u32 = 64;
    pub const BITS_MIN: u32 = 256;
    pub const RESET: u32 = 64 | (2 << 12) | (2 << 16) | (8 << 20);
    pub const TIME_RESET: u32 = 1024 | (1024 << 16);
    pub const DDSP_RESET: u32 = 1024 | (16 << 16);
    /// Smallest nonzero `block_frames`.
    pub const BLOCK_MIN: u32 = 4;
}

/// `BTR` fields (value - 1 encodings, as the DRCC's `BTR`; [23:15] and [31:28]
/// read 0).
pub mod btr {
    pub const BRP_MASK: u32 = 0x3F;
    /// `brp_ext` [27:24] is BRP[9:6].
    pub const BRP_EXT_SHIFT: u32 = 24;
    pub const TSEG1_SHIFT: u32 = 6;
    pub const TSEG2_SHIFT: u32 = 10;
    pub const SJW_SHIFT: u32 = 13;
    /// Every stored bit.
    pub const DEFINED: u32 = 0x0F00_7FFF;
    /// brp 0, tseg1 field 4 (5 tq), tseg2 field 1 (2 tq), sjw field 0 (1 tq).
    pub const RESET: u32 = (4 << TSEG1_SHIFT) | (1 << TSEG2_SHIFT);
}

/// `GUARD_CFG`: [5:0] `sd_run_up`, [13:8] `sd_run_sub`, [19:16] `sr_frames`.
pub mod guard_cfg {
    /// Smallest stored stuck-dominant threshold (writes below are clamped).
    pub const SD_MIN: u32 = 14;
    pub const RESET: u32 = 14 | (28 << 8) | (8 << 16);
}

/// `BF_CFG`: [7:0] `bf_up`, [15:8] `bf_sub`.
pub mod bf_cfg {
    /// Smallest stored port error counter limit (writes below are clamped).
    pub const BF_MIN: u32 = 8;
    pub const RESET: u32 = 32 | (64 << 8);
}

/// `RESTORE_CFG`: [15:0] `restore_bits`, [31:16] `decouple_bits`.
pub mod restore_cfg {
    pub const RESET: u32 = 1408 | (4096 << 16);
}

/// `INT_STATUS` / `INT_ENABLE` bits.
pub mod int {
    pub const ISOLATION: u32 = 1 << 0;
    pub const RESTORATION: u32 = 1 << 1;
    pub const DECOUPLED: u32 = 1 << 2;
    pub const ILLEGAL: u32 = 1 << 3;
    /// The ACK unit intervened (§4.1).
    pub const ACK_UNIT: u32 = 1 << 4;
    /// An NRAP phase change (§9).
    pub const NRAP: u32 = 1 << 5;
    pub const ALL: u32 = 0x3F;
}

/// The register file and the Wishbone slave's output registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Regs {
    /// `CTRL.reset_mode` [1].
    pub reset_mode: bool,
    /// `reset_mode` one edge earlier (1 after `rst`): the BTL is held in reset by
    /// `reset_mode | reset_mode_q` (§5, as the DRCC channels).
    pub reset_mode_q: bool,
    /// `CTRL.ack_interdep` [1].
    pub ack_interdep: bool,
    /// `CTRL.fi_ack_leak` [0] (§4.1).
    pub fi_ack_leak: bool,
    /// `CTRL.fi_no_twin` [0] (§9.6).
    pub fi_no_twin: bool,
    /// Stored `BTR` ([14:0]).
    pub btr: u32,
    /// Stored `GUARD_CFG` (clamped fields).
    pub guard: u32,
    /// Stored `BF_CFG` (clamped fields).
    pub bf: u32,
    /// Stored `RESTORE_CFG`.
    pub restore: u32,
    /// `CTRL.nrap_on` [1].
    pub nrap_on: bool,
    /// Stored `NRAP_CFG`, `NRAP_TIME`, `NRAP_DDSP` (clamped fields).
    pub nrap_cfg: u32,
    pub nrap_time: u32,
    pub nrap_ddsp: u32,
    pub int_status: u32,
    pub int_enable: u32,
    /// `irq` register: `|(INT_STATUS & INT_ENABLE)` one edge later.
    pub irq: bool,
    pub wb_ack: bool,
    /// Wishbone `ERR` (bus_contract.md §1).
    pub wb_err: bool,
    pub wb_dat: u32,
}

impl Default for Regs {
    fn default() -> Self {
        Self::reset()
    }
}

/// What a Wishbone write asks of the rest of the hub.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WriteEffects {
    /// `INT_STATUS.illegal` event.
    pub illegal: bool,
    /// `INT_STATUS` bits written 1 (cleared unless an event sets them at this edge).
    pub w1c: u32,
    /// `CTRL.force_decouple` acts at this edge.
    pub force_decouple: bool,
    /// `CTRL.recouple` acts at this edge.
    pub recouple: bool,
}

impl Regs {
    /// Values after `rst`.
    pub fn reset() -> Self {
        Regs {
            reset_mode: true,
            reset_mode_q: true,
            ack_interdep: true,
            fi_ack_leak: false,
            fi_no_twin: false,
            btr: btr::RESET,
            guard: guard_cfg::RESET,
            bf: bf_cfg::RESET,
            restore: restore_cfg::RESET,
            nrap_on: true,
            nrap_cfg: nrap_cfg::RESET,
            nrap_time: nrap_cfg::TIME_RESET,
            nrap_ddsp: nrap_cfg::DDSP_RESET,
            int_status: 0,
            int_enable: 0,
            irq: false,
            wb_ack: false,
            wb_err: false,
            wb_dat: 0,
        }
    }

    /// `CTRL` as read (the commands read 0).
    pub fn ctrl(&self) -> u32 {
        self.reset_mode as u32
            | if self.fi_no_twin { ctrl::FI_NO_TWIN } else { 0 }
            | if self.fi_ack_leak {
                ctrl::FI_ACK_LEAK
            } else {
                0
            }
            | if self.ack_interdep {
                ctrl::ACK_INTERDEP
            } else {
                0
            }
            | if self.nrap_on { ctrl::NRAP_ON } else { 0 }
    }

    /// The NRAP settings (§9.5).
    pub fn nrap(&self) -> super::nrap::NrapCfg {
        super::nrap::NrapCfg {
            force_bits: (self.nrap_cfg & 0x3FF) as u16,
            srp_pairs: ((self.nrap_cfg >> 12) & 0xF) as u8,
            nrp_pairs: ((self.nrap_cfg >> 16) & 0xF) as u8,
            ddsp_frames: ((self.nrap_cfg >> 20) & 0xF) as u8,
            srp_bits: self.nrap_time as u16,
            nrp_bits: (self.nrap_time >> 16) as u16,
            ddsp_bits: self.nrap_ddsp as u16,
            block_frames: ((self.nrap_ddsp >> 16) & 0x1F) as u8,
        }
    }

    /// `sd_run_up`.
    pub fn sd_run_up(&self) -> u8 {
        (self.guard & 0x3F) as u8
    }
    /// `sd_run_sub`.
    pub fn sd_run_sub(&self) -> u8 {
        ((self.guard >> 8) & 0x3F) as u8
    }
    /// `sr_frames` (0 = silence rule off).
    pub fn sr_frames(&self) -> u8 {
        ((self.guard >> 16) & 0xF) as u8
    }
    /// `bf_up`.
    pub fn bf_up(&self) -> u8 {
        self.bf as u8
    }
    /// `bf_sub`.
    pub fn bf_sub(&self) -> u8 {
        (self.bf >> 8) as u8
    }
    /// `restore_bits` (0 = never restore).
    pub fn restore_bits(&self) -> u16 {
        self.restore as u16
    }
    /// `decouple_bits` (0 = never decouple).
    pub fn decouple_bits(&self) -> u16 {
        (self.restore >> 16) as u16
    }

    /// A write of `d` to word `adr`, decided on `before` (the registers before the
    /// edge) and stored into `self` (the registers after it). Writes to `PORT_p`
    /// are refused like those to any other read-only word.
    pub fn write(&mut self, before: &Regs, adr: u8, d: u32) -> WriteEffects {
        let mut fx = WriteEffects::default();
        let rm = before.reset_mode;
        match adr {
            idx::CTRL => {
                if d & ctrl::FORCE_DECOUPLE != 0 && d & ctrl::RECOUPLE != 0 {
                    // Both commands in one write: refused whole.
                    fx.illegal = true;
                    return fx;
                }
                let interdep = d & ctrl::ACK_INTERDEP != 0;
                let nrap_on = d & ctrl::NRAP_ON != 0;
                if rm {
                    self.ack_interdep = interdep;
                    self.nrap_on = nrap_on;
                } else if interdep != before.ack_interdep || nrap_on != before.nrap_on {
                    fx.illegal = true;
                }
                let rm_w = d & ctrl::RESET_MODE != 0;
                self.reset_mode = rm_w;
                self.fi_ack_leak = d & ctrl::FI_ACK_LEAK != 0;
                self.fi_no_twin = d & ctrl::FI_NO_TWIN != 0;
                if !rm && !rm_w {
                    fx.force_decouple = d & ctrl::FORCE_DECOUPLE != 0;
                    fx.recouple = d & ctrl::RECOUPLE != 0;
                }
            }
            idx::BTR
            | idx::GUARD_CFG
            | idx::BF_CFG
            | idx::RESTORE_CFG
            | idx::NRAP_CFG
            | idx::NRAP_TIME
            | idx::NRAP_DDSP => {
                if !rm {
                    fx.illegal = true;
                } else {
                    match adr {
                        idx::BTR => self.btr = d & btr::DEFINED,
                        idx::GUARD_CFG => {
                            let up = (d & 0x3F).max(guard_cfg::SD_MIN);
                            let sub = ((d >> 8) & 0x3F).max(guard_cfg::SD_MIN);
                            let sr = (d >> 16) & 0xF;
                            self.guard = up | sub << 8 | sr << 16;
                        }
                        idx::BF_CFG => {
                            let up = (d & 0xFF).max(bf_cfg::BF_MIN);
                            let sub = ((d >> 8) & 0xFF).max(bf_cfg::BF_MIN);
                            self.bf = up | sub << 8;
                        }
                        idx::NRAP_CFG => {
                            let force = (d & 0x3FF).max(nrap_cfg::FORCE_MIN);
                            let one = |f: u32| f.max(1);
                            self.nrap_cfg = force
                                | one((d >> 12) & 0xF) << 12
                                | one((d >> 16) & 0xF) << 16
                                | one((d >> 20) & 0xF) << 20;
                        }
                        idx::NRAP_TIME => {
                            let srp = (d & 0xFFFF).max(nrap_cfg::BITS_MIN);
                            let nrp = (d >> 16).max(nrap_cfg::BITS_MIN);
                            self.nrap_time = srp | nrp << 16;
                        }
                        idx::NRAP_DDSP => {
                            let block = match (d >> 16) & 0x1F {
                                0 => 0,
                                b => b.max(nrap_cfg::BLOCK_MIN),
                            };
                            self.nrap_ddsp = (d & 0xFFFF).max(nrap_cfg::BITS_MIN) | block << 16;
                        }
                        _ => self.restore = d,
                    }
                }
            }
            idx::INT_STATUS => fx.w1c = d & int::ALL,
            idx::INT_ENABLE => self.int_enable = d & int::ALL,
            // ID, STATUS, STATS, ACK_UNIT, NRAP_STATUS, PORT_p (read only) and
            // unmapped words.
            _ => fx.illegal = true,
        }
        fx
    }
}
