//! The host's DMR configuration (DMR contract §2): what firmware writes in reset mode
//! to run a DRCC in CiA 701 dual-modular redundancy mode, and the register sequence
//! that writes it.
//!
//! Order matters (contract §2.2): the connection-service identifiers are written
//! before any mailbox is enabled (a `DMR_CS` write while a mailbox is enabled is
//! refused), and each mailbox gets its identifier and mask before its `MB_CFG` enables
//! it (an enabled mailbox whose identifier equals a CS identifier is refused). Every
//! field position comes from the register table (`drcc_hdl::host::registers::MAP`).

use drcc_hdl::host::dmr_registers::MAILBOXES;
use drcc_hdl::host::registers::{self as map, MAP};

/// Mailboxes of the default generation (`M`, contract §2).
pub const MB_COUNT: usize = MAILBOXES as usize;

/// `reg.field` placed in a register word (positions from the table).
fn put(reg: &str, field: &str, value: u32) -> u32 {
    MAP.field(reg, field).put(value)
}

/// The reset value of `reg.field` (the table's, so defaults never drift from it).
fn reset(reg: &str, field: &str) -> u32 {
    MAP.field(reg, field).reset
}

/// One DMR mailbox (contract §4.1): the frames whose key matches `id` under `mask`
/// are counted by it; `transmit` mailboxes count the DRCC's own messages, receive
/// mailboxes the others'.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DmrMailbox {
    /// Direction: `MB_ID.dir` 1 (transmit) or 0 (receive).
    pub transmit: bool,
    /// Extended identifier (`MB_ID.ide`).
    pub ide: bool,
    /// Identifier (base frame: `id[10:0]`).
    pub id: u32,
    /// A 1 bit must match (`MB_MASK.mask`).
    pub mask: u32,
    /// Deviation limit 1..=127 (`MB_CFG.limit`).
    pub limit: u8,
}

/// The DMR configuration of one DRCC (registers `DMR_CFG`, `DMR_TIME`, `DMR_CS` and
/// the mailbox window).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DmrConfig {
    /// Mailbox and CS timeout, DMR ticks (`DMR_CFG.timeout`).
    pub timeout: u16,
    /// DMR ticks between periodic CS frames, 0 = none (`DMR_CFG.cs_period`).
    pub cs_period: u16,
    /// Nominal bit times per DMR tick (`DMR_TIME.tick_bits`).
    pub tick_bits: u16,
    /// DMR ticks before a faulty line is recovered (`DMR_TIME.recovery_delay`).
    pub recovery_delay: u16,
    /// Connection-service identifiers on the DCL and on the RCL (`DMR_CS`).
    pub cs_id_dcl: u16,
    pub cs_id_rcl: u16,
    /// Mailbox `i` (enabled iff `Some`).
    pub mailboxes: [Option<DmrMailbox>; MB_COUNT],
    /// `CTRL.first_copy` (DMR contract §8.1): the first copy of a frame from
    /// either line reaches the host, instead of the ACL's copies only.
    pub first_copy: bool,
}

impl Default for DmrConfig {
    /// The register table's reset values, no mailbox enabled.
    fn default() -> Self {
        DmrConfig {
            timeout: reset("DMR_CFG", "timeout") as u16,
            cs_period: reset("DMR_CFG", "cs_period") as u16,
            tick_bits: reset("DMR_TIME", "tick_bits") as u16,
            recovery_delay: reset("DMR_TIME", "recovery_delay") as u16,
            cs_id_dcl: reset("DMR_CS", "cs_id_dcl") as u16,
            cs_id_rcl: reset("DMR_CS", "cs_id_rcl") as u16,
            mailboxes: [None; MB_COUNT],
            first_copy: reset("CTRL", "first_copy") != 0,
        }
    }
}

impl DmrConfig {
    /// `DMR_CFG` word.
    pub fn dmr_cfg(&self) -> u32 {
        put("DMR_CFG", "timeout", self.timeout as u32)
            | put("DMR_CFG", "cs_period", self.cs_period as u32)
    }

    /// `DMR_TIME` word.
    pub fn dmr_time(&self) -> u32 {
        put("DMR_TIME", "tick_bits", self.tick_bits as u32)
            | put("DMR_TIME", "recovery_delay", self.recovery_delay as u32)
    }

    /// `DMR_CS` word.
    pub fn dmr_cs(&self) -> u32 {
        put("DMR_CS", "cs_id_dcl", self.cs_id_dcl as u32)
            | put("DMR_CS", "cs_id_rcl", self.cs_id_rcl as u32)
    }

    /// The register writes, in order, that configure DMR in reset mode (after
    /// `CTRL` has set `dmr`, before `CTRL` leaves reset mode): `DMR_CFG`, `DMR_TIME`,
    /// `DMR_CS`, then per enabled mailbox `MB_SEL`, `MB_ID`, `MB_MASK`, `MB_CFG`.
    pub fn writes(&self) -> Vec<(u8, u32)> {
        let mut w = vec![
            (map::DMR_CFG as u8, self.dmr_cfg()),
            (map::DMR_TIME as u8, self.dmr_time()),
            (map::DMR_CS as u8, self.dmr_cs()),
        ];
        for (i, mb) in self.mailboxes.iter().enumerate() {
            let Some(mb) = mb else { continue };
            w.push((map::MB_SEL as u8, put("MB_SEL", "index", i as u32)));
            w.push((
                map::MB_ID as u8,
                put("MB_ID", "id", mb.id)
                    | put("MB_ID", "ide", mb.ide as u32)
                    | put("MB_ID", "dir", mb.transmit as u32),
            ));
            w.push((map::MB_MASK as u8, put("MB_MASK", "mask", mb.mask)));
            w.push((
                map::MB_CFG as u8,
                put("MB_CFG", "limit", mb.limit as u32) | put("MB_CFG", "enable", 1),
            ));
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_tables_reset_values() {
        // DMR contract §2.1: timeout 100, cs_period 0, tick_bits 125, recovery_delay
        // 2000, CS identifiers 0x7EA / 0x7EB.
        let c = DmrConfig::default();
        assert_eq!(
            (c.timeout, c.cs_period, c.tick_bits, c.recovery_delay),
            (100, 0, 125, 2000)
        );
        assert_eq!((c.cs_id_dcl, c.cs_id_rcl), (0x7EA, 0x7EB));
        assert!(c.mailboxes.iter().all(|m| m.is_none()));
    }

    #[test]
    fn the_sequence_writes_cs_before_mailboxes_and_id_before_enable() {
        let mut c = DmrConfig {
            timeout: 20,
            recovery_delay: 200,
            ..DmrConfig::default()
        };
        c.mailboxes[3] = Some(DmrMailbox {
            transmit: true,
            ide: false,
            id: 0x123,
            mask: 0x7F0,
            limit: 3,
        });
        let w = c.writes();
        let regs: Vec<u32> = w.iter().map(|&(r, _)| r as u32).collect();
        assert_eq!(
            regs,
            [
                map::DMR_CFG,
                map::DMR_TIME,
                map::DMR_CS,
                map::MB_SEL,
                map::MB_ID,
                map::MB_MASK,
                map::MB_CFG
            ]
        );
        // Contract §2.1 field positions, written out independently of the table.
        assert_eq!(w[0].1, 20);
        assert_eq!(w[1].1, 125 | 200 << 16);
        assert_eq!(w[2].1, 0x7EA | 0x7EB << 16);
        assert_eq!(w[3].1, 3);
        assert_eq!(w[4].1, 0x123 | 1 << 30);
        assert_eq!(w[5].1, 0x7F0);
        assert_eq!(w[6].1, 3 | 1 << 31);
    }
}
