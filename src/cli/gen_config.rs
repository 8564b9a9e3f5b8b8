//! `drcc generate --config NAME|FILE`: the configuration a DRCC is generated
//! with (drcc_contract.md §1.1, `drcc_hdl::config`). NAME is one of the named
//! configurations (`default`, `m0`, `small`: the tops `drcc`, `drcc_m0`,
//! `drcc_small` of `rtl-out/`); FILE is a small TOML file:
//!
//! ```toml
//! name = "drcc_tiny"   # module and file name: a Verilog identifier
//! mailboxes = 0        # DMR mailboxes: 0 or 16
//! rx_fifo_depth = 16   # 4, 8, 16 or 32
//! tx_queue_depth = 4   # 2, 4 or 8
//! history = 8          # duplicate-removal history: 4, 8, 16 or 32
//! dmr = false          # the CiA 701 DMR function (CTRL.dmr)
//! star = false         # the replicated-star node (CTRL.star)
//! ```
//!
//! or, with `top = "hub"`, a ReCANcentrate hub of another shape (hub contract):
//!
//! ```toml
//! top = "hub"
//! name = "hub_6x3"
//! nodes = 6            # node ports N: 2..8 (default 4)
//! interlinks = 3       # interlinks M: 2..4 (default 2)
//! hub_id = 0           # 0 hub A (identification frame 0x000), 1 hub B (0x001)
//! ```
//!
//! Keys left out take the default configuration's value. Anything else (an
//! unknown key, a size not offered, a name that is not an identifier or is an
//! emitted top's) is refused with one message naming it.

use std::io::Read;
use std::path::Path;

use drcc_hdl::bus::Bus;
use drcc_hdl::config::DrccConfig;
use drcc_hdl::pelican::PelicanKeys;

/// Config files are a few lines; anything larger is refused unread.
const MAX_CONFIG_BYTES: u64 = 64 * 1024;

/// The keys a DRCC config file may have.
const KEYS: &[&str] = &[
    "top",
    "name",
    "mailboxes",
    "rx_fifo_depth",
    "tx_queue_depth",
    "history",
    "dmr",
    "star",
    "bus",
    "data_width",
    "host",
    "pelican_stride",
    "pelican_default_mode",
    "pelican_policy",
    "pelican_k",
    "pelican_dual_tx",
    "pelican_star",
    "pelican_busoff",
    "pelican_report",
];

/// The keys a hub config file may have.
const HUB_KEYS: &[&str] = &[
    "top",
    "name",
    "nodes",
    "interlinks",
    "hub_id",
    "bus",
    "data_width",
];

/// What a configuration generates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A DRCC with these sizes, on this host bus.
    Drcc(DrccConfig, Bus),
    /// A DRCC with these sizes behind the SJA1000 (PeliCAN) view (`host =
    /// "pelican"`), on this host bus.
    Pelican(DrccConfig, PelicanKeys, Bus),
    /// A hub with N node ports, M interlinks and this identification frame, on
    /// this host bus.
    Hub {
        nodes: usize,
        interlinks: usize,
        hub_id: usize,
        bus: Bus,
    },
}

/// A configuration to generate: the module name and the sizes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Generated {
    /// Module and file name (`<name>.v`).
    pub name: String,
    /// What it is.
    pub shape: Shape,
    /// A named configuration, whose top is in `rtl-out/`.
    pub named: bool,
}

impl Generated {
    /// The finished Verilog.
    pub fn verilog(&self) -> Result<String, String> {
        match (drcc_hdl::tops::top(&self.name), self.shape) {
            (Some(t), _) if self.named => Ok(t.verilog()),
            (_, Shape::Drcc(c, bus)) => drcc_hdl::tops::drcc_with_config_on(&self.name, &c, bus),
            (_, Shape::Pelican(c, k, bus)) => {
                drcc_hdl::tops::pelican_with_config(&self.name, &c, &k, bus)
            }
            (
                _,
                Shape::Hub {
                    nodes,
                    interlinks,
                    hub_id,
                    bus,
                },
            ) => drcc_hdl_shapes::hub_with_shape_on(&self.name, nodes, interlinks, hub_id, bus),
        }
    }

    /// `NAME = value` pairs, for the summary line.
    pub fn params(&self) -> Vec<String> {
        match self.shape {
            Shape::Drcc(c, bus) => c
                .params()
                .iter()
                .map(|(k, v)| format!("{k} = {v}"))
                .chain((bus != Bus::Wishbone).then(|| format!("BUS = {}", bus.name())))
                .collect(),
            Shape::Pelican(c, k, bus) => c
                .params()
                .into_iter()
                .chain(k.params())
                .map(|(key, v)| format!("{key} = {v}"))
                .chain((bus != Bus::Wishbone).then(|| format!("BUS = {}", bus.name())))
                .collect(),
            Shape::Hub {
                nodes,
                interlinks,
                hub_id,
                bus,
            } => [
                format!("HUB_ID = {hub_id}"),
                format!("N = {nodes}"),
                format!("M = {interlinks}"),
            ]
            .into_iter()
            .chain((bus != Bus::Wishbone).then(|| format!("BUS = {}", bus.name())))
            .collect(),
        }
    }
}

/// A named configuration, or the file at `spec`.
pub fn resolve(spec: &str) -> Result<Generated, String> {
    if let Some(config) = DrccConfig::named(spec) {
        let name = match spec {
            "default" => "drcc",
            "m0" => "drcc_m0",
            _ => "drcc_small",
        };
        return Ok(Generated {
            name: name.to_string(),
            shape: Shape::Drcc(config, Bus::Wishbone),
            named: true,
        });
    }
    let path = Path::new(spec);
    if !path.exists() {
        let names: Vec<&str> = DrccConfig::NAMED.iter().map(|(n, _)| *n).collect();
        return Err(format!(
            "--config {spec:?}: no such file and not a named configuration; give a TOML \
             file or one of {}",
            names.join(", ")
        ));
    }
    let text = read_capped(path)?;
    parse(&text).map_err(|e| format!("{}: {e}", path.display()))
}

fn read_capped(path: &Path) -> Result<String, String> {
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_CONFIG_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    if bytes.len() as u64 > MAX_CONFIG_BYTES {
        return Err(format!(
            "{}: larger than {MAX_CONFIG_BYTES} bytes: a configuration is a few lines of TOML",
            path.display()
        ));
    }
    String::from_utf8(bytes).map_err(|_| format!("{}: not UTF-8 text", path.display()))
}

/// Parses a config file's text.
pub fn parse(text: &str) -> Result<Generated, String> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        let msg = e.message().trim().to_string();
        match e.span() {
            Some(s) => format!("line {}: {msg}", text[..s.start].lines().count().max(1)),
            None => msg,
        }
    })?;
    let hub = match table.get("top") {
        None => false,
        Some(toml::Value::String(t)) if t == "drcc" => false,
        Some(toml::Value::String(t)) if t == "hub" => true,
        Some(v) => {
            return Err(format!(
                "top must be \"drcc\" or \"hub\", not {}",
                shorten(&v.to_string())
            ))
        }
    };
    let keys = if hub { HUB_KEYS } else { KEYS };
    for key in table.keys() {
        if !keys.contains(&key.as_str()) {
            return Err(format!(
                "unknown key {:?} for a {}: the keys are {}",
                shorten(key),
                if hub { "hub" } else { "DRCC" },
                keys.join(", ")
            ));
        }
    }
    let name = match table.get("name") {
        None if hub => "hub_custom".to_string(),
        None => "drcc_custom".to_string(),
        Some(toml::Value::String(s)) => s.clone(),
        Some(_) => return Err("name must be a string, e.g. name = \"drcc_tiny\"".to_string()),
    };
    check_name(&name)?;
    let size = |key: &str, default: usize| size(&table, key, default);
    let switch = |key: &str, default: bool| switch(&table, key, default);
    let bus = match table.get("bus") {
        None => "wishbone".to_string(),
        Some(toml::Value::String(b)) => b.clone(),
        Some(v) => {
            return Err(format!(
                "bus must be a string, one of {}, not {}",
                Bus::NAMES.join(", "),
                shorten(&v.to_string())
            ))
        }
    };
    let bus = Bus::parse(&shorten(&bus), size("data_width", 32)?)?;
    if hub {
        let shape = Shape::Hub {
            nodes: size("nodes", 4)?,
            interlinks: size("interlinks", 2)?,
            hub_id: size("hub_id", 0)?,
            bus,
        };
        let g = Generated {
            name,
            shape,
            named: false,
        };
        // refuses a shape outside the offer, naming the ranges
        g.verilog()?;
        return Ok(g);
    }
    let d = DrccConfig::DEFAULT;
    let config = DrccConfig {
        mailboxes: size("mailboxes", d.mailboxes)?,
        rx_fifo_depth: size("rx_fifo_depth", d.rx_fifo_depth)?,
        tx_queue_depth: size("tx_queue_depth", d.tx_queue_depth)?,
        history: size("history", d.history)?,
        dmr: switch("dmr", d.dmr)?,
        star: switch("star", d.star)?,
    };
    config.check()?;
    let pelican = match table.get("host") {
        None => false,
        Some(toml::Value::String(h)) if h == "native" => false,
        Some(toml::Value::String(h)) if h == "pelican" => true,
        Some(v) => {
            return Err(format!(
                "host must be \"native\" or \"pelican\" (the SJA1000 view), not {}",
                shorten(&v.to_string())
            ))
        }
    };
    let pelican_keys: Vec<&String> = table.keys().filter(|k| k.starts_with("pelican_")).collect();
    if !pelican {
        if let Some(k) = pelican_keys.first() {
            return Err(format!("{k} needs host = \"pelican\""));
        }
        return Ok(Generated {
            name,
            shape: Shape::Drcc(config, bus),
            named: false,
        });
    }
    let keys = pelican_keys_of(&table, &config)?;
    keys.check(&config)?;
    keys.check_bus(bus)?;
    Ok(Generated {
        name,
        shape: Shape::Pelican(config, keys, bus),
        named: false,
    })
}

/// The `pelican_*` keys of a config file (pelican_contract.md P-GEN-1).
fn pelican_keys_of(table: &toml::Table, config: &DrccConfig) -> Result<PelicanKeys, String> {
    let d = PelicanKeys::default();
    let choice = |key: &str, names: &[&str], default: u8| -> Result<u8, String> {
        match table.get(key) {
            None => Ok(default),
            Some(toml::Value::String(s)) if names.contains(&s.as_str()) => {
                Ok(names.iter().position(|n| n == s).unwrap_or(0) as u8)
            }
            Some(v) => Err(format!(
                "{key} must be one of {}, not {}",
                names.join(", "),
                shorten(&v.to_string())
            )),
        }
    };
    let stride = size(table, "pelican_stride", d.stride)?;
    let k = size(table, "pelican_k", d.k as usize)?;
    Ok(PelicanKeys {
        stride,
        mode: choice(
            "pelican_default_mode",
            &["single_a", "redundancy", "dmr", "single_b"],
            d.mode,
        )?,
        policy: choice(
            "pelican_policy",
            &["none", "error-passive", "k-failed", "warning"],
            d.policy,
        )?,
        k: k.min(u8::MAX as usize) as u8,
        dual_tx: switch(table, "pelican_dual_tx", d.dual_tx)?,
        star_on: switch(table, "pelican_star", d.star_on)?,
        bom: choice("pelican_busoff", &["auto", "sja1000"], d.bom as u8)? == 1,
        report_best: choice("pelican_report", &["in_use", "best"], d.report_best as u8)? == 1,
        dmr: config.dmr,
        star: config.star,
    })
}

/// The non-negative integer at `key`, or `default` without it.
fn size(table: &toml::Table, key: &str, default: usize) -> Result<usize, String> {
    match table.get(key) {
        None => Ok(default),
        Some(toml::Value::Integer(v)) if *v >= 0 => Ok(*v as usize),
        Some(v) => Err(format!(
            "{key} must be a non-negative integer, not {}",
            shorten(&v.to_string())
        )),
    }
}

/// The boolean at `key`, or `default` without it.
fn switch(table: &toml::Table, key: &str, default: bool) -> Result<bool, String> {
    match table.get(key) {
        None => Ok(default),
        Some(toml::Value::Boolean(b)) => Ok(*b),
        Some(v) => Err(format!(
            "{key} must be true or false, not {}",
            shorten(&v.to_string())
        )),
    }
}

/// A module name: a Verilog identifier, not an emitted top's name.
fn check_name(name: &str) -> Result<(), String> {
    let ident = !name.is_empty()
        && name.len() <= 64
        && name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.contains("__");
    if !ident {
        return Err(format!(
            "name {:?} is not a module name: use letters, digits and single underscores, \
             starting with a letter, at most 64 characters (e.g. \"drcc_tiny\")",
            shorten(name)
        ));
    }
    if drcc_hdl::tops::top(name).is_some() {
        return Err(format!(
            "name {name:?} is an emitted top of rtl-out/: choose another (e.g. \"{name}_custom\")"
        ));
    }
    Ok(())
}

/// At most 40 characters of user text, control characters escaped.
fn shorten(s: &str) -> String {
    let t: String = s.chars().take(40).collect();
    let t = t.escape_debug().to_string();
    if s.chars().count() > 40 {
        format!("{t}...")
    } else {
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_sets_the_sizes_and_omitted_keys_are_the_default() {
        let g = parse("name = \"drcc_tiny\"\nmailboxes = 0\nhistory = 8\n").unwrap();
        assert_eq!(g.name, "drcc_tiny");
        assert_eq!(
            g.shape,
            Shape::Drcc(
                DrccConfig {
                    mailboxes: 0,
                    history: 8,
                    ..DrccConfig::DEFAULT
                },
                Bus::Wishbone
            )
        );
        assert!(!g.named);
        let g = parse("name = \"drcc_apb_s\"\nbus = \"apb\"\ndata_width = 32\n").unwrap();
        assert_eq!(g.shape, Shape::Drcc(DrccConfig::DEFAULT, Bus::Apb));
        let g = parse("top = \"hub\"\nname = \"hub_axi\"\nbus = \"axi4-lite\"\n").unwrap();
        assert_eq!(
            g.shape,
            Shape::Hub {
                nodes: 4,
                interlinks: 2,
                hub_id: 0,
                bus: Bus::AxiLite
            }
        );
        assert!(g.params().contains(&"BUS = axi4-lite".to_string()));
    }

    #[test]
    fn bad_files_are_refused_naming_the_fault() {
        for (text, says) in [
            ("histroy = 8", "unknown key \"histroy\""),
            ("history = 12", "history = 12 is not offered"),
            ("history = -4", "history must be a non-negative integer"),
            ("tx_queue_depth = \"4\"", "tx_queue_depth must be"),
            ("mailboxes = 4", "mailboxes = 4 is not offered"),
            ("name = \"drcc\"", "is an emitted top"),
            ("name = \"9lives\"", "is not a module name"),
            ("name = \"a__b\"", "is not a module name"),
            ("name = 3", "name must be a string"),
            ("dmr = 0", "dmr must be true or false"),
            ("dmr = false", "mailboxes = 16 needs the DMR function"),
            ("top = \"ring\"", "top must be \"drcc\" or \"hub\""),
            (
                "top = \"hub\"\nhistory = 8",
                "unknown key \"history\" for a hub",
            ),
            ("top = \"hub\"\nnodes = 9", "nodes 2..8"),
            (
                "top = \"hub\"\nbus = \"avalon\"",
                "choose one of wishbone, apb, axi4-lite",
            ),
            (
                "top = \"hub\"\nbus = \"apb\"\ndata_width = 8",
                "data_width 8 is not offered",
            ),
            ("top = \"hub\"\nname = \"hub_b\"", "is an emitted top"),
            ("history = ", "line 1"),
            ("bus = \"avalon\"", "choose one of wishbone, apb, axi4-lite"),
            (
                "bus = 3",
                "bus must be a string, one of wishbone, apb, axi4-lite",
            ),
            (
                "bus = \"apb\"\ndata_width = 64",
                "data_width 64 is not offered",
            ),
        ] {
            let e = parse(text).unwrap_err();
            assert!(e.contains(says), "{text:?}: {e}");
        }
    }

    #[test]
    fn named_configurations_are_their_tops() {
        assert_eq!(resolve("small").unwrap().name, "drcc_small");
        assert_eq!(
            resolve("small").unwrap().shape,
            Shape::Drcc(DrccConfig::SMALL, Bus::Wishbone)
        );
        assert_eq!(resolve("default").unwrap().name, "drcc");
        assert!(resolve("tiny").unwrap_err().contains("default, m0, small"));
    }

    #[test]
    fn host_pelican_takes_the_pelican_keys() {
        let g = parse(
            "name = \"my_sja\"\nhost = \"pelican\"\npelican_stride = 1\n\
             pelican_default_mode = \"single_b\"\npelican_policy = \"k-failed\"\n\
             pelican_k = 3\npelican_busoff = \"auto\"\npelican_report = \"best\"\n",
        )
        .unwrap();
        assert_eq!(
            g.shape,
            Shape::Pelican(
                DrccConfig::DEFAULT,
                PelicanKeys {
                    stride: 1,
                    mode: 3,
                    policy: 2,
                    k: 3,
                    bom: false,
                    report_best: true,
                    ..PelicanKeys::default()
                },
                Bus::Wishbone
            )
        );
        let g = parse("host = \"pelican\"\nbus = \"axi4-lite\"\n").unwrap();
        assert_eq!(
            g.shape,
            Shape::Pelican(DrccConfig::DEFAULT, PelicanKeys::default(), Bus::AxiLite)
        );
        for (text, says) in [
            ("pelican_k = 2", "pelican_k needs host = \"pelican\""),
            ("host = \"sja\"", "host must be \"native\" or \"pelican\""),
            (
                "host = \"pelican\"\nbus = \"apb\"\npelican_stride = 1",
                "pelican_stride = 1 is offered on Wishbone only",
            ),
            (
                "host = \"pelican\"\npelican_stride = 2",
                "pelican_stride must be 1 or 4",
            ),
            (
                "host = \"pelican\"\npelican_k = 0",
                "pelican_k must be 1..15",
            ),
            (
                "host = \"pelican\"\nmailboxes = 0\ndmr = false\npelican_default_mode = \"dmr\"",
                "needs dmr = true",
            ),
            (
                "host = \"pelican\"\npelican_policy = \"always\"",
                "pelican_policy must be one of none",
            ),
        ] {
            let e = parse(text).unwrap_err();
            assert!(e.contains(says), "{text:?}: {e}");
        }
    }
}
