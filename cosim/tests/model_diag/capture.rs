//! Error capture: the kind and position of the first error as receiver and as
//! transmitter (stuff, CRC, form, ACK and bit errors).

use super::*;

/// A receiver's stuff error: SOF and four dominant ID bits, then a sixth dominant
/// bit at the stuff position (the next non-stuff bit is still ID_A).
#[test]
fn capture_stuff_error_receiver() {
    let mut bits = vec![false; 6];
    bits.extend([true; 10]);
    let outs = receive(&bits);
    let (d, before) = only_error(&outs);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::ID_A, false)
    );
    assert_eq!(before, code::ID_A);
    assert_counts(&outs.last().unwrap().diag, 0, 1, 0, 0, 0);
}

/// A transmitter's recessive stuff bit in arbitration read dominant: STUFF with
/// `err_tx` (rule c exception 2: TEC unchanged); the receiver sees six dominant
/// bits: STUFF, not transmitter.
#[test]
fn capture_stuff_error_in_arbitration_transmitter() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    // 0x03F: SOF + ID bits 10..7 are five dominant bits, the stuff bit is the first
    // recessive bit the transmitter sends.
    bus.step(&[Some(frame(0x03F, &[1])), None]);
    let outs = force_first_recessive_bit(&mut bus, code::ID_A);
    let n0: Vec<ChannelOutputs> = outs.iter().map(|o| o[0]).collect();
    let n1: Vec<ChannelOutputs> = outs.iter().map(|o| o[1]).collect();
    let (d, _) = first_error(&n0);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::ID_A, true)
    );
    let k = n0.iter().position(|o| o.diag.err_valid).unwrap();
    assert_eq!(n0[k].probes.tec, 0, "rule c exception 2");
    let (d, _) = first_error(&n1);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::ID_A, false)
    );
}

/// A receiver's CRC error: signalled at the ACK delimiter (`err_field` ACK_DELIM),
/// the tester drives the ACK (the node does not ACK a wrong CRC).
#[test]
fn capture_crc_error() {
    for k in [0usize, 7, 14] {
        let f = frame(0x3A1, &[0xCA, 0xFE]);
        let bits: Vec<bool> = frame_bits(&f, false, Some(k))
            .iter()
            .map(|b| b.value)
            .collect();
        let outs = receive(&bits);
        let (d, before) = only_error(&outs);
        assert_eq!(
            (d.err_kind, d.err_field, d.err_tx),
            (KIND_CRC, code::ACK_DELIM, false)
        );
        assert_eq!(before, code::ACK_DELIM);
        let last = outs.last().unwrap();
        assert_counts(&last.diag, 0, 0, 1, 0, 0);
        assert!(outs.iter().all(|o| !o.rx_valid));
    }
}

/// A receiver's form errors: dominant CRC delimiter, ACK delimiter, EOF bit 3.
#[test]
fn capture_form_errors() {
    let f = frame(0x1B4, &[0x01, 0x80]);
    for (target, n) in [(code::CRC_DELIM, 0), (code::ACK_DELIM, 0), (code::EOF, 2)] {
        let mut bits = frame_bits(&f, false, None);
        let i = bits
            .iter()
            .enumerate()
            .filter(|(_, b)| b.field == target && !b.stuff)
            .nth(n)
            .unwrap()
            .0;
        bits[i].value = false;
        let values: Vec<bool> = bits.iter().map(|b| b.value).collect();
        let outs = receive(&values);
        let (d, before) = first_error(&outs);
        assert_eq!(
            (d.err_kind, d.err_field, d.err_tx),
            (KIND_FORM, target, false)
        );
        assert_eq!(before, target);
        assert_counts(&outs.last().unwrap().diag, 0, 0, 0, 1, 0);
    }
}

/// A lone transmitter's ACK error: ACK, field ACK_SLOT, transmitter.
#[test]
fn capture_ack_error() {
    let mut bus = Bus::new(1, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x111, &[0x22]))]);
    let outs: Vec<ChannelOutputs> = (0..100 * 8).map(|_| bus.step(&[])[0]).collect();
    let (d, before) = first_error(&outs);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_ACK, code::ACK_SLOT, true)
    );
    assert_eq!(before, code::ACK_SLOT);
    let k = outs.iter().position(|o| o.diag.err_valid).unwrap();
    assert_eq!(outs[k].probes.tec, 8);
    assert_counts(&outs[k].diag, 0, 0, 0, 0, 1);
}

/// A transmitter's bit error: a recessive data bit forced dominant. The
/// transmitter captures BIT in DATA; the receiver, which has then seen five equal
/// dominant bits, meets the transmitter's error flag at the stuff position: STUFF.
#[test]
fn capture_bit_error_transmitter() {
    // 0x555, DLC 1, data 0x0F: the four dominant data bits 0..3 follow DLC bit 0
    // (recessive) without a stuff bit between; data bit 4 is the first recessive one.
    let f = frame(0x555, &[0x0F]);
    let bits = frame_bits(&f, false, None);
    let data: Vec<_> = bits.iter().filter(|b| b.field == code::DATA).collect();
    assert!(
        data[..5].iter().all(|b| !b.stuff),
        "no stuff bit in data bits 0..4"
    );
    let first_data = bits.iter().position(|b| b.field == code::DATA).unwrap();
    assert!(
        bits[first_data - 1].value,
        "recessive bit before the data field"
    );

    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(f), None]);
    // The bit_start of the first recessive data bit (after dominant ones).
    let outs = force_first_recessive_bit(&mut bus, code::DATA);
    let n0: Vec<ChannelOutputs> = outs.iter().map(|o| o[0]).collect();
    let n1: Vec<ChannelOutputs> = outs.iter().map(|o| o[1]).collect();
    let (d, before) = first_error(&n0);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_BIT, code::DATA, true)
    );
    assert_eq!(before, code::DATA);
    let (d, _) = first_error(&n1);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::DATA, false)
    );
    let end = n0.last().unwrap().diag;
    assert_eq!(end.cnt_bit, 1);
}

/// A receiver's own ACK read back recessive is a BIT error in ACK_SLOT. The
/// lower tester cannot override a dominant bit, so the node's `rx` is driven
/// directly here (a bus fault that makes the ACK invisible).
#[test]
fn capture_bit_error_receiver_ack() {
    let f = frame(0x0A0, &[0x77]);
    let bits = frame_bits(&f, true, None);
    let mut t = Tester::new(timing(0));
    t.idle(20);
    let mut outs = Vec::new();
    for b in &bits {
        for _ in 0..8 {
            // rx ignores the node's tx: the bus shows exactly `bits`.
            let o = t.node.step(&drcc_cosim::ChannelInputs {
                rx: b.value,
                timing: timing(0),
                ..Default::default()
            });
            outs.push(o);
        }
    }
    let (d, before) = first_error(&outs);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_BIT, code::ACK_SLOT, false)
    );
    assert_eq!(before, code::ACK_SLOT);
}

/// Runs the bus for 100 bit times (8 clocks a bit) and, at the first rising edge
/// of node 0's `tx` while its next bit is in `field`, forces the bus dominant for
/// that one bit (8 clocks). Returns every clock's outputs.
fn force_first_recessive_bit(bus: &mut Bus, field: u8) -> Vec<Vec<ChannelOutputs>> {
    let mut outs = Vec::new();
    let mut forced = false;
    let mut prev_tx = true;
    for _ in 0..100 * 8 {
        let o = bus.step(&[]);
        outs.push(o.clone());
        let rising = !prev_tx && o[0].tx;
        prev_tx = o[0].tx;
        if !forced && rising && o[0].probes.field == field {
            forced = true;
            bus.force_dominant = true;
            for _ in 0..8 {
                outs.push(bus.step(&[]));
            }
            bus.force_dominant = false;
        }
    }
    outs
}
