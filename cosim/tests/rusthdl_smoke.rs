//! Smoke test of the rust-hdl engine on its own: three channels on a wired-AND
//! bus, two of them starting at the same time; the lower identifier must win
//! arbitration, the loser must retry, and every frame must reach the two other
//! nodes unchanged (the frames come from the test, not from the engine).

use drcc_cosim::engine::rusthdl::RustHdlEngine;
use drcc_cosim::{BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs, Frame};

fn run(frames: &[(usize, Frame)], timing: BitTiming, cycles: usize) -> Vec<Vec<Frame>> {
    let mut nodes: Vec<RustHdlEngine> = (0..3).map(|_| RustHdlEngine::new()).collect();
    let mut outs = [ChannelOutputs {
        tx: true,
        ..Default::default()
    }; 3];
    let mut received = vec![Vec::new(); 3];
    let mut arb_lost = 0;
    for cycle in 0..cycles {
        let bus = outs.iter().all(|o| o.tx);
        for (n, node) in nodes.iter_mut().enumerate() {
            let mut inp = ChannelInputs {
                rst: cycle < 4,
                rx: bus,
                timing,
                ..Default::default()
            };
            if cycle == 10 {
                if let Some((_, f)) = frames.iter().find(|(who, _)| *who == n) {
                    inp.tx_req = true;
                    inp.tx_frame = *f;
                }
            }
            outs[n] = node.step(&inp);
            if outs[n].rx_valid {
                received[n].push(outs[n].rx_frame);
            }
            arb_lost += outs[n].arb_lost as usize;
        }
    }
    assert_eq!(arb_lost, 1, "exactly one node loses arbitration");
    received
}

#[test]
fn three_nodes_contested_arbitration() {
    let a = Frame {
        id: 0x123,
        ide: false,
        rtr: false,
        dlc: 3,
        data: [0xDE, 0xAD, 0xBE, 0, 0, 0, 0, 0],
    };
    let b = Frame {
        id: 0x0ABC_DEF1,
        ide: true,
        rtr: false,
        dlc: 8,
        data: [1, 2, 3, 4, 5, 6, 7, 8],
    };
    let timing = BitTiming {
        brp: 1,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple_sampling: false,
    };
    let got = run(&[(0, a), (1, b)], timing, 16 * 400);
    // Base ID 0x123 vs extended 0x0ABCDEF1 (base part 0x0AB...>>18 = 0x2AF): 0x123 wins.
    assert_eq!(got[2], vec![a, b]);
    assert_eq!(got[1], vec![a]);
    assert_eq!(got[0], vec![b]);
}
