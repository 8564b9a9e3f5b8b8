//! Tests of `drcc_hdl::channel::bsp::fault_confinement_rules`.

use drcc_hdl::channel::bsp::fault_confinement_rules::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn uut() -> FaultConfinementRules {
        let mut uut = FaultConfinementRules::default();
        uut.connect_all();
        uut.sample.next = true;
        uut.sampled.next = true;
        simulate(&mut uut, 100);
        uut
    }

    /// 12.1.4.2 rules a and c: an error costs a receiver REC + 1 and a
    /// transmitter TEC + 8; in listen-only mode nothing is counted.
    #[test]
    fn rules_a_and_c() {
        let mut uut = uut();
        uut.error.next = true;
        simulate(&mut uut, 100);
        assert!(uut.rec_add1.val() && !uut.tec_add8.val());
        uut.as_tx.next = true;
        simulate(&mut uut, 100);
        assert!(uut.tec_add8.val() && !uut.rec_add1.val());
        // Rule c exception 2: the recessive stuff bit in arbitration.
        uut.tec_exempt.next = true;
        simulate(&mut uut, 100);
        assert!(!uut.tec_add8.val());
        uut.tec_exempt.next = false;
        uut.listen_only.next = true;
        simulate(&mut uut, 100);
        assert!(!uut.tec_add8.val());
    }

    /// Rules d/e: a bit error in its own flag costs 8, on the node's role.
    #[test]
    fn rules_d_and_e() {
        let mut uut = uut();
        uut.flag_error.next = true;
        simulate(&mut uut, 100);
        assert!(uut.rec_add8.val() && !uut.tec_add8.val());
        uut.is_tx.next = true;
        simulate(&mut uut, 100);
        assert!(uut.tec_add8.val() && !uut.rec_add8.val());
    }

    /// Rule i (12.1.4.2 / 12.1.4.3): TEC 120 + 8 = 128 makes the flag passive;
    /// 12.1.4.4: TEC 248 + 8 > 255 is bus-off.
    #[test]
    fn error_state_after_the_events() {
        let mut uut = uut();
        uut.tec_ge120.next = true;
        uut.error.next = true;
        uut.as_tx.next = true;
        simulate(&mut uut, 100);
        assert!(uut.passive_after.val() && !uut.bus_off_after.val());
        uut.tec_ge248.next = true;
        simulate(&mut uut, 100);
        assert!(uut.bus_off_after.val());
    }

    #[test]
    fn fault_confinement_rules_synthesize() {
        let mut uut = FaultConfinementRules::default();
        uut.connect_all();
        crate::synth_check::yosys_check("fault_confinement_rules", &generate_verilog(&uut));
    }
}
