//! Tests of `drcc_hdl::bus`.

use drcc_hdl::bus::*;

mod tests {
    use super::Bus;

    #[test]
    fn buses_and_widths_outside_the_offer_are_refused_naming_the_choices() {
        assert_eq!(Bus::parse("apb", 32), Ok(Bus::Apb));
        assert_eq!(Bus::parse("axi4-lite", 32), Ok(Bus::AxiLite));
        let e = Bus::parse("avalon", 32).unwrap_err();
        assert!(e.contains("wishbone, apb, axi4-lite"), "{e}");
        let e = Bus::parse("apb", 64).unwrap_err();
        assert!(e.contains("data_width 64") && e.contains("32"), "{e}");
    }
}

mod apb;
mod axi_lite;
mod hub_tops;
