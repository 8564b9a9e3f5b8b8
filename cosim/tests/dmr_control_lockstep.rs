//! Block-level lock-step of the DMR control (`drcc_hdl::dmr::control::DmrControl`)
//! against the reference model's `DmrBlock` (`dmr_contract.md` §3, §5-§7): both get
//! the same seeded random inputs every clock, inputs that keep the channel's
//! protocol (a `tx_done` / `tx_failed` only for an attempt the block requested, an
//! abort ends it soon, a restart or reset cancels it), and every output and every
//! observable register is compared after every edge.
//!
//! The engine is not part of the block. How its events are checked:
//! 1. the raises (`raise_*`, `key_*`) are compared each edge with the events §4.1
//!    names, derived from the model's registers before the edge (`REQ(L)` = the
//!    `req` register with the read data's key, `TX(L)` = `tx_done` of a host copy
//!    while neither line has `tx_fault` with `key_sent`, `RX(L)` = the model's
//!    `rx_deliver` with the frame's key);
//! 2. a shadow of the model's engine (a clone of `eng` and `mbx` before the edge,
//!    stepped with the block's raises, then `clear_state` if the block says
//!    `clear_mailboxes`) must equal the model's `eng` and `mbx` after the edge: the
//!    model's engine latched exactly what the block raised (flags, keys, jobs);
//! 3. the shadow's verdict is what the block gets on `eval_*` (the verdict at the
//!    edge of the fault). With every mailbox disabled (first test) there is none;
//!    the second test enables mailboxes whose keys the traffic uses, so the model's
//!    own evaluation judges lines and the block hears the same verdict.

#[path = "dmr_control_lockstep/bench.rs"]
mod bench;
#[path = "dmr_control_lockstep/checks.rs"]
mod checks;
#[path = "dmr_control_lockstep/stimulus.rs"]
mod stimulus;

use bench::Bench;
use checks::Coverage;

fn report(name: &str, cov: &Coverage) {
    eprintln!("{name}: {cov:#?}");
}

fn check_coverage(cov: &Coverage, mailboxes: bool) {
    let named = [
        ("holds", cov.holds),
        ("rsts", cov.rsts),
        ("dmr_ticks", cov.dmr_ticks),
        ("host_req DCL", cov.host_req[0]),
        ("host_req RCL", cov.host_req[1]),
        ("cs_req DCL", cov.cs_req[0]),
        ("cs_req RCL", cov.cs_req[1]),
        ("periodic_cs", cov.periodic_cs),
        ("first_copies", cov.first_copies),
        ("pops", cov.pops),
        ("cs_success", cov.cs_success),
        ("recoveries", cov.recoveries),
        ("cs_failed", cov.cs_failed),
        ("busoff", cov.busoff),
        ("deletion_abort", cov.deletion_abort),
        ("cs_abort", cov.cs_abort),
        ("returns", cov.returns),
        ("restarts", cov.restarts),
        ("acl_switches", cov.acl_switches),
        ("state active", cov.state[0]),
        ("state disabled", cov.state[2]),
        ("state disconnected", cov.state[3]),
        ("cs_good", cov.cs_good),
        ("cs_bad", cov.cs_bad),
        ("raise_tx", cov.raise_tx),
        ("raise_rx", cov.raise_rx),
        ("raise_req", cov.raise_req),
        ("raise_eval", cov.raise_eval),
    ];
    for (n, v) in named {
        assert!(v > 0, "coverage: {n} never reached");
    }
    if mailboxes {
        for (n, v) in [
            ("eval tx fault", cov.eval_tx),
            ("eval rx fault", cov.eval_rx),
            ("eval rx fault on a tx-faulty line", cov.eval_rx_ignored),
            ("state passive", cov.state[1]),
        ] {
            assert!(v > 0, "coverage: {n} never reached");
        }
    }
}

const CLOCKS: u64 = 40_000;

/// Every mailbox disabled: the engine never judges; everything else of the block.
#[test]
fn dmr_control_lockstep_no_verdicts() {
    let mut total = Coverage::default();
    for seed in [1u64, 2, 3, 4] {
        let mut b = Bench::new(seed, false);
        b.run(CLOCKS);
        report(&format!("seed {seed}"), &b.cov);
        add(&mut total, &b.cov);
    }
    report("total", &total);
    check_coverage(&total, false);
    assert_eq!(total.eval_tx + total.eval_rx + total.eval_rx_ignored, 0);
}

/// Mailboxes enabled over the traffic's keys: the model's evaluation judges the
/// lines (deviations and timeouts, transmit and receive), the block gets the same
/// verdict on `eval_*`.
#[test]
fn dmr_control_lockstep_with_verdicts() {
    let mut total = Coverage::default();
    for seed in [11u64, 12, 13, 14] {
        let mut b = Bench::new(seed, true);
        b.run(CLOCKS);
        report(&format!("seed {seed}"), &b.cov);
        add(&mut total, &b.cov);
    }
    report("total", &total);
    check_coverage(&total, true);
}

fn add(t: &mut Coverage, c: &Coverage) {
    macro_rules! sum {
        ($($f:ident),*) => { $( t.$f += c.$f; )* };
    }
    sum!(
        edges,
        holds,
        rsts,
        dmr_ticks,
        periodic_cs,
        first_copies,
        pops,
        cs_success,
        recoveries,
        cs_failed,
        busoff,
        eval_tx,
        eval_rx,
        eval_rx_ignored,
        deletion_abort,
        cs_abort,
        returns,
        restarts,
        acl_switches,
        cs_good,
        cs_bad,
        raise_tx,
        raise_rx,
        raise_req,
        raise_eval
    );
    for l in 0..2 {
        t.host_req[l] += c.host_req[l];
        t.cs_req[l] += c.cs_req[l];
    }
    for s in 0..4 {
        t.state[s] += c.state[s];
    }
}
