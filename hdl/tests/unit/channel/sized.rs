//! Tests of `drcc_hdl::channel::sized`.

use drcc_hdl::channel::sized::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// A block whose only non-signal fields are `Const`s derives `Default`, and
    /// the constant is emitted as a sized localparam.
    #[derive(LogicBlock, Default)]
    struct AddFive {
        a: Signal<In, Bits<7>>,
        y: Signal<Out, Bits<7>>,
        five: Const<7, 5>,
    }

    impl Logic for AddFive {
        #[hdl_gen]
        fn update(&mut self) {
            self.y.next = self.a.val() + self.five.val();
        }
    }

    #[test]
    fn const_is_a_sized_localparam() {
        let mut uut = AddFive::default();
        uut.connect_all();
        let v = generate_verilog(&uut);
        assert!(v.contains("localparam  five = 7'b101;"), "{v}");
        uut.a.next = 3.into();
        simulate(&mut uut, 10);
        assert_eq!(uut.y.val(), Bits::<7>::from(8));
        crate::synth_check::yosys_check("sized_const", &v);
    }
}
