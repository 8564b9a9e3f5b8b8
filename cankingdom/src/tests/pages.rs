//! Pages: expected bytes written by hand from the seed's form layouts,
//! round trips, and every decode-level rejection.

use super::{ext_frame, std_frame, TestFrame};
use crate::king_pages::*;
use crate::letter::*;
use crate::mayor_pages::MayorPage;
use crate::postmaster::CommMode;
use embedded_can::{Frame, StandardId};

fn std(n: u32) -> Envelope {
    Envelope::standard(n).unwrap()
}
fn ext(n: u32) -> Envelope {
    Envelope::extended(n).unwrap()
}
fn enc(address: u8, page: KingPage) -> [u8; 8] {
    KingLetter { address, page }.encode().unwrap()
}
fn dec(bytes: &[u8]) -> Result<KingLetter, Reject> {
    KingLetter::decode(bytes)
}

/// Encode, compare with the hand-written bytes, decode back.
fn check(address: u8, page: KingPage, wire: [u8; 8]) {
    assert_eq!(enc(address, page), wire, "{page:?}");
    assert_eq!(dec(&wire), Ok(KingLetter { address, page }));
}

#[test]
fn default_letter() {
    // Envelope 2031 = 0x7EF standard, all eight lines AA hex.
    assert_eq!(Letter::DEFAULT.envelope, std(0x7EF));
    assert_eq!(Letter::DEFAULT.page, [0xAA; 8]);
    let f: TestFrame = Letter::DEFAULT.to_frame().unwrap();
    assert_eq!(f.id(), StandardId::new(0x7EF).unwrap().into());
    assert!(Letter::from_frame(&f).unwrap().is_default_letter());
    // Same id, one line differs; same data in an extended envelope.
    let mut p = [0xAA; 8];
    p[7] = 0xAB;
    assert!(!Letter::from_frame(&std_frame(2031, &p))
        .unwrap()
        .is_default_letter());
    assert!(!Letter::from_frame(&ext_frame(2031, &[0xAA; 8]))
        .unwrap()
        .is_default_letter());
}

#[test]
fn king_page1_bytes() {
    // Line 0 city 3, Line 1 page 1, Line 2 respond with page 0, Line 3 r,
    // Lines 4..7 base 0x400 LSB first, Line 7 E=0 rr=00.
    let p = KingPage::Page1(Initiation {
        response: Some(0),
        base: BaseNumber::Set(std(0x400)),
    });
    check(3, p, [0x03, 0x01, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00]);
    // Broadcast, no response (11111111), extended base 0x12345678:
    // Line 7 = E(1) rr(00) xxxxx(0x12) = 1001_0010.
    let p = KingPage::Page1(Initiation {
        response: None,
        base: BaseNumber::Set(ext(0x1234_5678)),
    });
    check(0, p, [0x00, 0x01, 0xFF, 0x00, 0x78, 0x56, 0x34, 0x92]);
    // Keep current base (all x = 0), respond with page 1.
    let p = KingPage::Page1(Initiation {
        response: Some(1),
        base: BaseNumber::Keep,
    });
    check(7, p, [0x07, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00]);
    // Base undefined (all 29 x = 1).
    let p = KingPage::Page1(Initiation {
        response: None,
        base: BaseNumber::Undefined,
    });
    check(0, p, [0x00, 0x01, 0xFF, 0x00, 0xFF, 0xFF, 0xFF, 0x1F]);
    // E is ignored for keep / undefined.
    assert_eq!(
        dec(&[0, 1, 0xFF, 0, 0, 0, 0, 0x80]).unwrap().page,
        KingPage::Page1(Initiation {
            response: None,
            base: BaseNumber::Keep
        })
    );
}

#[test]
fn king_page1_unencodable() {
    for base in [std(0), ext(MAX_EXTENDED)] {
        let l = KingLetter {
            address: 1,
            page: KingPage::Page1(Initiation {
                response: None,
                base: BaseNumber::Set(base),
            }),
        };
        assert_eq!(l.encode(), Err(EncodeError::BaseNumberNotExpressible));
    }
    let l = KingLetter {
        address: 1,
        page: KingPage::Page1(Initiation {
            response: Some(0xFF),
            base: BaseNumber::Keep,
        }),
    };
    assert_eq!(l.encode(), Err(EncodeError::ResponsePageNotExpressible));
}

#[test]
fn king_page0_bytes() {
    let rc = |action, comm, city_mode| {
        KingPage::Page0(RuntimeControl {
            action,
            comm,
            city_mode,
        })
    };
    // Run (AA=01), Communicate (CC=11), keep City Mode, to all.
    check(
        0,
        rc(Some(Action::Run), Some(CommMode::Communicate), 0),
        [0, 0, 0x01, 0x03, 0, 0, 0, 0],
    );
    // Freeze (10), Silent (01), City Mode 5, to group 0x80.
    check(
        0x80,
        rc(Some(Action::Freeze), Some(CommMode::Silent), 5),
        [0x80, 0, 0x02, 0x01, 5, 0, 0, 0],
    );
    // Reset (11), Listen Only (10).
    check(
        4,
        rc(Some(Action::Reset), Some(CommMode::ListenOnly), 0),
        [4, 0, 0x03, 0x02, 0, 0, 0, 0],
    );
    // Keep everything.
    check(4, rc(None, None, 0), [4, 0, 0, 0, 0, 0, 0, 0]);
}

#[test]
fn king_page2_bytes() {
    let p2 = |envelope, action| KingPage::Page2(EnvelopeAssignment { envelope, action });
    // Assign std 0x123 to folder 9, enabled: Line 7 rrrrrAAD = 00000_01_1.
    let e = EnvelopeSpec::plain(std(0x123));
    check(
        3,
        p2(
            e,
            AssignAction::Assign {
                folder: 9,
                enable: true,
            },
        ),
        [3, 2, 0x23, 0x01, 0, 0, 9, 0x03],
    );
    check(
        3,
        p2(
            e,
            AssignAction::Assign {
                folder: 9,
                enable: false,
            },
        ),
        [3, 2, 0x23, 0x01, 0, 0, 9, 0x02],
    );
    // Transfer ext compressed 0x1ABCDEF0 to folder 4, disabled:
    // Line 5 = E(1) C(1) r(0) 11010 = 0xDA, Line 7 = 110.
    let c = EnvelopeSpec {
        envelope: ext(0x1ABC_DEF0),
        compressed: true,
    };
    check(
        3,
        p2(
            c,
            AssignAction::Transfer {
                folder: 4,
                enable: false,
            },
        ),
        [3, 2, 0xF0, 0xDE, 0xBC, 0xDA, 4, 0x06],
    );
    check(
        3,
        p2(
            c,
            AssignAction::Transfer {
                folder: 4,
                enable: true,
            },
        ),
        [3, 2, 0xF0, 0xDE, 0xBC, 0xDA, 4, 0x07],
    );
    // Expel (AAD = 100), keep+enable (001), keep+disable (000).
    check(
        3,
        p2(e, AssignAction::Expel),
        [3, 2, 0x23, 0x01, 0, 0, 0, 0x04],
    );
    check(
        3,
        p2(e, AssignAction::Keep { enable: true }),
        [3, 2, 0x23, 0x01, 0, 0, 0, 0x01],
    );
    check(
        3,
        p2(e, AssignAction::Keep { enable: false }),
        [3, 2, 0x23, 0x01, 0, 0, 0, 0x00],
    );
    // The folder line is ignored for keep and expel.
    assert_eq!(
        dec(&[3, 2, 0x23, 0x01, 0, 0, 77, 0x04]).unwrap().page,
        p2(e, AssignAction::Expel)
    );
}

#[test]
fn king_page5_and_10_bytes() {
    let link = ActionReaction {
        action_folder: 0x11,
        action_form: 0x22,
        reaction_folder: 0x33,
        reaction_form: 0x44,
    };
    check(
        2,
        KingPage::Page5(link),
        [2, 5, 0x11, 0x22, 0, 0x33, 0x44, 0],
    );
    // Page 10: Line 1 = 0x0A (see the crate doc), std 0x7FF, 12 segments,
    // 3 revolutions.
    let m = MinInterval {
        envelope: EnvelopeSpec::plain(std(0x7FF)),
        segments: 12,
        revolutions: 3,
    };
    check(2, KingPage::Page10(m), [2, 0x0A, 0xFF, 0x07, 0, 0, 12, 3]);
    // Page 10 with an extended, compressed envelope (line 5 = 110_00001).
    let m = MinInterval {
        envelope: EnvelopeSpec {
            envelope: ext(0x0100_0000),
            compressed: true,
        },
        segments: 0xFF,
        revolutions: 0x80,
    };
    check(2, KingPage::Page10(m), [2, 0x0A, 0, 0, 0, 0xC1, 0xFF, 0x80]);
}

#[test]
fn mayor_pages_bytes() {
    // Page 0, EAN 0x12_3456_789A: LSB in Line 2 .. MSB in Line 6.
    let p = MayorPage::Identification {
        ean: 0x12_3456_789A,
    };
    let wire = [0x00, 0x00, 0x9A, 0x78, 0x56, 0x34, 0x12, 0x00];
    assert_eq!(p.encode(), Ok(wire));
    assert_eq!(MayorPage::decode(&wire), Ok(p));
    // EAN-13 7312345678903 without check digit: 731234567890 = 0xAA40FA06D2.
    let p = MayorPage::Identification {
        ean: 731_234_567_890,
    };
    let wire = [0x00, 0x00, 0xD2, 0x06, 0xFA, 0x40, 0xAA, 0x00];
    assert_eq!(p.encode(), Ok(wire));
    assert_eq!(MayorPage::decode(&wire), Ok(p));
    // Page 1, serial 0xFF_0000_0001.
    let p = MayorPage::Serial {
        serial: 0xFF_0000_0001,
    };
    let wire = [0x00, 0x01, 0x01, 0x00, 0x00, 0x00, 0xFF, 0x00];
    assert_eq!(p.encode(), Ok(wire));
    assert_eq!(MayorPage::decode(&wire), Ok(p));
    // Largest and too large.
    let max = MayorPage::Serial {
        serial: (1 << 40) - 1,
    };
    assert_eq!(max.encode(), Ok([0, 1, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0]));
    assert_eq!(
        MayorPage::Serial { serial: 1 << 40 }.encode(),
        Err(EncodeError::ValueTooLarge)
    );
}

#[test]
fn round_trips() {
    let envs = [
        EnvelopeSpec::plain(std(0)),
        EnvelopeSpec::plain(std(0x7FF)),
        EnvelopeSpec {
            envelope: ext(MAX_EXTENDED),
            compressed: true,
        },
        EnvelopeSpec::plain(ext(0x800)),
    ];
    let mut pages = Vec::new();
    for action in [
        None,
        Some(Action::Run),
        Some(Action::Freeze),
        Some(Action::Reset),
    ] {
        for comm in [
            None,
            Some(CommMode::Silent),
            Some(CommMode::ListenOnly),
            Some(CommMode::Communicate),
        ] {
            pages.push(KingPage::Page0(RuntimeControl {
                action,
                comm,
                city_mode: 0xC3,
            }));
        }
    }
    for response in [None, Some(0), Some(1), Some(0xFE)] {
        for base in [
            BaseNumber::Keep,
            BaseNumber::Undefined,
            BaseNumber::Set(std(1)),
            BaseNumber::Set(ext(0x1FFF_FFFE)),
        ] {
            pages.push(KingPage::Page1(Initiation { response, base }));
        }
    }
    for envelope in envs {
        for action in [
            AssignAction::Keep { enable: false },
            AssignAction::Keep { enable: true },
            AssignAction::Assign {
                folder: 0xFF,
                enable: true,
            },
            AssignAction::Transfer {
                folder: 1,
                enable: false,
            },
            AssignAction::Expel,
        ] {
            pages.push(KingPage::Page2(EnvelopeAssignment { envelope, action }));
        }
        pages.push(KingPage::Page10(MinInterval {
            envelope,
            segments: 1,
            revolutions: 255,
        }));
    }
    pages.push(KingPage::Page5(ActionReaction {
        action_folder: 255,
        action_form: 0,
        reaction_folder: 1,
        reaction_form: 254,
    }));
    for page in pages {
        for address in [0, 1, 255] {
            let l = KingLetter { address, page };
            assert_eq!(dec(&l.encode().unwrap()), Ok(l));
        }
    }
    for v in [0, 1, 0x12_3456_789A, (1 << 40) - 1] {
        for p in [
            MayorPage::Identification { ean: v },
            MayorPage::Serial { serial: v },
        ] {
            assert_eq!(MayorPage::decode(&p.encode().unwrap()), Ok(p));
        }
    }
}

#[test]
fn reject_wrong_length() {
    for bytes in [
        &[][..],
        &[0, 1, 0xFF, 0, 0, 4, 0][..],
        &[0, 1, 0xFF, 0, 0, 4, 0, 0, 0][..],
    ] {
        assert_eq!(dec(bytes), Err(Reject::WrongLength));
        assert_eq!(MayorPage::decode(bytes), Err(Reject::WrongLength));
    }
    assert_eq!(
        Letter::from_frame(&std_frame(5, &[1, 2, 3])),
        Err(Reject::WrongLength)
    );
}

#[test]
fn reject_remote_frame() {
    let f = TestFrame::new_remote(StandardId::new(0).unwrap(), 8).unwrap();
    assert_eq!(Letter::from_frame(&f), Err(Reject::RemoteFrame));
}

#[test]
fn reject_unknown_page() {
    for page in [3u8, 4, 6, 7, 8, 9, 11, 0xFF] {
        assert_eq!(dec(&[0, page, 0, 0, 0, 0, 0, 0]), Err(Reject::UnknownPage));
    }
    assert_eq!(
        MayorPage::decode(&[0, 2, 0, 0, 0, 0, 0, 0]),
        Err(Reject::UnknownPage)
    );
}

#[test]
fn reject_reserved_bits() {
    let bad: [[u8; 8]; 14] = [
        [0, 0, 0x04, 0, 0, 0, 0, 0],  // Page 0 Line 2 bit 2
        [0, 0, 0, 0x80, 0, 0, 0, 0],  // Page 0 Line 3 bit 7
        [0, 0, 0, 0, 0, 1, 0, 0],     // Page 0 Line 5
        [0, 0, 0, 0, 0, 0, 1, 0],     // Page 0 Line 6
        [0, 0, 0, 0, 0, 0, 0, 1],     // Page 0 Line 7
        [0, 1, 0, 1, 0, 4, 0, 0],     // Page 1 Line 3
        [0, 1, 0, 0, 0, 4, 0, 0x40],  // Page 1 Line 7 r (bit 6)
        [0, 1, 0, 0, 0, 4, 0, 0x20],  // Page 1 Line 7 r (bit 5)
        [0, 2, 0, 0, 0, 0x20, 0, 1],  // Page 2 Line 5 r
        [0, 2, 0, 0, 0, 0, 0, 0x09],  // Page 2 Line 7 rrrrr
        [0, 5, 0, 0, 1, 0, 0, 0],     // Page 5 Line 4
        [0, 5, 0, 0, 0, 0, 0, 0x80],  // Page 5 Line 7
        [0, 10, 0, 0, 0, 0x20, 0, 0], // Page 10 Line 5 r
        [0, 2, 0, 0, 0, 0x20, 0, 4],  // Page 2 Line 5 r with expel
    ];
    for b in bad {
        assert_eq!(dec(&b), Err(Reject::ReservedBitsSet), "{b:02X?}");
    }
    for b in [[1, 0, 0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0, 0, 1]] {
        assert_eq!(
            MayorPage::decode(&b),
            Err(Reject::ReservedBitsSet),
            "{b:02X?}"
        );
    }
}

#[test]
fn reject_reserved_combination() {
    // AAD = 101 is the only combination left reserved.
    assert_eq!(
        dec(&[3, 2, 0x23, 1, 0, 0, 9, 0x05]),
        Err(Reject::ReservedCombination)
    );
    for aad in [0u8, 1, 2, 3, 4, 6, 7] {
        assert!(dec(&[3, 2, 0x23, 1, 0, 0, 9, aad]).is_ok());
    }
}

#[test]
fn reject_envelope_out_of_range() {
    // Standard format (E = 0) with number 0x800.
    assert_eq!(
        dec(&[3, 2, 0x00, 0x08, 0, 0, 9, 0x03]),
        Err(Reject::EnvelopeOutOfRange)
    );
    assert_eq!(
        dec(&[3, 10, 0x00, 0x00, 0x01, 0x00, 1, 1]),
        Err(Reject::EnvelopeOutOfRange)
    );
    assert_eq!(
        dec(&[3, 1, 0, 0, 0x00, 0x08, 0, 0]),
        Err(Reject::EnvelopeOutOfRange)
    );
    // The same numbers are fine as extended.
    assert!(dec(&[3, 2, 0x00, 0x08, 0, 0x80, 9, 0x03]).is_ok());
    assert!(dec(&[3, 1, 0, 0, 0x00, 0x08, 0, 0x80]).is_ok());
}

#[test]
fn envelope_and_counters() {
    assert_eq!(Envelope::standard(0x800), None);
    assert_eq!(Envelope::extended(0x2000_0000), None);
    assert_eq!(std(0x7FE).offset(1), Some(std(0x7FF)));
    assert_eq!(std(0x7FF).offset(1), None);
    assert_eq!(ext(MAX_EXTENDED).offset(u32::MAX), None);
    assert_eq!(Envelope::from_id(ext(0x1234).id()), ext(0x1234));
    let mut c = RejectCounters::default();
    for (i, r) in Reject::ALL.iter().enumerate() {
        for _ in 0..=i {
            c.record(*r);
        }
    }
    for (i, r) in Reject::ALL.iter().enumerate() {
        assert_eq!(c.get(*r), i as u32 + 1);
    }
    assert_eq!(c.total(), 66);
}
