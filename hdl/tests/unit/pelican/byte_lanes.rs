//! Tests of `drcc_hdl::pelican::byte_lanes` against pelican_contract.md
//! P-BUS-1..3: the addressing of Linux's `reg-io-width` 4 (register `r` at
//! byte `4r`, lane 0) and 1 (register `r` at byte `r`, its own lane), and the
//! accesses an 8-bit bus could not make, which are refused.

use drcc_hdl::pelican::byte_lanes::ByteLanes;
use rust_hdl::prelude::*;

struct Out {
    reg: u64,
    wbyte: u64,
    refused: bool,
    rdat: u64,
}

fn access(stride: usize, byte_addr: u64, sel: u64, we: bool, wdat: u64, rbyte: u64) -> Out {
    let mut uut = ByteLanes::new(stride);
    uut.connect_all();
    uut.adr.next = ((byte_addr >> 2) & 0x7F).into();
    uut.sel.next = sel.into();
    uut.we.next = we;
    uut.wdat.next = wdat.into();
    uut.rbyte.next = rbyte.into();
    assert!(simulate(&mut uut, 100));
    Out {
        reg: uut.reg_num.val().to_u64(),
        wbyte: uut.wbyte.val().to_u64(),
        refused: uut.refused.val(),
        rdat: uut.rdat.val().to_u64(),
    }
}

/// P-BUS-1: stride 4; Linux's width-4 accessor is a byte access at `4r`
/// (lane 0), and a 32-bit access works the same.
#[test]
fn stride_4_register_r_is_lane_0_of_word_r() {
    for r in [0u64, 1, 16, 31, 96, 127] {
        for sel in [0b0001, 0b1111] {
            let w = access(4, 4 * r, sel, true, 0xDDCC_BBAA, 0);
            assert_eq!(
                (w.reg, w.wbyte, w.refused),
                (r, 0xAA, false),
                "r {r} sel {sel:04b}"
            );
        }
        // a read ignores sel and returns the byte in [7:0]
        for sel in [0b0000, 0b0001, 0b1000, 0b1111] {
            let rd = access(4, 4 * r, sel, false, 0, 0x5C);
            assert_eq!((rd.reg, rd.rdat, rd.refused), (r, 0x5C, false));
        }
    }
    // a write without lane 0 is refused
    for sel in [0b0000, 0b0010, 0b1100, 0b1110] {
        assert!(access(4, 8, sel, true, 0, 0).refused, "sel {sel:04b}");
    }
}

/// P-BUS-2: stride 1; a byte store or load of address `r` addresses register
/// `r` in its own lane, the read byte is on every lane, and anything wider
/// than a byte is refused (read or write).
#[test]
fn stride_1_register_r_is_byte_r() {
    for r in [0u64, 1, 2, 3, 17, 30, 115, 127] {
        let lane = r & 3;
        let sel = 1 << lane;
        let w = access(1, r, sel, true, 0x44332211, 0);
        assert_eq!(
            (w.reg, w.wbyte, w.refused),
            (r, 0x11 * (lane + 1), false),
            "r {r}"
        );
        let rd = access(1, r, sel, false, 0, 0xA7);
        assert_eq!((rd.reg, rd.rdat, rd.refused), (r, 0xA7A7_A7A7, false));
    }
    for sel in [0b0000, 0b0011, 0b1100, 0b1111, 0b0101] {
        assert!(access(1, 4, sel, true, 0, 0).refused, "write sel {sel:04b}");
        assert!(access(1, 4, sel, false, 0, 0).refused, "read sel {sel:04b}");
    }
}

#[test]
fn byte_lanes_synthesize() {
    for stride in [1, 4] {
        let mut uut = ByteLanes::new(stride);
        uut.connect_all();
        crate::synth_check::yosys_check("byte_lanes", &generate_verilog(&uut));
    }
}
