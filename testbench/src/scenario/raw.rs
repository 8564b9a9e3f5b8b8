//! The TOML schema as read by serde: every key of the format, spanned where an
//! error must name its line. the loader turns it into a [`Scenario`].

use super::*;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScenario {
    pub(super) name: Spanned<String>,
    pub(super) description: Option<String>,
    pub(super) clock_hz: Spanned<u64>,
    pub(super) bitrate: Option<Spanned<u64>>,
    pub(super) timing: Option<Spanned<RawTiming>>,
    pub(super) nodes: Spanned<toml::Value>,
    #[serde(default)]
    pub(super) frame: Vec<Spanned<RawFrame>>,
    pub(super) expect: Option<Vec<Spanned<RawExpect>>>,
    #[serde(default)]
    pub(super) fault: Vec<Spanned<RawFault>>,
    #[serde(default)]
    pub(super) abort: Vec<Spanned<RawAbort>>,
    pub(super) max_cycles: Option<Spanned<u64>>,
    pub(super) max_bits: Option<Spanned<u64>>,
    pub(super) max_ms: Option<Spanned<f64>>,
    pub(super) reset_cycles: Option<Spanned<u64>>,
    pub(super) mode: Option<Spanned<String>>,
    pub(super) ewl: Option<Spanned<i64>>,
    pub(super) single_shot: Option<bool>,
    #[serde(default)]
    pub(super) node_config: Vec<Spanned<RawNodeConfig>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawNodeConfig {
    pub(super) node: Spanned<toml::Value>,
    pub(super) mode: Option<Spanned<String>>,
    pub(super) ewl: Option<Spanned<i64>>,
    pub(super) single_shot: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawTiming {
    pub(super) brp: Spanned<i64>,
    pub(super) tseg1: Spanned<i64>,
    pub(super) tseg2: Spanned<i64>,
    pub(super) sjw: Option<Spanned<i64>>,
    #[serde(default)]
    pub(super) triple_sampling: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFrame {
    pub(super) node: Spanned<toml::Value>,
    pub(super) at_cycle: Option<Spanned<u64>>,
    pub(super) at_bit: Option<Spanned<u64>>,
    pub(super) id: Spanned<i64>,
    #[serde(default)]
    pub(super) extended: bool,
    #[serde(default)]
    pub(super) remote: bool,
    pub(super) dlc: Option<Spanned<i64>>,
    pub(super) data: Option<Spanned<Vec<i64>>>,
    #[serde(default)]
    pub(super) single_shot: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawExpect {
    pub(super) node: Spanned<toml::Value>,
    pub(super) receives: Option<Spanned<Vec<usize>>>,
    pub(super) sends: Option<Spanned<Vec<usize>>>,
    pub(super) fails: Option<Spanned<Vec<usize>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawAbort {
    pub(super) node: Spanned<toml::Value>,
    pub(super) at_cycle: Option<Spanned<u64>>,
    pub(super) at_bit: Option<Spanned<u64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFault {
    pub(super) kind: Spanned<String>,
    pub(super) target: Option<Spanned<String>>,
    pub(super) node: Option<Spanned<toml::Value>>,
    pub(super) at_cycle: Option<Spanned<u64>>,
    pub(super) at_bit: Option<Spanned<u64>>,
    pub(super) cycles: Option<Spanned<u64>>,
    pub(super) bits: Option<Spanned<u64>>,
}
