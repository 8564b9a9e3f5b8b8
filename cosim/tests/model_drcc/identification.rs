//! Driver features, identification (contract §10.1): `VERSION` and `SIZES` in
//! each configuration, and their refusal of writes. Expected values come from
//! the contract's tables (§1.1, §3).

use super::*;

// CTRL bits besides those of main.rs.
const STAR: u32 = 1 << 5;
const DMR: u32 = 1 << 17;
const FIRST_COPY: u32 = 1 << 19;

/// VERSION is 0x105 (§10.1, §12.1: major 1, minor 5 since §12 added the ECSS
/// registers; minor 4 was DMR §8.1's `CTRL.first_copy`, minor 3 §11.6, minor 2
/// §11.1-§11.5) and
/// SIZES the configuration's sizes, in every configuration
/// of §1.1; `dmr` and `star` say whether CTRL takes those bits; all four new
/// registers are read-only.
#[test]
fn version_and_sizes_identify_the_instance() {
    // drcc_small per §1.1: M 0, F 8, Q 4, H 16, without DMR and the star node
    // (`drcc_m0` with DMR = 0, STAR = 0). The model's configuration must be it.
    let small = DrccParams {
        mailboxes: 0,
        rx_fifo_depth: 8,
        tx_queue_depth: 4,
        history: 16,
        dmr: false,
        star: false,
    };
    assert_eq!(small, DrccParams::SMALL);
    let cases = [
        // drcc: F 32 -> [5:0] 0x20, Q 8 -> [11:8] 0x800, H 32 -> [21:16] 0x20_0000,
        // M 16 -> [28:24] 0x1000_0000, dmr [29] 0x2000_0000, star [30] 0x4000_0000.
        ("drcc", DrccParams::DEFAULT, 0x7020_0820u32),
        // drcc_m0: the default sizes without mailboxes; its DMR and STAR parameters
        // are 1 (§1.1: setting both to 0 with the small sizes gives drcc_small), so
        // CTRL.dmr can still be set (§10.1: "a top without mailboxes whose DMR is 1").
        ("drcc_m0", DrccParams::with_mailboxes(0), 0x6020_0820),
        // drcc_small: 8 | 4 << 8 | 16 << 16 = 0x0010_0408.
        ("drcc_small", small, 0x0010_0408),
    ];
    for (name, p, sizes) in cases {
        let mut sys = Sys::with_params(1, &p);
        assert_eq!(sys.read(0, VERSION), 0x105, "{name}: major 1, minor 5");
        assert_eq!(sys.read(0, SIZES), sizes, "{name}: SIZES");
        // CTRL.dmr / CTRL.star are taken (in reset mode) iff SIZES says they can be
        // set. (CTRL.star is written with redundancy, where it means something.)
        // CTRL.first_copy is stored iff the DMR function is there (DMR §2), even
        // written on its own.
        for (bit, extra, has) in [
            (DMR, 0, sizes >> 29 & 1),
            (FIRST_COPY, 0, sizes >> 29 & 1),
            (STAR, REDUNDANCY, sizes >> 30 & 1),
        ] {
            let ctrl = RESET_MODE | extra | policy(1) | k(1);
            sys.write(0, CTRL, ctrl | bit);
            assert_eq!(
                sys.read(0, CTRL) & bit != 0,
                has == 1,
                "{name}: CTRL bit {bit:#x} taken iff SIZES has it"
            );
            sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
            sys.write(0, INT_STATUS, I_ILLEGAL);
        }
        // Read-only (§9, §10.1, §3): a write ends with ERR, sets illegal and changes
        // nothing, in reset mode and out of it.
        for running in [false, true] {
            if running {
                sys.start(0, policy(1) | k(1));
            }
            for (adr, value) in [(VERSION, 0x105), (SIZES, sizes), (CAP_A, 0), (CAP_B, 0)] {
                let (_, err) = sys.access_lanes(0, adr, true, 0xFFFF_FFFF, 0xF);
                assert!(err, "{name}: a write to word {adr} is refused (ERR)");
                assert_eq!(
                    sys.read(0, INT_STATUS) & I_ILLEGAL,
                    I_ILLEGAL,
                    "{name}: illegal after a write to word {adr}"
                );
                sys.write(0, INT_STATUS, I_ILLEGAL);
                assert_eq!(sys.read(0, adr), value, "{name}: word {adr} unchanged");
            }
        }
        // The words after CAP_B (§11: the filters, RX_TIME, STATS_CLR) read 0
        // after rst.
        assert_eq!(sys.read(0, CAP_B + 1), 0);
        // rst leaves the constants as they are.
        sys.nodes[0].wb.rst = true;
        sys.step();
        sys.nodes[0].wb.rst = false;
        assert_eq!(sys.read(0, VERSION), 0x105);
        assert_eq!(sys.read(0, SIZES), sizes, "{name}: SIZES after rst");
    }
}

// ---------------------------------------------------------------------------
// §10.2 arbitration-lost capture
// ---------------------------------------------------------------------------

// The contests' identifiers, MSB first (bit position i = 0 is ID[10]; alc = i for
// a base-ID bit, timing contract §9):
//
//   0x123 = 001 0010 0011      0x120 = 001 0010 0000
//   0x133 = 001 0011 0011      0x122 = 001 0010 0010
//   i     = 012 3456 789A      i     = 012 3456 789A
//
// 0x123/0x133 first differ at i = 6 (ID[4], 0x010): 0x123 sends dominant (0) and
// wins, the sender of 0x133 sent recessive, reads dominant: alc = 6.
// 0x120/0x122 first differ at i = 9 (ID[1], 0x002): the sender of 0x122 loses,
// alc = 9. Node 1 always sends the higher identifier and loses.
