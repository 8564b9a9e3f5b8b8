//! Coupling (hub contract §2, §3), the frame tracker (§5) and ACK
//! interdependence (§4).

use super::*;

#[test]
fn reset_mode_is_a_transparent_two_stage_and_star() {
    let mut b = Bench::new(3, 2);
    let nodes = 0b111u16;
    let subs = 0b11u8;
    // Node port 1 dominant at step s: downlink and sublink_out follow 3 edges later
    // (after the edge of step s + 2), all bits alike.
    b.pins = 0x1F & !(1 << 1);
    let s = b.step();
    b.step();
    b.step();
    for k in [s, s + 1] {
        assert_eq!(b.log[k].downlink, nodes, "step {}", k - s);
        assert_eq!(b.log[k].sublink_out, subs);
        assert!(b.log[k].probes.coupled);
    }
    assert_eq!(b.log[s + 2].downlink, 0);
    assert_eq!(b.log[s + 2].sublink_out, 0);
    assert!(!b.log[s + 2].probes.coupled);
    // Released: recessive again 3 edges later.
    b.pins = 0x1F;
    let r = b.step();
    b.step();
    b.step();
    assert_eq!(b.log[r + 1].downlink, 0);
    assert_eq!(b.log[r + 2].downlink, nodes);
    assert_eq!(b.log[r + 2].sublink_out, subs);
    // Twin contribution (sublink 1 = port 4): reaches the downlinks, not the
    // outgoing sublinks.
    b.pins = 0x1F & !(1 << 4);
    let t = b.step();
    b.step();
    b.step();
    assert_eq!(b.log[t + 1].downlink, nodes);
    assert_eq!(b.log[t + 2].downlink, 0);
    assert_eq!(b.log[t + 2].sublink_out, subs);
    // A stuck-dominant node for 300 bit times is never isolated in reset mode.
    b.drive(&[0x1F & !1; 300]);
    assert!(b.log.iter().all(|o| o.probes.port_enabled == 0x1F));
    assert!(b.log.iter().all(|o| !o.probes.sample_point));
    assert_eq!(b.read(STATUS), 1 | 0x1F << 16);
}

#[test]
fn running_hub_couples_own_and_twin_in_two_stages() {
    let mut b = Bench::running(2, 2, &[], true);
    // Twin dominant on sublink 0 (port 2): downlink dominant, sublink_out not.
    b.pins = 0xF & !(1 << 2);
    let s = b.step();
    b.step();
    b.step();
    assert_eq!(b.log[s + 1].downlink, 0b11);
    assert_eq!((b.log[s + 2].downlink, b.log[s + 2].sublink_out), (0, 0b11));
    assert!(!b.log[s + 2].probes.coupled);
    // Plus a node: both.
    b.pins &= !1;
    let s = b.step();
    b.step();
    b.step();
    assert_eq!((b.log[s + 2].downlink, b.log[s + 2].sublink_out), (0, 0));
}

// ---------------------------------------------------------------------------
// Tracker (§5).

#[test]
fn tracker_follows_base_and_extended_frames_to_the_ack_slot() {
    let mut b = Bench::running(3, 1, &[], true);
    let frames = [
        encode(0x123, false, false, 2, &[0xA5, 0x0F]),
        encode(0x7F0, false, false, 8, &[0xFF; 8]), // long runs: many stuff bits
        encode(0x040, false, false, 15, &[0; 8]),   // DLC > 8: 8 bytes
        encode(0x3AA, false, true, 5, &[]),         // remote: no data field
        encode(0x1FFF_FFFF, true, false, 1, &[0x80]),
        encode(0x1555_0F0F, true, true, 3, &[]),
        encode(0x1234_5678, true, false, 8, &[1, 2, 3, 4, 5, 6, 7, 8]),
    ];
    let mut stuffed_any = 0;
    for (i, f) in frames.iter().enumerate() {
        stuffed_any += f.crc_delim - f.raw_at.len();
        // Port 0 sends, every other port acknowledges.
        let t0 = b.send(f, 0, b.port_mask() & !1);
        let trk_at = |j: usize| {
            let o = &b.log[sample_step(t0, j)];
            assert!(o.probes.sample_point, "frame {i}: bit {j} is sampled there");
            o.probes.trk_state
        };
        for j in 0..f.crc_delim {
            assert_eq!(trk_at(j), FRAME, "frame {i}: bit {j}");
        }
        assert_eq!(trk_at(f.crc_delim), ACK_SLOT, "frame {i}: CRC delimiter");
        assert_eq!(trk_at(f.ack), ACK_DELIM, "frame {i}: ACK slot");
        assert_eq!(trk_at(f.ack + 1), IDLE_WAIT, "frame {i}: ACK delimiter");
        assert_eq!(b.read(STATS), i as u32 + 1, "frame {i}: frames tracked");
    }
    assert!(stuffed_any > 10, "the frames exercise destuffing");
    // Every port was active in every frame, nobody blamed.
    for p in 0..4 {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}");
    }
}

#[test]
fn stats_count_frames_and_tracker_errors() {
    let mut b = Bench::running(2, 1, &[], true);
    let f = encode(0x2A5, false, false, 1, &[0x33]);
    b.send(&f, 0, 0b110);
    // A stuff error: six dominant bits after SOF (an error flag at the start).
    let mut flag = vec![0b111 & !1u16; 7];
    flag.extend([0b111; 12]);
    let t0 = b.drive(&flag);
    // SOF + 4 bits make 5, the 6th dominant is the stuff error: IDLE_WAIT again.
    assert_eq!(b.log[sample_step(t0, 4)].probes.trk_state, FRAME);
    assert_eq!(b.log[sample_step(t0, 5)].probes.trk_state, IDLE_WAIT);
    // A form error: dominant CRC delimiter.
    let mut lanes = b.frame_lanes(&f, 0, 0b110);
    lanes[f.crc_delim] &= !1;
    let t1 = b.drive(&lanes);
    assert_eq!(
        b.log[sample_step(t1, f.crc_delim)].probes.trk_state,
        IDLE_WAIT
    );
    b.idle_bits(12);
    b.send(&f, 1, 0b101);
    assert_eq!(b.read(STATS), 2 | 2 << 16);
    // Reset mode clears STATS.
    b.write(CTRL, RESET_MODE | ACK_INTERDEP);
    assert_eq!(b.read(STATS), 0);
}

// ---------------------------------------------------------------------------
// ACK interdependence (§4).

/// One frame from port 0 of a 2x1 hub, ACKed by node port 1 and, if `twin_ack`,
/// by the sublink (port 2). Returns the bench and the step of the ACK slot's
/// first clock.
fn ack_run(interdep: bool, twin_ack: bool, decouple: bool) -> (Bench, usize) {
    let mut b = Bench::running(2, 1, &[], interdep);
    if decouple {
        b.write(
            CTRL,
            FORCE_DECOUPLE | if interdep { ACK_INTERDEP } else { 0 },
        );
        b.idle_bits(2);
    }
    let f = encode(0x155, false, false, 1, &[0xC3]);
    let ackers = if twin_ack { 0b110 } else { 0b010 };
    let t0 = b.send(&f, 0, ackers);
    (b, t0 + CPB * f.ack)
}

#[test]
fn ack_window_masks_downlinks_to_the_twin() {
    let (b, ta) = ack_run(true, false, false);
    // ACK_SLOT from the CRC delimiter's sample edge (= step ta), ACK_DELIM from
    // the ACK slot's, IDLE_WAIT from the ACK delimiter's (ta + 16).
    for k in ta - 4..ta + 20 {
        let w = (ta..ta + 16).contains(&k);
        assert_eq!(
            b.log[k].probes.ack_window,
            w,
            "step ta{:+}",
            k as i64 - ta as i64
        );
    }
    // Node 1's ACK is on the pins during ta..ta+8 and would reach the downlinks at
    // ta+2..ta+10; the mask applies to edges ta+1..=ta+16 (ack_window before them).
    for k in ta + 1..=ta + 16 {
        assert_eq!(b.log[k].downlink, 0b11, "masked downlink at ta+{}", k - ta);
    }
    for k in ta + 2..ta + 10 {
        // The hub itself sees the ACK and forwards it to the twin.
        assert!(!b.log[k].probes.coupled);
        assert_eq!(b.log[k].sublink_out, 0);
    }
    // The twin's ACK reaches the downlinks.
    let (b, ta) = ack_run(true, true, false);
    for k in ta + 2..ta + 10 {
        assert_eq!(b.log[k].downlink, 0, "twin ACK at ta+{}", k - ta);
    }
    assert_eq!(b.log[ta + 10].downlink, 0b11);
    // No mask without ack_interdep, nor while decoupled.
    for (interdep, decouple) in [(false, false), (true, true)] {
        let (b, ta) = ack_run(interdep, false, decouple);
        assert!(b.log[ta + 5].probes.ack_window);
        for k in ta + 2..ta + 10 {
            assert_eq!(b.log[k].downlink, 0, "unmasked ACK at ta+{}", k - ta);
        }
    }
}
