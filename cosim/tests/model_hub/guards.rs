//! Guards (hub contract §6): stuck-dominant ports and sublinks, bit flipping,
//! six recessive bits, reserved identifiers, silent ports, restoration.

use super::*;

#[test]
fn stuck_dominant_node_port_is_isolated_at_its_14th_dominant_sample() {
    let mut b = Bench::running(2, 1, &[(INT_ENABLE, INT_ISOLATION)], true);
    b.pins = 0b111 & !1;
    let k = b.now();
    for _ in 0..40 * CPB {
        b.step();
    }
    // Samples at k+8, k+16, ...: dom_run reaches 14 at the 14th.
    let iso = k + 8 + 13 * CPB;
    assert!(b.log[iso].probes.sample_point);
    // §6.1: decided at the SAMPLE edge, in the guard registers one clock later.
    assert!(enabled(&b.log[iso], 0));
    assert!(!enabled(&b.log[iso + 1], 0));
    // Effective on the coupling at the edge after that.
    assert!(!b.log[iso + 1].probes.coupled && b.log[iso + 1].downlink == 0);
    assert!(b.log[iso + 2].probes.coupled && b.log[iso + 2].downlink == 0b11);
    // INT_STATUS.isolation at iso + 1, the registered irq one edge later.
    assert!(!b.log[iso + 1].irq && b.log[iso + 2].irq);
    assert_eq!(b.port_reg(0), 1 << 1 | 1 << 16, "kind 1, one isolation");
    assert_eq!(b.port_reg(1), 1);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
    assert_eq!(b.read(STATUS) >> 16, 0b110);
}

#[test]
fn stuck_dominant_sublink_is_isolated_at_its_28th_dominant_sample() {
    let mut b = Bench::running(2, 1, &[], true);
    b.pins = 0b011;
    let k = b.now();
    for _ in 0..40 * CPB {
        b.step();
    }
    let iso = k + 8 + 27 * CPB;
    // §6.1: in the guard registers one clock after the SAMPLE edge
    assert!(enabled(&b.log[iso], 2));
    assert!(!enabled(&b.log[iso + 1], 2));
    assert!(b.log[iso + 2].probes.coupled);
    assert_eq!(b.port_reg(2), 1 << 1 | 1 << 16);
    // Thresholds from GUARD_CFG: sd_run_sub 20.
    let mut b = Bench::running(2, 1, &[(GUARD_CFG, 14 | 20 << 8 | 8 << 16)], true);
    b.pins = 0b011;
    let k = b.now();
    for _ in 0..40 * CPB {
        b.step();
    }
    let iso = k + 8 + 19 * CPB;
    assert!(enabled(&b.log[iso], 2) && !enabled(&b.log[iso + 1], 2));
}

#[test]
fn isolation_event_beats_a_w1c_clear_at_the_same_edge() {
    let mut b = Bench::running(2, 1, &[], true);
    b.pins = 0b110;
    let k = b.now();
    // decided at the SAMPLE edge k + 8 + 13 * CPB, the event one clock later (§6.1)
    let iso = k + 8 + 13 * CPB + 1;
    while b.now() < iso {
        b.step();
    }
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: INT_STATUS,
        wb_dat_w: 0xF,
        ..b.pin_inputs()
    });
    assert!(o.wb_ack && !enabled(&o, 0));
    b.step();
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
}

/// Port 1 of a 3x1 hub drives dominant in the r0 bit (after the arbitration
/// field) of a frame it does not send; the transmitter's r0 is dominant too, so
/// the frame is undisturbed. Everybody else acknowledges.
fn flipping_frame(b: &Bench, flip: bool) -> Vec<u16> {
    let f = encode(0x2B4, false, false, 2, &[0x5A, 0x11]);
    let mut lanes = b.frame_lanes(&f, 0, 0b1110);
    if flip {
        lanes[f.raw_at[14]] &= !(1 << 1); // r0
    }
    lanes
}

#[test]
fn bit_flipping_port_is_blamed_per_frame_and_isolated_at_bf_up() {
    let mut b = Bench::running(3, 1, &[], true);
    let f = encode(0x2B4, false, false, 2, &[0x5A, 0x11]);
    assert!(!f.bits[f.raw_at[14]], "r0 is dominant");
    for i in 1..=3u32 {
        let lanes = flipping_frame(&b, true);
        b.drive(&lanes);
        let r = b.port_reg(1);
        assert_eq!(
            pec(r),
            8 * i,
            "frame {i}: +8, no decrement in a blamed frame"
        );
        assert_eq!(r & 1, 1);
        assert_eq!(pec(b.port_reg(0)), 0, "the transmitter is not blamed");
    }
    // The 4th blamed frame: pec 32 >= bf_up 32, isolated at the r0 sample.
    let lanes = flipping_frame(&b, true);
    let t0 = b.drive(&lanes);
    let at = sample_step(t0, f.raw_at[14]);
    assert!(enabled(&b.log[at], 1) && !enabled(&b.log[at + 1], 1));
    let r = b.port_reg(1);
    assert_eq!((r & 1, kind(r), pec(r), r >> 16 & 0xFF), (0, 3, 32, 1));
    assert_eq!(b.read(STATS) & 0xFFFF, 4);
}

#[test]
fn clean_frames_decrement_the_port_error_counter() {
    let mut b = Bench::running(3, 1, &[], true);
    for _ in 0..2 {
        let lanes = flipping_frame(&b, true);
        b.drive(&lanes);
    }
    assert_eq!(pec(b.port_reg(1)), 16);
    for i in 1..=3u32 {
        let lanes = flipping_frame(&b, false);
        b.drive(&lanes);
        assert_eq!(pec(b.port_reg(1)), 16 - i);
    }
    // bf_up from BF_CFG: 8 isolates at the first blame.
    let mut b = Bench::running(3, 1, &[(BF_CFG, 8 | 64 << 8)], true);
    let lanes = flipping_frame(&b, true);
    b.drive(&lanes);
    assert_eq!(kind(b.port_reg(1)), 3);
}

#[test]
fn six_recessive_bits_blame_the_transmitter() {
    let mut b = Bench::running(2, 1, &[], true);
    // Port 0 sends SOF and then six recessive bits: it failed to stuff.
    let mut lanes = vec![0b110u16];
    lanes.extend([0b111; 16]);
    let t0 = b.drive(&lanes);
    assert_eq!(b.log[sample_step(t0, 5)].probes.trk_state, FRAME);
    assert_eq!(b.log[sample_step(t0, 6)].probes.trk_state, IDLE_WAIT);
    assert_eq!(b.port_reg(0), 1 | 8 << 8);
    assert_eq!(b.port_reg(1), 1, "not a candidate: not blamed");
    assert_eq!(b.read(STATS), 1 << 16);
}

#[test]
fn reserved_identifier_from_a_node_port_isolates_it() {
    for id in [0x000, 0x001] {
        let mut b = Bench::running(2, 1, &[], true);
        let f = encode(id, false, false, 0, &[]);
        // Nobody acknowledges: once port 0 is cut off, the bus is recessive for
        // more than 10 bits and a dominant ACK would be a start of frame.
        let t0 = b.send(&f, 0, 0);
        // Isolated at the sample of identifier bit 10 (data bit pos 10).
        let at = sample_step(t0, f.raw_at[10]);
        // §6.1: in the guard registers one clock after the SAMPLE edge
        assert!(enabled(&b.log[at], 0), "id {id:#x}");
        assert!(!enabled(&b.log[at + 1], 0), "id {id:#x}");
        let r = b.port_reg(0);
        assert_eq!((kind(r), r & 1), (4, 0), "id {id:#x}");
        assert_eq!(b.port_reg(1), 1);
        assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
    }
    // The rule looks at identifier bits 1..10 before IDE is known, so an extended
    // frame whose base part is 0x000 / 0x001 is caught as well.
    let mut b = Bench::running(2, 1, &[], true);
    let f = encode(0x0000_0F0F, true, false, 0, &[]);
    let t0 = b.send(&f, 0, 0);
    assert!(!enabled(&b.log[sample_step(t0, f.raw_at[10]) + 1], 0));
    assert_eq!(kind(b.port_reg(0)), 4);
    // 0x002 is an ordinary identifier.
    let mut b = Bench::running(2, 1, &[], true);
    b.send(&encode(0x002, false, false, 0, &[]), 0, 0b110);
    assert_eq!(b.port_reg(0), 1);
    assert_eq!(b.read(STATS), 1);
}

#[test]
fn reserved_identifier_from_a_sublink_is_legitimate() {
    let mut b = Bench::running(2, 1, &[], true);
    let f = encode(0x000, false, false, 0, &[]);
    b.send(&f, 2, 0b011);
    for p in 0..3 {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}");
    }
    assert_eq!(b.read(STATS), 1);
    assert_eq!(b.read(INT_STATUS), 0);
}

#[test]
fn silent_port_is_isolated_after_sr_frames() {
    let mut b = Bench::running(3, 1, &[], true);
    let f = encode(0x0F1, false, false, 1, &[0x42]);
    // Port 0 sends, ports 1 and the sublink (3) acknowledge, port 2 says nothing.
    for i in 1..=7 {
        b.send(&f, 0, 0b1010);
        assert_eq!(b.port_reg(2), 1, "frame {i}");
    }
    let t0 = b.send(&f, 0, 0b1010);
    let at = sample_step(t0, f.ack);
    assert!(enabled(&b.log[at], 2) && !enabled(&b.log[at + 1], 2));
    let r = b.port_reg(2);
    assert_eq!((r & 1, kind(r)), (0, 2));
    for p in [0, 1, 3] {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}");
    }
    // sr_frames = 0: the silence rule is off.
    let mut b = Bench::running(3, 1, &[(GUARD_CFG, 14 | 16 << 8)], true);
    for _ in 0..10 {
        b.send(&f, 0, 0b1010);
    }
    assert_eq!(b.port_reg(2), 1);
}

#[test]
fn isolated_port_is_restored_after_restore_bits_symptom_free_samples() {
    let cfg = [(RESTORE_CFG, 20 | 4096 << 16), (INT_ENABLE, 0xF)];
    let mut b = Bench::running(2, 1, &cfg, true);
    b.pins = 0b110;
    let k = b.now();
    for _ in 0..20 * CPB {
        b.step();
    }
    // Isolated at the 14th sample; released at k + 160: the last dominant sample
    // is k + 160 (pb = pin of step 157), the first recessive one k + 168.
    assert!(!enabled(&b.log[k + 8 + 13 * CPB + 1], 0));
    b.pins = 0b111;
    for _ in 0..40 * CPB {
        b.step();
    }
    let back = k + 168 + 19 * CPB; // the 20th symptom-free sample
    assert!(b.log[back].probes.sample_point);
    // §6.1: decisions reach the guard registers one clock after their edge
    for s in k + 8 + 13 * CPB + 1..=back {
        assert!(!enabled(&b.log[s], 0), "step k+{}", s - k);
    }
    assert!(enabled(&b.log[back + 1], 0));
    let r = b.port_reg(0);
    // enabled, kind kept (1), pec 0, 1 isolation, 1 restoration.
    assert_eq!(r, 1 | 1 << 1 | 1 << 16 | 1 << 24);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION | INT_RESTORATION);
    // restore_bits = 0: never restored.
    let mut b = Bench::running(2, 1, &[(RESTORE_CFG, 4096 << 16)], true);
    b.pins = 0b110;
    for _ in 0..20 * CPB {
        b.step();
    }
    b.idle_bits(300);
    assert_eq!(b.port_reg(0) & 1, 0);
}
