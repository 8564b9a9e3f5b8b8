//! Tests of `drcc_hdl::tops::shim_table`.

use drcc_hdl::tops::shim_table::*;

mod tests {
    use super::*;

    #[test]
    fn names_and_types() {
        assert_eq!(camel("can_channel"), "CanChannel");
        assert_eq!(camel("hub"), "Hub");
        assert_eq!(c_type(1), "uint8_t");
        assert_eq!(c_type(8), "uint8_t");
        assert_eq!(c_type(9), "uint16_t");
        assert_eq!(c_type(29), "uint32_t");
        assert_eq!(c_type(64), "uint64_t");
    }
}
