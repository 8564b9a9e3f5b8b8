//! Tests of `drcc_hdl::pins::sync_cell`.

use drcc_hdl::pins::sync_cell::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn edge(uut: &mut SyncCell) {
        uut.clock.next = Clock { clk: true };
        assert!(simulate(uut, 100));
        uut.clock.next = Clock { clk: false };
        assert!(simulate(uut, 100));
    }

    /// Two edges of latency; reset makes both stages recessive at once.
    #[test]
    fn two_edges_of_latency_and_reset_to_recessive() {
        let mut uut = SyncCell::default();
        uut.connect_all();
        uut.rst.next = true;
        edge(&mut uut);
        edge(&mut uut);
        assert!(uut.q.val());
        uut.rst.next = false;
        uut.d.next = false;
        edge(&mut uut);
        assert!(uut.q.val(), "one edge: not yet through");
        edge(&mut uut);
        assert!(!uut.q.val(), "two edges: through");
        uut.rst.next = true;
        edge(&mut uut);
        assert!(uut.q.val(), "reset: recessive at the next edge");
    }

    #[test]
    fn sync_cell_synthesizes() {
        let mut uut = SyncCell::default();
        uut.connect_all();
        crate::synth_check::yosys_check("sync_cell", &generate_verilog(&uut));
    }
}
