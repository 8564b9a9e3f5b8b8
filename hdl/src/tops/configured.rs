//! Tops generated with a configuration of their own (`drcc generate --config`):
//! the DRCC with the sizes and modes of a [`DrccConfig`] (drcc_contract.md §1.1)
//! and the hub in any shape it offers, each finished like an emitted top (header,
//! port table, port comments) under the user's module name.

use super::{port_docs, ports_of, raw_verilog_of, top, verilog, Port, Top};
use crate::bus::drcc_tops::{DrccApb, DrccAxi};
use crate::bus::hub_tops::{HubApb, HubAxi};
use crate::bus::Bus;
use crate::config::DrccConfig;
use crate::drcc::DrccTop;
use crate::hub::hub::Hub;
use crate::pelican::bus_tops::{DrccPelicanApb, DrccPelicanAxi};
use crate::pelican::top::DrccPelican;
use crate::pelican::PelicanKeys;
use rust_hdl::prelude::*;

/// The raw Verilog of the DRCC with the sizes of `cfg` (`M` = `cfg.mailboxes`).
fn raw_verilog_drcc<const M: usize>(cfg: &DrccConfig) -> String {
    let mut uut = DrccTop::<M>::with_config(cfg);
    uut.connect_all();
    generate_verilog(&uut)
}

/// The raw Verilog of the DRCC with the sizes of `cfg` on `bus`.
fn raw_verilog_drcc_on<const M: usize>(cfg: &DrccConfig, bus: Bus) -> String {
    match bus {
        Bus::Wishbone => raw_verilog_drcc::<M>(cfg),
        Bus::Apb => {
            let mut uut = DrccApb::<M>::with_config(cfg);
            uut.connect_all();
            generate_verilog(&uut)
        }
        Bus::AxiLite => {
            let mut uut = DrccAxi::<M>::with_config(cfg);
            uut.connect_all();
            generate_verilog(&uut)
        }
    }
}

pub(super) fn raw_verilog_small() -> String {
    raw_verilog_drcc::<0>(&DrccConfig::SMALL)
}

/// A top like `base` under another module name, summary and parameters: a
/// one-shot top of the CLI (`drcc generate --config`), whose few strings live
/// for the process.
fn configured(
    base: &Top,
    name: &str,
    summary: &'static str,
    params: Vec<(&'static str, String)>,
) -> Top {
    let params: Vec<(&'static str, &'static str)> = params
        .into_iter()
        .map(|(k, v)| (k, &*Box::leak(v.into_boxed_str())))
        .collect();
    Top {
        name: Box::leak(name.to_string().into_boxed_str()),
        summary,
        params: Box::leak(params.into_boxed_slice()),
        ..*base
    }
}

/// The finished Verilog of a DRCC generated with `cfg`, as module `name`
/// (`drcc generate --config`): the `drcc` top's header, ports and notes, with
/// `cfg`'s parameters. Refuses a configuration [`DrccConfig::check`] refuses.
pub fn drcc_with_config(name: &str, cfg: &DrccConfig) -> Result<String, String> {
    drcc_with_config_on(name, cfg, Bus::Wishbone)
}

/// [`drcc_with_config`] on the host bus `bus` (bus_contract.md): the header,
/// ports and notes of the `drcc`, `drcc_apb` or `drcc_axi` top.
pub fn drcc_with_config_on(name: &str, cfg: &DrccConfig, bus: Bus) -> Result<String, String> {
    cfg.check()?;
    let raw = match cfg.mailboxes {
        0 => raw_verilog_drcc_on::<0>(cfg, bus),
        _ => raw_verilog_drcc_on::<16>(cfg, bus),
    };
    let base = match bus {
        Bus::Wishbone => "drcc",
        Bus::Apb => "drcc_apb",
        Bus::AxiLite => "drcc_axi",
    };
    let mut params = cfg.params();
    if bus != Bus::Wishbone {
        params.push(("BUS", bus.name().to_string()));
    }
    let t = configured(
        top(base).expect("the drcc tops"),
        name,
        "the DRCC generated with a configuration of its own (drcc generate --config)",
        params,
    );
    Ok(verilog::finish(&t, &raw, &t.ports()))
}

/// The raw Verilog and the ports of the hub with `n` node ports, `m`
/// interlinks and identification frame `hub_id` (hub contract §9.1) on `bus`, for
/// every shape the hub supports (N 2..8, M 1..4, P = N + M); `None` for another.
fn hub_of_shape(n: usize, m: usize, hub_id: usize, bus: Bus) -> Option<(String, Vec<Port>)> {
    fn of<B: Block + Default>() -> Option<(String, Vec<Port>)> {
        Some((raw_verilog_of::<B>(), ports_of::<B>()))
    }
    fn on<const N: usize, const M: usize, const P: usize, const H: usize>(
        bus: Bus,
    ) -> Option<(String, Vec<Port>)> {
        match bus {
            Bus::Wishbone => of::<Hub<N, M, P, H>>(),
            Bus::Apb => of::<HubApb<N, M, P, H>>(),
            Bus::AxiLite => of::<HubAxi<N, M, P, H>>(),
        }
    }
    macro_rules! shapes {
        ($( ($N:literal, $M:literal, $P:literal) ),* $(,)?) => {
            match (n, m, hub_id) {
                $(
                    ($N, $M, 0) => on::<$N, $M, $P, 0>(bus),
                    ($N, $M, 1) => on::<$N, $M, $P, 1>(bus),
                )*
                _ => None,
            }
        };
    }
    shapes!(
        (2, 1, 3),
        (2, 2, 4),
        (2, 3, 5),
        (2, 4, 6),
        (3, 1, 4),
        (3, 2, 5),
        (3, 3, 6),
        (3, 4, 7),
        (4, 1, 5),
        (4, 2, 6),
        (4, 3, 7),
        (4, 4, 8),
        (5, 1, 6),
        (5, 2, 7),
        (5, 3, 8),
        (5, 4, 9),
        (6, 1, 7),
        (6, 2, 8),
        (6, 3, 9),
        (6, 4, 10),
        (7, 1, 8),
        (7, 2, 9),
        (7, 3, 10),
        (7, 4, 11),
        (8, 1, 9),
        (8, 2, 10),
        (8, 3, 11),
        (8, 4, 12),
    )
}

/// The finished Verilog of a hub generated with `n` node ports, `m` interlinks
/// and identification frame `hub_id` (0 = hub A, 1 = hub B), as module `name`
/// (`drcc generate --config`): the `hub` top's header, port docs and notes with
/// these parameters. Refuses a shape the hub does not support, naming the ranges.
pub fn hub_with_shape(name: &str, n: usize, m: usize, hub_id: usize) -> Result<String, String> {
    hub_with_shape_on(name, n, m, hub_id, Bus::Wishbone)
}

/// The base tops of the hub on an APB or an AXI4-Lite bus: not emitted into
/// `rtl-out/` (the hub's named tops are on Wishbone), generated by `--config`.
fn hub_bus_top(bus: Bus) -> Top {
    let (block, notes) = match bus {
        Bus::Apb => (
            "HubApb",
            "The hub behind the APB front end of cosim/src/model/bus_contract.md section 2:\n\
             every access phase lasts two clocks, a refused access ends with PSLVERR.\n\
             Registers: docs/hub_registers.md.",
        ),
        _ => (
            "HubAxi",
            "The hub behind the AXI4-Lite front end of cosim/src/model/bus_contract.md\n\
             section 3: one access at a time, a refused access ends with SLVERR.\n\
             Registers: docs/hub_registers.md.",
        ),
    };
    Top {
        name: "hub",
        block,
        source_path: "hdl/src/bus/hub_tops.rs",
        source: include_str!("../bus/hub_tops.rs"),
        contract: "cosim/src/model/bus_contract.md",
        notes,
        can_tx: &["downlink", "sublink_out"],
        ..*top("hub").expect("the hub top")
    }
}

/// [`hub_with_shape`] on the host bus `bus` (bus_contract.md §4): the hub's
/// links and interrupt, its register port on Wishbone, APB or AXI4-Lite.
pub fn hub_with_shape_on(
    name: &str,
    n: usize,
    m: usize,
    hub_id: usize,
    bus: Bus,
) -> Result<String, String> {
    // M = 1 simulates (rust-hdl, the model) but is not emitted: rust-hdl writes a
    // one-bit vector as a scalar and still indexes it (`sub_q[0]`), which
    // Verilog refuses
    let offered = m >= 2;
    let (raw, mut ports) = hub_of_shape(n, m, hub_id, bus)
        .filter(|_| offered)
        .ok_or_else(|| {
            format!(
                "hub shape nodes = {n}, interlinks = {m}, hub_id = {hub_id} is not offered: \
                 nodes 2..8, interlinks 2..4, hub_id 0 (hub A) or 1 (hub B)"
            )
        })?;
    let on_bus;
    let base = match bus {
        Bus::Wishbone => top("hub").expect("the hub top"),
        _ => {
            on_bus = hub_bus_top(bus);
            &on_bus
        }
    };
    let mut params = vec![
        ("HUB_ID", hub_id.to_string()),
        ("N", n.to_string()),
        ("M", m.to_string()),
    ];
    if bus != Bus::Wishbone {
        params.push(("BUS", bus.name().to_string()));
    }
    let t = configured(
        base,
        name,
        "the ReCANcentrate hub generated with a shape of its own (drcc generate --config)",
        params,
    );
    let docs = port_docs::port_docs(t.source, t.block);
    for p in &mut ports {
        if let Some((_, doc)) = docs.iter().find(|(nm, _)| *nm == p.name) {
            p.doc = doc.clone();
        }
    }
    Ok(verilog::finish(&t, &raw, &ports))
}

/// The raw Verilog of the SJA1000 view over a core with the sizes of `cfg`, on `bus`.
fn raw_verilog_pelican<const M: usize>(cfg: &DrccConfig, keys: &PelicanKeys, bus: Bus) -> String {
    match bus {
        Bus::Wishbone => {
            let mut uut = DrccPelican::<M>::with_config(cfg, keys);
            uut.connect_all();
            generate_verilog(&uut)
        }
        Bus::Apb => {
            let mut uut = DrccPelicanApb::<M>::with_config(cfg, keys);
            uut.connect_all();
            generate_verilog(&uut)
        }
        Bus::AxiLite => {
            let mut uut = DrccPelicanAxi::<M>::with_config(cfg, keys);
            uut.connect_all();
            generate_verilog(&uut)
        }
    }
}

/// The finished Verilog of the SJA1000 (PeliCAN) view generated with `keys` over
/// a core with `cfg` (`drcc generate --config` with `host = "pelican"`) on `bus`,
/// as module `name`: the `drcc_pelican`, `drcc_pelican_apb` or `drcc_pelican_axi`
/// top's header, ports and notes with these parameters. APB and AXI4-Lite take
/// stride 4 only (their reads carry no byte lanes).
pub fn pelican_with_config(
    name: &str,
    cfg: &DrccConfig,
    keys: &PelicanKeys,
    bus: Bus,
) -> Result<String, String> {
    cfg.check()?;
    keys.check(cfg)?;
    keys.check_bus(bus)?;
    let raw = match cfg.mailboxes {
        0 => raw_verilog_pelican::<0>(cfg, keys, bus),
        _ => raw_verilog_pelican::<16>(cfg, keys, bus),
    };
    let base = match bus {
        Bus::Wishbone => "drcc_pelican",
        Bus::Apb => "drcc_pelican_apb",
        Bus::AxiLite => "drcc_pelican_axi",
    };
    let mut params = cfg.params();
    params.extend(keys.params());
    if bus != Bus::Wishbone {
        params.push(("BUS", bus.name().to_string()));
    }
    let t = configured(
        top(base).expect("the drcc_pelican tops"),
        name,
        "the DRCC behind the SJA1000 (PeliCAN) view, generated with a configuration of its own (drcc generate --config)",
        params,
    );
    Ok(verilog::finish(&t, &raw, &t.ports()))
}
