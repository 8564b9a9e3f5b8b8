//! Measures clocks per second of one Verilated `can_channel` through the raw port
//! structs (node's tx looped back to rx, a frame requested every 4096 clocks), and
//! optionally writes the first 2000 clocks as a VCD; `--exact` forces two evals
//! per clock: `cargo run -p verilator-sys --release --example throughput [-- [--exact] out.vcd]`.

use verilator_sys::{CanChannel, CanChannelIn, CanChannelOut};

fn main() {
    let mut ch = match CanChannel::new() {
        Ok(ch) => ch,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let exact = args.iter().any(|a| a == "--exact");
    ch.set_exact(exact);
    let vcd = args.iter().find(|a| *a != "--exact");
    if let Some(path) = &vcd {
        ch.trace_open(path).expect("open VCD");
    }
    let mut input = CanChannelIn {
        rst: 1,
        cfg_tseg1: 4,
        cfg_tseg2: 1,
        rx: 1,
        tx_id: 0x123,
        tx_dlc: 8,
        tx_data: 0x5555_5555_5555_5555,
        ..CanChannelIn::default()
    };
    let mut out = CanChannelOut::default();
    for _ in 0..3 {
        ch.step_into(&input, &mut out);
    }
    input.rst = 0;
    if vcd.is_some() {
        for n in 0..2000u64 {
            input.rx = out.tx;
            input.tx_req = (n == 200) as u8;
            ch.step_into(&input, &mut out);
        }
        ch.trace_close();
    }
    let clocks = 20_000_000u64;
    let start = std::time::Instant::now();
    for n in 0..clocks {
        input.rx = out.tx;
        input.tx_req = (n % 4096 == 0) as u8;
        ch.step_into(&input, &mut out);
    }
    let s = start.elapsed().as_secs_f64();
    println!(
        "{clocks} clocks in {s:.2} s = {:.2} M clocks/s ({})",
        clocks as f64 / s / 1e6,
        if exact || !CanChannel::fast_edge() {
            "two evals per clock"
        } else if CanChannel::skips_settled_inputs() {
            "single-eval edge, input logic skipped when no input changed"
        } else {
            "single-eval edge"
        }
    );
}
