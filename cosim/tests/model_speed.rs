//! Rough speed of the reference model in release mode (no timed assertions):
//! `cargo test -p drcc-cosim --release --test model_speed -- --ignored --nocapture`.

use drcc_cosim::model::ChannelModel;
use drcc_cosim::{BitTiming, ChannelInputs, Frame};
use std::time::Instant;

fn run(timing: BitTiming, clocks: u64) -> (f64, u64) {
    // Two channels on a wired-AND bus, both transmitting back to back.
    let mut nodes = [ChannelModel::new(), ChannelModel::new()];
    let mut tx = [true; 2];
    let frames = [
        Frame {
            id: 0x123,
            ide: false,
            rtr: false,
            dlc: 8,
            data: [0x55; 8],
        },
        Frame {
            id: 0x1ABCDEF,
            ide: true,
            rtr: false,
            dlc: 8,
            data: [0x0F; 8],
        },
    ];
    let mut delivered = 0u64;
    let start = Instant::now();
    for _ in 0..clocks {
        let rx = tx[0] && tx[1];
        for i in 0..2 {
            let out = nodes[i].step(&ChannelInputs {
                rst: false,
                rx,
                timing,
                tx_req: true,
                tx_frame: frames[i],
                ..Default::default()
            });
            tx[i] = out.tx;
            delivered += out.tx_done as u64;
        }
    }
    let secs = start.elapsed().as_secs_f64();
    ((2 * clocks) as f64 / secs, delivered)
}

#[test]
#[ignore]
fn model_speed() {
    let clocks = 20_000_000;
    for brp in [0u16, 3] {
        let timing = BitTiming {
            brp,
            tseg1: 5,
            tseg2: 2,
            sjw: 1,
            triple_sampling: false,
        };
        let (rate, delivered) = run(timing, clocks);
        println!(
            "brp {brp}: {:.1} M channel-clocks/s ({delivered} frames delivered)",
            rate / 1e6
        );
        assert!(delivered > 0);
    }
}
