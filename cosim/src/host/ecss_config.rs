//! What a host writes to run the ECSS bus selection (DRCC contract §12): the
//! redundancy object's `Bdefault`, `Ttoggle`, `Ntoggle`, the master's heartbeat
//! and its period, as the register words of the table.

use drcc_hdl::host::registers::MAP;

/// The ECSS registers' values (`ECSS_CFG` with `enable` set, `ECSS_HB`,
/// `ECSS_PERIOD`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EcssConfig {
    /// Heartbeat periods without a heartbeat before a toggle (1..255).
    pub ttoggle: u8,
    /// Toggles in a row without a heartbeat (0 = never toggle).
    pub ntoggle: u8,
    /// The bus on leaving reset mode: false A, true B.
    pub bdefault_b: bool,
    /// The master's heartbeat: a base identifier.
    pub hb_id: u16,
    /// The consumer heartbeat time in nominal bit times (1..2^24 - 1).
    pub period_bits: u32,
}

impl EcssConfig {
    /// The register writes, in reset mode.
    pub fn writes(&self) -> Vec<(u8, u32)> {
        let put = |reg: &str, field: &str, v: u32| MAP.field(reg, field).put(v);
        vec![
            (
                super::reg::ECSS_CFG,
                put("ECSS_CFG", "ttoggle", self.ttoggle as u32)
                    | put("ECSS_CFG", "ntoggle", self.ntoggle as u32)
                    | put("ECSS_CFG", "bdefault", self.bdefault_b as u32)
                    | put("ECSS_CFG", "enable", 1),
            ),
            (super::reg::ECSS_HB, put("ECSS_HB", "id", self.hb_id as u32)),
            (
                super::reg::ECSS_PERIOD,
                put("ECSS_PERIOD", "period", self.period_bits),
            ),
        ]
    }
}
