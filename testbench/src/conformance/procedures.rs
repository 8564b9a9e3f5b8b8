//! Recurring lower-tester procedures, each with the counter arithmetic of
//! ISO 11898-1:2015 12.1.4.2 (rules a..l) worked out by the tester itself:
//! receive errors (to bring REC to a value), ACK errors, bit errors and successful
//! transmissions (to bring TEC to a value). [`Expected`] is the tester's own
//! account of the counters; every procedure checks the IUT against it.

use drcc_cosim::Frame;

use super::bits::{Field, FrameBits};
use super::lower_tester::{state, LowerTester, Lt, Run, Script};

/// A base data frame.
pub fn base(id: u32, data: &[u8]) -> Frame {
    let mut f = Frame {
        id,
        dlc: data.len() as u8,
        ..Frame::default()
    };
    f.data[..data.len()].copy_from_slice(data);
    f
}

/// An extended data frame.
pub fn ext(id: u32, data: &[u8]) -> Frame {
    Frame {
        ide: true,
        ..base(id, data)
    }
}

/// A remote frame.
pub fn remote(id: u32, ide: bool, dlc: u8) -> Frame {
    Frame {
        id,
        ide,
        rtr: true,
        dlc,
        data: [0; 8],
    }
}

/// The tester's account of the IUT's error counters (ISO 11898-1 12.1.4.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Expected {
    /// Transmit error counter.
    pub tec: u16,
    /// Receive error counter.
    pub rec: u8,
    /// Bus-off was entered (rules j, l: left only by recovery).
    pub bus_off: bool,
}

impl Expected {
    /// Rules i, j, k: the error state (0 active, 1 passive, 2 bus-off).
    pub fn state(&self) -> u8 {
        if self.bus_off || self.tec > 255 {
            state::BUS_OFF
        } else if self.tec >= 128 || self.rec >= 128 {
            state::PASSIVE
        } else {
            state::ACTIVE
        }
    }

    /// Error active.
    pub fn active(&self) -> bool {
        self.state() == state::ACTIVE
    }

    /// Rules c, d, f: TEC + `n` (no change while bus-off).
    pub fn tec_add(&mut self, n: u16) {
        if self.state() != state::BUS_OFF {
            self.tec += n;
            if self.tec > 255 {
                self.bus_off = true;
            }
        }
    }

    /// Rules a, b, e, f: REC + `n`.
    pub fn rec_add(&mut self, n: u8) {
        if self.state() != state::BUS_OFF {
            self.rec = self.rec.saturating_add(n);
        }
    }

    /// Rule g: successful transmission.
    pub fn tx_ok(&mut self) {
        self.tec = self.tec.saturating_sub(1);
    }

    /// Rule h: successful reception (REC above 127 becomes a value in 119..=127;
    /// 127 here, see `receiver::check_after_rx_ok` for the range).
    pub fn rx_ok(&mut self) {
        if self.rec > 127 {
            self.rec = 127;
        } else {
            self.rec = self.rec.saturating_sub(1);
        }
    }
}

impl LowerTester {
    /// Asserts the IUT's counters and error state against `exp`.
    #[track_caller]
    pub fn check(&self, exp: &Expected, what: &str) {
        self.assert_counters(exp.tec, exp.rec, exp.state(), what);
    }
}

/// The frame of [`rx_error`]: base ID 0, no data; its 6th bit (index 5) is a
/// recessive stuff bit after SOF and four dominant identifier bits.
pub fn rx_error_frame() -> FrameBits {
    let fb = FrameBits::new(&base(0, &[]));
    assert!(fb.bits[5].stuff && fb.bits[5].value);
    fb
}

/// The IUT receives a frame whose first stuff bit the tester turns dominant: a
/// stuff error (REC + 1, rule a), the IUT's error flag from the next bit (the tester
/// recessive under it), then `dominant_after` dominant bits from the tester (rule b:
/// plus 8 when at least one; rule f: + 8 for every 8), the error delimiter and the
/// intermission. The IUT must be idle and have nothing to send.
pub fn rx_error(lt: &mut LowerTester, exp: &mut Expected, dominant_after: usize) -> Run {
    let mut s = rx_stuff_error(exp);
    s.error_flag(exp.active());
    if dominant_after > 0 {
        s.repeat(dominant_after, Lt::D, Some(true), "Dominant after flag");
        exp.rec_add(8);
        for _ in 0..dominant_after / 8 {
            exp.rec_add(8);
        }
    }
    s.error_delim().intermission();
    let run = lt.run(&s);
    lt.check(exp, "after a receive error");
    run
}

/// The IUT receives [`rx_error_frame`] and the tester turns its first stuff bit
/// dominant: a stuff error (REC + 1, rule a). The script goes on with the IUT's
/// error flag.
pub fn rx_stuff_error(exp: &mut Expected) -> Script {
    let fb = rx_error_frame();
    let mut s = Script::new();
    s.receive(&fb, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
    s
}

/// Brings REC from `exp.rec` up to `target` with receive errors (+9 and +1).
pub fn rec_to(lt: &mut LowerTester, exp: &mut Expected, target: u8) {
    while exp.rec as u16 + 9 <= target as u16 {
        rx_error(lt, exp, 1);
    }
    while exp.rec < target {
        rx_error(lt, exp, 0);
    }
}

/// What ends the suspend-free part of an error frame or frame for the IUT as
/// transmitter: the 3 intermission bits, plus suspend transmission (8 bits) when
/// the IUT is error passive (ISO 11898-1 10.4.6.4).
pub fn interframe_tx(s: &mut Script, exp: &Expected) {
    s.intermission();
    if exp.state() == state::PASSIVE {
        s.suspend();
    }
}

/// The IUT transmits `fb` (already requested; its SOF within `sof_within` bit
/// times) and nobody acknowledges it: ACK error at the ACK slot, error flag from
/// the ACK delimiter (TEC + 8 when error active, rule c; unchanged when error
/// passive, rule c exception 1), delimiter, intermission (and suspend when passive).
pub fn tx_ack_error(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    sof_within: u32,
) -> Run {
    let mut s = Script::new();
    s.transmit(fb, 0..fb.ack_slot() + 1, false, sof_within);
    if exp.active() {
        exp.tec_add(8);
    }
    s.error_flag(exp.active()).error_delim();
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    lt.check(exp, "after an ACK error");
    run
}

/// The IUT transmits `fb` (already requested) and the tester corrupts its r0 bit
/// (dominant, forced recessive): bit error, TEC + 8 (rule c), flag, delimiter,
/// intermission (and suspend when passive).
pub fn tx_bit_error(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    sof_within: u32,
) -> Run {
    let r0 = fb.pos(Field::R0, 0);
    assert!(!fb.bits[r0].value, "r0 must be dominant");
    let mut s = Script::new();
    s.transmit(fb, 0..r0, false, sof_within);
    s.push(Lt::ForceR, None, "r0 forced recessive");
    exp.tec_add(8);
    if exp.state() == state::BUS_OFF {
        // Bus-off at this edge: no flag, recessive from the next bit.
        s.repeat(14, Lt::R, Some(true), "Bus-off");
    } else {
        s.error_flag(exp.active()).error_delim();
        interframe_tx(&mut s, exp);
    }
    let run = lt.run(&s);
    lt.check(exp, "after a bit error");
    run
}

/// The IUT transmits `fb` (already requested) and the tester acknowledges it:
/// `tx_done` at EOF bit 7, TEC - 1 (rule g), intermission (and suspend when passive).
pub fn tx_ok(lt: &mut LowerTester, exp: &mut Expected, fb: &FrameBits, sof_within: u32) -> Run {
    let mut s = Script::new();
    s.transmit(fb, 0..fb.len(), true, sof_within);
    exp.tx_ok();
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    assert_eq!(
        run.tx_done_bits(),
        vec![fb.eof(7)],
        "{}: tx_done must pulse once, at EOF bit 7",
        lt.name()
    );
    lt.check(exp, "after a successful transmission");
    run
}

/// Requests `frame` and lets the IUT fail it with ACK errors until TEC reaches at
/// least `target` (all while error active: + 8 each), then bit errors while
/// passive (+ 8 each) up to `target`; the frame stays pending. `target` is a
/// multiple of 8.
pub fn tec_to(lt: &mut LowerTester, exp: &mut Expected, frame: &Frame, target: u16) -> FrameBits {
    assert_eq!(target % 8, 0);
    let fb = FrameBits::new(frame);
    lt.request(*frame);
    let mut within = 2;
    while exp.tec < target {
        if exp.active() {
            tx_ack_error(lt, exp, &fb, within);
        } else {
            tx_bit_error(lt, exp, &fb, within);
        }
        within = 0;
    }
    fb
}
