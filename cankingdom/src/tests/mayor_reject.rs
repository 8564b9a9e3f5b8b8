//! Every rejection reason, counted by the Mayor; a rejected letter changes
//! nothing.

use super::mayor::{cfg, default_letter, feed, joined, king};
use super::{std_frame, FakePost, TestFrame};
use crate::letter::{Envelope, Reject};
use crate::mayor::Mayor;
use embedded_can::{Frame, StandardId};

/// Feed `frame` to a joined Mayor (city 3) and check it is counted once as
/// `reason` and nothing else.
fn rejected(frame: TestFrame, reason: Reject) -> (Mayor, FakePost) {
    let (mut m, mut p) = joined();
    feed(&mut m, &mut p, frame);
    assert_eq!(m.rejected(reason), 1, "{reason:?}");
    assert_eq!(m.rejects().total(), 1, "{reason:?}");
    assert_eq!(m.letters_accepted(), 0);
    assert!(p.tx.is_empty());
    (m, p)
}

#[test]
fn wrong_length() {
    rejected(std_frame(0, &[3, 0, 1, 3, 0, 0, 0]), Reject::WrongLength);
    rejected(std_frame(0, &[]), Reject::WrongLength);
}

#[test]
fn remote_frame() {
    let f = TestFrame::new_remote(StandardId::new(0).unwrap(), 8).unwrap();
    rejected(f, Reject::RemoteFrame);
}

#[test]
fn unknown_page() {
    rejected(king([3, 3, 0, 0, 0, 0, 0, 0]), Reject::UnknownPage);
    rejected(king([0, 11, 0, 0, 0, 0, 0, 0]), Reject::UnknownPage);
}

#[test]
fn reserved_bits() {
    let (m, _) = rejected(
        king([3, 0, 0x05, 0x03, 0, 0, 0, 0]),
        Reject::ReservedBitsSet,
    );
    assert_eq!(m.action(), None, "nothing of it applied");
    rejected(
        king([3, 1, 0, 0, 0, 0x04, 0, 0x20]),
        Reject::ReservedBitsSet,
    );
    rejected(
        king([3, 2, 0x23, 1, 0, 0, 9, 0x13]),
        Reject::ReservedBitsSet,
    );
    rejected(king([3, 5, 1, 1, 0xFF, 1, 1, 0]), Reject::ReservedBitsSet);
    rejected(king([3, 10, 1, 0, 0, 0x20, 1, 1]), Reject::ReservedBitsSet);
}

#[test]
fn reserved_combination() {
    let (m, _) = rejected(
        king([3, 2, 0x23, 1, 0, 0, 9, 0x05]),
        Reject::ReservedCombination,
    );
    assert!(m.folders().is_empty());
}

#[test]
fn envelope_out_of_range() {
    // Decode level: standard envelope 0x800.
    rejected(
        king([3, 2, 0x00, 0x08, 0, 0, 9, 0x03]),
        Reject::EnvelopeOutOfRange,
    );
    // Mayor level: standard base 0x7FF + address 3 does not fit 11 bits.
    let (m, _) = rejected(
        king([3, 1, 0, 0, 0xFF, 0x07, 0, 0]),
        Reject::EnvelopeOutOfRange,
    );
    assert_eq!(m.base_number(), None);
}

#[test]
fn unsupported_response_page() {
    let (m, _) = rejected(
        king([3, 1, 2, 0, 0x00, 0x04, 0, 0]),
        Reject::UnsupportedResponsePage,
    );
    assert_eq!(m.base_number(), None);
}

#[test]
fn base_number_unknown() {
    // Keep (unknown) base and respond: impossible.
    rejected(king([3, 1, 0, 0, 0, 0, 0, 0]), Reject::BaseNumberUnknown);
    // Undefined base and respond: rejected whole, the base is kept.
    let (mut m, mut p) = joined();
    feed(&mut m, &mut p, king([3, 1, 0xFF, 0, 0x00, 0x04, 0, 0]));
    feed(&mut m, &mut p, king([3, 1, 0, 0, 0xFF, 0xFF, 0xFF, 0x1F]));
    assert_eq!(m.rejected(Reject::BaseNumberUnknown), 1);
    assert_eq!(m.base_number(), Envelope::standard(0x400));
    // Undefined without a response is fine.
    feed(
        &mut m,
        &mut p,
        king([3, 1, 0xFF, 0, 0xFF, 0xFF, 0xFF, 0x1F]),
    );
    assert_eq!(m.base_number(), None);
}

#[test]
fn not_assigned() {
    rejected(king([3, 2, 0x23, 1, 0, 0, 0, 0x01]), Reject::NotAssigned); // keep
    rejected(king([3, 2, 0x23, 1, 0, 0, 4, 0x07]), Reject::NotAssigned); // transfer
}

#[test]
fn already_assigned() {
    let (mut m, mut p) = joined();
    feed(&mut m, &mut p, king([3, 2, 0x23, 1, 0, 0, 1, 0x03]));
    feed(&mut m, &mut p, king([3, 2, 0x23, 1, 0, 0, 2, 0x03]));
    assert_eq!(m.rejected(Reject::AlreadyAssigned), 1);
    assert_eq!(
        m.folders()
            .get(Envelope::standard(0x123).unwrap())
            .unwrap()
            .folder,
        1
    );
}

#[test]
fn table_full() {
    let mut m: Mayor<1, 1, 1> = Mayor::new(cfg(3)).unwrap();
    let mut p = FakePost::default();
    m.poll(0, &mut p);
    p.rx.push_back(default_letter());
    for lines in [
        [3, 2, 0x23, 1, 0, 0, 1, 0x03],
        [3, 2, 0x24, 1, 0, 0, 1, 0x03], // second envelope
        [3, 5, 1, 2, 0, 3, 4, 0],
        [3, 5, 1, 2, 0, 3, 5, 0], // second link
        [3, 10, 0x23, 1, 0, 0, 1, 1],
        [3, 10, 0x24, 1, 0, 0, 1, 1], // second envelope
    ] {
        p.rx.push_back(king(lines));
    }
    m.poll(1_000, &mut p);
    assert_eq!(m.letters_accepted(), 3);
    assert_eq!(m.rejected(Reject::TableFull), 3);
    assert_eq!(
        (m.folders().len(), m.links().len(), m.intervals().len()),
        (1, 1, 1)
    );
}

#[test]
fn any_bytes_never_panic() {
    // Every (page, line) byte value in a King's Letter, and random-ish fill.
    let (mut m, mut p) = joined();
    let mut x: u32 = 0x1234_5678;
    for i in 0..20_000u32 {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        let b = x.to_le_bytes();
        let len = (i % 10) as usize;
        let mut data = [
            3,
            (i % 12) as u8,
            b[0],
            b[1],
            b[2],
            b[3],
            b[0] ^ b[1],
            b[2] & 7,
            0,
            0,
        ];
        data[0] = if i % 3 == 0 { 0 } else { 3 };
        if len <= 8 {
            p.rx.push_back(std_frame(0, &data[..len]));
        }
        m.poll(2_000 + u64::from(i), &mut p);
        p.tx.clear();
    }
    assert!(m.rejects().total() > 0);
    assert!(m.letters_accepted() > 0);
}
