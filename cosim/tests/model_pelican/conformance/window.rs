//! The extension's window onto the DRCC's native registers (§13, P-X-3,
//! P-X-4): a load reads the native word through the core's own register port,
//! the words the view owns read 0, a commit writes a configuration word by the
//! native rules, and a load of a capture re-arms it. No SJA1000 has these
//! addresses (DS 6.4.1: 112..127 read 0x00); they are the "differs" row of the
//! extension. Expected native values come from the DRCC register map
//! (`docs/registers.md`, DRCC contract §D3, §D10) and the view's composition
//! rules (P-CFG-2, P-CFG-3).

use super::*;

const XWIN_IDX: u8 = 122;
const XWIN_CMD: u8 = 123;
const XWIN_D0: u8 = 124;
const COMMIT: u8 = 0x01;
const RELOAD: u8 = 0x02;

/// Native word indices (DRCC register map).
mod idx {
    pub const ID: u8 = 0;
    pub const CTRL: u8 = 1;
    pub const BTR: u8 = 2;
    pub const RMB_CFG: u8 = 3;
    pub const DEDUP_CFG: u8 = 4;
    pub const STATUS: u8 = 5;
    pub const INT_STATUS: u8 = 6;
    pub const INT_ENABLE: u8 = 7;
    pub const RX_ID: u8 = 17;
    pub const RX_CTRL: u8 = 18;
    pub const DMR_CFG: u8 = 25;
    pub const VERSION: u8 = 38;
    pub const CAP_A: u8 = 40;
    pub const CAP_B: u8 = 41;
}

/// `XWIN_D0..3` as one word (`D0` = bits [7:0]).
fn window_word(n: &mut Net) -> u32 {
    (0..4u8).fold(0, |w, k| w | (n.r(XWIN_D0 + k) as u32) << (8 * k))
}

/// Load native word `i` (a write of `XWIN_IDX`) and read it back.
fn load(n: &mut Net, i: u8) -> u32 {
    n.w(XWIN_IDX, i);
    window_word(n)
}

/// Write `w` into `XWIN_D0..3` and commit it to the loaded index.
fn commit(n: &mut Net, w: u32) {
    for k in 0..4u8 {
        n.w(XWIN_D0 + k, (w >> (8 * k)) as u8);
    }
    n.w(XWIN_CMD, COMMIT);
}

/// The default top (redundancy, error-passive policy, k = 1) in reset mode.
fn default_top() -> Net {
    let mut n = Net::keyed(PelicanParams::default());
    n.peer_on = [false, false];
    n
}

/// P-X-3: the identification words read as the native map has them; `CTRL`
/// and `BTR` read the words the view composes from `MOD`, `XMODE`, `XK`
/// (P-CFG-3) and `BTR0/1`, `EWLR` (P-CFG-2), in reset and operating mode; a
/// reload reads the word again.
#[test]
fn window_loads_native_words_and_the_composed_configuration() {
    let mut n = default_top();
    assert_eq!(load(&mut n, idx::ID), 0x4452_4343, "§D3: ID \"DRCC\"");
    assert_eq!(
        load(&mut n, idx::VERSION),
        0x0000_0105,
        "§D10.1: VERSION 1.5"
    );
    // P-CFG-3 in REDUNDANCY: reset_mode = RM (1), redundancy, policy
    // error-passive (1 << 2), k = 1 (1 << 8), both channels NORMAL.
    assert_eq!(
        load(&mut n, idx::CTRL),
        0x0000_0107,
        "P-CFG-3: CTRL in reset mode"
    );
    // P-CFG-2 from the reset values BTR0 = 0, BTR1 = 0x14, EWLR = 96:
    // brp = 2 x 0 + 1, tseg1 = 4, tseg2 = 1, sjw 0, ewl 96.
    assert_eq!(
        load(&mut n, idx::BTR),
        0x0060_0501,
        "P-CFG-2: BTR after reset"
    );
    // BTR0 = 0x41 (SJW 1, BRP 1), BTR1 = 0xAF (SAM, TSEG2 2, TSEG1 15), EWLR
    // 10: brp = 3, tseg1 15 << 6, tseg2 2 << 10, sjw 1 << 13, triple 1 << 15,
    // ewl 10 << 16 (DS 6.5.1, 6.5.2: SJW and SAM reach the channels).
    n.w(reg::BTR0, 0x41);
    n.w(reg::BTR1, 0xAF);
    n.w(reg::EWLR, 10);
    n.w(XWIN_CMD, RELOAD);
    assert_eq!(
        window_word(&mut n),
        0x000A_ABC3,
        "P-X-3: a reload reads BTR again"
    );
    n.w(reg::MOD, 0x00);
    assert_eq!(
        load(&mut n, idx::CTRL),
        0x0000_0106,
        "P-CFG-3: reset_mode = RM = 0"
    );
    let status = load(&mut n, idx::STATUS);
    assert_eq!(status >> 13 & 1, 0, "§D3: STATUS.reset_mode follows CTRL");
    assert_eq!(n.r(reg::XIR) & xir::WIN, 0, "loads never refuse");
}

/// P-X-3: the words the view owns (`INT_STATUS`, `INT_ENABLE`, `TX_*`,
/// `RX_*`) load 0 although the core's are not: after a reception the native
/// `INT_STATUS.rx` and `RX_ID.not_empty` are set (§D3, §D8) and `STATUS`
/// counts the frame, which the window does read.
#[test]
fn window_words_the_view_owns_load_zero() {
    let mut n = op_single(0x00, 0x00);
    peer_sends(&mut n, 0, Frame::base(0x321, &[7, 8]));
    assert_eq!(
        n.r(reg::SR) & sr::RBS,
        sr::RBS,
        "DS 6.4.5: the frame is in the FIFO"
    );
    assert_eq!(
        load(&mut n, idx::STATUS) >> 24 & 0x3F,
        1,
        "§D3: STATUS.rx_count, read through the window"
    );
    for i in [idx::INT_STATUS, idx::INT_ENABLE, idx::RX_ID, idx::RX_CTRL] {
        assert_eq!(load(&mut n, i), 0, "P-X-3: native word {i} reads 0");
    }
    for i in 12..=21u8 {
        assert_eq!(load(&mut n, i), 0, "P-X-3: TX_*/RX_* word {i} reads 0");
    }
    assert_eq!(n.r(reg::SR) & sr::RBS, sr::RBS, "the loads popped nothing");
}

/// P-X-4: in host reset mode a commit writes `RMB_CFG` and `DEDUP_CFG` as
/// the native map stores them (`DEDUP_CFG.window` is [14:0]); `XWIN_CMD[0]`
/// reads 0. In operating mode the same commit is refused: `XWIN_CMD[0] = 1`,
/// `XIR.win`, the word unchanged.
#[test]
fn window_commit_writes_configuration_words_in_reset_mode_only() {
    let mut n = default_top();
    assert_eq!(load(&mut n, idx::DEDUP_CFG), 0x400, "§D3: DEDUP_CFG reset");
    commit(&mut n, 0xFFFF_0123);
    assert_eq!(n.r(XWIN_CMD), 0, "P-X-4: accepted");
    n.w(XWIN_CMD, RELOAD);
    assert_eq!(window_word(&mut n), 0x0123, "§D3: window [14:0] stored");
    assert_eq!(load(&mut n, idx::RMB_CFG), 0x400, "§D3: RMB_CFG reset");
    commit(&mut n, 0x0010_0200);
    assert_eq!(
        load(&mut n, idx::RMB_CFG),
        0x0010_0200,
        "§D3: RMB_CFG stored"
    );
    assert_eq!(n.r(reg::XIR) & xir::WIN, 0, "accepted commits flag nothing");
    n.w(reg::MOD, 0x00);
    assert_eq!(
        load(&mut n, idx::DEDUP_CFG),
        0x0123,
        "kept in operating mode"
    );
    commit(&mut n, 0x0055);
    assert_eq!(n.r(XWIN_CMD), 1, "P-X-4: refused outside host reset mode");
    assert_eq!(n.r(reg::XIR) & xir::WIN, xir::WIN, "P-X-4: XIR.win");
    assert_eq!(
        load(&mut n, idx::DEDUP_CFG),
        0x0123,
        "P-X-4: nothing changes"
    );
}

/// P-X-4: a word outside the list (`ID`, `CTRL`, `BTR`) is refused without a
/// native write; a value the native rules refuse (`DMR_CFG.timeout = 0`,
/// §M2.2) is refused by the core's error answer, one clock later,
/// the same way. A legal `DMR_CFG` is then taken.
#[test]
fn window_commit_refused_by_the_list_or_by_the_native_rules() {
    let mut n = default_top();
    load(&mut n, idx::CTRL);
    commit(&mut n, 0x0000_0001);
    assert_eq!(n.r(XWIN_CMD), 1, "P-X-4: CTRL is not committable");
    assert_eq!(n.r(reg::XIR) & xir::WIN, xir::WIN, "P-X-4: XIR.win");
    assert_eq!(
        load(&mut n, idx::CTRL),
        0x0000_0107,
        "P-X-4: CTRL unchanged"
    );
    assert_eq!(load(&mut n, idx::DMR_CFG), 0x64, "§M2.1: DMR_CFG reset");
    commit(&mut n, 0x0005_0000);
    assert_eq!(n.r(XWIN_CMD), 1, "§M2.2: timeout 0 refused");
    assert_eq!(n.r(reg::XIR) & xir::WIN, xir::WIN, "P-X-4: XIR.win");
    assert_eq!(
        load(&mut n, idx::DMR_CFG),
        0x64,
        "the refused word unchanged"
    );
    commit(&mut n, 0x0005_0032);
    assert_eq!(n.r(XWIN_CMD), 0, "P-X-4: a legal DMR_CFG is accepted");
    assert_eq!(load(&mut n, idx::DMR_CFG), 0x0005_0032, "§M2.1: stored");
}

/// P-X-3: `CAP_A` reads the native capture (§D10.2: an ACK error as
/// transmitter, kind 5, `err_tx`, `err_valid`); a load of `CAP_B` leaves
/// channel A's capture alone; a load of `CAP_A` re-arms it, so the next load
/// reads `err_valid = 0` with the fields kept (§D10.2: a re-arm alone empties
/// the capture). Reset mode keeps the captures and stops the channel.
#[test]
fn window_load_of_a_capture_rearms_that_channel() {
    let mut n = op_single(0x00, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    n.w(reg::MOD, md::RM);
    assert_eq!(
        load(&mut n, idx::CAP_B),
        0,
        "§D10.2: channel B captured nothing"
    );
    let cap = load(&mut n, idx::CAP_A);
    assert_eq!(cap & 0x307, 0x305, "§D10.2: ACK error, transmitter, valid");
    let again = load(&mut n, idx::CAP_A);
    assert_eq!(again & 0x200, 0, "P-X-3: the load re-armed CAP_A");
    assert_eq!(again & 0x107, 0x105, "§D10.2: the re-arm keeps the fields");
}
