//! ISO 16845-1 8.5: the error-passive transmitter (passive flags, suspend
//! transmission, bus-off recovery, retransmission delays).

use super::*;

/// 8.5.1: an error-passive transmitter's passive flag overlapped by another node's
/// active flag (starting 0..=5 bits late) ends after 6 equal bits; TEC + 8 once.
pub fn iso_8_5_1_passive_flag_with_active_flag_from_others(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x551, &[5, 5, 1]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for late in 0..=5usize {
        lt.set_context(format!("active flag {late} bits late"));
        let (mut s, _) = bit_error_at_r0(&mut exp, &fb, if late == 0 { 2 } else { 0 });
        s.repeat(late, Lt::R, Some(true), "PassiveFlag R");
        s.repeat(6, Lt::D, Some(true), "Active flag of others");
        s.error_delim();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        assert_eq!(
            run.at("Active flag of others 6").probes.field,
            field::ERROR_DELIM
        );
        assert_eq!(
            run.at("Active flag of others 5").probes.field,
            field::ERROR_FLAG
        );
        lt.check(&exp, "TEC + 8 once");
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// Passive IUT (frame pending): bit error at r0, passive flag, delimiter,
/// intermission bits 1 and 2; returns the script (the caller continues at
/// intermission bit 3).
fn passive_error_until_intermission_3(
    exp: &mut Expected,
    fb: &FrameBits,
    sof_within: u32,
) -> Script {
    let (mut s, _) = bit_error_at_r0(exp, fb, sof_within);
    assert!(!exp.active());
    s.passive_flag("PassiveFlag").error_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s
}

/// 8.5.2: an error-passive transmitter receives a frame whose SOF is the 3rd
/// intermission bit after its error frame (it does not join: suspend is due),
/// then sends its frame without suspend.
pub fn iso_8_5_2_passive_receives_after_error_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let mine = FrameBits::new(&base(0x552, &[2]));
    let theirs = FrameBits::new(&base(0x7FF, &[0xFF]));
    lt.request(mine.frame);
    let mut s = passive_error_until_intermission_3(&mut exp, &mine, 2);
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame]);
    assert_eq!(run.tx_done_bits().len(), 1);
    lt.check(&exp, "after both frames");
}

/// 8.5.3: after its passive flag, 1..=7 dominant bits are tolerated; TEC + 8 per
/// error only.
pub fn iso_8_5_3_passive_dominant_bits_in_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x553, &[]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for n in 1..=7 {
        lt.set_context(format!("{n} dominant bits after the passive flag"));
        let before = exp.tec;
        tx_error_with_dominant_after(&mut lt, &mut exp, &fb, n, if n == 1 { 2 } else { 0 });
        assert_eq!(exp.tec, before + 8);
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.4: an error-passive transmitter receives a frame whose SOF falls into its
/// suspend transmission (suspend bit 4), then sends its own frame.
pub fn iso_8_5_4_passive_receives_during_suspend(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let mine = FrameBits::new(&base(0x554, &[4]));
    let theirs = FrameBits::new(&ext(0x1FFF_FFFF, &[]));
    lt.request(mine.frame);
    let mut s = passive_error_until_intermission_3(&mut exp, &mine, 2);
    s.push(Lt::R, Some(true), "Intermission 3");
    s.repeat(3, Lt::R, Some(true), "Suspend");
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame]);
    lt.check(&exp, "after both frames");
}

/// 8.5.5: an error-passive transmitter waits exactly 8 suspend bits after the
/// intermission of its error frame before its SOF.
pub fn iso_8_5_5_suspend_after_error_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x555, &[5]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_bit_error(&mut lt, &mut exp, &fb, 2);
    let run = tx_ok(&mut lt, &mut exp, &fb, 0);
    assert!(run.recs[0].waited.unwrap() < lt.cpb());
}

/// 8.5.6: suspend transmission after an overload frame that follows its own frame.
pub fn iso_8_5_6_suspend_after_overload_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 136);
    let a = FrameBits::new(&base(0x556, &[6]));
    let b = FrameBits::new(&base(0x0B6, &[]));
    lt.request(a.frame);
    let mut s = own_frame_then_overload(&a, 1, 6, 2);
    let i = s.len() - 6;
    s.request_at(i, b.frame);
    s.overload_delim().intermission().suspend();
    s.transmit(&b, 0..b.len(), true, 0);
    exp.tx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 2);
    lt.check(&exp, "after both frames");
}

/// 8.5.7: suspend transmission after its own successful frame.
pub fn iso_8_5_7_suspend_after_own_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 136);
    let a = FrameBits::new(&ext(0x0557_0557, &[7]));
    let b = FrameBits::new(&base(0x0B7, &[7, 7]));
    lt.request(a.frame);
    let mut s = Script::new();
    s.transmit(&a, 0..a.len(), true, 2);
    s.intermission().suspend();
    let i = s.len() - 11;
    s.request_at(i, b.frame);
    s.transmit(&b, 0..b.len(), true, 0);
    exp.tx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 2);
    lt.check(&exp, "after both frames");
}

/// 8.5.8: an error-passive node that lost arbitration does not suspend: its SOF
/// follows the intermission after the winner's frame.
pub fn iso_8_5_8_no_suspend_after_arbitration_lost(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    lose_arbitration(&mut lt, &mut exp, &base(0x558, &[8]), &base(0x550, &[0]));
}

/// 8.5.9: an error-passive node never transmits without its own SOF: after its
/// error frame, a frame of lower priority from the tester whose SOF is the 3rd
/// intermission bit, suspend bit 1 or suspend bit 7 is received and acknowledged
/// (the IUT's `tx` recessive except its ACK: had it joined, its higher-priority
/// identifier would show on `tx`); its retransmission starts with its own SOF
/// after that frame. The same after its own successful frame (a second frame
/// pending, SOF at intermission bit 3).
pub fn iso_8_5_9_passive_never_transmits_without_sof(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let mine = FrameBits::new(&base(0x259, &[9]));
    let theirs = FrameBits::new(&base(0x6AA, &[1]));
    let mut n = 0;
    // The tester's SOF after 0 (intermission bit 3), 1 (suspend bit 1) and 7
    // (suspend bit 7) recessive bits.
    for wait in [0usize, 1, 7] {
        lt.set_context(format!("SOF {wait} bits after intermission bit 2"));
        lt.request(mine.frame);
        let mut s = passive_error_until_intermission_3(&mut exp, &mine, 2);
        s.repeat(wait, Lt::R, Some(true), "Intermission 3 / Suspend");
        s.receive(&theirs, 0..theirs.len(), true).intermission();
        s.transmit(&mine, 0..mine.len(), true, 0);
        exp.rx_ok();
        exp.tx_ok();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        n += 1;
        assert_eq!(lt.received.len(), n, "{}: frame received", lt.name());
        assert_eq!(run.tx_done_bits().len(), 1);
        lt.check(&exp, "after both frames");
    }
    // After its own frame (a second frame pending).
    lt.set_context("after its own frame");
    let a = FrameBits::new(&base(0x510, &[1, 0]));
    lt.request(a.frame);
    let mut s = Script::new();
    s.transmit(&a, 0..a.len(), true, 2);
    let i = s.len();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.request_at(i, mine.frame);
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.tx_ok();
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame; 4]);
    lt.check(&exp, "after the frames");
}

/// Number of completed occurrences of 11 consecutive recessive bits in `bus`
/// (ISO 11898-1 12.1.4.2 l; a dominant bit restarts the run) and the length of
/// the run in progress at its end.
fn recessive_runs(bus: &[bool]) -> (u32, u32) {
    let (mut run, mut occurrences) = (0, 0);
    for &b in bus {
        run = if b { run + 1 } else { 0 };
        if run == 11 {
            run = 0;
            occurrences += 1;
        }
    }
    (occurrences, run)
}

/// 8.5.10 (the ISO 16845-1 procedure, classical): an error-passive transmitter
/// (TEC 247) sends frame A, acknowledged (246), frame B pending; a dominant
/// intermission bit 1 starts an overload frame whose 1st bit the tester forces
/// recessive (rule d: 254, a passive flag); 6 + 7 bits later a dominant 8th
/// delimiter bit starts another overload frame, whose 1st bit forced recessive
/// makes TEC exceed 255: bus-off from the next bit (no flag). 25 bits later the
/// tester sends a frame: the bus-off IUT does not acknowledge it, does not deliver
/// it and does not send B (only A was transmitted); after 128 occurrences of 11
/// recessive bits it is error active with TEC = REC = 0 and sends B.
pub fn iso_8_5_10_bus_off_no_transmission(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 240);
    assert_eq!(exp.tec, 247);
    let a = FrameBits::new(&base(0x5A0, &[0xA0]));
    let b = FrameBits::new(&base(0x5A1, &[0xA1]));
    let theirs = FrameBits::new(&base(0x7A5, &[0x5A, 0xA5]));
    lt.request(a.frame);
    let mut s = Script::new();
    s.transmit(&a, 0..a.len(), true, 2);
    exp.tx_ok();
    let i = s.len();
    s.push(Lt::D, Some(true), "Intermission 1 dominant");
    s.request_at(i, b.frame);
    s.push(Lt::ForceR, Some(false), "OvlFlag 1 forced recessive");
    exp.tec_add(8);
    assert_eq!((exp.tec, exp.state()), (254, state::PASSIVE));
    s.passive_flag("PassiveFlag");
    s.repeat(7, Lt::R, Some(true), "ErrDelim");
    s.push(Lt::D, Some(true), "ErrDelim 8 dominant");
    s.push(Lt::ForceR, Some(false), "OvlFlag 1 (2nd) forced recessive");
    exp.tec_add(8);
    assert_eq!(exp.state(), state::BUS_OFF);
    let off = s.len() - 1;
    s.repeat(24, Lt::R, Some(true), "Bus-off");
    s.receive(&theirs, 0..theirs.len(), false);
    let bus: Vec<bool> = s.bits[off + 1..].iter().map(|b| b.drive != Lt::D).collect();
    let (mut occurrences, mut run) = recessive_runs(&bus);
    assert!(occurrences < 128);
    while occurrences < 128 {
        s.push(Lt::R, Some(true), "Bus-off recovery");
        run += 1;
        if run == 11 {
            run = 0;
            occurrences += 1;
        }
    }
    let rec = lt.run(&s);
    assert_eq!(rec.tx_done_bits(), vec![a.eof(7)], "{}: only A", lt.name());
    let p = rec.at("OvlFlag 1 forced recessive").probes;
    assert_eq!((p.tec, p.err_state), (254, state::PASSIVE), "{}", lt.name());
    let p = rec.recs[off].probes;
    assert!(
        p.tec > 255 && p.err_state == state::BUS_OFF,
        "{}: bus-off at the 2nd overload flag bit error (TEC {}, state {})",
        lt.name(),
        p.tec,
        p.err_state
    );
    let last = rec.recs.len() - 1;
    for (k, r) in rec.recs.iter().enumerate().skip(off) {
        let want = if k < last {
            state::BUS_OFF
        } else {
            state::ACTIVE
        };
        assert_eq!(
            r.probes.err_state,
            want,
            "{}: error state at bit {k} ({})",
            lt.name(),
            r.label
        );
    }
    assert!(
        lt.received.is_empty(),
        "{}: no frame delivered while bus-off",
        lt.name()
    );
    exp = Expected::default();
    lt.check(&exp, "after the recovery");
    tx_ok(&mut lt, &mut exp, &b, 0);
}

/// 8.5.11: bus-off at TEC > 255; the IUT stays bus-off (recessive, no flag, no
/// ACK for a frame on the bus, which it does not deliver) until 128 occurrences of
/// 11 consecutive recessive bits (a dominant bit restarts the current run), then
/// is error active with TEC = REC = 0 and sends its pending frame.
pub fn iso_8_5_11_bus_off_recovery(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x5B0, &[0xB0]);
    let fb = tec_to(&mut lt, &mut exp, &f, 256);
    assert_eq!(lt.probes().err_state, state::BUS_OFF);
    assert!(lt.probes().tec > 255);
    // Bus after the bit that made the IUT bus-off: the 14 recessive bits of the
    // procedure, 50 more, another node's frame, then recessive bits up to the
    // 128th occurrence of 11 consecutive recessive bits, counted here.
    let other = FrameBits::new(&base(0x001, &[0x00, 0x00]));
    let mut s = Script::new();
    s.repeat(50, Lt::R, Some(true), "BusOff A");
    for i in 0..other.len() {
        s.push(
            Lt::from_value(other.bits[i].value),
            Some(true),
            other.name(i),
        );
    }
    let mut bus: Vec<bool> = vec![true; 14];
    bus.extend(s.bits.iter().map(|b| b.drive == Lt::R));
    let (mut run, mut occurrences) = (0, 0);
    for &b in &bus {
        run = if b { run + 1 } else { 0 };
        if run == 11 {
            run = 0;
            occurrences += 1;
        }
    }
    assert!(occurrences < 128);
    while occurrences < 128 {
        s.push(Lt::R, Some(true), "BusOff B");
        run += 1;
        if run == 11 {
            run = 0;
            occurrences += 1;
        }
    }
    let run = lt.run(&s);
    for (i, r) in run.recs.iter().enumerate() {
        let want = if i + 1 < run.recs.len() {
            state::BUS_OFF
        } else {
            state::ACTIVE
        };
        assert_eq!(
            r.probes.err_state,
            want,
            "{}: error state at bus-off bit {} ({})",
            lt.name(),
            i,
            r.label
        );
    }
    assert!(
        lt.received.is_empty(),
        "{}: no frame while bus-off",
        lt.name()
    );
    exp = Expected::default();
    lt.check(&exp, "after the recovery");
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.12: an error-passive transmitter's passive flag completes only after 6
/// equal consecutive bits.
pub fn iso_8_5_12_passive_flag_tx_six_equal_bits(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x512, &[0x12]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for (k, p) in ["RRRRRR", "DDDDDD", "RRDRRRRRR", "DRRRRRDDDDDD"]
        .into_iter()
        .enumerate()
    {
        lt.set_context(format!("bits during the passive flag: {p}"));
        let (mut s, _) = bit_error_at_r0(&mut exp, &fb, if k == 0 { 2 } else { 0 });
        for (i, c) in p.chars().enumerate() {
            let d = if c == 'D' { Lt::D } else { Lt::R };
            s.push(d, Some(true), format!("PassiveFlag {}", i + 1));
        }
        s.error_delim();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        let first = run.find("PassiveFlag 1");
        let n = p.len();
        assert_eq!(run.recs[first + n - 2].probes.field, field::ERROR_FLAG);
        assert_eq!(run.recs[first + n - 1].probes.field, field::ERROR_DELIM);
        lt.check(&exp, "TEC + 8 per error");
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.13: form error in the delimiter after its passive flag: TEC + 8, a new
/// passive flag.
pub fn iso_8_5_13_passive_form_error_in_delimiter_tx(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x513, &[]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for (i, k) in [2, 4, 7].into_iter().enumerate() {
        tx_delimiter_dominant(&mut lt, &mut exp, &fb, k, if i == 0 { 2 } else { 0 });
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.14: an error-passive transmitter retransmits at most 31 bit times after the
/// error: passive flag (6..=12 bits with another node's active flag starting 0..=6
/// bits late), 8 delimiter, 3 intermission and 8 suspend bits; the SOF comes
/// exactly then.
pub fn iso_8_5_14_retransmission_within_31_bits(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x514, &[0x14]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for late in 0..=6usize {
        lt.set_context(format!("active flag {late} bits late"));
        let (mut s, r0) = bit_error_at_r0(&mut exp, &fb, if late == 0 { 2 } else { 0 });
        s.repeat(late, Lt::R, Some(true), "PassiveFlag R");
        s.repeat(6, Lt::D, Some(true), "Active flag of others");
        s.error_delim();
        interframe_tx(&mut s, &exp);
        let n = s.len() - r0;
        let want = if late < 6 { late + 6 } else { 12 } + 8 + 3 + 8;
        assert_eq!(n - 1, want);
        assert!(want <= 31);
        lt.run(&s);
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.15: the active flag of a transmitter forced recessive bit after bit (TEC 8,
/// 16, .., 128): at 128 the IUT turns passive, its flag is passive and the frame
/// starts again 6 + 8 + 3 + 8 bits after the last forced bit.
pub fn iso_8_5_15_turning_passive_retransmits_after_25_bits(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x515, &[0x80]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let (mut s, _) = bit_error_at_r0(&mut exp, &fb, 2);
    for j in 1..=15 {
        s.push(Lt::ForceR, Some(false), format!("forced {j}"));
        exp.tec_add(8);
    }
    assert_eq!(exp.tec, 128);
    s.passive_flag("PassiveFlag").error_delim();
    interframe_tx(&mut s, &exp);
    let last = s.len();
    let run = lt.run(&s);
    assert_eq!(last - run.find("forced 15") - 1, 25);
    assert_eq!(run.at("forced 14").probes.err_state, state::ACTIVE);
    assert_eq!(run.at("forced 15").probes.err_state, state::PASSIVE);
    lt.check(&exp, "error passive");
    tx_ok(&mut lt, &mut exp, &fb, 0);
}
