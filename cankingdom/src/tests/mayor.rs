//! The Mayor's start-up paths 2a/2b/3a/3b and the King's pages it applies.

use super::{ext_frame, std_frame, std_id, FakePost, TestFrame};
use crate::king_pages::Action;
use crate::letter::{Envelope, Reject};
use crate::mayor::{JoinPath, Mayor, MayorConfig, MayorConfigError, Startup};
use crate::postmaster::{BitRate, BitTiming, CommMode};
use embedded_can::Frame;

pub const EAN: u64 = 0x12_3456_789A;
pub const PRESUMED: BitRate = BitRate::Custom(BitTiming {
    prescaler: 4,
    tseg1: 13,
    tseg2: 2,
    sjw: 1,
});

pub fn cfg(address: u8) -> MayorConfig {
    let mut c = MayorConfig::new(address, EAN, 0xFF_0000_0001);
    c.presumed_bit_rate = PRESUMED;
    c
}

/// A King's Letter frame (envelope 0) with the given lines.
pub fn king(lines: [u8; 8]) -> TestFrame {
    std_frame(0, &lines)
}

pub fn default_letter() -> TestFrame {
    std_frame(2031, &[0xAA; 8])
}

/// A Mayor for city 3 that took path 2a (Listen Only, no base number).
pub fn joined() -> (Mayor, FakePost) {
    let mut m: Mayor = Mayor::new(cfg(3)).unwrap();
    let mut p = FakePost::default();
    m.poll(0, &mut p);
    p.rx.push_back(default_letter());
    m.poll(1_000, &mut p);
    assert_eq!(m.startup(), Startup::Joined(JoinPath::DefaultLetter));
    (m, p)
}

/// Deliver one frame and poll.
pub fn feed(m: &mut Mayor, p: &mut FakePost, f: TestFrame) {
    p.rx.push_back(f);
    m.poll(2_000, p);
}

#[test]
fn path_2a_default_letter() {
    let mut m: Mayor = Mayor::new(cfg(3)).unwrap();
    let mut p = FakePost::default();
    assert_eq!(m.startup(), Startup::NotStarted);
    m.poll(0, &mut p);
    assert_eq!(p.rates, [BitRate::Kbit125]);
    assert_eq!(p.modes, [CommMode::Silent]);
    assert_eq!(m.startup(), Startup::AwaitingDefaultLetter);
    // A near-miss (one line differs) and a King's Letter do not count.
    let mut near = [0xAA; 8];
    near[3] = 0xAB;
    p.rx.push_back(std_frame(2031, &near));
    p.rx.push_back(king([0, 0, 1, 3, 0, 0, 0, 0]));
    m.poll(100_000, &mut p);
    assert_eq!(m.startup(), Startup::AwaitingDefaultLetter);
    assert_eq!(m.letters_accepted(), 0);
    // The Default Letter just inside the window: keep 125 kbit/s, Listen Only.
    p.rx.push_back(default_letter());
    m.poll(199_999, &mut p);
    assert_eq!(m.startup(), Startup::Joined(JoinPath::DefaultLetter));
    assert_eq!(p.modes, [CommMode::Silent, CommMode::ListenOnly]);
    assert_eq!(p.rates, [BitRate::Kbit125]);
    assert!(p.tx.is_empty(), "no announcement in Listen Only");
    m.poll(500_000, &mut p);
    assert_eq!(p.rates, [BitRate::Kbit125], "window is over, timing kept");
    // The King's Page 1: base 0x400, respond with Mayor's Page 0.
    feed(&mut m, &mut p, king([3, 1, 0, 0, 0x00, 0x04, 0, 0]));
    assert_eq!(m.base_number(), Envelope::standard(0x400));
    assert_eq!(p.tx.len(), 1);
    assert_eq!(std_id(&p.tx[0]), 0x403);
    assert_eq!(p.tx[0].data(), [0, 0, 0x9A, 0x78, 0x56, 0x34, 0x12, 0]);
    assert_eq!(p.silent_violations, 0);
}

#[test]
fn path_2b_then_3a_known_base() {
    let mut c = cfg(5);
    c.base_number = Envelope::standard(0x100);
    let mut m: Mayor = Mayor::new(c).unwrap();
    let mut p = FakePost::default();
    m.poll(0, &mut p);
    m.poll(199_999, &mut p);
    assert_eq!(m.startup(), Startup::AwaitingDefaultLetter);
    m.poll(200_000, &mut p);
    assert_eq!(m.startup(), Startup::AwaitingLetter);
    assert_eq!(p.rates, [BitRate::Kbit125, PRESUMED]);
    assert_eq!(p.modes, [CommMode::Silent], "still Silent");
    assert!(p.tx.is_empty());
    // Any correctly received letter (here an application letter).
    p.rx.push_back(std_frame(0x55, &[1, 2]));
    let mut others = Vec::new();
    m.poll_with(250_000, &mut p, |f| others.push(f.clone()));
    assert_eq!(others, [std_frame(0x55, &[1, 2])]);
    assert_eq!(m.startup(), Startup::Joined(JoinPath::Announced));
    assert_eq!(p.modes, [CommMode::Silent, CommMode::Communicate]);
    assert_eq!(p.tx.len(), 1);
    assert_eq!(std_id(&p.tx[0]), 0x105);
    assert_eq!(p.tx[0].data(), [0, 0, 0x9A, 0x78, 0x56, 0x34, 0x12, 0]);
}

#[test]
fn path_2b_then_3b_unknown_base() {
    let mut m: Mayor = Mayor::new(cfg(5)).unwrap();
    let mut p = FakePost::default();
    m.poll(0, &mut p);
    m.poll(300_000, &mut p);
    assert_eq!(m.startup(), Startup::AwaitingLetter);
    // A remote frame is a correctly received letter too.
    p.rx.push_back(TestFrame::new_remote(embedded_can::StandardId::new(9).unwrap(), 0).unwrap());
    m.poll(310_000, &mut p);
    assert_eq!(m.startup(), Startup::Joined(JoinPath::Listening));
    assert_eq!(p.modes, [CommMode::Silent, CommMode::ListenOnly]);
    assert!(p.tx.is_empty());
    // The King polls: extended base 0x1000_0000, respond with page 1.
    feed(&mut m, &mut p, king([0, 1, 1, 0, 0, 0, 0, 0x90]));
    assert_eq!(p.tx, [ext_frame(0x1000_0005, &[0, 1, 1, 0, 0, 0, 0xFF, 0])]);
}

#[test]
fn path_3b_letter_is_also_a_kings_letter() {
    // After 2b, the first letter is the King's Page 1 itself: 3b, then apply.
    let mut m: Mayor = Mayor::new(cfg(2)).unwrap();
    let mut p = FakePost::default();
    m.poll(0, &mut p);
    m.poll(200_000, &mut p);
    feed(&mut m, &mut p, king([0, 1, 0, 0, 0x00, 0x04, 0, 0]));
    assert_eq!(m.startup(), Startup::Joined(JoinPath::Listening));
    assert_eq!(p.tx.len(), 1);
    assert_eq!(std_id(&p.tx[0]), 0x402);
}

#[test]
fn page0_modes() {
    let (mut m, mut p) = joined();
    feed(&mut m, &mut p, king([3, 0, 0x01, 0x03, 7, 0, 0, 0]));
    assert_eq!(m.action(), Some(Action::Run));
    assert_eq!(m.comm_mode(), CommMode::Communicate);
    assert_eq!(p.mode(), Some(CommMode::Communicate));
    assert_eq!(m.city_mode(), 7);
    // Keep everything: nothing changes, no mode command.
    let n = p.modes.len();
    feed(&mut m, &mut p, king([0, 0, 0, 0, 0, 0, 0, 0]));
    assert_eq!(
        (m.action(), m.comm_mode(), m.city_mode()),
        (Some(Action::Run), CommMode::Communicate, 7)
    );
    assert_eq!(p.modes.len(), n);
    // Freeze + Silent: a Page 1 response is then dropped and counted.
    feed(&mut m, &mut p, king([3, 0, 0x02, 0x01, 0, 0, 0, 0]));
    assert_eq!(
        (m.action(), m.comm_mode()),
        (Some(Action::Freeze), CommMode::Silent)
    );
    feed(&mut m, &mut p, king([3, 1, 0, 0, 0x00, 0x04, 0, 0]));
    assert!(p.tx.is_empty());
    assert_eq!(m.unsent(), 1);
    assert_eq!(m.base_number(), Envelope::standard(0x400), "still applied");
    // Reset + Listen Only.
    feed(&mut m, &mut p, king([3, 0, 0x03, 0x02, 0, 0, 0, 0]));
    assert_eq!(
        (m.action(), m.comm_mode()),
        (Some(Action::Reset), CommMode::ListenOnly)
    );
    assert_eq!(m.letters_accepted(), 5);
}

#[test]
fn addressing() {
    let mut c = cfg(3);
    c.groups[1] = 0x80;
    let mut m: Mayor = Mayor::new(c).unwrap();
    let mut p = FakePost::default();
    m.poll(0, &mut p);
    feed(&mut m, &mut p, default_letter());
    // Other city: ignored, even when it would be malformed for us.
    feed(&mut m, &mut p, king([4, 0, 0x01, 0, 0, 0, 0, 0]));
    feed(&mut m, &mut p, king([4, 11, 0, 0, 0, 0, 0, 0]));
    assert_eq!(m.action(), None);
    assert_eq!(m.rejects().total(), 0);
    // Group 0x80, then broadcast.
    feed(&mut m, &mut p, king([0x80, 0, 0x02, 0, 0, 0, 0, 0]));
    assert_eq!(m.action(), Some(Action::Freeze));
    feed(&mut m, &mut p, king([0, 0, 0x01, 0, 0, 0, 0, 0]));
    assert_eq!(m.action(), Some(Action::Run));
    // Same bytes in another envelope: an application letter.
    feed(&mut m, &mut p, std_frame(1, &[3, 0, 0x03, 0, 0, 0, 0, 0]));
    assert_eq!(m.action(), Some(Action::Run));
    assert_eq!(m.letters_accepted(), 2);
}

#[test]
fn page2_folder_table() {
    let (mut m, mut p) = joined();
    let e1 = Envelope::standard(0x123).unwrap();
    let e2 = Envelope::standard(0x124).unwrap();
    // Assign 0x123 and 0x124 to folder 9 (kept in parallel).
    feed(&mut m, &mut p, king([3, 2, 0x23, 0x01, 0, 0, 9, 0x03]));
    feed(&mut m, &mut p, king([3, 2, 0x24, 0x01, 0, 0, 9, 0x02]));
    assert_eq!(m.folders().in_folder(9).count(), 2);
    assert!(m.folders().get(e1).unwrap().enabled);
    assert!(!m.folders().get(e2).unwrap().enabled);
    // Keep + enable 0x124.
    feed(&mut m, &mut p, king([3, 2, 0x24, 0x01, 0, 0, 0, 0x01]));
    assert!(m.folders().get(e2).unwrap().enabled);
    // Transfer 0x123 to folder 4, compressed, disabled.
    feed(&mut m, &mut p, king([3, 2, 0x23, 0x01, 0, 0x40, 4, 0x06]));
    let a = m.folders().get(e1).unwrap();
    assert_eq!((a.folder, a.enabled, a.compressed), (4, false, true));
    assert_eq!(m.folders().in_folder(9).count(), 1);
    // Re-assign to the same folder updates D.
    feed(&mut m, &mut p, king([3, 2, 0x23, 0x01, 0, 0, 4, 0x03]));
    assert!(m.folders().get(e1).unwrap().enabled);
    // Expel; expelling again is a no-op.
    feed(&mut m, &mut p, king([3, 2, 0x23, 0x01, 0, 0, 0, 0x04]));
    feed(&mut m, &mut p, king([3, 2, 0x23, 0x01, 0, 0, 0, 0x04]));
    assert_eq!(m.folders().get(e1), None);
    assert_eq!(m.folders().len(), 1);
    assert_eq!(m.letters_accepted(), 7);
}

#[test]
fn page5_and_page10_tables() {
    let (mut m, mut p) = joined();
    feed(&mut m, &mut p, king([3, 5, 0x11, 0x22, 0, 0x33, 0x44, 0]));
    feed(&mut m, &mut p, king([3, 5, 0x11, 0x22, 0, 0x33, 0x44, 0]));
    feed(&mut m, &mut p, king([3, 5, 0x11, 0x22, 0, 0x35, 0x45, 0]));
    assert_eq!(m.links().len(), 2);
    let r: Vec<_> = m
        .links()
        .reactions_to(0x11, 0x22)
        .map(|l| l.reaction_folder)
        .collect();
    assert_eq!(r, [0x33, 0x35]);
    let first = *m.links().iter().next().unwrap();
    assert!(m.links_mut().remove(&first));
    assert_eq!(m.links().len(), 1);
    // Page 10 for std 0x7FF, replaced by a second one.
    let e = Envelope::standard(0x7FF).unwrap();
    feed(&mut m, &mut p, king([3, 10, 0xFF, 0x07, 0, 0, 12, 3]));
    assert_eq!(
        m.intervals().get(e).map(|i| (i.segments, i.revolutions)),
        Some((12, 3))
    );
    feed(&mut m, &mut p, king([3, 10, 0xFF, 0x07, 0, 0, 1, 2]));
    assert_eq!(
        m.intervals().get(e).map(|i| (i.segments, i.revolutions)),
        Some((1, 2))
    );
    assert_eq!(m.intervals().len(), 1);
}

#[test]
fn busy_controller_retries() {
    let (mut m, mut p) = joined();
    p.busy = true;
    feed(&mut m, &mut p, king([3, 1, 0, 0, 0x00, 0x04, 0, 0]));
    assert!(p.tx.is_empty());
    assert_eq!(m.pending(), 1);
    p.busy = false;
    m.poll(3_000, &mut p);
    assert_eq!(p.tx.len(), 1);
    assert_eq!(m.pending(), 0);
}

#[test]
fn restart_and_config() {
    let (mut m, mut p) = joined();
    feed(&mut m, &mut p, king([3, 1, 0xFF, 0, 0x00, 0x04, 0, 0]));
    feed(&mut m, &mut p, king([3, 9, 0, 0, 0, 0, 0, 0]));
    m.restart();
    assert_eq!(m.startup(), Startup::NotStarted);
    assert_eq!(m.base_number(), None);
    assert_eq!(m.rejected(Reject::UnknownPage), 1, "counters kept");
    m.poll(10_000_000, &mut p);
    assert_eq!(m.startup(), Startup::AwaitingDefaultLetter);
    assert_eq!(p.mode(), Some(CommMode::Silent));

    assert_eq!(
        Mayor::<1, 1, 1>::new(cfg(0)).err(),
        Some(MayorConfigError::AddressZero)
    );
    let mut c = cfg(1);
    c.ean = 1 << 40;
    assert_eq!(
        Mayor::<1, 1, 1>::new(c).err(),
        Some(MayorConfigError::ValueTooLarge)
    );
    let mut c = cfg(1);
    c.base_number = Envelope::standard(0x7FF);
    assert_eq!(
        Mayor::<1, 1, 1>::new(c).err(),
        Some(MayorConfigError::BaseOutOfRange)
    );
}
