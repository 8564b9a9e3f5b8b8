//! Hub Wishbone register file (hub contract §8, Wishbone timing as DRCC contract
//! §D.2): word indices, field positions, reset values and clamps, the register
//! values a host can read or write, and the decoding of one write (which fields are
//! taken, which writes are refused and set `INT_STATUS.illegal`, which commands
//! act). The registers that only mirror guard or tracker state (`STATUS`, `STATS`,
//! `PORT_p`) are assembled by the hub (`super::HubModel`) from that state.

/// `ID` register without the shape: "HU" in the two upper bytes; `N << 8 | M` is
/// or-ed in.
pub const ID_BASE: u32 = 0x4855_0000;

/// `ID` register value of a hub with `n` node ports and `m` interlinks.
pub fn id_value(n: usize, m: usize) -> u32 {
    ID_BASE | (n as u32) << 8 | m as u32
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
    /// cfg.
    pub const ACK_INTERDEP: u32 = 1 << 8;
}

/// `BTR` fields (value - 1 encodings, as the DRCC's `BTR`; [31:15] read 0).
pub mod btr {
    pub const BRP_MASK: u32 = 0x3F;
    pub const TSEG1_SHIFT: u32 = 6;
    pub const TSEG2_SHIFT: u32 = 10;
    pub const SJW_SHIFT: u32 = 13;
    /// Every stored bit.
    pub const DEFINED: u32 = 0x7FFF;
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
    pub const ALL: u32 = 0x1F;
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
    /// Stored `BTR` ([14:0]).
    pub btr: u32,
    /// Stored `GUARD_CFG` (clamped fields).
    pub guard: u32,
    /// Stored `BF_CFG` (clamped fields).
    pub bf: u32,
    /// Stored `RESTORE_CFG`.
    pub restore: u32,
    pub int_status: u32,
    pub int_enable: u32,
    /// `irq` register: `|(INT_STATUS & INT_ENABLE)` one edge later.
    pub irq: bool,
    pub wb_ack: bool,
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
            btr: btr::RESET,
            guard: guard_cfg::RESET,
            bf: bf_cfg::RESET,
            restore: restore_cfg::RESET,
            int_status: 0,
            int_enable: 0,
            irq: false,
            wb_ack: false,
            wb_dat: 0,
        }
    }

    /// `CTRL` as read (the commands read 0).
    pub fn ctrl(&self) -> u32 {
        self.reset_mode as u32
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
                if rm {
                    self.ack_interdep = interdep;
                } else if interdep != before.ack_interdep {
                    fx.illegal = true;
                }
                let rm_w = d & ctrl::RESET_MODE != 0;
                self.reset_mode = rm_w;
                self.fi_ack_leak = d & ctrl::FI_ACK_LEAK != 0;
                if !rm && !rm_w {
                    fx.force_decouple = d & ctrl::FORCE_DECOUPLE != 0;
                    fx.recouple = d & ctrl::RECOUPLE != 0;
                }
            }
            idx::BTR | idx::GUARD_CFG | idx::BF_CFG | idx::RESTORE_CFG => {
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
                        _ => self.restore = d,
                    }
                }
            }
            idx::INT_STATUS => fx.w1c = d & int::ALL,
            idx::INT_ENABLE => self.int_enable = d & int::ALL,
            // ID, STATUS, STATS, ACK_UNIT, PORT_p (read only) and unmapped words.
            _ => fx.illegal = true,
        }
        fx
    }
}
