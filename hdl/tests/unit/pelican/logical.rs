//! Tests of `drcc_hdl::pelican::logical` against pelican_contract.md §5
//! (P-LOG-1..4), P-SR-1 (`RS`, `TS`) and P-ERR-1 (`TXERR`, `RXERR`; the
//! SJA1000 data sheet 6.4.12: 127 loaded at bus-off, counted down by the
//! recovery). Expected values are the contract's rules applied by hand.

use drcc_hdl::channel::bsp::field::Field;
use drcc_hdl::pelican::logical::LogicalController;
use rust_hdl::prelude::*;

const SINGLE_A: u64 = 0;
const REDUNDANCY: u64 = 1;
const DMR: u64 = 2;
const SINGLE_B: u64 = 3;
const ACTIVE: u64 = 0;
const PASSIVE: u64 = 1;
const BUS_OFF: u64 = 2;
const VALID: u64 = 0;
const FAILED: u64 = 1;

/// One channel's probes.
#[derive(Clone, Copy)]
struct Chan {
    err_state: u64,
    ew: bool,
    tec: u64,
    rec: u64,
    boff_runs: u64,
    field: Field,
    is_tx: bool,
}

const IDLE: Chan = Chan {
    err_state: ACTIVE,
    ew: false,
    tec: 0,
    rec: 0,
    boff_runs: 0,
    field: Field::Idle,
    is_tx: false,
};

/// The view and core inputs.
#[derive(Clone, Copy)]
struct In {
    mode: u64,
    policy: u64,
    rm: bool,
    hrm: bool,
    rep: bool,
    tx_channel: bool,
    acl: bool,
    aux: [u64; 2],
    ch: [Chan; 2],
}

const OP: In = In {
    mode: SINGLE_A,
    policy: 1,
    rm: false,
    hrm: false,
    rep: false,
    tx_channel: false,
    acl: false,
    aux: [VALID, VALID],
    ch: [IDLE, IDLE],
};

/// The outputs: (u, BS, ES, EP, RS, TS, TXERR, RXERR).
type Out = (bool, bool, bool, bool, bool, bool, u8, u8);

fn eval(i: In) -> Out {
    let mut uut = LogicalController::default();
    uut.connect_all();
    uut.mode.next = i.mode.into();
    uut.policy.next = i.policy.into();
    uut.rm.next = i.rm;
    uut.hrm.next = i.hrm;
    uut.rep.next = i.rep;
    uut.tx_channel.next = i.tx_channel;
    uut.acl.next = i.acl;
    uut.aux_a_state.next = i.aux[0].into();
    uut.aux_b_state.next = i.aux[1].into();
    let [a, b] = i.ch;
    uut.err_state_a.next = a.err_state.into();
    uut.ew_a.next = a.ew;
    uut.tec_a.next = a.tec.into();
    uut.rec_a.next = a.rec.into();
    uut.boff_runs_a.next = a.boff_runs.into();
    uut.field_a.next = a.field;
    uut.is_tx_a.next = a.is_tx;
    uut.err_state_b.next = b.err_state.into();
    uut.ew_b.next = b.ew;
    uut.tec_b.next = b.tec.into();
    uut.rec_b.next = b.rec.into();
    uut.boff_runs_b.next = b.boff_runs.into();
    uut.field_b.next = b.field;
    uut.is_tx_b.next = b.is_tx;
    assert!(simulate(&mut uut, 100));
    (
        uut.u.val(),
        uut.bs.val(),
        uut.es.val(),
        uut.ep.val(),
        uut.rs.val(),
        uut.ts.val(),
        uut.txerr.val().to_u64() as u8,
        uut.rxerr.val().to_u64() as u8,
    )
}

/// P-LOG-1: A, B, the main FSM's channel, the active CAN line.
#[test]
fn p_log_1_channel_in_use() {
    for (tx_channel, acl) in [(false, false), (true, false), (false, true), (true, true)] {
        let i = In {
            tx_channel,
            acl,
            ..OP
        };
        assert!(
            !eval(In {
                mode: SINGLE_A,
                ..i
            })
            .0
        );
        assert!(
            eval(In {
                mode: SINGLE_B,
                ..i
            })
            .0
        );
        assert_eq!(
            eval(In {
                mode: REDUNDANCY,
                ..i
            })
            .0,
            tx_channel
        );
        assert_eq!(eval(In { mode: DMR, ..i }).0, acl);
    }
}

/// P-LOG-4: ES, EP, TXERR, RXERR are channel u's, not the other's.
#[test]
fn p_log_4_status_of_u() {
    let warn = Chan {
        err_state: PASSIVE,
        ew: true,
        tec: 130,
        rec: 9,
        ..IDLE
    };
    let quiet = Chan { rec: 3, ..IDLE };
    let i = In {
        mode: REDUNDANCY,
        ch: [quiet, warn],
        ..OP
    };
    let on_a = eval(i);
    assert_eq!((on_a.2, on_a.3, on_a.6, on_a.7), (false, false, 0, 3));
    let on_b = eval(In {
        tx_channel: true,
        ..i
    });
    assert_eq!((on_b.2, on_b.3, on_b.6, on_b.7), (true, true, 130, 9));
}

/// P-LOG-3: logical bus-off in each mode.
#[test]
fn p_log_3_logical_bus_off() {
    let off = Chan {
        err_state: BUS_OFF,
        tec: 256,
        ..IDLE
    };
    // single modes: u's bus-off, not the other's
    assert!(
        eval(In {
            ch: [off, IDLE],
            ..OP
        })
        .1
    );
    assert!(
        !eval(In {
            mode: SINGLE_B,
            ch: [off, IDLE],
            ..OP
        })
        .1
    );
    // redundancy: only while no switch carries the message to a valid channel
    let red = In {
        mode: REDUNDANCY,
        ch: [off, IDLE],
        ..OP
    };
    assert!(!eval(red).1, "B valid, a policy: the DRCC switches");
    assert!(eval(In { policy: 0, ..red }).1, "policy none: no switch");
    assert!(
        eval(In {
            aux: [VALID, FAILED],
            ..red
        })
        .1,
        "B not valid: no switch"
    );
    // DMR: both lines
    let dmr = In {
        mode: DMR,
        ch: [off, IDLE],
        ..OP
    };
    assert!(!eval(dmr).1);
    assert!(
        eval(In {
            ch: [off, off],
            ..dmr
        })
        .1
    );
}

/// P-ERR-1: 127 minus the recovery's runs while bus-off; 0 in host reset mode.
#[test]
fn p_err_1_counters() {
    let off = Chan {
        err_state: BUS_OFF,
        tec: 256,
        rec: 40,
        boff_runs: 5,
        ..IDLE
    };
    let o = eval(In {
        ch: [off, IDLE],
        ..OP
    });
    assert_eq!((o.6, o.7), (122, 40));
    let done = Chan {
        boff_runs: 127,
        ..off
    };
    assert_eq!(
        eval(In {
            ch: [done, IDLE],
            ..OP
        })
        .6,
        0
    );
    let busy = Chan {
        tec: 200,
        rec: 17,
        ..IDLE
    };
    let o = eval(In {
        ch: [busy, IDLE],
        ..OP
    });
    assert_eq!((o.6, o.7), (200, 17));
    let o = eval(In {
        rm: true,
        hrm: true,
        ch: [busy, IDLE],
        ..OP
    });
    assert_eq!((o.6, o.7), (0, 0));
}

/// P-SR-1: RS, TS from u's role and field; both 1 in reset mode.
#[test]
fn p_sr_1_receive_and_transmit_status() {
    let with = |field: Field, is_tx: bool| {
        let o = eval(In {
            ch: [
                Chan {
                    field,
                    is_tx,
                    ..IDLE
                },
                IDLE,
            ],
            ..OP
        });
        (o.4, o.5)
    };
    assert_eq!(with(Field::Data, true), (false, true));
    assert_eq!(with(Field::Data, false), (true, false));
    assert_eq!(with(Field::ErrorFlag, false), (true, false));
    for quiet in [Field::Idle, Field::Intermission, Field::Suspend] {
        assert_eq!(with(quiet, false), (false, false), "{quiet:?}");
    }
    // waiting for bus idle: both set (DS 6.4.5 Table 14 note 3)
    for waiting in [Field::Integrating, Field::BusOff] {
        assert_eq!(with(waiting, false), (true, true), "{waiting:?}");
    }
    // channel B's activity does not show on A's status
    let o = eval(In {
        ch: [
            IDLE,
            Chan {
                field: Field::Data,
                is_tx: true,
                ..IDLE
            },
        ],
        ..OP
    });
    assert_eq!((o.4, o.5), (false, false));
    let o = eval(In { rm: true, ..OP });
    assert_eq!((o.4, o.5), (true, true));
}

#[test]
fn logical_synthesizes() {
    let mut uut = LogicalController::default();
    uut.connect_all();
    crate::synth_check::yosys_check("logical", &generate_verilog(&uut));
}

/// P-LOG-1, P-LOG-3: through the bus-off hold `u` stays the channel in use at
/// the edge where the hold began, and `BS` is that channel's bus-off, though
/// the held main FSM idles on A and A becomes valid; after the hold `u`
/// follows the main FSM again.
#[test]
fn p_log_1_u_and_bs_kept_through_the_busoff_hold() {
    let mut uut = LogicalController::default();
    uut.connect_all();
    let clock = |uut: &mut LogicalController| {
        uut.clk.next = Clock::from(false);
        assert!(simulate(uut, 100));
        uut.clk.next = Clock::from(true);
        assert!(simulate(uut, 100));
    };
    uut.mode.next = REDUNDANCY.into();
    uut.policy.next = 1u64.into();
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    // on B, B bus-off, A failed: a logical bus-off
    uut.tx_channel.next = true;
    uut.err_state_b.next = BUS_OFF.into();
    uut.aux_a_state.next = FAILED.into();
    assert!(simulate(&mut uut, 100));
    assert!(uut.u.val() && uut.bs.val());
    clock(&mut uut);
    // the hold: the main FSM back on A, A valid again
    uut.boh.next = true;
    uut.tx_channel.next = false;
    uut.aux_a_state.next = VALID.into();
    for _ in 0..3 {
        clock(&mut uut);
        assert!(uut.u.val(), "u kept on B");
        assert!(uut.bs.val(), "BS: B is still bus-off");
    }
    uut.boh.next = false;
    assert!(simulate(&mut uut, 100));
    assert!(
        !uut.u.val() && !uut.bs.val(),
        "after the hold: A carries it"
    );
}

/// P-LOG-5: with `rep`, the other channel reports when it can carry the
/// traffic and ranks better (error state, then warning); a tie keeps `u`;
/// `BS` stays the logical bus-off; single modes and policy `none` keep `u`.
#[test]
fn p_log_5_best_channel_reports() {
    let warn = Chan {
        ew: true,
        tec: 100,
        rec: 3,
        ..IDLE
    };
    let passive = Chan {
        err_state: PASSIVE,
        tec: 130,
        ..IDLE
    };
    let red = In {
        mode: REDUNDANCY,
        rep: true,
        ch: [warn, IDLE],
        ..OP
    };
    // (u, BS, ES, EP, RS, TS, TXERR, RXERR)
    let o = eval(red);
    assert_eq!(
        (o.0, o.2, o.6, o.7),
        (false, false, 0, 0),
        "B reports for A"
    );
    let o = eval(In { rep: false, ..red });
    assert_eq!((o.2, o.6, o.7), (true, 100, 3), "in_use: A's");
    let o = eval(In {
        aux: [VALID, FAILED],
        ..red
    });
    assert_eq!((o.2, o.6), (true, 100), "B not valid: A's");
    let o = eval(In { policy: 0, ..red });
    assert!(o.2, "policy none: no switch, A's");
    let o = eval(In {
        ch: [passive, warn],
        ..red
    });
    assert_eq!(
        (o.2, o.3, o.6),
        (true, false, 100),
        "B warning beats A passive"
    );
    let o = eval(In {
        ch: [warn, warn],
        ..red
    });
    assert_eq!((o.2, o.6), (true, 100), "a tie keeps u");
    let o = eval(In {
        mode: SINGLE_A,
        ..red
    });
    assert_eq!(o.6, 100, "single mode: u");
    let dmr = eval(In {
        mode: DMR,
        acl: true,
        ch: [IDLE, passive],
        ..red
    });
    assert_eq!(
        (dmr.0, dmr.3, dmr.6),
        (true, false, 0),
        "DMR: A reports for B"
    );
}
