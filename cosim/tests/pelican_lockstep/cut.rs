//! An SJA1000 driver's traffic while line A is cut mid-frame, in lock step
//! (`crate::shadow`): the Linux `sja1000` driver's bring-up, its transmit path
//! (load the window, `CMR.TR`, wait for `TI`) and its interrupt handler (read
//! `IR` until 0; on `RI` read the window and release it while `SR.RBS`; `TI`
//! checks `SR.TCS`; `EI`, `DOI`, `EPI`, `ALI`, `BEI` are errors it reports).
//! The other nodes send each of their frames on both lines, as a DRCC network
//! carries it. Every frame must arrive exactly once, both ways.

use crate::harness::{Net, BIT};
use drcc_cosim::model::pelican::{PelicanInputs, PelicanParams};
use drcc_cosim::Frame;

/// `IR` bits (SJA1000 data sheet 6.4.6).
const RI: u8 = 0x01;
const TI: u8 = 0x02;
const ERRORS: u8 = 0xFC;

/// What the driver saw.
#[derive(Default, Debug)]
struct Seen {
    rx: Vec<Frame>,
    tx_done: usize,
    tx_failed: usize,
    /// `IR` error bits with `SR` at the time, in order.
    errors: Vec<(u8, u8)>,
}

/// The driver's interrupt handler (`sja1000_interrupt`).
fn isr(n: &mut Net, seen: &mut Seen) {
    for _ in 0..16 {
        let ir = n.r(3);
        if ir == 0 {
            break;
        }
        if ir & TI != 0 {
            if n.r(2) & 0x08 != 0 {
                seen.tx_done += 1;
            } else {
                seen.tx_failed += 1;
            }
        }
        if ir & RI != 0 {
            while n.r(2) & 0x01 != 0 {
                let f = n.read_rx();
                seen.rx.push(f);
                n.w(1, 0x04);
            }
        }
        if ir & ERRORS != 0 {
            let sr = n.r(2);
            seen.errors.push((ir & ERRORS, sr));
        }
    }
}

/// `count` frames each way; line A cut at the DUT in the middle of its
/// `cut_at`-th frame. `xmode`: an `XMODE` written in reset mode before the
/// driver starts (the reset value another `pelican_*` key gives). Returns what
/// the driver saw and the frames the other nodes received.
fn run(p: PelicanParams, xmode: Option<u8>, ier: u8, count: u32, cut_at: u32) -> (Seen, Net) {
    let mut n = Net::new(p);
    if let Some(x) = xmode {
        n.w(115, x);
    }
    n.linux_start(ier, 0x00);
    let mut seen = Seen::default();
    let (mut sent, mut peer_sent) = (0u32, 0u32);
    let mut busy = false;
    let mut cut_armed = false;
    for _ in 0..400_000 * BIT {
        if n.out.irq {
            let before = seen.tx_done + seen.tx_failed;
            isr(&mut n, &mut seen);
            if seen.tx_done + seen.tx_failed > before {
                busy = false;
            }
        }
        if !busy && sent < count {
            n.load_tx(&Frame::base(0x100 + sent, &[sent as u8, 0xA5]));
            n.w(1, 0x01);
            busy = true;
            cut_armed = sent == cut_at;
            sent += 1;
        }
        // mid-frame: 20 bits after the DUT's first dominant bit on line A
        if cut_armed && !n.out.chan_a_tx {
            n.idle(20 * BIT);
            n.cut[0] = true;
            cut_armed = false;
        }
        // the other nodes: on the lines the DUT still hears (line A's node,
        // alone on its line after the cut, retries without an ACK)
        let idle =
            (0..2).all(|x| n.cut[x] || (n.peer_req[x].is_none() && !n.peer_out[x].tx_pending));
        if idle && peer_sent < count {
            let f = Frame::base(0x300 + peer_sent, &[peer_sent as u8]);
            n.peer_req = [(!n.cut[0]).then_some(f), Some(f)];
            peer_sent += 1;
        }
        if sent == count && peer_sent == count && !busy && idle && seen.rx.len() >= count as usize {
            break;
        }
        n.clk(PelicanInputs::default());
    }
    n.idle(50 * BIT);
    if n.out.irq {
        isr(&mut n, &mut seen);
    }
    (seen, n)
}

/// Each frame exactly once, both ways.
fn check_delivery(seen: &Seen, n: &Net, count: u32) {
    let ids: Vec<u32> = seen.rx.iter().map(|f| f.id).collect();
    let want: Vec<u32> = (0..count).map(|k| 0x300 + k).collect();
    assert_eq!(ids, want, "the driver reads every frame once, in order");
    for k in 0..count {
        let copies = n.received.iter().filter(|(_, f)| f.id == 0x100 + k).count();
        assert_eq!(
            copies,
            1,
            "frame {:#x} arrives once on the network",
            0x100 + k
        );
    }
    assert_eq!(
        seen.tx_done, count as usize,
        "every transmission succeeds (TCS)"
    );
    assert_eq!(seen.tx_failed, 0);
}

/// With `pelican_report = "in_use"` (`XMODE.rep = 0`, written in reset mode as
/// the key's reset value would be; Verilated too), and Linux's interrupt
/// enables without bus-error reporting (`IER = 0x7F`): every frame arrives
/// exactly once both ways and every transmission succeeds. What the driver sees
/// of the cut is channel A's error state while it is the channel in use
/// (P-LOG-4): `EI` as `ES` rises, `EPI` as it turns error
/// passive (the DRCC moves a message when its channel fails, §D4, §D5), and `EI`
/// as `ES` falls at the switch to line B (no `EPI` then: P-IR-6). Never a bus-off,
/// an overrun, a failed transmission; error active at the end.
#[test]
fn line_a_cut_with_in_use_report_shows_channel_a_failing() {
    let keys = PelicanParams {
        report_best: false,
        ..PelicanParams::default()
    };
    let (seen, mut n) = run(PelicanParams::default(), Some(keys.xmode()), 0x7F, 6, 2);
    check_delivery(&seen, &n, 6);
    let bits: Vec<u8> = seen.errors.iter().map(|&(ir, _)| ir).collect();
    assert_eq!(
        bits,
        vec![0x04, 0x20, 0x04],
        "EI, EPI, EI: {:?}",
        seen.errors
    );
    assert!(
        seen.errors.iter().all(|&(_, sr)| sr & 0x80 == 0),
        "no bus-off"
    );
    assert_eq!(n.r(2) & 0xC0, 0, "error active at the end: ES = BS = 0");
    assert_eq!(n.r(117) & 1, 1, "XSTAT.u: line B");
}

/// The generator's default keys (redundancy, error-passive policy,
/// `pelican_report = "best"`: `XMODE.rep`, P-LOG-5), Verilated too, with an
/// unmodified Linux driver's interrupt enables (`IER = 0x7F`): the driver's error
/// state is the better channel that can carry its frames, line B, so the cut
/// of line A shows nothing at all. Every frame arrives exactly once both ways,
/// every transmission succeeds, no interrupt but `RI` and `TI`; the DRCC's own
/// registers tell the cut (`XSTAT.u` = B, `XIR.switch`).
#[test]
fn line_a_cut_mid_frame_every_frame_once_and_the_driver_sees_no_error() {
    let (seen, mut n) = run(PelicanParams::default(), None, 0x7F, 6, 2);
    check_delivery(&seen, &n, 6);
    assert!(seen.errors.is_empty(), "no error seen: {:?}", seen.errors);
    assert_eq!(n.r(2) & 0xC0, 0, "error active: ES = BS = 0");
    assert_eq!(n.r(14), 0, "RXERR of line B");
    assert_eq!(n.r(15), 0, "TXERR of line B");
    assert_eq!(n.r(117) & 1, 1, "XSTAT.u: line B");
    assert_eq!(n.r(120) & 0x01, 0x01, "XIR.switch: the DRCC switched lines");
}
