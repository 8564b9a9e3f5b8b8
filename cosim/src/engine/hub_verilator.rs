//! The `verilator` engine of the hub tops: `rtl-out/hub.v` (hub A) and
//! `rtl-out/hub_b.v` (hub B) (N = 4 node ports, M = 2 interlinks) compiled by Verilator, driven through `verilator-sys`. The sign-off
//! engine of the hub (`hub_contract.md`).

use super::hub::{HubEngine, HubInputs, HubOutputs, HubProbes};
use std::path::Path;
use verilator_sys::{Hub, HubB, HubBIn, HubBOut, HubIn, HubOut};

/// Node ports of the emitted hubs.
pub const N: usize = 4;
/// Interlinks of the emitted hubs.
pub const M: usize = 2;

/// One of the two emitted hub tops: `hub.v` (hub A, identification frame 0x000)
/// or `hub_b.v` (hub B, 0x001, hub contract §9.1). Their ports are the same.
enum Top {
    A(Hub, HubIn, HubOut),
    B(HubB, HubBIn, HubBOut),
}

/// The Verilated `hub` or `hub_b`.
pub struct HubVerilatorEngine {
    top: Top,
}

impl std::fmt::Debug for HubVerilatorEngine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("HubVerilatorEngine").finish_non_exhaustive()
    }
}

impl HubVerilatorEngine {
    /// A fresh hub A (`hub.v`), not yet reset. Fails with an actionable message
    /// when this build has no Verilated model (Verilator missing, or the RTL not
    /// generated).
    pub fn new() -> Result<Self, String> {
        Self::new_hub(0)
    }

    /// Hub `hub_id`: 0 = `hub.v`, 1 = `hub_b.v`.
    pub fn new_hub(hub_id: u8) -> Result<Self, String> {
        let top = match hub_id {
            0 => Top::A(
                Hub::new().map_err(|e| e.to_string())?,
                HubIn::default(),
                HubOut::default(),
            ),
            _ => Top::B(
                HubB::new().map_err(|e| e.to_string())?,
                HubBIn::default(),
                HubBOut::default(),
            ),
        };
        Ok(HubVerilatorEngine { top })
    }

    /// Starts a VCD trace of every RTL signal (Verilator's own trace; times in half
    /// clock periods).
    pub fn open_vcd(&mut self, path: impl AsRef<Path>) -> std::io::Result<()> {
        match &mut self.top {
            Top::A(t, ..) => t.trace_open(path),
            Top::B(t, ..) => t.trace_open(path),
        }
    }

    /// Flushes and closes the VCD trace, if one is open.
    pub fn close_vcd(&mut self) {
        match &mut self.top {
            Top::A(t, ..) => t.trace_close(),
            Top::B(t, ..) => t.trace_close(),
        }
    }
}

/// The two tops' port structs have the same fields: one body for both.
macro_rules! step_top {
    ($top:expr, $pin:expr, $pout:expr, $In:ident, $i:expr) => {{
        *$pin = $In {
            rst: $i.rst as u8,
            wb_cyc_i: $i.wb_cyc as u8,
            wb_stb_i: $i.wb_stb as u8,
            wb_we_i: $i.wb_we as u8,
            wb_adr_i: $i.wb_adr & 0x3F,
            wb_dat_i: $i.wb_dat_w,
            wb_sel_i: $i.wb_sel & 0xF,
            uplink: ($i.uplink & ((1 << N) - 1)) as u8,
            sublink_in: $i.sublink_in & ((1 << M) - 1),
        };
        $top.step_into($pin, $pout);
        let o = &*$pout;
        HubOutputs {
            wb_ack: o.wb_ack_o != 0,
            wb_err: o.wb_err_o != 0,
            wb_dat_r: o.wb_dat_o,
            irq: o.irq != 0,
            downlink: o.downlink as u16,
            sublink_out: o.sublink_out,
            probes: HubProbes {
                coupled: o.coupled != 0,
                sample_point: o.sample_point != 0,
                trk_state: o.trk_state,
                ack_window: o.ack_window != 0,
                decoupled: o.decoupled != 0,
                port_enabled: o.port_enabled as u16,
                nrap_phase: o.nrap_phase,
                hub_tx: o.hub_tx != 0,
            },
        }
    }};
}

impl HubEngine for HubVerilatorEngine {
    fn name(&self) -> &'static str {
        "verilator"
    }

    fn shape(&self) -> (usize, usize) {
        (N, M)
    }

    #[inline]
    fn step(&mut self, i: &HubInputs) -> HubOutputs {
        match &mut self.top {
            Top::A(t, pin, pout) => step_top!(t, pin, pout, HubIn, i),
            Top::B(t, pin, pout) => step_top!(t, pin, pout, HubBIn, i),
        }
    }
}

#[cfg(test)]
mod tests {
    //! Lock-step comparison of the Verilated hub with rust-hdl's simulator of the
    //! same block (N = 4, M = 2): every output and probe, every clock, under real
    //! frames, acknowledgements through the twin, a stuck-dominant node, a
    //! bit-flipping node, a silent sublink, Wishbone reads of every register and
    //! the commands. It checks that the emitted Verilog means what the Rust means
    //! (the contract itself is signed off against the independent model).
    use super::*;
    use crate::engine::hub_rusthdl::HubRustHdlEngine;

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
        let Ok(mut v) = HubVerilatorEngine::new() else {
            eprintln!("skipped: no Verilated hub in this build");
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
}
