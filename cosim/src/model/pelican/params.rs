//! Generation keys of a `host = "pelican"` top (P-GEN-1).

use crate::model::drcc::DrccParams;

/// `pelican_*` keys and the native sizes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PelicanParams {
    /// `pelican_stride`: 4 or 1 (P-BUS-1, P-BUS-2).
    pub stride: u8,
    /// `pelican_default_mode` as an `XMODE.mode` code (0 `single_a`,
    /// 1 `redundancy`, 2 `dmr`, 3 `single_b`).
    pub mode: u8,
    /// `pelican_policy` as a §D5 code (0 none, 1 error-passive, 2 k-failed,
    /// 3 warning).
    pub policy: u8,
    /// `pelican_k` (1..15).
    pub k: u8,
    pub dual_tx: bool,
    pub star: bool,
    /// `pelican_busoff = "sja1000"` (`XMODE.bom`).
    pub bom: bool,
    /// `pelican_report = "best"` (`XMODE.rep`, P-LOG-5).
    pub report_best: bool,
    /// The native sizes (`rx_fifo_depth`, `dmr`, `star`, ...).
    pub core: DrccParams,
}

/// `XMODE.mode` codes (§13).
pub mod mode {
    pub const SINGLE_A: u8 = 0;
    pub const REDUNDANCY: u8 = 1;
    pub const DMR: u8 = 2;
    pub const SINGLE_B: u8 = 3;
}

impl Default for PelicanParams {
    /// The generator's defaults: stride 4, redundancy, error-passive, k = 1,
    /// no dual TX, no star, SJA1000 bus-off, the best channel reported.
    fn default() -> Self {
        PelicanParams {
            stride: 4,
            mode: mode::REDUNDANCY,
            policy: 1,
            k: 1,
            dual_tx: false,
            star: false,
            bom: true,
            report_best: true,
            core: DrccParams::DEFAULT,
        }
    }
}

impl PelicanParams {
    /// The reset value of `XMODE` (§13).
    pub fn xmode(&self) -> u8 {
        (self.mode & 3)
            | (self.policy & 3) << 2
            | (self.dual_tx as u8) << 4
            | (self.star as u8) << 5
            | (self.bom as u8) << 6
            | (self.report_best as u8) << 7
    }
}
