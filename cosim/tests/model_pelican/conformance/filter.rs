//! The acceptance filter end to end (DS 6.4.15; P-ACF-1, P-ACF-2, P-RX-5):
//! ACR / AMR with MOD.AFM, single and dual filter, standard and extended
//! frames, RTR and data-byte matching, missing data bytes accepted; the
//! filter in redundancy (both copies get the same verdict) and on the own
//! frames of SRR. ACR / AMR access rules are in `map`.

use super::*;
use drcc_cosim::Frame;

/// The frames of `frames`, sent by line A's peer, that the DUT stores with
/// `ACR = acr`, `AMR = amr`, `AFM = afm` (read back through the RX window).
fn stored(afm: bool, acr: [u8; 4], amr: [u8; 4], frames: &[Frame]) -> Vec<Frame> {
    let mut n = Net::keyed(single_a(4, true));
    for k in 0..4u8 {
        n.w(reg::WIN + k, acr[k as usize]);
        n.w(reg::WIN + 4 + k, amr[k as usize]);
    }
    n.w(reg::MOD, if afm { md::AFM } else { 0 });
    n.idle(12 * BIT);
    for f in frames {
        peer_sends(&mut n, 0, *f);
    }
    let mut got = vec![];
    while n.r(reg::SR) & sr::RBS != 0 {
        got.push(n.read_rx());
        n.w(reg::CMR, cmd::RRB);
    }
    got
}

/// DS 6.4.15 single filter, standard frame (P-ACF-1): ACR0 = ID.28..21,
/// ACR1[7:4] = ID.20..18 and RTR, ACR2 = data 1, ACR3 = data 2; a frame
/// without data byte 1 or 2 is not compared on it (nb0, nb1).
#[test]
fn acf_single_filter_standard_id_rtr_data() {
    // id 0x2A5 = 010_1010_0101: ACR0 = 0x54, ACR1 = {101, rtr 0} = 0xA0.
    let a = Frame::base(0x2A5, &[0x11, 0x22, 0x33]);
    let d = Frame::base(0x2A5, &[0x11]);
    let f = Frame::base(0x2A5, &[]);
    let got = stored(
        true,
        [0x54, 0xA0, 0x11, 0x22],
        [0x00, 0x0F, 0x00, 0x00],
        &[
            a,
            Frame::base(0x2A4, &[0x11, 0x22]), // ID.18 differs
            Frame::base(0x2A5, &[0x11, 0x23]), // data 2 differs
            d,                                 // no data 2: accepted
            base_rtr(0x2A5, 2),                // RTR compared
            f,                                 // no data: accepted
        ],
    );
    assert_eq!(got, vec![a, d, f], "DS 6.4.15: single filter, standard");
}

/// DS 6.4.15 single filter, extended frame (P-ACF-1): ACR0..2 = ID.28..5,
/// ACR3[7:2] = ID.4..0 and RTR (ACR3[1:0] unused); AMR bit 1 = don't care;
/// data not compared.
#[test]
fn acf_single_filter_extended_id_rtr() {
    let id = 0x0123_4567;
    let acr = [
        (id >> 21) as u8,
        (id >> 13) as u8,
        (id >> 5) as u8,
        ((id << 3) as u8) | 0x03,
    ];
    let a = ext(id, &[1]);
    let e = ext(id ^ 0x20, &[2]);
    let f = ext(id, &[0x99, 0x88]);
    let got = stored(
        true,
        acr,
        [0x00, 0x00, 0xFF, 0x00],
        &[
            a,
            ext(id ^ 1, &[1]),         // ID.0 differs
            ext_rtr(id, 1),            // RTR compared
            ext(id ^ (1 << 28), &[1]), // ID.28 differs
            e,                         // ID.5 differs, AMR2 don't care
            f,                         // data not compared
        ],
    );
    assert_eq!(got, vec![a, e, f], "DS 6.4.15: single filter, extended");
}

/// DS 6.4.15 dual filter, standard frame (P-ACF-1): filter 1 = ACR0,
/// ACR1[7:4] and data 1 as {ACR1[3:0], ACR3[3:0]}; filter 2 = ACR2,
/// ACR3[7:4] (no data); accepted if either matches.
#[test]
fn acf_dual_filter_standard() {
    // Filter 1: id 0x2A5, data 1 = 0x3C; filter 2: id 0x111 = 001_0001_0001.
    let a = Frame::base(0x2A5, &[0x3C, 0x77]);
    let c = Frame::base(0x2A5, &[]);
    let d = Frame::base(0x111, &[0x99]);
    let got = stored(
        false,
        [0x54, 0xA3, 0x22, 0x2C],
        [0; 4],
        &[
            a,                           // filter 1, data 2 not compared
            Frame::base(0x2A5, &[0x3D]), // data 1 differs
            c,                           // no data 1: accepted
            d,                           // filter 2, data not compared
            Frame::base(0x112, &[]),     // ID.19..18 differ
            base_rtr(0x111, 0),          // RTR compared by filter 2
        ],
    );
    assert_eq!(got, vec![a, c, d], "DS 6.4.15: dual filter, standard");
}

/// DS 6.4.15 dual filter, extended frame (P-ACF-1): filter 1 = ACR0 / ACR1 on
/// ID.28..13, filter 2 = ACR2 / ACR3 on ID.28..13; ID.12..0 and RTR are not
/// compared.
#[test]
fn acf_dual_filter_extended() {
    let id1: u32 = 0x00AB_CDEF;
    let id2: u32 = 0x1555_5555;
    let acr = [
        (id1 >> 21) as u8,
        (id1 >> 13) as u8,
        (id2 >> 21) as u8,
        (id2 >> 13) as u8,
    ];
    let a = ext(id1, &[]);
    let b = ext(id1 ^ 0x1FFF, &[]);
    let d = ext(id2 ^ 0x1F, &[5]);
    let e = ext_rtr(id2, 0);
    let got = stored(
        false,
        acr,
        [0; 4],
        &[
            a,
            b,                         // ID.12..0 not compared
            ext(id1 ^ 0x2000, &[]),    // ID.13 differs
            d,                         // filter 2
            e,                         // RTR not compared
            ext(id2 ^ (1 << 20), &[]), // ID.20 differs
        ],
    );
    assert_eq!(got, vec![a, b, d, e], "DS 6.4.15: dual filter, extended");
}

/// DS 6.4.3 MOD.3 AFM (same): the same ACR / AMR accept a frame as a dual
/// filter (filter 2) and reject it as a single filter.
#[test]
fn mod_afm_selects_single_or_dual_filter() {
    let acr = [0x54, 0xA3, 0x22, 0x2C];
    let f = Frame::base(0x111, &[0x99]);
    assert_eq!(stored(false, acr, [0; 4], &[f]), vec![f], "AFM = 0: dual");
    assert_eq!(stored(true, acr, [0; 4], &[f]), vec![], "AFM = 1: single");
}

/// Same (ACR/AMR "also in redundancy: both copies get the same verdict"):
/// P-RX-5. Both lines carry each message; an accepted one is stored once, a
/// rejected one not at all.
#[test]
fn acf_in_redundancy_both_copies_same_verdict() {
    let mut n = Net::keyed(PelicanParams::default());
    // Single filter: standard id 0x2A5 with any data.
    for (k, (c, m)) in [(0x54, 0x00), (0xA0, 0x0F), (0, 0xFF), (0, 0xFF)]
        .into_iter()
        .enumerate()
    {
        n.w(reg::WIN + k as u8, c);
        n.w(reg::WIN + 4 + k as u8, m);
    }
    n.w(reg::MOD, md::AFM);
    n.idle(12 * BIT);
    peers_send_both(&mut n, Frame::base(0x2A5, &[1]));
    peers_send_both(&mut n, Frame::base(0x2A4, &[2]));
    peers_send_both(&mut n, Frame::base(0x2A5, &[3]));
    assert_eq!(n.r(reg::RMC), 2, "P-RX-5: one copy each of the accepted");
    assert_eq!(n.read_rx(), Frame::base(0x2A5, &[1]));
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.read_rx(), Frame::base(0x2A5, &[3]));
}

/// Same ("receive only frames of other nodes, own only with SRR"; P-ACF-2):
/// a self-received frame passes the acceptance filter too.
#[test]
fn own_frame_self_received_only_through_the_filter() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::WIN, 0x54);
    n.w(reg::WIN + 1, 0xA0);
    n.w(reg::WIN + 4, 0x00);
    n.w(reg::WIN + 5, 0x0F);
    n.w(reg::MOD, md::AFM);
    n.idle(12 * BIT);
    let rejected = Frame::base(0x300, &[]);
    n.load_tx(&rejected);
    n.w(reg::CMR, cmd::SRR);
    wait_tbs(&mut n, 200);
    n.idle(4);
    assert_eq!(n.received, vec![(0, rejected)], "sent");
    assert_eq!(
        n.r(reg::RMC),
        0,
        "P-ACF-2: own frame rejected by the filter"
    );
    let accepted = Frame::base(0x2A5, &[]);
    n.load_tx(&accepted);
    n.w(reg::CMR, cmd::SRR);
    wait_tbs(&mut n, 200);
    n.idle(4);
    assert_eq!(n.r(reg::RMC), 1, "P-ACF-2: own frame accepted");
    assert_eq!(n.read_rx(), accepted);
}
