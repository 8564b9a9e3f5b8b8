//! Lock-step comparison of the Verilated hub with rust-hdl's simulator of the
//! same block (N = 4, M = 2): every output and probe, every clock, under real
//! frames, acknowledgements through the twin, a stuck-dominant node, a
//! bit-flipping node, a silent sublink, Wishbone reads of every register and
//! the commands. It checks that the emitted Verilog means what the Rust means
//! (the contract itself is signed off against the independent model).
//! Without Verilator it skips, except in CI.

use drcc_cosim::engine::hub::{HubEngine, HubInputs};
use drcc_cosim::engine::hub_rusthdl::HubRustHdlEngine;
use drcc_cosim::engine::hub_verilator::HubVerilatorEngine;

struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> u32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) as u32
    }
}

/// Bits of a base data frame from SOF to the CRC delimiter (stuffed), then ACK
/// slot (dominant), ACK delimiter, EOF and intermission.
fn frame_bits(id: u16, data: &[u8]) -> (Vec<bool>, usize) {
    let mut raw = vec![false];
    for k in (0..11).rev() {
        raw.push((id >> k) & 1 == 1);
    }
    raw.extend([false, false, false]); // RTR, IDE, r0
    for k in (0..4).rev() {
        raw.push((data.len() >> k) & 1 == 1);
    }
    for byte in data {
        for k in (0..8).rev() {
            raw.push((byte >> k) & 1 == 1);
        }
    }
    let mut crc: u16 = 0;
    for &b in &raw {
        let nxt = b ^ ((crc >> 14) & 1 == 1);
        crc = (crc << 1) & 0x7FFF;
        if nxt {
            crc ^= 0x4599;
        }
    }
    for k in (0..15).rev() {
        raw.push((crc >> k) & 1 == 1);
    }
    let mut out = Vec::new();
    let (mut last, mut run) = (true, 0);
    for &b in &raw {
        if run == 5 {
            out.push(!last);
            last = !last;
            run = 1;
        }
        if b == last {
            run += 1;
        } else {
            last = b;
            run = 1;
        }
        out.push(b);
    }
    if run == 5 {
        out.push(!last);
    }
    out.push(true); // CRC delimiter
    let ack = out.len();
    out.push(false); // ACK slot
    out.extend([true; 11]); // ACK delimiter, EOF, intermission
    (out, ack)
}

#[test]
fn verilator_and_rusthdl_agree_clock_by_clock() {
    let Some(mut v) = drcc_tools::verilated("hub top", HubVerilatorEngine::new()) else {
        return;
    };
    let mut r = HubRustHdlEngine::new(4, 2).unwrap();
    let mut rng = Lcg(0x5eed);
    let mut cycle = 0u64;
    let mut i = HubInputs {
        rst: true,
        uplink: 0xF,
        sublink_in: 0x3,
        ..HubInputs::default()
    };
    let mut saw_isolation = false;
    let mut saw_ack = false;
    let mut twin_delay = [0x3u8; 3];
    let mut step = |i: &mut HubInputs, v: &mut HubVerilatorEngine, r: &mut HubRustHdlEngine| {
        let a = v.step(i);
        let b = r.step(i);
        assert_eq!(a, b, "cycle {cycle}: verilator vs rust-hdl, inputs {i:?}");
        saw_isolation |= a.probes.port_enabled != 0x3F;
        saw_ack |= a.probes.ack_window;
        cycle += 1;
        a
    };
    for _ in 0..3 {
        step(&mut i, &mut v, &mut r);
    }
    i.rst = false;
    // configuration in reset mode: short restoration and decoupling, then run
    let writes = [
        (3u8, 0x0004_1010u32),   // GUARD_CFG: sd 16/16, sr_frames 4
        (4, 0x0000_1008),        // BF_CFG: bf_up 8, bf_sub 16
        (5, (3000 << 16) | 400), // RESTORE_CFG: restore 400, decouple 3000
        (8, 0xF),                // INT_ENABLE
        (1, 0x100),              // CTRL: leave reset mode, ack_interdep
    ];
    for (adr, dat) in writes {
        i.wb_cyc = true;
        i.wb_stb = true;
        i.wb_we = true;
        i.wb_adr = adr;
        i.wb_dat_w = dat;
        step(&mut i, &mut v, &mut r);
        i.wb_cyc = false;
        i.wb_stb = false;
        i.wb_we = false;
        step(&mut i, &mut v, &mut r);
    }
    const BIT: usize = 8; // default BTR: 1 + 5 + 2 tq of one clock
    for n in 0..60u32 {
        let tx = (n % 3) as usize; // transmitting node
        let id = (rng.next() & 0x7FF) as u16 | 0x10;
        let len = (rng.next() % 9) as usize;
        let data: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        let (bits, ack) = frame_bits(id, &data);
        let stuck = (10..14).contains(&n); // node 3 stuck dominant
        let flip = (25..35).contains(&n); // node 2 flips bits
        let silent_sub = (40..50).contains(&n); // sublink 1 recessive
        for (k, &bit) in bits.iter().enumerate() {
            for c in 0..BIT {
                let mut up = 0xFu16;
                if !bit {
                    up &= !(1 << tx);
                }
                if stuck {
                    up &= !(1 << 3);
                }
                if flip && c == 2 && rng.next().is_multiple_of(4) {
                    up &= !(1 << 2);
                }
                i.uplink = up;
                // the twin echoes our contribution 3 clocks later and
                // acknowledges in the ACK slot
                let mut twin = twin_delay[0];
                if k == ack {
                    twin = 0;
                }
                if silent_sub {
                    twin |= 0x2;
                }
                i.sublink_in = twin;
                // Wishbone: read a register now and then, commands sometimes
                if c == 0 && k % 3 == 0 {
                    i.wb_cyc = true;
                    i.wb_stb = true;
                    i.wb_we = false;
                    i.wb_adr = (rng.next() % 24) as u8;
                    if rng.next().is_multiple_of(50) {
                        i.wb_we = true;
                        i.wb_adr = [1u8, 1, 1, 7, 2, 0][(rng.next() % 6) as usize];
                        i.wb_dat_w =
                            [0x102u32, 0x104, 0x106, 0xF, 0x500, 0][(rng.next() % 6) as usize];
                    }
                } else {
                    i.wb_cyc = false;
                    i.wb_stb = false;
                    i.wb_we = false;
                }
                let out = step(&mut i, &mut v, &mut r);
                twin_delay = [twin_delay[1], twin_delay[2], out.sublink_out];
            }
        }
    }
    // STATS: frames tracked to their ACK slot
    i.wb_cyc = true;
    i.wb_stb = true;
    i.wb_we = false;
    i.wb_adr = 9;
    let stats = step(&mut i, &mut v, &mut r).wb_dat_r;
    eprintln!("hub cosim: {cycle} clocks, STATS = {stats:#010x}");
    assert!(stats & 0xFFFF >= 20, "frames tracked: STATS = {stats:#x}");
    assert!(saw_ack, "the tracker reached the ACK slot");
    assert!(saw_isolation, "a port was isolated");
}
