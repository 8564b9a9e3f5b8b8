//! DMR register interface on all three engines (DMR contract §2; bad
//! input): every illegal DMR configuration of §2.2 is refused (nothing stored,
//! `INT_STATUS.illegal` set), legal ones are stored and read back, and a mode
//! change outside reset mode is refused. One Wishbone script drives the model,
//! rust-hdl's simulator and the Verilated RTL in lock step (every output compared
//! at every clock); the expected read values come from the contract and the
//! register table, checked on the model's reads.
//!
//! The last test leaves reset mode in DMR mode with each channel alone on its own
//! wire: the DMR function (§3-§7) runs on all three engines in lock step; the plan's
//! network runs (`dmr_plan.rs`) compare it on four devices with the Verilated RTL.

use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::engine::drcc_rusthdl;
use drcc_cosim::engine::drcc_verilator::{DrccM0VerilatorEngine, DrccVerilatorEngine};
use drcc_hdl::host::registers::{self as map, ChannelMode, Mode, SwitchPolicy, MAP};

/// The engines in lock step; reads return the model's data.
struct Bench {
    engines: Vec<Box<dyn DrccEngine>>,
    cycle: u64,
    /// Each channel's rx pin reads its own tx pin (a wire with no other node).
    self_loop: bool,
    last: DrccOutputs,
}

impl Bench {
    /// The `drcc` top (16 DMR mailboxes) on three engines.
    fn new() -> Self {
        let mut engines: Vec<Box<dyn DrccEngine>> =
            vec![Box::new(DrccModelEngine::new()), drcc_rusthdl::drcc()];
        if let Some(v) = drcc_tools::verilated("drcc top", DrccVerilatorEngine::new()) {
            engines.push(Box::new(v));
        }
        Self::start(engines)
    }

    /// The `drcc_m0` top (no DMR mailboxes) on three engines; the model is built
    /// with `M = 0`.
    fn without_mailboxes() -> Self {
        let mut engines: Vec<Box<dyn DrccEngine>> = vec![
            Box::new(DrccModelEngine::with_mailboxes(0)),
            drcc_rusthdl::drcc_m0(),
        ];
        if let Some(v) = drcc_tools::verilated("drcc_m0 top", DrccM0VerilatorEngine::new()) {
            engines.push(Box::new(v));
        }
        Self::start(engines)
    }

    fn start(engines: Vec<Box<dyn DrccEngine>>) -> Self {
        let mut b = Bench {
            engines,
            cycle: 0,
            self_loop: false,
            last: DrccOutputs::default(),
        };
        for _ in 0..3 {
            b.step(DrccInputs {
                rst: true,
                chan_a_rx: true,
                chan_b_rx: true,
                ..Default::default()
            });
        }
        b
    }

    /// One clock on every engine; the CAN pins read recessive (no bus).
    fn step(&mut self, mut i: DrccInputs) -> DrccOutputs {
        if self.self_loop {
            i.chan_a_rx = self.last.chan_a_tx;
            i.chan_b_rx = self.last.chan_b_tx;
        }
        let outs: Vec<DrccOutputs> = self.engines.iter_mut().map(|e| e.step(&i)).collect();
        for (e, o) in self.engines.iter().zip(&outs).skip(1) {
            assert_eq!(
                o,
                &outs[0],
                "cycle {}: {} differs from the model",
                self.cycle,
                e.name()
            );
        }
        self.cycle += 1;
        self.last = outs[0];
        outs[0]
    }

    fn access(&mut self, we: bool, adr: u32, dat: u32) -> u32 {
        let idle = DrccInputs {
            chan_a_rx: true,
            chan_b_rx: true,
            ..Default::default()
        };
        let o = self.step(DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr as u8,
            wb_dat_w: dat,
            ..idle
        });
        assert!(o.wb_ack != o.wb_err, "no answer");
        self.step(idle);
        o.wb_dat_r
    }

    fn write(&mut self, adr: u32, dat: u32) {
        self.access(true, adr, dat);
    }

    fn read(&mut self, adr: u32) -> u32 {
        self.access(false, adr, 0)
    }

    /// Writes `dat` to `adr` and tells whether it was refused (INT_STATUS.illegal,
    /// which is cleared again).
    fn refused(&mut self, adr: u32, dat: u32) -> bool {
        let illegal = MAP.field("INT_STATUS", "illegal").put(1);
        assert_eq!(self.read(map::INT_STATUS) & illegal, 0, "illegal was clear");
        self.write(adr, dat);
        let r = self.read(map::INT_STATUS) & illegal != 0;
        self.write(map::INT_STATUS, illegal);
        r
    }
}

fn put(reg: &str, field: &str, v: u32) -> u32 {
    MAP.field(reg, field).put(v)
}

/// A CTRL word in reset mode with the given extra fields (policy error-passive, k 1).
fn ctrl(reset_mode: bool, fields: &[(&str, u32)]) -> u32 {
    fields.iter().fold(
        put("CTRL", "reset_mode", reset_mode as u32)
            | put("CTRL", "policy", SwitchPolicy::ErrorPassive.code())
            | put("CTRL", "k", 1),
        |w, (f, v)| w | put("CTRL", f, *v),
    )
}

#[test]
fn dmr_configuration_is_refused_or_stored_as_the_contract_says() {
    let mut b = Bench::new();
    // reset values (§2.1, the table)
    assert_eq!(
        b.read(map::DMR_CFG),
        100,
        "timeout 100 ticks, no periodic CS"
    );
    assert_eq!(
        b.read(map::DMR_TIME),
        125 | (2000 << 16),
        "1 ms ticks, 2 s delay"
    );
    assert_eq!(b.read(map::DMR_CS), 0x7EA | (0x7EB << 16));
    assert_eq!(b.read(map::MB_SEL), 0);
    assert_eq!(b.read(map::MB_CFG), 3, "limit 3, disabled");
    assert_eq!(b.read(map::DMR_STATUS), 0, "redundancy active, ACL = DCL");

    // §2.2: zero durations are refused and nothing is stored
    assert!(b.refused(map::DMR_CFG, 7 << 16), "timeout 0");
    assert!(b.refused(map::DMR_TIME, 2000 << 16), "tick_bits 0");
    assert!(b.refused(map::DMR_TIME, 125), "recovery_delay 0");
    assert_eq!(b.read(map::DMR_CFG), 100);
    assert_eq!(b.read(map::DMR_TIME), 125 | (2000 << 16));
    assert!(!b.refused(map::DMR_CFG, 50 | (7 << 16)));
    assert!(!b.refused(map::DMR_TIME, 16 | (300 << 16)));
    assert_eq!(b.read(map::DMR_CFG), 50 | (7 << 16));
    assert_eq!(b.read(map::DMR_TIME), 16 | (300 << 16));

    // §2.2: equal CS identifiers are refused
    assert!(b.refused(map::DMR_CS, 0x100 | (0x100 << 16)));
    assert!(!b.refused(map::DMR_CS, 0x120 | (0x121 << 16)));
    assert_eq!(b.read(map::DMR_CS), 0x120 | (0x121 << 16));

    // mailbox 2: an identifier equal to a CS identifier cannot be enabled
    let enable = put("MB_CFG", "enable", 1);
    assert!(!b.refused(map::MB_SEL, 2));
    assert!(
        !b.refused(map::MB_ID, 0x120),
        "stored while the mailbox is disabled"
    );
    assert_eq!(b.read(map::MB_ID), 0x120);
    assert!(
        b.refused(map::MB_CFG, enable | 5),
        "enabling a CS identifier"
    );
    assert_eq!(b.read(map::MB_CFG), 3, "nothing stored");
    // an extended identifier with the same low bits is not a CS identifier
    let ext = put("MB_ID", "ide", 1);
    assert!(!b.refused(map::MB_ID, ext | 0x120));
    assert!(!b.refused(map::MB_CFG, enable | 5));
    assert!(!b.refused(map::MB_ID, 0x300 | put("MB_ID", "dir", 1)));
    assert_eq!(b.read(map::MB_CFG), enable | 5);
    assert!(
        b.refused(map::MB_ID, 0x121),
        "a CS identifier into an enabled mailbox"
    );
    assert_eq!(b.read(map::MB_ID), 0x300 | put("MB_ID", "dir", 1));
    assert!(b.refused(map::MB_CFG, enable), "limit 0");
    assert!(!b.refused(map::MB_CFG, 9), "limit 9, disabled");
    assert!(!b.refused(map::MB_CFG, enable | 9));
    // §2.2: the CS identifiers cannot change while a mailbox is enabled
    assert!(b.refused(map::DMR_CS, 0x130 | (0x131 << 16)));
    assert!(!b.refused(map::MB_MASK, 0x1FFF_FFFF));
    assert_eq!(b.read(map::MB_MASK), 0x1FFF_FFFF);
    // mailbox 0 kept its reset values
    assert!(!b.refused(map::MB_SEL, 0));
    assert_eq!(b.read(map::MB_CFG), 3);
    assert_eq!(b.read(map::MB_ID), 0);

    // §2: DMR with redundancy, or with a listen-only channel, is refused as a whole
    let listen = ChannelMode::ListenOnly.code();
    let red = Mode::Redundancy.code();
    assert!(b.refused(map::CTRL, ctrl(true, &[("dmr", 1), ("redundancy", red)])));
    assert!(b.refused(map::CTRL, ctrl(true, &[("dmr", 1), ("mode_b", listen)])));
    assert_eq!(b.read(map::CTRL) & put("CTRL", "dmr", 1), 0);
    assert!(!b.refused(map::CTRL, ctrl(true, &[("dmr", 1)])));
    assert_eq!(b.read(map::CTRL), ctrl(true, &[("dmr", 1)]));
    // §2: first-copy delivery is a cfg field of its own
    let first_copy = [("dmr", 1), ("first_copy", 1)];
    assert!(!b.refused(map::CTRL, ctrl(true, &first_copy)));
    assert_eq!(b.read(map::CTRL), ctrl(true, &first_copy));
    assert!(!b.refused(map::CTRL, ctrl(true, &[])));

    // outside reset mode (normal mode): no mode change, no DMR configuration;
    // the mailbox configuration reads 0, MB_SEL stays writable
    assert!(!b.refused(map::CTRL, ctrl(false, &[])));
    assert!(
        b.refused(map::CTRL, ctrl(false, &[("dmr", 1)])),
        "mode change"
    );
    assert!(
        b.refused(map::CTRL, ctrl(false, &[("first_copy", 1)])),
        "a cfg field outside reset mode"
    );
    assert_eq!(b.read(map::CTRL), ctrl(false, &[]));
    assert!(b.refused(map::DMR_CFG, 60));
    assert!(b.refused(map::DMR_TIME, 125 | (2000 << 16)));
    assert!(b.refused(map::MB_CFG, 4));
    assert!(b.refused(map::MB_ID, 0x200));
    assert!(!b.refused(map::MB_SEL, 2));
    assert_eq!(b.read(map::MB_SEL), 2);
    assert_eq!(b.read(map::MB_ID), 0);
    assert_eq!(b.read(map::MB_CFG), 0);
    assert_eq!(b.read(map::DMR_CFG), 50 | (7 << 16), "unchanged");
    // read-only DMR registers refuse writes
    assert!(b.refused(map::DMR_STATUS, 1));
    assert!(b.refused(map::MB_STATE, 1));
    // back in reset mode the stored mailbox 2 reads back again
    assert!(!b.refused(map::CTRL, ctrl(true, &[])));
    assert_eq!(b.read(map::MB_CFG), enable | 9);
    assert_eq!(b.read(map::MB_MASK), 0x1FFF_FFFF);
}

/// `DMR_STATUS` fields (§2.1): (dmr_state, acl, cause, state_changes, acl_switches).
fn dmr_status(w: u32) -> (u32, u32, u32, u32, u32) {
    (w & 3, w >> 2 & 1, w >> 8 & 3, w >> 16 & 0xFF, w >> 24)
}

#[test]
fn dmr_function_alone_on_its_wires_on_three_engines() {
    let mut b = Bench::new();
    // mailbox 0: transmit, identifier 0x100
    b.write(map::MB_SEL, 0);
    b.write(map::MB_ID, 0x100 | put("MB_ID", "dir", 1));
    b.write(map::MB_MASK, 0x7FF);
    b.write(map::MB_CFG, put("MB_CFG", "enable", 1) | 2);
    alone_on_its_wires(b);
}

/// `drcc_m0` (§2, `M = 0`): `MB_SEL` and every window write are refused, the window
/// reads 0, the rest of the DMR configuration is taken; on model, rust-hdl and
/// Verilator in lock step.
#[test]
fn dmr_without_mailboxes_refuses_the_window_on_three_engines() {
    let mut b = Bench::without_mailboxes();
    let enable = put("MB_CFG", "enable", 1);
    assert!(b.refused(map::MB_SEL, 0), "MB_SEL 0 >= M = 0");
    assert!(b.refused(map::MB_SEL, 3));
    assert!(b.refused(map::MB_ID, 0x100 | put("MB_ID", "dir", 1)));
    assert!(b.refused(map::MB_MASK, 0x7FF));
    assert!(b.refused(map::MB_CFG, enable | 2));
    assert!(b.refused(map::MB_CFG, 2), "a disabled mailbox too");
    for reg in [
        map::MB_SEL,
        map::MB_ID,
        map::MB_MASK,
        map::MB_CFG,
        map::MB_STATE,
    ] {
        assert_eq!(b.read(reg), 0, "window register {reg} reads 0 with M = 0");
    }
    // the rest of §2.2 holds as with mailboxes
    assert!(b.refused(map::DMR_CFG, 7 << 16), "timeout 0");
    assert!(
        b.refused(map::DMR_CS, 0x100 | (0x100 << 16)),
        "equal CS ids"
    );
    assert!(!b.refused(map::DMR_CS, 0x120 | (0x121 << 16)));
    assert_eq!(b.read(map::DMR_CS), 0x120 | (0x121 << 16));
    // outside reset mode the window stays refused
    assert!(!b.refused(map::CTRL, ctrl(false, &[])));
    assert!(b.refused(map::MB_SEL, 0));
    assert_eq!(b.read(map::MB_STATE), 0);
}

/// `drcc_m0` in DMR mode alone on its wires: no mailbox can judge a line, and the
/// connection service still finds both (§7), as with mailboxes.
#[test]
fn dmr_without_mailboxes_alone_on_its_wires_on_three_engines() {
    alone_on_its_wires(Bench::without_mailboxes());
}

/// DMR mode with each channel alone on its own wire, two host messages queued:
/// both CS attempts fail at the CS timeout (nobody acknowledges), the device is
/// "network disconnected", and the recovery restarts the DCL channel.
fn alone_on_its_wires(mut b: Bench) {
    b.self_loop = true;
    // 1 DMR tick = 16 bit times = 128 clocks (8 clocks per bit at the reset BTR);
    // CS timeout 8 ticks, recovery delay 4 ticks
    b.write(map::DMR_TIME, 16 | (4 << 16));
    b.write(map::DMR_CFG, 8);
    b.write(map::INT_ENABLE, put("INT_STATUS", "dmr", 1));
    b.write(map::CTRL, ctrl(true, &[("dmr", 1)]));
    b.write(map::CTRL, ctrl(false, &[("dmr", 1)]));
    for _ in 0..2 {
        b.write(map::TX_ID, 0x100);
        b.write(map::TX_CTRL, 1);
        b.write(map::TX_DATA0, 0x55);
        b.write(map::TX_CMD, 1);
    }
    let idle = DrccInputs {
        chan_a_rx: true,
        chan_b_rx: true,
        ..Default::default()
    };
    // Every clock the engines agree (Bench::step). Watch the DCL's transmit error
    // counter: ACK errors raise it, the recovery's channel restart clears it.
    let (mut tec_max, mut restarted, mut first_fault) = (0, false, None);
    while b.cycle < 4_000 {
        let o = b.step(idle);
        let tec = o.probes.chan_a_bsp_tx_err_cnt;
        if tec_max > 0 && tec == 0 {
            restarted = true;
        }
        tec_max = tec_max.max(tec);
        if first_fault.is_none() && o.probes.dcl_tx_fault && o.probes.rcl_tx_fault {
            first_fault = Some(b.cycle);
        }
    }
    // §7: no other node acknowledges the CS frames (ISO 11898-1: a transmitter does
    // not acknowledge its own frame), so each line's attempt fails after the CS
    // timeout: 8 ticks = 1024 clocks after it started, both lines at the same tick.
    let at = first_fault.expect("both lines failed their CS attempt");
    assert!(
        (1024..1024 + 2 * 128 + 200).contains(&at),
        "CS failure at {at}"
    );
    let (state, acl, cause, changes, switches) = dmr_status(b.read(map::DMR_STATUS));
    assert_eq!(state, 3, "network disconnected");
    assert_eq!(cause, 3, "CS failed");
    assert_eq!(
        (acl, switches),
        (0, 0),
        "both lines failed at one edge: no ACL switch (§6)"
    );
    assert_eq!(changes, 1, "active -> disconnected, then it stays");
    assert!(tec_max >= 8, "ACK errors on the CS frames");
    assert!(restarted, "the recovery restarted the DCL channel (§7)");
    // §5: the host copies wait behind the CS frame and then behind the faults
    assert_eq!(
        b.read(map::STATUS) >> 16 & 0xF,
        2,
        "both messages still queued"
    );
    assert_ne!(b.read(map::INT_STATUS) & put("INT_STATUS", "dmr", 1), 0);
    assert_eq!(b.read(map::DMR_CS_COUNT), 0, "no CS frame was received");
}
