//! Tests of `drcc_hdl::host::map`.

use drcc_hdl::host::map::*;
use drcc_hdl::register_enum;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    register_enum! {
        /// A test enum.
        pub enum Colour {
            /// the first
            Red = 0 => "RED",
            Blue = 2 => "BLUE",
        }
    }

    #[test]
    fn enum_codes_come_from_the_declaration() {
        assert_eq!(Colour::Blue.code(), 2);
        assert_eq!(Colour::from_code(0), Some(Colour::Red));
        assert_eq!(Colour::from_code(1), None);
        assert_eq!(Colour::ENCODING[0].desc.trim(), "the first");
        assert_eq!(Colour::ENCODING[1].name, "BLUE");
    }

    #[test]
    fn field_put_and_get_are_inverse() {
        let fl = f("x", 12, 2, 0, "");
        assert_eq!(fl.mask(), 0x3000);
        assert_eq!(fl.put(3), 0x3000);
        assert_eq!(fl.put(5), 0x1000, "excess bits dropped");
        assert_eq!(fl.get(0xFFFF), 3);
    }

    #[test]
    #[should_panic(expected = "X.b is 3 bits wide in the table, 2 in the RTL")]
    fn lsb_names_a_field_whose_width_disagrees() {
        static MAP: RegisterMap = RegisterMap {
            title: "t",
            prefix: "T",
            header: "t.h",
            source: "s",
            intro: "",
            registers: &[Register {
                name: "X",
                index: 0,
                access: Access::Rw,
                desc: "",
                fields: &[f("a", 0, 1, 0, ""), f("b", 1, 3, 0, "")],
            }],
            lists: &[],
            defines: &[],
            sizes: &[],
        };
        let _: Constant<Bits<5>> = lsb(&MAP, "X", "b", 2);
    }
}
