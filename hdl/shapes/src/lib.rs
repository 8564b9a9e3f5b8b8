//! The ReCANcentrate hub in every shape `drcc generate --config` offers: N node
//! ports 2..8, M interlinks 2..4 and identification frame `hub_id` 0 (hub A) or
//! 1 (hub B), on Wishbone, APB or AXI4-Lite.
//!
//! rust-hdl sizes a block's ports by const generics, so each shape is a type of
//! its own, `Hub<N, M, N + M, H>`, and each is compiled: 21 shapes, two hubs,
//! three buses. This crate holds that table apart from `drcc-hdl`, and the
//! workspace compiles it without optimization (`opt-level = 0` in the root
//! `Cargo.toml`): its code only writes a Verilog text once per command, while
//! the same blocks at full optimization were most of `drcc-hdl`'s compile time
//! (docs/design.md, § CI). `drcc-hdl` finishes the text
//! ([`drcc_hdl::tops::finish_shaped_hub`]) like any emitted top.

use drcc_hdl::bus::hub_tops::{HubApb, HubAxi};
use drcc_hdl::bus::Bus;
use drcc_hdl::hub::hub::Hub;
use drcc_hdl::tops::{finish_shaped_hub, ports_of, raw_verilog_of, Port};
use rust_hdl::prelude::*;

/// The finished Verilog of a hub with `n` node ports, `m` interlinks and
/// identification frame `hub_id` (0 = hub A, 1 = hub B), as module `name`
/// (`drcc generate --config`): the `hub` top's header, port docs and notes with
/// these parameters. Refuses a shape the hub does not offer, naming the ranges.
pub fn hub_with_shape(name: &str, n: usize, m: usize, hub_id: usize) -> Result<String, String> {
    hub_with_shape_on(name, n, m, hub_id, Bus::Wishbone)
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
    let (raw, ports) = hub_of_shape(n, m, hub_id, bus).ok_or_else(|| {
        format!(
            "hub shape nodes = {n}, interlinks = {m}, hub_id = {hub_id} is not offered: \
             nodes 2..8, interlinks 2..4, hub_id 0 (hub A) or 1 (hub B)"
        )
    })?;
    Ok(finish_shaped_hub(name, (n, m, hub_id), bus, &raw, ports))
}

/// The raw Verilog and the ports of the hub with `n` node ports, `m`
/// interlinks and identification frame `hub_id` (hub contract §9.1) on `bus`,
/// for every shape offered (N 2..8, M 2..4, P = N + M); `None` for another.
/// M = 1 simulates (rust-hdl, the model) but is not offered: rust-hdl writes a
/// one-bit vector as a scalar and still indexes it (`sub_q[0]`), which Verilog
/// refuses.
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
        (2, 2, 4),
        (2, 3, 5),
        (2, 4, 6),
        (3, 2, 5),
        (3, 3, 6),
        (3, 4, 7),
        (4, 2, 6),
        (4, 3, 7),
        (4, 4, 8),
        (5, 2, 7),
        (5, 3, 8),
        (5, 4, 9),
        (6, 2, 8),
        (6, 3, 9),
        (6, 4, 10),
        (7, 2, 9),
        (7, 3, 10),
        (7, 4, 11),
        (8, 2, 10),
        (8, 3, 11),
        (8, 4, 12),
    )
}
