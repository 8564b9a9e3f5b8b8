//! The King's start-up driver against a recording Postmaster.

use super::{ext_frame, std_frame, std_id, FakePost, TestFrame};
use crate::king::*;
use crate::king_pages::{KingPage, MinInterval};
use crate::letter::{EncodeError, Envelope, EnvelopeSpec, Reject};
use crate::postmaster::{BitRate, CommMode};
use embedded_can::{Frame, StandardId};

const EAN1: u64 = 0x11_1111_1111;
const EAN2: u64 = 0x22_2222_2222;

fn king2() -> King<2> {
    let cities = [
        ExpectedCity {
            address: 1,
            ean: EAN1,
        },
        ExpectedCity {
            address: 2,
            ean: EAN2,
        },
    ];
    King::new(KingConfig::new(cities, Envelope::standard(0x400).unwrap())).unwrap()
}

/// Mayor's Page 0 reply from `address` (base 0x400).
fn reply(address: u16, ean: u64) -> TestFrame {
    let b = ean.to_le_bytes();
    std_frame(0x400 + address, &[0, 0, b[0], b[1], b[2], b[3], b[4], 0])
}

fn sent(p: &mut FakePost) -> Vec<(u16, Vec<u8>)> {
    p.tx.drain(..)
        .map(|f| (std_id(&f), f.data().to_vec()))
        .collect()
}

const DEFAULT: (u16, [u8; 8]) = (2031, [0xAA; 8]);
// King's Page 1, broadcast, respond with page 0, base 0x400 standard.
const PAGE1: [u8; 8] = [0x00, 0x01, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00];
// King's Page 0, broadcast, Run (AA=01), Communicate (CC=11).
const RUN: [u8; 8] = [0x00, 0x00, 0x01, 0x03, 0x00, 0x00, 0x00, 0x00];

#[test]
fn startup_timeline_agreed() {
    let mut k = king2();
    let mut p = FakePost::default();
    assert_eq!(k.phase(), KingPhase::NotStarted);
    k.poll(0, &mut p);
    assert_eq!(p.rates, [BitRate::Kbit125]);
    assert_eq!(p.modes, [CommMode::Communicate]);
    assert_eq!(k.phase(), KingPhase::DefaultLetters);
    let mut defaults = 0;
    for t in (0..200_000).step_by(1_000) {
        k.poll(t, &mut p);
        for (id, data) in sent(&mut p) {
            assert_eq!((id, data.as_slice()), (DEFAULT.0, &DEFAULT.1[..]));
            defaults += 1;
        }
    }
    assert_eq!(defaults, 4, "at 0, 50, 100 and 150 ms");
    k.poll(200_000, &mut p);
    assert_eq!(sent(&mut p), [(0, PAGE1.to_vec())]);
    assert_eq!(k.phase(), KingPhase::Polling { attempt: 1 });
    assert_eq!(k.membership(), Membership::Pending);
    p.rx.push_back(reply(2, EAN2));
    p.rx.push_back(reply(1, EAN1));
    k.poll(250_000, &mut p);
    assert!(p.tx.is_empty());
    k.poll(300_000, &mut p);
    assert_eq!(sent(&mut p), [(0, RUN.to_vec())]);
    assert_eq!(k.phase(), KingPhase::Running);
    assert_eq!(k.membership(), Membership::Agreed);
    assert_eq!(k.city(1).unwrap().status(), CityStatus::Agreed);
    assert_eq!(k.city(2).unwrap().reported_ean, Some(EAN2));
}

#[test]
fn missing_city_is_polled_again_then_halts() {
    let mut k = king2();
    let mut p = FakePost::default();
    let mut page1s = 0;
    for t in (0..=600_000).step_by(1_000) {
        if t == 210_000 {
            p.rx.push_back(reply(1, EAN1));
        }
        k.poll(t, &mut p);
        page1s += sent(&mut p).iter().filter(|(_, d)| d[..] == PAGE1).count();
    }
    assert_eq!(page1s, 3);
    assert_eq!(k.phase(), KingPhase::Halted);
    assert_eq!(
        k.membership(),
        Membership::Disagreed {
            missing: 1,
            mismatched: 0,
            unknown: 0
        }
    );
    assert_eq!(k.city(2).unwrap().status(), CityStatus::Missing);
    // A late reply still updates the report.
    p.rx.push_back(reply(2, EAN2));
    k.poll(700_000, &mut p);
    assert_eq!(k.membership(), Membership::Agreed);
    assert_eq!(
        k.phase(),
        KingPhase::Halted,
        "the decision is not revisited"
    );
}

#[test]
fn mismatch_and_unknown_and_serials() {
    let mut k = king2();
    let mut p = FakePost::default();
    k.poll(0, &mut p);
    k.poll(200_000, &mut p);
    p.rx.push_back(reply(1, EAN1));
    p.rx.push_back(reply(2, 0x99));
    p.rx.push_back(reply(9, 0x77));
    // Serial (Mayor's Page 1) of city 9 and city 1.
    p.rx.push_back(std_frame(0x409, &[0, 1, 5, 0, 0, 0, 0, 0]));
    p.rx.push_back(std_frame(0x401, &[0, 1, 6, 0, 0, 0, 0, 0]));
    k.poll(300_000, &mut p);
    assert_eq!(k.phase(), KingPhase::Halted);
    assert_eq!(
        k.membership(),
        Membership::Disagreed {
            missing: 0,
            mismatched: 1,
            unknown: 1
        }
    );
    assert_eq!(k.city(2).unwrap().status(), CityStatus::Mismatch);
    assert_eq!(k.city(1).unwrap().serial, Some(6));
    let u: Vec<_> = k.unknown_cities().copied().collect();
    assert_eq!(
        u,
        [UnknownCity {
            address: 9,
            ean: Some(0x77),
            serial: Some(5)
        }]
    );
    assert_eq!(k.unknown_count(), 1);
    // Halted: no Run; pages the application queues still go out.
    assert!(!sent(&mut p).iter().any(|(_, d)| d[..] == RUN));
    let run = KingPage::Page0(crate::king_pages::RuntimeControl {
        action: Some(crate::king_pages::Action::Run),
        comm: Some(CommMode::Communicate),
        city_mode: 0,
    });
    k.send_page(0, run).unwrap();
    k.poll(310_000, &mut p);
    assert_eq!(sent(&mut p), [(0, RUN.to_vec())]);
}

#[test]
fn queued_pages_go_before_run() {
    let mut k = king2();
    let mut p = FakePost::default();
    let m = MinInterval {
        envelope: EnvelopeSpec::plain(Envelope::standard(0x7FF).unwrap()),
        segments: 12,
        revolutions: 3,
    };
    k.send_page(2, KingPage::Page10(m)).unwrap();
    assert_eq!(k.queued(), 1);
    k.poll(0, &mut p);
    k.poll(200_000, &mut p);
    p.rx.push_back(reply(1, EAN1));
    p.rx.push_back(reply(2, EAN2));
    p.tx.clear();
    k.poll(300_000, &mut p);
    assert_eq!(
        sent(&mut p),
        [
            (0, vec![2, 0x0A, 0xFF, 0x07, 0, 0, 12, 3]),
            (0, RUN.to_vec())
        ]
    );
    assert_eq!(k.queued(), 0);
}

#[test]
fn send_page_errors() {
    let mut k: King<2, 1> = King::new(*king2().config()).unwrap();
    let bad = KingPage::Page1(crate::king_pages::Initiation {
        response: Some(0xFF),
        base: crate::king_pages::BaseNumber::Keep,
    });
    assert_eq!(
        k.send_page(1, bad),
        Err(SendError::Encode(EncodeError::ResponsePageNotExpressible))
    );
    let ok = KingPage::Page5(crate::king_pages::ActionReaction {
        action_folder: 1,
        action_form: 2,
        reaction_folder: 3,
        reaction_form: 4,
    });
    assert_eq!(k.send_page(1, ok), Ok(()));
    assert_eq!(k.send_page(1, ok), Err(SendError::QueueFull));
}

#[test]
fn king_rejects_malformed_mayor_letters() {
    let mut k = king2();
    let mut p = FakePost::default();
    k.poll(0, &mut p);
    let remote = TestFrame::new_remote(StandardId::new(0x401).unwrap(), 8).unwrap();
    p.rx.extend([
        std_frame(0x401, &[0, 0, 1, 2, 3, 4, 5]),    // 7 lines
        remote,                                      // remote frame
        std_frame(0x401, &[1, 0, 1, 2, 3, 4, 5, 0]), // Line 0 reserved
        std_frame(0x401, &[0, 0, 1, 2, 3, 4, 5, 1]), // Line 7 reserved
        std_frame(0x401, &[0, 2, 1, 2, 3, 4, 5, 0]), // no Mayor's Page 2
    ]);
    // Not Mayor's Letters: base itself, base + 256, other format.
    let others = [
        std_frame(0x400, &[0; 8]),
        std_frame(0x500, &[0; 8]),
        ext_frame(0x401, &[0; 8]),
    ];
    p.rx.extend(others.iter().cloned());
    let mut seen = Vec::new();
    k.poll_with(1_000, &mut p, |f| seen.push(f.clone()));
    assert_eq!(seen, others);
    assert_eq!(k.rejected(Reject::WrongLength), 1);
    assert_eq!(k.rejected(Reject::RemoteFrame), 1);
    assert_eq!(k.rejected(Reject::ReservedBitsSet), 2);
    assert_eq!(k.rejected(Reject::UnknownPage), 1);
    assert_eq!(k.rejects().total(), 5);
    assert_eq!(k.city(1).unwrap().reported_ean, None);
}

#[test]
fn king_config_errors() {
    let c = |address, base| KingConfig::new([ExpectedCity { address, ean: 1 }], base);
    let std = |n| Envelope::standard(n).unwrap();
    assert_eq!(
        King::<1>::new(c(0, std(0x400))).err(),
        Some(KingConfigError::AddressZero)
    );
    assert_eq!(
        King::<1>::new(c(1, std(0))).err(),
        Some(KingConfigError::BaseNotExpressible)
    );
    let top = Envelope::extended(0x1FFF_FFFF).unwrap();
    assert_eq!(
        King::<1>::new(c(1, top)).err(),
        Some(KingConfigError::BaseNotExpressible)
    );
    assert_eq!(
        King::<1>::new(c(1, std(0x7FF))).err(),
        Some(KingConfigError::BaseOutOfRange)
    );
    assert!(King::<1>::new(c(255, std(0x700))).is_ok());
}
