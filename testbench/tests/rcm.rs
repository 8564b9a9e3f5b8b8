//! The REDCAN relay module (`ring_contract.md` §2) in lock step: the reference
//! model, the rust-hdl block and the Verilated `rtl-out/rcm.v` on every clock of a
//! random host, with every control word (the illegal `00` included), strobes
//! held for several clocks, and resets in between. The expected decode of each
//! mode is checked against the contract's table on the model's outputs.

use drcc_cosim::engine::rcm::{
    RcmEngine, RcmInputs, RcmModelEngine, RcmOutputs, RcmRustHdlEngine, RcmVerilatorEngine,
};
use drcc_testbench::random::SplitMix64;

/// The contract's table (§2) for a mode in force.
fn decode(mode: u8) -> (bool, bool, bool, bool, bool) {
    match mode {
        3 => (true, true, true, false, false),
        1 => (false, true, false, true, true),
        2 => (false, false, true, true, true),
        m => panic!("mode {m} is never in force"),
    }
}

#[test]
fn rcm_engines_agree_clock_by_clock_and_follow_the_table() {
    let mut engines: Vec<Box<dyn RcmEngine>> = vec![
        Box::<RcmModelEngine>::default(),
        Box::<RcmRustHdlEngine>::default(),
    ];
    if let Some(v) = drcc_tools::verilated("rcm top", RcmVerilatorEngine::new()) {
        engines.push(Box::new(v));
    }
    let mut rng = SplitMix64::new(0x002E_0CA9);
    let (mut refused, mut changes_seen) = (0, 0u32);
    let mut prev: Option<RcmOutputs> = None;
    for cycle in 0..20_000u32 {
        let r = rng.next_u64();
        let i = RcmInputs {
            rst: cycle < 2 || r.is_multiple_of(997),
            ctl_we: r & 0x30 == 0x30,
            ctl: ((r >> 8) & 3) as u8,
        };
        let outs: Vec<RcmOutputs> = engines.iter_mut().map(|e| e.step(&i)).collect();
        for (e, o) in engines.iter().zip(&outs) {
            assert_eq!(
                *o,
                outs[0],
                "cycle {cycle}: {} differs from the model",
                e.name()
            );
        }
        let o = outs[0];
        let (relay, nl, nr, tl, tr) = decode(o.mode);
        assert_eq!(
            (
                o.relay,
                o.node_left,
                o.node_right,
                o.term_left,
                o.term_right
            ),
            (relay, nl, nr, tl, tr),
            "cycle {cycle}: mode {} decodes as the table",
            o.mode
        );
        if i.rst {
            assert_eq!((o.mode, o.illegal, o.changes), (3, false, 0));
        } else if let Some(p) = prev {
            if i.ctl_we && i.ctl == 0 {
                refused += 1;
                assert!(o.illegal && o.mode == p.mode, "cycle {cycle}: 00 refused");
            } else if i.ctl_we {
                assert_eq!(o.mode, i.ctl);
                if i.ctl != p.mode {
                    changes_seen += 1;
                    assert_eq!(o.changes, p.changes.wrapping_add(1));
                }
            } else {
                assert_eq!(o, p, "cycle {cycle}: nothing changes without a write");
            }
        }
        prev = Some(o);
    }
    assert!(
        refused > 100 && changes_seen > 1000,
        "{refused} {changes_seen}"
    );
}
