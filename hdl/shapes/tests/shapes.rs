//! The hub in a shape of its own: the emitted shapes give the emitted tops'
//! Verilog, another shape has its own port widths on every bus, and a shape
//! outside the offered ranges is refused with them named.

use drcc_hdl::bus::Bus;
use drcc_hdl::tops::top;
use drcc_hdl_shapes::{hub_with_shape, hub_with_shape_on};

/// `hub_with_shape` of the emitted shapes is the `hub` / `hub_b` Verilog
/// body; another shape has its own port widths; shapes outside 2..8 x 2..4
/// are refused.
#[test]
fn hub_shapes_are_generated_with_their_widths() {
    for (name, id) in [("hub", 0), ("hub_b", 1)] {
        let emitted = top(name).unwrap().verilog();
        let shaped = hub_with_shape(name, 4, 2, id).unwrap();
        let body = |t: &str| t[t.find(&format!("module {name}(")).unwrap()..].to_string();
        assert_eq!(body(&emitted), body(&shaped), "{name}");
    }
    let v = hub_with_shape("hub_6x3", 6, 3, 0).unwrap();
    assert!(
        v.contains("Parameters: HUB_ID = 0, N = 6, M = 3"),
        "{}",
        &v[..600]
    );
    assert!(v.contains("output reg  [5:0] downlink;"), "6 downlinks");
    assert!(v.contains("input wire  [2:0] sublink_in;"), "3 interlinks");
    assert!(hub_with_shape("x", 9, 2, 0)
        .unwrap_err()
        .contains("nodes 2..8"));
    assert!(hub_with_shape("x", 4, 1, 0)
        .unwrap_err()
        .contains("interlinks 2..4"));
    assert!(hub_with_shape("x", 4, 2, 2).is_err());
}

/// Every offered shape is generated on every bus, as its module, with the
/// widths of its shape, and hub B's identification (`HUB_ID = 1`) where asked.
#[test]
fn every_offered_shape_is_generated_on_every_bus() {
    for n in 2..=8usize {
        for m in 2..=4usize {
            for (bus, port) in [
                (Bus::Wishbone, "input wire  wb_cyc_i;"),
                (Bus::Apb, "input wire  s_apb_psel;"),
                (Bus::AxiLite, "input wire  s_axi_awvalid;"),
            ] {
                let id = (n + m) % 2;
                let name = format!("hub_{n}x{m}");
                let v = hub_with_shape_on(&name, n, m, id, bus)
                    .unwrap_or_else(|e| panic!("{name} on {bus:?}: {e}"));
                assert!(v.contains(&format!("module {name}(")), "{name} on {bus:?}");
                assert!(
                    v.contains(&format!("HUB_ID = {id}, N = {n}, M = {m}")),
                    "{name} on {bus:?}"
                );
                assert!(
                    v.contains(&format!("[{}:0] downlink;", n - 1)),
                    "{name} on {bus:?}: {n} downlinks"
                );
                assert!(
                    v.contains(&format!("[{}:0] sublink_in;", m - 1)),
                    "{name} on {bus:?}: {m} interlinks"
                );
                assert!(v.contains(port), "{name} on {bus:?}: its bus port {port}");
            }
        }
    }
}
