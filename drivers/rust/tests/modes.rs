//! Modes and refusals on the Verilated DRCC, through the drivers: DMR mode
//! between two nodes (C sender, Rust receiver), the mode switch through reset
//! mode, a configuration the controller refuses (redundancy with a listen-only
//! channel, docs/registers.md), and the full TX queue (8 frames, README
//! "two queues of 8") as `embedded-can`'s `WouldBlock`. Expected values come
//! from the docs and the frames sent.

mod common;

use common::{
    bus_or_skip, c_send, exchange, frames, port, rust_isr, Budget, Regs, BIT, BITRATE, CLOCK_HZ,
    FRAME_BITS,
};
use drcc_driver::{
    regs, BitTiming, ChanMode, Channel, Config, DmrConfig, Drcc, Error, Mode, Registers,
};
use drcc_driver_sim::{c_call_with_version, CCall, CConfig, CDriver};

/// DRCC_MODE_DMR of the C driver.
const C_MODE_DMR: i32 = 2;
/// DEDUP_CFG.window for DMR mode: docs/dmr.md asks for more than
/// timeout x tick_bits + tick_bits = 100 x 125 + 125 = 12625 bit times (defaults).
const DMR_WINDOW: u16 = 20_000;

fn config(mode: Mode) -> Config {
    Config {
        timing: BitTiming::calc(CLOCK_HZ, BITRATE).expect("16 clocks a bit"),
        mode,
        int_enable: regs::INT_ENABLE_RX_MASK,
        ..Config::default()
    }
}

#[test]
fn dmr_mode_delivers_every_frame_once_from_the_default_line() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = CDriver::open(port(&bus, 0)).expect("drcc_init");
    let rc = tx.configure(&CConfig {
        clock_hz: CLOCK_HZ,
        bitrate: BITRATE,
        mode: C_MODE_DMR,
        policy: regs::CTRL_POLICY_ERROR_PASSIVE,
        k: 1,
        dual_tx: false,
        stall_limit: 0,
        recovery_bits: 1024,
        dedup_window: DMR_WINDOW,
        int_enable: 0,
    });
    assert_eq!(rc, 0, "drcc_configure in DMR mode (rtl-out/drcc.v has DMR)");
    let mut rx = Drcc::new(common::Regs(port(&bus, 1))).expect("the DRCC answers");
    let cfg = Config {
        dedup_window: DMR_WINDOW,
        dmr: DmrConfig::default(),
        ..config(Mode::Dmr)
    };
    rx.configure(&cfg).expect("DMR mode");
    bus.borrow_mut().tick(20 * BIT);
    let sent = frames();
    let got = exchange(
        &bus,
        1,
        &sent,
        c_send(&mut tx),
        rust_isr(&mut rx),
        |_, _| {},
        Budget {
            settle_bits: 3 * FRAME_BITS,
            budget_bits: 30 * FRAME_BITS,
        },
    );
    // The host sees the active CAN line only: after initialisation the DCL,
    // channel A (docs/dmr.md); the connection-service frames never reach it.
    let want: Vec<_> = sent.into_iter().map(|f| (f, 0u8)).collect();
    assert_eq!(got, want, "every frame once, from the DCL (channel A)");
    let dmr_state = regs::get(
        regs::DMR_STATUS_DMR_STATE_MASK,
        regs::DMR_STATUS_DMR_STATE_SHIFT,
        rx.stats().dmr_status,
    );
    assert_eq!(
        dmr_state,
        regs::DMR_REDUNDANCY_ACTIVE,
        "no fault on either line"
    );
    assert_eq!(bus.borrow().refused(), 0, "no register access was refused");
}

/// DMR first-copy delivery (`CTRL.first_copy`, DMR contract §8.1, map 1.4):
/// the Rust driver sets the bit on the Verilated DRCC and the frames still
/// arrive once each; on an instance older than 1.4 both drivers refuse it
/// before any write (`Error::Unsupported`, `DRCC_E_UNSUPPORTED` -9).
#[test]
fn both_drivers_set_dmr_first_copy_from_map_1_4() {
    let first_copy = Config {
        dedup_window: DMR_WINDOW,
        dmr: DmrConfig {
            first_copy: true,
            ..DmrConfig::default()
        },
        ..config(Mode::Dmr)
    };
    let mut old = Drcc::new(common::Fake {
        version: 0x103,
        writes: vec![],
    })
    .expect("major 1");
    assert_eq!(old.configure(&first_copy), Err(Error::Unsupported));
    assert_eq!(old.release().writes, vec![], "Rust: nothing written");
    assert_eq!(
        c_call_with_version(0x103, 0, CCall::ConfigureFirstCopy(true)),
        (-9, 0, (0, 0)),
        "C on 1.3"
    );
    // On 1.4 both go on (these fake registers never enter reset mode, so they
    // stop after the reset-mode write with Refused, -4).
    let reset_mode = (regs::CTRL_OFFSET, regs::CTRL_RESET_MODE_MASK);
    assert_eq!(
        c_call_with_version(0x104, 0, CCall::ConfigureFirstCopy(true)),
        (-4, 1, reset_mode),
        "C on 1.4"
    );

    let Some(bus) = bus_or_skip() else { return };
    let mut tx = Drcc::new(Regs(port(&bus, 0))).expect("the DRCC answers");
    tx.configure(&Config {
        dedup_window: DMR_WINDOW,
        ..config(Mode::Dmr)
    })
    .expect("DMR mode");
    let mut rx = Drcc::new(Regs(port(&bus, 1))).expect("the DRCC answers");
    rx.configure(&first_copy).expect("DMR mode with first copy");
    let ctrl = rx.registers().read32(regs::CTRL_OFFSET);
    assert_ne!(ctrl & regs::CTRL_FIRST_COPY_MASK, 0, "CTRL {ctrl:#x}");
    bus.borrow_mut().tick(20 * BIT);
    let sent = frames();
    let got = exchange(
        &bus,
        1,
        &sent,
        common::rust_send(&mut tx),
        rust_isr(&mut rx),
        |_, _| {},
        Budget {
            settle_bits: 3 * FRAME_BITS,
            budget_bits: 30 * FRAME_BITS,
        },
    );
    let frames_got: Vec<_> = got.into_iter().map(|(f, _)| f).collect();
    assert_eq!(frames_got, sent, "every frame once, from either line");
    assert_eq!(bus.borrow().refused(), 0, "no register access was refused");
}

#[test]
fn set_mode_switches_through_reset_mode() {
    let Some(bus) = bus_or_skip() else { return };
    let mut d = Drcc::new(Regs(port(&bus, 0))).expect("the DRCC answers");
    d.configure(&config(Mode::Normal)).expect("normal mode");
    for (mode, redundancy, dmr) in [
        (Mode::Redundancy, 1, 0),
        (Mode::Dmr, 0, 1),
        (Mode::Normal, 0, 0),
    ] {
        d.set_mode(mode).expect("mode taken");
        let ctrl = d.registers().read32(regs::CTRL_OFFSET);
        assert_eq!(ctrl & regs::CTRL_RESET_MODE_MASK, 0, "{mode:?}: running");
        let r = regs::get(
            regs::CTRL_REDUNDANCY_MASK,
            regs::CTRL_REDUNDANCY_SHIFT,
            ctrl,
        );
        let m = regs::get(regs::CTRL_DMR_MASK, regs::CTRL_DMR_SHIFT, ctrl);
        assert_eq!((r, m), (redundancy, dmr), "{mode:?}: CTRL {ctrl:#x}");
        assert!(!d.status().reset_mode, "{mode:?}: STATUS.reset_mode 0");
    }
    assert_eq!(bus.borrow().refused(), 0, "no register access was refused");
}

#[test]
fn redundancy_with_a_listen_only_channel_is_refused() {
    let Some(bus) = bus_or_skip() else { return };
    let mut d = Drcc::new(Regs(port(&bus, 0))).expect("the DRCC answers");
    let bad = Config {
        mode_b: ChanMode::ListenOnly,
        ..config(Mode::Redundancy)
    };
    // docs/registers.md: "a CTRL write with redundancy and a listen-only
    // channel (refused as a whole) ... sets INT_STATUS.illegal".
    assert_eq!(d.configure(&bad), Err(Error::Refused));
    assert!(
        d.status().reset_mode,
        "the refused write left reset mode on"
    );
    assert_ne!(
        d.irq_status() & regs::INT_STATUS_ILLEGAL_MASK,
        0,
        "illegal set"
    );
    assert_eq!(
        bus.borrow().refused(),
        1,
        "exactly that write got the bus error"
    );
    d.irq_ack(regs::INT_STATUS_ILLEGAL_MASK);
    d.configure(&config(Mode::Redundancy))
        .expect("the legal one is taken");
    assert!(!d.status().reset_mode);
    assert_eq!(d.irq_status() & regs::INT_STATUS_ILLEGAL_MASK, 0);
}

#[test]
fn full_tx_queue_is_would_block_and_blocking_traits_deliver() {
    use embedded_can::{blocking, nb as nb_can, StandardId};
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = Drcc::new(Regs(port(&bus, 0))).expect("the DRCC answers");
    let mut rx = Drcc::new(Regs(port(&bus, 1))).expect("the DRCC answers");
    tx.configure(&config(Mode::Normal)).expect("normal mode");
    // Node 1 stays in reset mode: nobody acknowledges, node 0 retries its
    // first frame forever and its queue A (8 frames) fills up.
    let f = |k: u8| {
        drcc_driver::Frame::data_frame(StandardId::new(0x100 + u16::from(k)).unwrap(), &[k])
            .unwrap()
    };
    for k in 0..8 {
        assert_eq!(
            nb_can::Can::transmit(&mut tx, &f(k)),
            Ok(None),
            "frame {k} queued"
        );
    }
    assert_eq!(tx.status().txq_a, 8, "STATUS.txq_a_count");
    assert_eq!(
        nb_can::Can::transmit(&mut tx, &f(8)),
        Err(nb::Error::WouldBlock),
        "queue full"
    );
    assert_eq!(tx.send(&f(8), Channel::A), Err(Error::Full));
    // Now node 1 joins: blocking::Can::receive gets the eight frames in order,
    // and blocking::Can::transmit queues a ninth as soon as there is room.
    rx.configure(&config(Mode::Normal)).expect("normal mode");
    blocking::Can::transmit(&mut tx, &f(8)).expect("queued once there is room");
    for k in 0..9 {
        let got = blocking::Can::receive(&mut rx).expect("a frame");
        assert_eq!(got, f(k).with_channel(Channel::A), "frame {k}");
    }
    assert_eq!(
        nb_can::Can::receive(&mut rx),
        Err(nb::Error::WouldBlock),
        "nothing more"
    );
}
