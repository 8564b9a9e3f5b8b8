//! ISO 16845-1 items 7.1 to 7.6: the IUT as receiver (valid frames, error
//! detection, error and overload frames, the error-passive receiver, the receive
//! error counter). One public function per ISO 16845-1 item or item group, named
//! after it; each takes an IUT factory and panics on the first deviation.
//!
//! Expected counters follow ISO 11898-1:2015 12.1.4.2: a receiver detecting an
//! error REC + 1 (rule a); dominant first bit after its error flag + 8 (rule b);
//! bit error in its active error flag or overload flag + 8 (rule e); 8th
//! consecutive dominant bit after a flag (14th after an active error flag or an
//! overload flag) and every further 8th + 8 (rule f); successful reception (ACK
//! sent and read back) - 1, from above 127 to a value in 119..=127 (rule h).
//!
//! One file per ISO 16845-1 group: `frames` (7.1), `error_detection` (7.2),
//! `error_frames` (7.3), `overload` (7.4), `passive` (7.5), `rec` (7.6); the
//! set-ups several groups share are here.

use drcc_cosim::Frame;

use super::bits::{stuff_site_set, stuffing_frames, Field, FrameBits, Options};
use super::lower_tester::{field, state, Iut, LowerTester, Lt, Run, Script};
use super::procedures::{base, ext, rec_to, remote, rx_error, rx_stuff_error, Expected};
use super::{timing, timing_brp, timing_slow};

mod error_detection;
mod error_frames;
mod frames;
mod overload;
mod passive;
mod rec;
pub use error_detection::*;
pub use error_frames::*;
pub use frames::*;
pub use overload::*;
pub use passive::*;
pub use rec::*;

fn start(iut: &Iut) -> (LowerTester, Expected) {
    (LowerTester::start(iut, timing()), Expected::default())
}

/// Checks the counters after a frame the IUT acknowledged (rule h); `prior` is
/// REC before it: from above 127 any value in 119..=127 is correct.
#[track_caller]
pub fn check_after_rx_ok(lt: &LowerTester, exp: &mut Expected, prior: u8, what: &str) {
    if prior > 127 {
        let r = lt.probes().rec;
        assert!(
            (119..=127).contains(&r),
            "{}: {what}: REC {r} after a valid frame with REC {prior} before; \
             ISO 11898-1 12.1.4.2 h needs 119..=127",
            lt.name()
        );
        exp.rec = r;
    }
    lt.check(exp, what);
}

/// The tester sends `fb` without error, then the intermission: the IUT must be
/// recessive except for its ACK, deliver the frame at EOF bit 6 and count rule h.
pub fn receive_ok(lt: &mut LowerTester, exp: &mut Expected, fb: &FrameBits) -> Run {
    let prior = exp.rec;
    let mut s = Script::new();
    s.receive(fb, 0..fb.len(), true).intermission();
    let run = lt.run(&s);
    exp.rx_ok();
    assert_eq!(
        run.rx_valid_bits(),
        vec![fb.eof(6)],
        "{}: rx_valid must pulse once, at EOF bit 6 (frame {})",
        lt.name(),
        fb.frame
    );
    assert_eq!(
        run.recs[fb.eof(6)].rx_frame,
        Some(fb.frame),
        "{}: rx_frame",
        lt.name()
    );
    check_after_rx_ok(lt, exp, prior, &format!("after receiving {}", fb.frame));
    run
}

/// The flag, delimiter and intermission after an error the IUT (receiver) detects
/// at the previous bit; `exp` already counts the error.
fn rx_error_tail(s: &mut Script, exp: &Expected) {
    s.error_flag(exp.active()).error_delim().intermission();
}

/// Value of `b` inverted, as the tester's drive (the IUT is a receiver, so its own
/// `tx` is recessive and a dominant bit can be turned recessive with `R`).
fn flipped(v: bool) -> Lt {
    Lt::from_value(!v)
}

/// ISO 16845-1 7.1.1 / 7.1.2 and 8.1.1 / 8.1.2: data frames with the ISO
/// identifiers (base 555h, 2AAh, 000h, 7FFh and one more; extended 15555555h,
/// 0AAAAAAAh, 00000000h, 1FFFFFFFh and one more), each with every DLC 0..=8, then
/// remote frames with DLC 0, 1, 4, 8, all of one format (`ide`).
pub fn iso_id_frames(ide: bool) -> Vec<Frame> {
    let data = [0x55, 0xAA, 0x00, 0xFF, 0x0F, 0xF0, 0x81, 0x7E];
    let ids: [u32; 5] = if ide {
        [
            0x1555_5555,
            0x0AAA_AAAA,
            0x0000_0000,
            0x1FFF_FFFF,
            0x1234_5678,
        ]
    } else {
        [0x555, 0x2AA, 0x000, 0x7FF, 0x123]
    };
    let mut v = Vec::new();
    for (k, &id) in ids.iter().enumerate() {
        for dlc in 0..=8usize {
            let mut d = data;
            d.rotate_left(k);
            let f = base(id, &d[..dlc]);
            v.push(Frame { ide, ..f });
        }
    }
    for dlc in [0u8, 1, 4, 8] {
        v.push(remote(if ide { 0x0A5A_5A5A } else { 0x5A5 }, ide, dlc));
    }
    v
}
