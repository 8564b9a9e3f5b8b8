//! Generation-time configuration of the DRCC (drcc_contract.md §1.1): the sizes
//! fixed when the Verilog is generated. The default is the configuration every
//! proof of the repository ran on (`drcc`); `small` is the one documented for a
//! small FPGA (`drcc_small`); `drcc generate --config FILE` takes any other one
//! that [`DrccConfig::check`] accepts.
//!
//! The register widths do not change with the configuration (the counts keep
//! their fields: `STATUS[19:16]` TX queue count, `[29:24]` RX FIFO count), so one
//! register map, one C header and one driver serve every configuration.

/// The sizes of one DRCC configuration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DrccConfig {
    /// DMR mailboxes `M` (DMR contract §2): 0 or 16.
    pub mailboxes: usize,
    /// RX FIFO entries (§7): 4, 8, 16 or 32.
    pub rx_fifo_depth: usize,
    /// Entries of each TX queue (§6): 2, 4 or 8.
    pub tx_queue_depth: usize,
    /// Duplicate-removal history entries (§7): 4, 8, 16 or 32.
    pub history: usize,
    /// The CiA 701 DMR function (`CTRL.dmr`, DMR contract): without it a `CTRL`
    /// write with `dmr` is refused and synthesis removes the DMR logic.
    pub dmr: bool,
    /// The replicated-star node (`CTRL.star`, §4.4, §4.5): without it a `CTRL`
    /// write with `star` is refused and synthesis removes the echo and the
    /// hub-frame follower's mode logic.
    pub star: bool,
}

/// The values each size may take (powers of two up to the default, which sets
/// the register and pointer widths).
pub const MAILBOXES: &[usize] = &[0, 16];
/// RX FIFO depths offered.
pub const RX_FIFO_DEPTHS: &[usize] = &[4, 8, 16, 32];
/// TX queue depths offered.
pub const TX_QUEUE_DEPTHS: &[usize] = &[2, 4, 8];
/// History sizes offered.
pub const HISTORY_SIZES: &[usize] = &[4, 8, 16, 32];

impl DrccConfig {
    /// The proven default (`rtl-out/drcc.v`).
    pub const DEFAULT: DrccConfig = DrccConfig {
        mailboxes: 16,
        rx_fifo_depth: 32,
        tx_queue_depth: 8,
        history: 32,
        dmr: true,
        star: true,
    };

    /// No mailboxes, otherwise the default (`rtl-out/drcc_m0.v`).
    pub const M0: DrccConfig = DrccConfig {
        mailboxes: 0,
        ..DrccConfig::DEFAULT
    };

    /// For a small FPGA (`rtl-out/drcc_small.v`): the DRCC paper's dual-bus
    /// controller without the later modes (no CiA 701 DMR, no replicated-star
    /// node), an RX FIFO of 8, TX queues of 4, a history of 16 (the 4-node fault
    /// scenarios need ~15 frames between a message's two copies, §7).
    pub const SMALL: DrccConfig = DrccConfig {
        mailboxes: 0,
        rx_fifo_depth: 8,
        tx_queue_depth: 4,
        history: 16,
        dmr: false,
        star: false,
    };

    /// The named configurations, as `drcc generate --config NAME` spells them.
    pub const NAMED: &'static [(&'static str, DrccConfig)] = &[
        ("default", DrccConfig::DEFAULT),
        ("m0", DrccConfig::M0),
        ("small", DrccConfig::SMALL),
    ];

    /// The named configuration `name`.
    pub fn named(name: &str) -> Option<DrccConfig> {
        Self::NAMED
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, c)| *c)
    }

    /// Refuses a size outside its offered values, naming the field and the values.
    pub fn check(&self) -> Result<(), String> {
        let sizes: [(&str, usize, &[usize]); 4] = [
            ("mailboxes", self.mailboxes, MAILBOXES),
            ("rx_fifo_depth", self.rx_fifo_depth, RX_FIFO_DEPTHS),
            ("tx_queue_depth", self.tx_queue_depth, TX_QUEUE_DEPTHS),
            ("history", self.history, HISTORY_SIZES),
        ];
        if self.mailboxes != 0 && !self.dmr {
            return Err(format!(
                "mailboxes = {} needs the DMR function: set dmr = true or mailboxes = 0",
                self.mailboxes
            ));
        }
        for (name, v, offered) in sizes {
            if !offered.contains(&v) {
                let list: Vec<String> = offered.iter().map(|o| o.to_string()).collect();
                return Err(format!(
                    "{name} = {v} is not offered: use one of {}",
                    list.join(", ")
                ));
            }
        }
        Ok(())
    }

    /// `name = value` pairs for the header of the generated Verilog.
    pub fn params(&self) -> Vec<(&'static str, String)> {
        vec![
            ("M", self.mailboxes.to_string()),
            ("RX_FIFO_DEPTH", self.rx_fifo_depth.to_string()),
            ("TX_QUEUE_DEPTH", self.tx_queue_depth.to_string()),
            ("HISTORY", self.history.to_string()),
            ("DMR", (self.dmr as u8).to_string()),
            ("STAR", (self.star as u8).to_string()),
        ]
    }
}

impl Default for DrccConfig {
    fn default() -> Self {
        Self::DEFAULT
    }
}
