//! The host-bus front ends (`cosim/src/model/bus_contract.md`): every register
//! map is served on its Wishbone register port (the tops' `wb_*` ports, with
//! `SEL` and `ERR`); [`apb`] and [`axi_lite`] bridge APB4 and AXI4-Lite to that
//! port, and [`drcc_tops`] and [`hub_tops`] put them in front of the DRCC and
//! the hub.
pub mod apb;
pub mod axi_lite;
pub mod drcc_tops;
pub mod hub_tops;

/// The host bus a top is generated with (`drcc generate --config`, key `bus`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Bus {
    /// Wishbone B4 classic with `SEL` and `ERR` (the register port itself).
    #[default]
    Wishbone,
    /// AMBA APB4 ([`apb`]).
    Apb,
    /// AMBA AXI4-Lite ([`axi_lite`]).
    AxiLite,
}

impl Bus {
    /// The names `bus = "..."` takes, in the order of the error messages.
    pub const NAMES: [&'static str; 3] = ["wishbone", "apb", "axi4-lite"];
    /// The data widths every bus is offered with.
    pub const DATA_WIDTHS: [usize; 1] = [32];

    /// The bus named `name` with `data_width` bits of data, or why not.
    pub fn parse(name: &str, data_width: usize) -> Result<Bus, String> {
        let bus = match name {
            "wishbone" => Bus::Wishbone,
            "apb" => Bus::Apb,
            "axi4-lite" => Bus::AxiLite,
            _ => {
                return Err(format!(
                    "bus {name:?} is not offered: choose one of {}",
                    Bus::NAMES.join(", ")
                ))
            }
        };
        if !Bus::DATA_WIDTHS.contains(&data_width) {
            return Err(format!(
                "data_width {data_width} is not offered for bus {name:?}: the register map \
                 is served on 32-bit data only (data_width = 32)"
            ));
        }
        Ok(bus)
    }

    /// Its name in a configuration file.
    pub fn name(self) -> &'static str {
        match self {
            Bus::Wishbone => "wishbone",
            Bus::Apb => "apb",
            Bus::AxiLite => "axi4-lite",
        }
    }
}
