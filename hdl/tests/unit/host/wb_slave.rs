//! Tests of `drcc_hdl::host::wb_slave`.

use drcc_hdl::host::wb_slave::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// One clock of the slave: inputs applied, then the rising edge.
    fn step(uut: &mut WbSlave<4>) {
        uut.clk.next = Clock::from(false);
        assert!(simulate(uut, 50));
        uut.clk.next = Clock::from(true);
        assert!(simulate(uut, 50));
    }

    fn bits4(v: u64) -> Bits<4> {
        v.into()
    }

    #[test]
    fn wb_slave_synthesizes() {
        let mut uut = WbSlave::<8>::default();
        uut.connect_all();
        crate::synth_check::yosys_check("wb_slave", &generate_verilog(&uut));
    }

    #[test]
    fn handshake_and_interrupts_follow_the_contract() {
        let mut uut = WbSlave::<4>::default();
        uut.connect_all();
        uut.rst.next = true;
        step(&mut uut);
        uut.rst.next = false;
        // a held request is acked at every other edge (classic cycle, §2)
        uut.wb_cyc_i.next = true;
        uut.wb_stb_i.next = true;
        uut.rdata.next = 0xABCD.into();
        let mut acks = vec![];
        for _ in 0..4 {
            step(&mut uut);
            acks.push(uut.wb_ack_o.val());
            if uut.wb_ack_o.val() {
                assert_eq!(
                    uut.wb_dat_o.val().to_u64(),
                    0xABCD,
                    "read data with the ack"
                );
            } else {
                assert_eq!(uut.wb_dat_o.val().to_u64(), 0, "0 without the ack");
            }
        }
        assert_eq!(acks, [true, false, true, false]);
        // a write acks with data 0
        uut.wb_we_i.next = true;
        step(&mut uut);
        assert!(uut.wb_ack_o.val());
        assert_eq!(uut.wb_dat_o.val().to_u64(), 0);
        uut.wb_cyc_i.next = false;
        uut.wb_stb_i.next = false;
        uut.wb_we_i.next = false;
        step(&mut uut);
        assert!(!uut.wb_ack_o.val());
        // event 0b0101 with INT_ENABLE 0b0100: irq one clock after INT_STATUS
        uut.int_enable_we.next = true;
        uut.int_enable_d.next = bits4(0b0100);
        uut.events.next = bits4(0b0101);
        step(&mut uut);
        uut.int_enable_we.next = false;
        uut.events.next = bits4(0);
        assert_eq!(uut.int_status.val().to_u64(), 0b0101);
        assert!(!uut.irq.val(), "irq is registered");
        step(&mut uut);
        assert!(uut.irq.val());
        // clearing bit 2 while it is raised again: the event wins (§8)
        uut.w1c.next = bits4(0b0100);
        uut.events.next = bits4(0b0100);
        step(&mut uut);
        assert_eq!(uut.int_status.val().to_u64(), 0b0101);
        uut.events.next = bits4(0);
        step(&mut uut);
        assert_eq!(uut.int_status.val().to_u64(), 0b0001);
        uut.w1c.next = bits4(0);
        step(&mut uut);
        assert!(!uut.irq.val());
    }
}
