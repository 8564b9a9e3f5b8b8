//! Tests of `drcc_hdl::hub::coupler`.

use drcc_hdl::hub::coupler::*;
use rust_hdl::prelude::*;

#[test]
fn coupler_synthesizes() {
    let mut uut = Coupler::<4, 2>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_coupler", &generate_verilog(&uut));
}

mod tests {
    use super::*;

    type Uut = Coupler<4, 2>;

    /// One clock: inputs applied with `clk` low, then the rising edge.
    fn clock(u: &mut Uut) {
        u.clk.next = Clock::from(false);
        assert!(simulate(u, 100));
        u.clk.next = Clock::from(true);
        assert!(simulate(u, 100));
    }

    fn fresh() -> Box<Uut> {
        let mut u = Box::<Uut>::default();
        u.connect_all();
        u.node_en.next = 0xF.into();
        u.sub_en.next = 0x3.into();
        u.uplink.next = 0xF.into();
        u.sublink_in.next = 0x3.into();
        u.tx_own.next = true;
        u.rst.next = true;
        clock(&mut u);
        u.rst.next = false;
        clock(&mut u);
        u
    }

    #[test]
    fn uplink_reaches_dl_next_two_edges_later_and_isolated_ports_are_ignored() {
        // dl_next is combinational on the synchronizers: the ACK unit registers it
        // (§4.1), so the downlink follows 3 edges after the uplink (§3)
        let mut u = fresh();
        u.uplink.next = 0xB.into(); // node 2 dominant
        for edge in 1..=3 {
            clock(&mut u);
            assert_eq!(u.dl_next.val(), edge < 2);
            assert_eq!(
                u.sublink_out.val().to_u64(),
                if edge == 3 { 0 } else { 0x3 }
            );
            assert_eq!(u.coupled.val(), edge < 3);
        }
        // node 2 isolated: its dominant level no longer reaches anybody
        u.node_en.next = 0xB.into();
        clock(&mut u);
        assert!(u.dl_next.val());
        assert_eq!(u.sublink_out.val().to_u64(), 0x3);
    }

    #[test]
    fn ack_mask_passes_only_the_twin_and_decoupling_drops_it() {
        let mut u = fresh();
        u.uplink.next = 0xE.into(); // own node ACKs
        for _ in 0..2 {
            clock(&mut u);
        }
        u.ack_mask.next = true;
        clock(&mut u);
        assert!(u.dl_next.val(), "own ACK masked");
        assert_eq!(
            u.sublink_out.val().to_u64(),
            0x0,
            "but forwarded to the twin"
        );
        assert!(!u.coupled.val(), "the tracker sees it");
        // §4.1 fault injection: the malicious hub passes its own nodes' ACK
        u.fi_ack_leak.next = true;
        clock(&mut u);
        assert!(!u.dl_next.val(), "fi_ack_leak: own ACK leaks");
        u.fi_ack_leak.next = false;
        u.uplink.next = 0xF.into();
        u.sublink_in.next = 0x1.into(); // the twin's ACK on interlink 1
        for _ in 0..2 {
            clock(&mut u);
        }
        assert!(!u.dl_next.val(), "twin ACK passes");
        u.decoupled.next = true;
        u.ack_mask.next = false;
        clock(&mut u);
        assert!(u.dl_next.val(), "decoupled: own star only");
    }

    #[test]
    fn nrap_transmitter_quiet_twin_and_fi_no_twin() {
        // §9.4: the transmitter joins stage 1 and reaches sublink_out and
        // coupled_q one edge later
        let mut u = fresh();
        u.tx_own.next = false;
        clock(&mut u);
        assert_eq!(u.sublink_out.val().to_u64(), 0x0);
        assert!(!u.coupled.val());
        // §9.4: quiet_twin keeps the sublinks recessive
        u.quiet_twin.next = true;
        clock(&mut u);
        assert_eq!(u.sublink_out.val().to_u64(), 0x3);
        assert!(!u.coupled.val(), "the own bus still sees the transmitter");
        u.quiet_twin.next = false;
        u.tx_own.next = true;
        clock(&mut u);
        // §9.6: fi_no_twin takes the twin's contribution as recessive
        u.sublink_in.next = 0x2.into(); // the twin dominant on interlink 0
        for _ in 0..3 {
            clock(&mut u);
        }
        assert!(!u.coupled.val());
        u.fi_no_twin.next = true;
        clock(&mut u);
        assert!(u.coupled.val() && u.dl_next.val());
    }
}
