//! The SJA1000 (PeliCAN) host view of the DRCC (`cosim/src/model/pelican_contract.md`,
//! user's page `docs/pelican.md`): its blocks, one concern each, the register
//! block that wires them ([`view::PelicanView`]) and the top ([`top::DrccPelican`]).

pub mod acceptance_filter;
pub mod armed_capture;
pub mod bus_tops;
pub mod byte_lanes;
pub mod config_regs;
pub mod ecc_code;
pub mod extension;
pub mod interrupts;
pub mod logical;
pub mod mode_control;
pub mod native_window;
pub mod rbsa;
pub mod rx_window;
pub mod top;
pub mod tx_frame_buffer;
pub mod view;

/// `XMODE.mode` codes (§13).
pub mod mode {
    pub const SINGLE_A: u8 = 0;
    pub const REDUNDANCY: u8 = 1;
    pub const DMR: u8 = 2;
    pub const SINGLE_B: u8 = 3;
}

/// The `pelican_*` generation keys (P-GEN-1) and the core's options the view
/// checks (`XMODE` refuses `DMR` and `star` without them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PelicanKeys {
    /// `pelican_stride`: 4 (register `r` at byte `4r`) or 1 (at byte `r`).
    pub stride: usize,
    /// `pelican_default_mode` as an `XMODE.mode` code ([`mode`]).
    pub mode: u8,
    /// `pelican_policy` as a switch-policy code (0 none, 1 error-passive,
    /// 2 k-failed, 3 warning).
    pub policy: u8,
    /// `pelican_k` (1..15).
    pub k: u8,
    /// `pelican_dual_tx`.
    pub dual_tx: bool,
    /// `XMODE.star` after reset (needs the star node).
    pub star_on: bool,
    /// `pelican_busoff = "sja1000"`: a bus-off enters reset mode.
    pub bom: bool,
    /// `pelican_report = "best"`: the error state and counters of the better
    /// channel that could carry the traffic (`XMODE.rep`, P-LOG-5).
    pub report_best: bool,
    /// The core has the DMR function.
    pub dmr: bool,
    /// The core has the replicated-star node.
    pub star: bool,
}

impl Default for PelicanKeys {
    /// The generator's defaults: stride 4, redundancy, error-passive, `k = 1`,
    /// no dual TX, star off, SJA1000 bus-off, the best channel
    /// reported, with the DMR function and the star node.
    fn default() -> Self {
        PelicanKeys {
            stride: 4,
            mode: mode::REDUNDANCY,
            policy: 1,
            k: 1,
            dual_tx: false,
            star_on: false,
            bom: true,
            report_best: true,
            dmr: true,
            star: true,
        }
    }
}

impl PelicanKeys {
    /// The reset value of `XMODE` (§13): [1:0] mode, [3:2] policy, [4] dual_tx,
    /// [5] star, [6] bom, [7] rep.
    pub fn xmode(&self) -> u8 {
        (self.mode & 3)
            | (self.policy & 3) << 2
            | (self.dual_tx as u8) << 4
            | (self.star_on as u8) << 5
            | (self.bom as u8) << 6
            | (self.report_best as u8) << 7
    }

    /// `Err` naming the key when the keys ask for what `cfg` lacks or a value
    /// outside its range.
    pub fn check(&self, cfg: &crate::config::DrccConfig) -> Result<(), String> {
        if self.stride != 1 && self.stride != 4 {
            return Err(format!(
                "pelican_stride must be 1 or 4, not {}",
                self.stride
            ));
        }
        if self.mode > 3 {
            return Err(
                "pelican_default_mode must be single_a, redundancy, dmr or single_b".into(),
            );
        }
        if self.policy > 3 {
            return Err("pelican_policy must be none, error-passive, k-failed or warning".into());
        }
        if !(1..=15).contains(&self.k) {
            return Err(format!("pelican_k must be 1..15, not {}", self.k));
        }
        if self.mode == mode::DMR && !cfg.dmr {
            return Err("pelican_default_mode = \"dmr\" needs dmr = true".into());
        }
        if self.star_on && !cfg.star {
            return Err("pelican_star = true needs star = true".into());
        }
        Ok(())
    }

    /// Refuses a stride the host bus cannot carry: APB and AXI4-Lite reads
    /// carry no byte lanes, so the view is offered on them at stride 4 only
    /// (pelican_contract.md P-GEN-1).
    pub fn check_bus(&self, bus: crate::bus::Bus) -> Result<(), String> {
        if bus != crate::bus::Bus::Wishbone && self.stride != 4 {
            return Err(format!(
                "pelican_stride = {} is offered on Wishbone only: {} reads carry no byte \
                 lanes to pick one of four registers in a word; use pelican_stride = 4 \
                 (Linux reg-io-width = <4>)",
                self.stride,
                bus.name()
            ));
        }
        Ok(())
    }

    /// `NAME = value` pairs for the generated file's header.
    pub fn params(&self) -> Vec<(&'static str, String)> {
        let mode = ["single_a", "redundancy", "dmr", "single_b"][self.mode as usize & 3];
        let policy = ["none", "error-passive", "k-failed", "warning"][self.policy as usize & 3];
        vec![
            ("HOST", "pelican".to_string()),
            ("PELICAN_STRIDE", self.stride.to_string()),
            ("PELICAN_DEFAULT_MODE", mode.to_string()),
            ("PELICAN_POLICY", policy.to_string()),
            ("PELICAN_K", self.k.to_string()),
            ("PELICAN_DUAL_TX", (self.dual_tx as u8).to_string()),
            ("PELICAN_STAR", (self.star_on as u8).to_string()),
            (
                "PELICAN_BUSOFF",
                if self.bom { "sja1000" } else { "auto" }.to_string(),
            ),
            (
                "PELICAN_REPORT",
                if self.report_best { "best" } else { "in_use" }.to_string(),
            ),
        ]
    }
}
