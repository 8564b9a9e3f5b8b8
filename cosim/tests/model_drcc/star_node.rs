//! The node side of a replicated star (DRCC contract §4.5, §5, §7): a
//! star node takes the hubs' identification frames out of its RX path and follows
//! their decision (`STAR_STATUS`), counts omissions per channel (`OMISSIONS`), and
//! the warning-limit policy fails a channel whose TEC reaches `ewl`. Plain
//! channels on the two buses stand in for the hubs and the other nodes.

use super::*;

const STAR: u32 = 1 << 5;
const STAR_STATUS: u8 = 36;
const OMISSIONS: u8 = 37;
const I_DOMAIN: u32 = 1 << 9;

/// A hub's identification frame (hub contract §9.1): base data frame 0x000 (hub A)
/// or 0x001 (hub B), DLC 0.
fn id_frame(hub: u32) -> Frame {
    frame(hub, false, false, 0, &[])
}

/// Has plain node `p` send `f` and waits until it is done.
fn send(sys: &mut Sys, p: usize, f: Frame) {
    let done = sys.plain[p].done;
    sys.plain[p].req = Some(f);
    for _ in 0..200 * CPB {
        sys.step();
        if sys.plain[p].done > done {
            sys.run(12 * CPB);
            return;
        }
    }
    panic!("plain node {p} could not send {f:?}");
}

#[test]
fn a_star_node_follows_the_hubs_identification_frames_and_keeps_them_from_its_host() {
    let mut sys = Sys::new(1);
    let on_a = sys.add_plain(0, true);
    let on_b = sys.add_plain(1, true);
    sys.write(0, INT_ENABLE, I_DOMAIN);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX | STAR);
    sys.run(20 * CPB);
    assert_eq!(sys.read(0, STAR_STATUS), 0);

    // Node restoration: the hubs' frames alternate on both stars (coupled).
    send(&mut sys, on_a, id_frame(0));
    send(&mut sys, on_b, id_frame(0));
    send(&mut sys, on_a, id_frame(1));
    send(&mut sys, on_b, id_frame(1));
    // last_a = hub B's (2), last_b = hub B's (2), 2 frames each, one domain.
    assert_eq!(sys.read(0, STAR_STATUS), 2 << 2 | 2 << 4 | 2 << 8 | 2 << 16);
    assert_eq!(sys.read(0, INT_STATUS) & I_DOMAIN, 0);

    // Definitive decoupling signalling: each hub's own frame, again and again, to
    // its own star only. Two of hub A's frames in a row on channel A: split.
    send(&mut sys, on_a, id_frame(0));
    assert_eq!(
        sys.read(0, STAR_STATUS) & 1,
        0,
        "one of its own hub's frames"
    );
    send(&mut sys, on_a, id_frame(0));
    assert_eq!(sys.read(0, STAR_STATUS) & 1, 1, "two in a row: split");
    assert_eq!(sys.read(0, INT_STATUS) & I_DOMAIN, I_DOMAIN);
    sys.write(0, INT_STATUS, I_DOMAIN);
    // Hub A's frame reaching channel B again means one domain.
    send(&mut sys, on_b, id_frame(0));
    assert_eq!(sys.read(0, STAR_STATUS) & 1, 0);
    assert_eq!(sys.read(0, INT_STATUS) & I_DOMAIN, I_DOMAIN);

    // None of them reached the host; an application frame does.
    assert_eq!(sys.pop(0), None);
    let app = frame(0x002, false, false, 0, &[]);
    send(&mut sys, on_a, app);
    assert_eq!(sys.pop(0), Some((app, 0)));

    // Without `star` the same identifiers are ordinary frames.
    sys.write(0, CTRL, RESET_MODE | REDUNDANCY | policy(1) | k(1));
    assert_eq!(sys.read(0, STAR_STATUS), 0, "reset mode clears it");
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    send(&mut sys, on_a, id_frame(0));
    assert_eq!(sys.pop(0), Some((id_frame(0), 0)));
    assert_eq!(sys.read(0, STAR_STATUS), 0);
}

#[test]
fn a_frame_only_one_channel_delivered_is_an_omission_of_the_other() {
    let mut sys = Sys::new(1);
    let on_a = sys.add_plain(0, true);
    sys.write(0, DEDUP_CFG, 50);
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    // A frame on line A only; a window later the next frame's scan judges it.
    send(&mut sys, on_a, frame(0x10, false, false, 1, &[1]));
    assert_eq!(
        sys.read(0, OMISSIONS),
        0,
        "not judged before the window ends"
    );
    sys.run(60 * CPB);
    send(&mut sys, on_a, frame(0x11, false, false, 1, &[2]));
    assert_eq!(sys.read(0, OMISSIONS), 1 << 16, "one omission of channel B");
    // Reset mode keeps the count (rst only clears it).
    sys.write(0, CTRL, RESET_MODE | REDUNDANCY | policy(1) | k(1));
    assert_eq!(sys.read(0, OMISSIONS), 1 << 16);
}

#[test]
fn the_warning_policy_fails_a_channel_at_the_warning_limit() {
    // Node 0 sends on line A, where nobody acknowledges: every attempt is an ACK
    // error, TEC += 8 (ISO 11898-1 12.1.4.2 rule c), so TEC reaches ewl (96) at
    // the 12th attempt, before error passive (128). Policy 3 fails channel A there
    // with the warning cause; the message then goes out on line B.
    let mut sys = Sys::new(1);
    let on_b = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | policy(3) | k(1));
    sys.run(20 * CPB);
    let m = frame(0x20, false, false, 1, &[7]);
    sys.push(0, &m, 0);
    let mut failed_tec = None;
    for _ in 0..20_000 * CPB {
        sys.step();
        if sys.nodes[0].out.probes.aux_a_state == FAILED && failed_tec.is_none() {
            failed_tec = Some(sys.nodes[0].out.probes.chan_a_bsp_tx_err_cnt);
        }
        if !sys.plain[on_b].received.is_empty() {
            break;
        }
    }
    let tec = failed_tec.expect("channel A failed");
    assert!((96..128).contains(&tec), "failed at TEC {tec}");
    assert_eq!(
        sys.read(0, AUX_A) >> 2 & 0x1F,
        1 << 4,
        "cause: warning only"
    );
    assert_eq!(sys.plain[on_b].received, vec![m]);
}
