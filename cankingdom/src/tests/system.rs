//! A King and three Mayors on an in-memory broadcast bus.

use super::mayor::PRESUMED;
use super::Bus;
use crate::king::*;
use crate::king_pages::*;
use crate::letter::{Envelope, EnvelopeSpec};
use crate::mayor::{JoinPath, Mayor, MayorConfig, Startup};
use crate::postmaster::{BitRate, CommMode};
use embedded_can::Frame;

const BASE: u32 = 0x400;
const EANS: [u64; 3] = [731_234_567_890, 731_234_567_891, 400_638_133_393];

fn expected() -> [ExpectedCity; 3] {
    [1, 2, 3].map(|a| ExpectedCity {
        address: a,
        ean: EANS[usize::from(a) - 1],
    })
}

fn mayor(address: u8, ean: u64) -> Mayor {
    let mut c = MayorConfig::new(address, ean, 1000 + u64::from(address));
    c.presumed_bit_rate = BitRate::Kbit125;
    Mayor::new(c).unwrap()
}

/// Node 0 is the King, node i the Mayor `mayors[i - 1]`; mayor i starts at
/// `starts[i - 1]` µs. Runs 1 ms steps up to `until_us`.
fn run(king: &mut King<3>, mayors: &mut [Mayor], starts: &[u64], until_us: u64) -> Bus {
    let mut bus = Bus::new(1 + mayors.len());
    for t in (0..=until_us).step_by(1_000) {
        king.poll(t, &mut bus.posts[0]);
        bus.deliver(0);
        for (i, m) in mayors.iter_mut().enumerate() {
            if t >= starts[i] {
                m.poll(t, &mut bus.posts[i + 1]);
                bus.deliver(i + 1);
            }
        }
    }
    bus
}

fn new_king() -> King<3> {
    King::new(KingConfig::new(
        expected(),
        Envelope::standard(BASE).unwrap(),
    ))
    .unwrap()
}

#[test]
fn three_cities_agree_and_run() {
    let mut k = new_king();
    // Pages for city 2, queued before start-up: they go out before Run.
    let env = EnvelopeSpec::plain(Envelope::standard(0x222).unwrap());
    let assign = AssignAction::Assign {
        folder: 7,
        enable: true,
    };
    k.send_page(
        2,
        KingPage::Page2(EnvelopeAssignment {
            envelope: env,
            action: assign,
        }),
    )
    .unwrap();
    let link = ActionReaction {
        action_folder: 7,
        action_form: 1,
        reaction_folder: 8,
        reaction_form: 2,
    };
    k.send_page(2, KingPage::Page5(link)).unwrap();
    let interval = MinInterval {
        envelope: env,
        segments: 4,
        revolutions: 1,
    };
    k.send_page(2, KingPage::Page10(interval)).unwrap();
    let mut ms = [mayor(1, EANS[0]), mayor(2, EANS[1]), mayor(3, EANS[2])];
    let bus = run(&mut k, &mut ms, &[0, 0, 0], 1_000_000);

    assert_eq!(bus.violations(), 0, "nobody transmitted while Silent");
    assert_eq!(k.phase(), KingPhase::Running);
    assert_eq!(k.membership(), Membership::Agreed);
    for (i, r) in k.cities().iter().enumerate() {
        assert_eq!((r.address, r.reported_ean), (i as u8 + 1, Some(EANS[i])));
    }
    for (i, m) in ms.iter().enumerate() {
        assert_eq!(m.startup(), Startup::Joined(JoinPath::DefaultLetter));
        assert_eq!(m.comm_mode(), CommMode::Communicate);
        assert_eq!(bus.posts[i + 1].mode(), Some(CommMode::Communicate));
        assert_eq!(m.action(), Some(Action::Run));
        assert_eq!(m.own_envelope(), Envelope::standard(BASE + i as u32 + 1));
        assert_eq!(m.rejects().total(), 0);
    }
    // Only city 2 got the pages addressed to it.
    let a = ms[1].folders().get(env.envelope).unwrap();
    assert_eq!((a.folder, a.enabled), (7, true));
    assert_eq!(ms[1].links().reactions_to(7, 1).count(), 1);
    assert_eq!(ms[1].intervals().get(env.envelope), Some(&interval));
    assert!(ms[0].folders().is_empty() && ms[2].links().is_empty());
    // One Page 1 sufficed; each Mayor answered once.
    let page1s = bus
        .log
        .iter()
        .filter(|(n, f)| *n == 0 && f.data()[1] == 1)
        .count();
    assert_eq!(page1s, 1);
    for i in 1..=3 {
        assert_eq!(bus.log.iter().filter(|(n, _)| *n == i).count(), 1);
    }
}

#[test]
fn wrong_ean_is_reported_and_nobody_runs() {
    let mut k = new_king();
    let mut ms = [mayor(1, EANS[0]), mayor(2, 0x0BAD), mayor(3, EANS[2])];
    let bus = run(&mut k, &mut ms, &[0, 0, 0], 1_000_000);
    assert_eq!(bus.violations(), 0);
    assert_eq!(k.phase(), KingPhase::Halted);
    assert_eq!(
        k.membership(),
        Membership::Disagreed {
            missing: 0,
            mismatched: 1,
            unknown: 0
        }
    );
    let r = k.city(2).unwrap();
    assert_eq!(
        (r.status(), r.expected_ean, r.reported_ean),
        (CityStatus::Mismatch, EANS[1], Some(0x0BAD))
    );
    assert_eq!(k.city(1).unwrap().status(), CityStatus::Agreed);
    for m in &ms {
        assert_eq!(m.action(), None);
        assert_eq!(m.comm_mode(), CommMode::ListenOnly);
    }
}

#[test]
fn unexpected_city_is_reported() {
    let mut k = new_king();
    let mut ms = [
        mayor(1, EANS[0]),
        mayor(2, EANS[1]),
        mayor(3, EANS[2]),
        mayor(9, 42),
    ];
    let bus = run(&mut k, &mut ms, &[0, 0, 0, 0], 1_000_000);
    assert_eq!(bus.violations(), 0);
    assert_eq!(
        k.membership(),
        Membership::Disagreed {
            missing: 0,
            mismatched: 0,
            unknown: 1
        }
    );
    let u: Vec<_> = k.unknown_cities().map(|u| (u.address, u.ean)).collect();
    assert_eq!(u, [(9, Some(42))]);
}

#[test]
fn late_city_joins_through_2b_and_3b() {
    // City 3 starts after the last Default Letter (150 ms): it misses them,
    // ignores the King's Letters during its own 200 ms window, loads the
    // presumed bit rate (125 kbit/s here) at 360 ms, and the King's third
    // Page 1 (at 500 ms with a 150 ms reply timeout) brings it in via 3b.
    let mut cfg = KingConfig::new(expected(), Envelope::standard(BASE).unwrap());
    cfg.reply_timeout_us = 150_000;
    let mut k: King<3> = King::new(cfg).unwrap();
    let mut ms = [mayor(1, EANS[0]), mayor(2, EANS[1]), mayor(3, EANS[2])];
    let bus = run(&mut k, &mut ms, &[0, 0, 160_000], 1_000_000);
    assert_eq!(bus.violations(), 0);
    assert_eq!(ms[2].startup(), Startup::Joined(JoinPath::Listening));
    assert_eq!(k.membership(), Membership::Agreed);
    assert_eq!(k.phase(), KingPhase::Running);
    assert!(ms.iter().all(|m| m.action() == Some(Action::Run)));
}

#[test]
fn city_on_wrong_presumed_rate_stays_out() {
    // City 3 starts late and presumes another bit rate: it never hears the
    // King, never transmits, and the King reports it missing.
    let mut k = new_king();
    let mut ms = [mayor(1, EANS[0]), mayor(2, EANS[1]), mayor(3, EANS[2])];
    let mut c = *ms[2].config();
    c.presumed_bit_rate = PRESUMED;
    ms[2] = Mayor::new(c).unwrap();
    let bus = run(&mut k, &mut ms, &[0, 0, 160_000], 1_000_000);
    assert_eq!(bus.violations(), 0);
    assert_eq!(ms[2].startup(), Startup::AwaitingLetter);
    assert_eq!(bus.posts[3].rate(), Some(PRESUMED));
    assert_eq!(k.city(3).unwrap().status(), CityStatus::Missing);
    assert_eq!(k.phase(), KingPhase::Halted);
}
