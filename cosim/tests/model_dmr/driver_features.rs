//! DRCC contract §11 in DMR mode: the acceptance filters act at the RX FIFO's
//! write port, which in DMR mode includes the release of waiting PCL frames
//! (§8 `RELEASE`); `STATS_CLR` clears `DMR_RX_STATS` and keeps `DMR_CS_COUNT`
//! (§11.4). The scenario is that of `reception.rs` (three PCL frames released at
//! the ACL switch), with a filter that rejects the second.

use super::*;

// DRCC contract §11 word indices and FILT_MASK fields.
const FILT_ID0: u8 = 42;
const FILT_MASK0: u8 = 43;
const STATS_CLR: u8 = 47;
const F_IDE: u32 = 1 << 29;
const F_EN: u32 = 1 << 31;

/// Filter 0: id 0x101, mask id[10:0] but bit 1, and ide. 0x101 and 0x103 match
/// (xor 0x000, 0x002; & 0x7FD = 0), 0x102 does not (xor 0x003 & 0x7FD = 0x001).
/// The ACL switch releases F1, F2, F3 oldest first (DMR §8); F2 is dropped at the
/// write: the host gets F1 and F3, `released` counts all three (the DMR rule saw
/// them). STATS_CLR then clears DMR_RX_STATS and keeps DMR_CS_COUNT.
#[test]
fn filters_act_at_the_release_and_stats_clr_clears_dmr_rx_stats() {
    let mut sys = Sys::new(1);
    let _pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.dmr_times(0, 200, 10, 1000);
    sys.write(0, DEDUP_CFG, 5000);
    sys.mailbox(0, 0, 0, 0, 10);
    sys.write(0, FILT_ID0, 0x101);
    sys.write(0, FILT_MASK0, 0x7FD | F_IDE | F_EN);
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    sys.start(0);
    sys.run(300 * CPB);
    let f: Vec<Frame> = (1..=3)
        .map(|i| frame(0x100 + i, false, 2, &[i as u8, 0x5A]))
        .collect();
    for x in &f {
        sys.send(pb, *x);
    }
    sys.run(100);
    assert_eq!(rx_count(&mut sys, 0), 0, "PCL frames wait");
    assert_eq!(sys.read(0, DMR_RX_STATS), 3, "pcl_frames 3");
    sys.run_until(15 * 200 * CPB, "the ACL switch", |s| s.probes(0).acl);
    sys.run(200);
    assert_eq!(sys.drain(0), vec![(f[0], 1), (f[2], 1)], "F2 rejected");
    assert_eq!(sys.read(0, DMR_RX_STATS), 3 | 3 << 16, "released 3");
    assert_eq!(sys.read(0, STATS0), 0, "no overrun, no duplicate");

    let cs_count = sys.read(0, DMR_CS_COUNT);
    sys.write(0, STATS_CLR, 1);
    assert_eq!(sys.read(0, DMR_RX_STATS), 0, "DMR_RX_STATS cleared");
    assert_eq!(sys.read(0, DMR_CS_COUNT), cs_count, "DMR_CS_COUNT kept");
    assert_eq!(status(&mut sys, 0).acl(), RCL, "the state is kept");
}
