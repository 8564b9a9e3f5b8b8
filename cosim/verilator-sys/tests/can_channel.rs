//! Tests of the Verilated `can_channel` through the safe wrapper: several instances
//! side by side, reset values, VCD traces, and the error when the model is missing.
//! Without the model they skip, except when Verilator is required
//! (`verilator_sys::required()`: `CI` or `DRCC_REQUIRE_VERILATOR` set), where a
//! missing model is a failure.

use verilator_sys::{
    available, unavailable_reason, CanChannel, CanChannelIn, CanChannelOut, RTL_MISSING_MSG,
    UNAVAILABLE_MSG,
};

/// True when the model is built; false (skip) outside CI; panics in CI.
fn model_or_skip(test: &str) -> bool {
    if available() {
        return true;
    }
    let reason = unavailable_reason().unwrap_or("?");
    let ci = verilator_sys::required();
    assert!(
        !ci,
        "{test}: the Verilated model is required in CI: {reason}"
    );
    eprintln!("{test}: skipped: {reason}");
    false
}

/// 8 MHz / 1 Mbit/s: BRP 0, TSEG1 5, TSEG2 2, SJW 1, in the minus-one encodings;
/// normal mode, error warning limit 96, automatic retransmission.
fn idle_inputs() -> CanChannelIn {
    CanChannelIn {
        rst: 0,
        cfg_brp: 0,
        cfg_tseg1: 4,
        cfg_tseg2: 1,
        cfg_sjw: 0,
        cfg_triple: 0,
        cfg_mode: 0,
        cfg_ewl: 96,
        cfg_single_shot: 0,
        rx: 1,
        ..CanChannelIn::default()
    }
}

fn reset(ch: &mut CanChannel, clocks: usize) -> CanChannelOut {
    let rst = CanChannelIn {
        rst: 1,
        ..idle_inputs()
    };
    let mut out = CanChannelOut::default();
    for _ in 0..clocks {
        ch.step_into(&rst, &mut out);
    }
    out
}

fn assert_reset_values(who: &str, o: &CanChannelOut) {
    assert_eq!(o.tx, 1, "{who}: tx recessive after reset");
    assert_eq!(o.tx_pending, 0, "{who}: nothing pending after reset");
    assert_eq!(
        (o.tx_done, o.arb_lost, o.rx_valid, o.tx_failed, o.err_valid),
        (0, 0, 0, 0, 0),
        "{who}: no pulses"
    );
    assert_eq!(
        (o.cnt_bit, o.cnt_stuff, o.cnt_crc, o.cnt_form, o.cnt_ack),
        (0, 0, 0, 0, 0),
        "{who}: error counters by kind"
    );
    assert_eq!(o.err_warning, 0, "{who}: below the warning limit");
    assert_eq!(
        (o.tec, o.rec, o.err_state),
        (0, 0, 0),
        "{who}: error counters"
    );
    assert_eq!(o.sampled_bit, 1, "{who}: last sample resets to recessive");
}

#[test]
fn two_instances_reset_and_step_independently() {
    if !model_or_skip("two_instances_reset_and_step_independently") {
        return;
    }
    let mut a = CanChannel::new().expect("instance a");
    let mut b = CanChannel::new().expect("instance b");
    let oa = reset(&mut a, 3);
    let ob = reset(&mut b, 3);
    assert_reset_values("a after reset", &oa);
    assert_reset_values("b after reset", &ob);

    // Stepped alternately on an idle (recessive) bus, both stay recessive.
    let idle = idle_inputs();
    for n in 0..200 {
        let oa = a.step(&idle);
        let ob = b.step(&idle);
        assert_eq!(
            (oa.tx, ob.tx),
            (1, 1),
            "clock {n}: idle nodes stay recessive"
        );
    }

    // A request latched by `a` must not show up in `b` (separate model state).
    let req = CanChannelIn {
        tx_req: 1,
        tx_id: 0x123,
        tx_dlc: 1,
        tx_data: 0xA5 << 56,
        ..idle_inputs()
    };
    let oa = a.step(&req);
    let ob = b.step(&idle);
    assert_eq!(oa.tx_pending, 1, "a latched its request at the edge");
    assert_eq!(ob.tx_pending, 0, "b is untouched by a's request");

    // Reset clears `a` again.
    let oa = reset(&mut a, 1);
    assert_reset_values("a after second reset", &oa);
}

#[test]
fn instance_can_move_to_another_thread() {
    if !model_or_skip("instance_can_move_to_another_thread") {
        return;
    }
    let mut ch = CanChannel::new().expect("instance");
    reset(&mut ch, 2);
    // The instance is stepped and then freed on the other thread.
    let out = std::thread::spawn(move || ch.step(&idle_inputs()))
        .join()
        .expect("thread");
    assert_eq!(out.tx, 1);
    // A new instance on this thread after the other one was freed elsewhere.
    let mut again = CanChannel::new().expect("instance");
    assert_eq!(reset(&mut again, 2).tx, 1);
}

#[test]
fn vcd_trace_has_two_time_stamps_per_clock() {
    if !model_or_skip("vcd_trace_has_two_time_stamps_per_clock") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("verilator-sys-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut ch = CanChannel::new().expect("instance");
    for round in 0..2 {
        // Reopening (a second file on the same instance) must work too.
        let path = dir.join(format!("can_channel_{round}.vcd"));
        ch.trace_open(&path).expect("open VCD");
        reset(&mut ch, 2);
        for _ in 0..8 {
            ch.step(&idle_inputs());
        }
        ch.trace_close();
        let vcd = std::fs::read_to_string(&path).unwrap();
        assert!(vcd.contains("$enddefinitions"), "VCD header");
        assert!(vcd.contains(" tx $end"), "tx is traced");
        // 10 steps per round; round r starts at step 10 r: times 20r .. 20r+19.
        let first = format!("\n#{}\n", 20 * round);
        let last = format!("\n#{}\n", 20 * round + 19);
        assert!(vcd.contains(&first), "first time stamp {first:?}");
        assert!(vcd.contains(&last), "last time stamp {last:?}");
        assert!(!vcd.contains(&format!("\n#{}\n", 20 * round + 20)));
    }
    let err = ch
        .trace_open(dir.join("no-such-dir").join("x.vcd"))
        .expect_err("unwritable path");
    assert!(err.to_string().contains("x.vcd"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// xorshift64*: deterministic stimulus without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

#[test]
fn single_eval_edge_matches_two_evals() {
    if !model_or_skip("single_eval_edge_matches_two_evals") {
        return;
    }
    eprintln!(
        "fast edge available: {}, skips settled inputs: {}",
        CanChannel::fast_edge(),
        CanChannel::skips_settled_inputs()
    );
    // Two identical buses of three nodes; bus 0 uses the default stepping, bus 1
    // forces clk=0/clk=1 evals. Same stimulus, same outputs, clock by clock.
    let mut buses: Vec<Vec<CanChannel>> = (0..2)
        .map(|_| {
            (0..3)
                .map(|_| CanChannel::new().expect("instance"))
                .collect()
        })
        .collect();
    for node in &mut buses[1] {
        node.set_exact(true);
    }
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut inputs = [idle_inputs(); 3];
    let mut bus = [1u8; 2];
    let (mut dominant, mut events) = (0u64, 0u64);
    for n in 0..150_000u64 {
        // A reset with new bit timing every 50k clocks (and at the start).
        let rst = n % 50_000 < 2;
        if n % 50_000 == 0 {
            let brp = rng.below(3) as u16;
            let tseg2 = 2 + rng.below(3) as u8;
            for i in &mut inputs {
                i.cfg_brp = brp;
                i.cfg_tseg1 = 4 + rng.below(4) as u8;
                i.cfg_tseg2 = tseg2 - 1;
                i.cfg_sjw = rng.below(2) as u8;
                i.cfg_triple = rng.below(2) as u8;
                // Mostly normal mode; the others exercise the mode logic.
                i.cfg_mode = if rng.below(2) == 0 {
                    0
                } else {
                    rng.below(4) as u8
                };
                i.cfg_ewl = rng.below(256) as u8;
                i.cfg_single_shot = rng.below(2) as u8;
            }
        }
        // Occasional dominant glitches exercise the error paths.
        let glitch = rng.below(2000) == 0;
        for (k, i) in inputs.iter_mut().enumerate() {
            i.rst = rst as u8;
            i.tx_req = (rng.below(700) == k as u64) as u8;
            i.tx_abort = (rng.below(5000) == k as u64) as u8;
            if i.tx_req == 1 {
                i.tx_ide = rng.below(2) as u8;
                i.tx_id = (rng.next() as u32) & if i.tx_ide == 1 { 0x1FFF_FFFF } else { 0x7FF };
                i.tx_rtr = (rng.below(5) == 0) as u8;
                i.tx_dlc = rng.below(16) as u8;
                i.tx_data = rng.next();
            }
        }
        let mut outs = [[CanChannelOut::default(); 3]; 2];
        for (b, nodes) in buses.iter_mut().enumerate() {
            for (k, node) in nodes.iter_mut().enumerate() {
                let input = CanChannelIn {
                    rx: bus[b] & !glitch as u8,
                    ..inputs[k]
                };
                node.step_into(&input, &mut outs[b][k]);
            }
            bus[b] = outs[b].iter().map(|o| o.tx).fold(1, |a, t| a & t);
        }
        assert_eq!(
            outs[0], outs[1],
            "clock {n}: single-eval and two-eval steps differ"
        );
        dominant += (bus[0] == 0) as u64;
        events += outs[0]
            .iter()
            .map(|o| (o.tx_done + o.rx_valid + o.arb_lost + o.tx_failed + o.err_valid) as u64)
            .sum::<u64>();
    }
    eprintln!(
        "{dominant} dominant clocks, {events} tx_done/rx_valid/arb_lost/tx_failed/err_valid pulses"
    );
    assert!(
        dominant > 0,
        "the bus never went dominant: the test stimulus is dead"
    );
}

#[test]
fn missing_model_gives_the_install_message() {
    match CanChannel::new() {
        Ok(_) => assert!(available()),
        Err(e) => {
            assert!(!available());
            let msg = e.to_string();
            assert_eq!(Some(msg.as_str()), unavailable_reason());
            assert!(
                msg.starts_with(UNAVAILABLE_MSG)
                    || msg.starts_with(RTL_MISSING_MSG)
                    || msg.contains("failed")
                    || msg.contains("ports"),
                "unexpected message: {msg}"
            );
            // No silent skip in CI.
            model_or_skip("missing_model_gives_the_install_message");
        }
    }
}
