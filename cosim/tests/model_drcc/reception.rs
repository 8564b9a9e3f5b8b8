//! Reception: the RX FIFO (channel tag, order, overrun at 33 frames), duplicate
//! removal with `dual_tx` and its window, `rx_ready` never paired with a stale
//! head.

use super::*;

#[test]
fn rx_fifo_tags_channels_and_counts_overrun() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    let frames: Vec<Frame> = (0..33u32)
        .map(|i| {
            let n = (i % 9) as usize;
            let data: Vec<u8> = (0..n as u8).map(|b| b ^ i as u8).collect();
            match i % 4 {
                0 => frame(0x100 + i, false, false, n as u8, &data),
                1 => frame(0x1000_0000 | i, true, false, n as u8, &data),
                2 => frame(0x300 + i, false, true, (i % 16) as u8, &[]),
                _ => frame(0x400 + i, false, false, 12, &[1, 2, 3, 4, 5, 6, 7, 8]),
            }
        })
        .collect();
    for (i, f) in frames.iter().enumerate() {
        let p = if i % 2 == 0 { pa } else { pb };
        let done = sys.plain[p].done;
        sys.plain[p].req = Some(*f);
        while sys.plain[p].done == done {
            sys.step();
        }
        sys.run(20 * CPB);
    }
    let s = sys.read(0, STATUS);
    assert_eq!(status_rx_count(s), 32);
    assert_eq!(sys.read(0, STATS0), 1 << 16, "one overrun, no duplicates");
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN),
        I_RX | I_OVERRUN
    );
    for (i, f) in frames.iter().take(32).enumerate() {
        let (g, ch) = sys.pop(0).expect("frame in the FIFO");
        assert_eq!(g, *f, "frame {i}");
        assert_eq!(ch, (i % 2) as u32, "channel of frame {i}");
        assert_eq!(status_rx_count(sys.read(0, STATUS)), 31 - i as u32);
    }
    assert!(sys.pop(0).is_none(), "the 33rd frame was dropped");
    sys.write(0, INT_STATUS, 0xFF);
    sys.write(0, RX_CMD, 1);
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
    // Normal mode never drops duplicates: the same frame on both channels is
    // delivered twice.
    let f = frame(0x77, false, false, 1, &[7]);
    sys.plain[pa].req = Some(f);
    sys.plain[pb].req = Some(f);
    sys.run(200 * CPB);
    assert_eq!(
        sys.pop(0),
        Some((f, 0)),
        "A first when both arrive together"
    );
    assert_eq!(sys.pop(0), Some((f, 1)));
    assert_eq!(sys.read(0, STATS0) & 0xFFFF, 0);
}

// ---------------------------------------------------------------------------
// (h) duplicate removal with dual_tx
// ---------------------------------------------------------------------------

#[test]
fn dual_tx_receiver_gets_each_message_once() {
    // Node 0 sends every message on A then its copy on B; node 1 receives.
    let mut sys = Sys::new(2);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX);
    sys.start(1, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let msgs = [
        frame(0x301, false, false, 2, &[1, 2]),
        frame(0x00AB_CDEF, true, false, 0, &[]),
        frame(0x301, false, false, 2, &[1, 2]), // the same frame again
    ];
    for m in &msgs {
        sys.push(0, m, 0);
    }
    sys.run(1200 * CPB);
    // Each message: transmission_ack after A (no tx_success for the first copy),
    // then after B with tx_success.
    assert_eq!(sys.trace.ack.len(), 6, "{:?}", sys.trace.ack);
    assert_eq!(
        sys.trace.success,
        vec![
            sys.trace.ack[1] + 1,
            sys.trace.ack[3] + 1,
            sys.trace.ack[5] + 1
        ]
    );
    assert_eq!(sys.nodes[0].out.probes.tx_ok_channel, 0b11, "both channels");
    // Every round trip passes idle2 and back through wait4, never a switch.
    assert_eq!(sys.read(0, STATS1) & 0xFFFF, 0);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0);
    // Receiver: each message once, from channel A; the copies on B were dropped.
    let mut got = Vec::new();
    while let Some(x) = sys.pop(1) {
        got.push(x);
    }
    assert_eq!(got, msgs.iter().map(|m| (*m, 0)).collect::<Vec<_>>());
    assert_eq!(
        sys.read(1, STATS0),
        3,
        "three duplicates dropped, no overrun"
    );
    assert_eq!(sys.read(1, INT_STATUS) & I_RX, I_RX);

    // window = 0 turns dedup off: both copies are delivered.
    let mut sys = Sys::new(2);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX);
    sys.write(1, DEDUP_CFG, 0);
    sys.start(1, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &msgs[0], 0);
    sys.run(400 * CPB);
    assert_eq!(sys.pop(1), Some((msgs[0], 0)));
    assert_eq!(sys.pop(1), Some((msgs[0], 1)));
    assert_eq!(sys.pop(1), None);
    assert_eq!(sys.read(1, STATS0), 0);
}

/// Copies older than `window` bit times are not duplicates: with a window of 10 bits
/// the copy on B (more than a frame later) is delivered.
#[test]
fn dedup_window_expires_entries() {
    let mut sys = Sys::new(2);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX);
    sys.write(1, DEDUP_CFG, 10);
    sys.start(1, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let m = frame(0x42, false, false, 1, &[0x42]);
    sys.push(0, &m, 0);
    sys.run(400 * CPB);
    assert_eq!(sys.pop(1), Some((m, 0)));
    assert_eq!(sys.pop(1), Some((m, 1)));
    assert_eq!(sys.read(1, STATS0), 0);
}

/// `RX_ID[31]` (`rx_ready`, §7) is 1 only when the read data holds the new head:
/// polling RX_ID back to back (every 2 clocks, at both clock phases) while a frame
/// arrives in an empty FIFO whose RAM head still holds an older frame never shows
/// the valid flag with the old frame.
#[test]
fn rx_ready_never_pairs_the_flag_with_a_stale_head() {
    for phase in 0..2 {
        let mut sys = Sys::new(1);
        let pa = sys.add_plain(0, true);
        sys.start(0, policy(1) | k(1));
        sys.run(20 * CPB);
        let old = frame(0x111, false, false, 1, &[1]);
        let new = frame(0x222, false, false, 1, &[2]);
        // Fill all 32 RAM entries with `old` (so the next head holds it), pop them.
        for _ in 0..32 {
            let d = sys.plain[pa].done;
            sys.plain[pa].req = Some(old);
            while sys.plain[pa].done == d {
                sys.step();
            }
        }
        sys.run(20 * CPB);
        for _ in 0..32 {
            assert_eq!(sys.pop(0), Some((old, 0)));
        }
        sys.run(phase);
        sys.plain[pa].req = Some(new);
        let mut seen = false;
        for _ in 0..(120 * CPB / 2) {
            let id = sys.read(0, RX_ID);
            if id >> 31 == 1 {
                assert_eq!(
                    id & 0x7FF,
                    0x222,
                    "phase {phase}: valid flag with a stale head"
                );
                seen = true;
            }
        }
        assert!(seen, "phase {phase}: the new frame arrived");
    }
}
