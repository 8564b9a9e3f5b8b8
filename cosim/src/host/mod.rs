//! The host side of one DRCC node: a Wishbone B4 classic master that runs a small
//! driver program, the way firmware on a soft CPU would:
//!
//! 1. configuration: `CTRL` (reset mode + configuration), `BTR`, `RMB_CFG`,
//!    `DEDUP_CFG`, in DMR mode the DMR registers and mailboxes
//!    ([`dmr_config`]), `INT_ENABLE`, then `CTRL` with reset mode cleared;
//! 2. forever: when a submitted frame is due, read `STATUS` and, if its TX queue has
//!    room, write `TX_ID`, `TX_CTRL`, `TX_DATA0/1` and `TX_CMD.push`; otherwise poll
//!    `RX_ID` and, when the FIFO is not empty, read the frame and pop it; explicit
//!    register reads asked for by a test go first.
//!
//! The driver only reacts to the DUT's outputs of the previous clock, so two engines
//! that agree clock by clock get identical stimulus. Register indices, field
//! positions and codes come from drcc-hdl's register table (the one source of the
//! map, which also generates `rtl-out/drcc_regs.h`), as firmware would take them
//! from that header; the reference model keeps its own copy, checked against the
//! table by `cosim/tests/register_maps.rs`.

use crate::engine::drcc::{DrccInputs, DrccOutputs};
use crate::frame::Frame;
use drcc_hdl::host::map::Field;
use drcc_hdl::host::registers::{SwitchPolicy, MAP};
use std::collections::VecDeque;
use std::sync::LazyLock;

pub mod dmr_config;
pub mod ecss_config;
pub mod reg;

use dmr_config::DmrConfig;
use ecss_config::EcssConfig;

/// `reg.field` placed in a register word (positions from the table).
fn put(reg: &str, field: &str, value: u32) -> u32 {
    MAP.field(reg, field).put(value)
}

/// `reg.field` of a register word.
fn get(reg: &str, field: &str, word: u32) -> u32 {
    MAP.field(reg, field).get(word)
}

/// `RX_ID.rx_ready`, looked up once: the host polls `RX_ID` every other clock,
/// and a lookup by name there was a twentieth of a campaign's time.
static RX_READY: LazyLock<&'static Field> = LazyLock::new(|| MAP.field("RX_ID", "rx_ready"));

/// Transmit policy of redundancy mode (`CTRL.policy`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Policy {
    /// Never switch (channel A only).
    None,
    /// The paper's policy: switch when the channel is error passive.
    ErrorPassive,
    /// Switch after `k` failed attempts (1..=15).
    KFailed(u8),
    /// Switch when the channel's TEC or REC reaches the warning limit `ewl`
    /// (DRCC contract §5, policy 3).
    Warning,
}

/// What the host writes at start-up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HostConfig {
    /// `BTR` register value.
    pub btr: u32,
    /// Redundancy mode (else normal mode).
    pub redundancy: bool,
    /// Redundancy policy.
    pub policy: Policy,
    /// Send every message on both channels (`CTRL.dual_tx`).
    pub dual_tx: bool,
    /// Replicated star node (`CTRL.star`, DRCC contract §4.4): the other channel's
    /// echo of an own frame completes the message.
    pub star: bool,
    /// Channel modes (contract §C.7 codes) of A and B.
    pub mode_a: u8,
    pub mode_b: u8,
    /// Error-free bit times before a failed channel is used again.
    pub recovery_bits: u16,
    /// Stall limit in bit times (0 = off).
    pub stall_limit: u16,
    /// Duplicate window in bit times (0 = off, at most 32767).
    pub dedup_window: u16,
    /// `INT_ENABLE`.
    pub int_enable: u32,
    /// CiA 701 DMR mode (`CTRL.dmr`) with its configuration; `redundancy` must then
    /// be false (the DRCC refuses both, DMR contract §2).
    pub dmr: Option<DmrConfig>,
    /// Entries per TX queue of the DRCC generated (drcc_contract.md §1.1): the
    /// driver pushes only while a queue holds fewer (firmware is built for its
    /// configuration; 8 in the default).
    pub tx_queue_depth: u32,
    /// `CTRL.busoff_manual` (DRCC contract §11.6): a bus-off channel recovers
    /// only after the host's `TX_CMD.recover_x`.
    pub busoff_manual: bool,
    /// The ECSS bus selection (DRCC contract §12), enabled with these values.
    pub ecss: Option<EcssConfig>,
}

impl Default for HostConfig {
    fn default() -> Self {
        HostConfig {
            // brp 0, TSEG1 5, TSEG2 2, SJW 1 (minus-one fields), EWL 96.
            btr: btr(0, 5, 2, 1, false, 96),
            redundancy: true,
            policy: Policy::ErrorPassive,
            dual_tx: false,
            star: false,
            mode_a: 0,
            mode_b: 0,
            recovery_bits: 1024,
            stall_limit: 0,
            dedup_window: 1024,
            // every interrupt
            int_enable: MAP.register("INT_ENABLE").map_or(0, |r| r.defined()),
            dmr: None,
            tx_queue_depth: 8,
            busoff_manual: false,
            ecss: None,
        }
    }
}

/// `BTR` value for the given timing in time quanta (brp 0..=1023, tseg1 1..=16,
/// tseg2 1..=8, sjw 1..=4): BRP[5:0] in `brp`, BRP[9:6] in `brp_ext`.
pub fn btr(brp: u16, tseg1: u8, tseg2: u8, sjw: u8, triple: bool, ewl: u8) -> u32 {
    put("BTR", "brp", brp as u32 & 0x3F)
        | put("BTR", "brp_ext", (brp as u32 >> 6) & 0xF)
        | put("BTR", "tseg1", tseg1.saturating_sub(1) as u32)
        | put("BTR", "tseg2", tseg2.saturating_sub(1) as u32)
        | put("BTR", "sjw", sjw.saturating_sub(1) as u32)
        | put("BTR", "triple", triple as u32)
        | put("BTR", "ewl", ewl as u32)
}

impl HostConfig {
    /// `CTRL` value with the given reset-mode bit.
    pub fn ctrl(&self, reset_mode: bool) -> u32 {
        let (policy, k) = match self.policy {
            Policy::None => (SwitchPolicy::None, 1),
            Policy::ErrorPassive => (SwitchPolicy::ErrorPassive, 1),
            Policy::KFailed(k) => (SwitchPolicy::KFailed, k as u32),
            Policy::Warning => (SwitchPolicy::Warning, 1),
        };
        put("CTRL", "reset_mode", reset_mode as u32)
            | put("CTRL", "redundancy", self.redundancy as u32)
            | put("CTRL", "policy", policy.code())
            | put("CTRL", "dual_tx", self.dual_tx as u32)
            | put("CTRL", "star", self.star as u32)
            | put("CTRL", "k", k)
            | put("CTRL", "mode_a", self.mode_a as u32)
            | put("CTRL", "mode_b", self.mode_b as u32)
            | put("CTRL", "dmr", self.dmr.is_some() as u32)
            | put("CTRL", "busoff_manual", self.busoff_manual as u32)
            | put(
                "CTRL",
                "first_copy",
                self.dmr.is_some_and(|d| d.first_copy) as u32,
            )
    }

    /// DMR mode (redundancy off) with `dmr`, the given bit timing and duplicate
    /// window (in DMR mode the window of the ACL rule, DMR contract §8).
    pub fn dmr(btr: u32, dmr: DmrConfig, dedup_window: u16) -> Self {
        HostConfig {
            btr,
            redundancy: false,
            dual_tx: false,
            dedup_window,
            dmr: Some(dmr),
            ..HostConfig::default()
        }
    }

    /// Whether the host hands every frame to TX queue A: redundancy mode, and DMR
    /// mode (its one logical queue, DMR contract §5).
    fn one_queue(&self) -> bool {
        self.redundancy || self.dmr.is_some()
    }
}

/// A frame the host read from the RX FIFO.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HostRx {
    /// Clock at which the pop was acknowledged.
    pub cycle: u64,
    pub frame: Frame,
    /// Channel the frame came from (0 = A, 1 = B).
    pub channel: u8,
}

/// A frame the host handed to the DRCC.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HostTx {
    /// Clock at which the push was acknowledged.
    pub cycle: u64,
    pub frame: Frame,
    /// Queue (normal mode: 0 = A, 1 = B).
    pub queue: u8,
}

/// A register read asked for by a test, and its result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HostRead {
    pub cycle: u64,
    pub reg: u8,
    pub value: u32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Purpose {
    Config,
    Write,
    TxSpace,
    TxWrite,
    TxPush,
    RxId,
    RxCtrl,
    RxData0,
    RxData1,
    RxPop,
    Explicit,
}

#[derive(Clone, Copy, Debug)]
struct Op {
    write: bool,
    reg: u8,
    value: u32,
    /// Byte lanes of a write (bus_contract.md §1).
    sel: u8,
    purpose: Purpose,
}

#[derive(Clone, Copy, Debug)]
struct Submission {
    due: u64,
    frame: Frame,
    queue: u8,
}

/// One node's host: configuration, transmit submissions, RX FIFO draining.
#[derive(Clone, Debug)]
pub struct HostDriver {
    config: HostConfig,
    ops: VecDeque<Op>,
    current: Option<Op>,
    submissions: VecDeque<Submission>,
    explicit: VecDeque<(u8, Option<(u32, u8)>)>,
    rx_partial: (Frame, u8),
    pushing: Option<Submission>,
    /// Frames pushed, frames popped, explicit reads.
    pub sent: Vec<HostTx>,
    pub received: Vec<HostRx>,
    pub reads: Vec<HostRead>,
    configured: bool,
}

impl HostDriver {
    /// A driver that will configure the DRCC with `config` after reset.
    pub fn new(config: HostConfig) -> Self {
        let mut d = HostDriver {
            config,
            ops: VecDeque::new(),
            current: None,
            submissions: VecDeque::new(),
            explicit: VecDeque::new(),
            rx_partial: (Frame::default(), 0),
            pushing: None,
            sent: Vec::new(),
            received: Vec::new(),
            reads: Vec::new(),
            configured: false,
        };
        let c = config;
        let mut writes = vec![
            (reg::CTRL, c.ctrl(true)),
            (reg::BTR, c.btr),
            (
                reg::RMB_CFG,
                put("RMB_CFG", "recovery_bits", c.recovery_bits as u32)
                    | put("RMB_CFG", "stall_limit", c.stall_limit as u32),
            ),
            (
                reg::DEDUP_CFG,
                put("DEDUP_CFG", "window", c.dedup_window as u32),
            ),
        ];
        if let Some(dmr) = c.dmr {
            writes.extend(dmr.writes());
        }
        if let Some(ecss) = c.ecss {
            writes.extend(ecss.writes());
        }
        writes.push((reg::INT_ENABLE, c.int_enable));
        writes.push((reg::CTRL, c.ctrl(false)));
        for (reg, value) in writes {
            d.ops.push_back(Op {
                write: true,
                reg,
                value,
                sel: 0xF,
                purpose: Purpose::Config,
            });
        }
        d
    }

    /// The configuration written at start-up.
    pub fn config(&self) -> &HostConfig {
        &self.config
    }

    /// Queues `frame` for transmission once the clock reaches `due` (queue 0 = A,
    /// 1 = B; redundancy mode ignores the queue).
    pub fn submit(&mut self, due: u64, frame: Frame, queue: u8) {
        let pos = self
            .submissions
            .iter()
            .position(|s| s.due > due)
            .unwrap_or(self.submissions.len());
        self.submissions.insert(
            pos,
            Submission {
                due,
                frame,
                queue: queue & 1,
            },
        );
    }

    /// Asks for one register read (result in [`HostDriver::reads`]).
    pub fn read(&mut self, reg: u8) {
        self.explicit.push_back((reg, None));
    }

    /// Asks for one register write (done before any further reads or pushes).
    pub fn write(&mut self, reg: u8, value: u32) {
        self.explicit.push_back((reg, Some((value, 0xF))));
    }

    /// Asks for one register write with the byte lanes `sel` (4 bits; a partial
    /// write: bus_contract.md §1).
    pub fn write_lanes(&mut self, reg: u8, value: u32, sel: u8) {
        self.explicit.push_back((reg, Some((value, sel & 0xF))));
    }

    /// Drops the submissions not yet being pushed (a host that gives up on what
    /// it queued, e.g. before emptying the DRCC's TX queues with reset mode).
    pub fn drop_submissions(&mut self) {
        self.submissions.clear();
    }

    /// Frames submitted but not yet pushed into the DRCC.
    pub fn backlog(&self) -> usize {
        self.submissions.len() + self.pushing.is_some() as usize
    }

    /// Whether the start-up configuration has been written.
    pub fn configured(&self) -> bool {
        self.configured
    }

    /// Whether nothing is left to do except polling.
    pub fn is_idle(&self) -> bool {
        self.configured
            && self.submissions.is_empty()
            && self.pushing.is_none()
            && self.explicit.is_empty()
            && self.ops.is_empty()
    }

    /// Wishbone inputs for clock `cycle`, given the DUT outputs of the previous clock
    /// (`prev`), and bookkeeping of the transaction those outputs acknowledged.
    pub fn drive(&mut self, cycle: u64, prev: &DrccOutputs, rst: bool, inputs: &mut DrccInputs) {
        inputs.wb_cyc = false;
        inputs.wb_stb = false;
        inputs.wb_we = false;
        inputs.wb_adr = 0;
        inputs.wb_dat_w = 0;
        inputs.wb_sel = 0xF;
        if rst {
            return;
        }
        if let Some(op) = self.current {
            if prev.wb_ack || prev.wb_err {
                self.current = None;
                self.complete(cycle, op, prev.wb_dat_r);
            }
        }
        if self.current.is_none() {
            self.current = self.next_op(cycle);
        }
        if let Some(op) = self.current {
            inputs.wb_cyc = true;
            inputs.wb_stb = true;
            inputs.wb_we = op.write;
            inputs.wb_adr = op.reg;
            inputs.wb_dat_w = op.value;
            inputs.wb_sel = op.sel;
        }
    }

    fn next_op(&mut self, cycle: u64) -> Option<Op> {
        if let Some(op) = self.ops.pop_front() {
            return Some(op);
        }
        self.configured = true;
        if let Some((reg, value)) = self.explicit.pop_front() {
            return Some(Op {
                write: value.is_some(),
                reg,
                value: value.map_or(0, |(v, _)| v),
                sel: value.map_or(0xF, |(_, sel)| sel),
                purpose: if value.is_some() {
                    Purpose::Write
                } else {
                    Purpose::Explicit
                },
            });
        }
        if self.pushing.is_none() && self.submissions.front().is_some_and(|s| s.due <= cycle) {
            self.pushing = self.submissions.pop_front();
        }
        if self.pushing.is_some() {
            return Some(Op {
                write: false,
                reg: reg::STATUS,
                value: 0,
                sel: 0xF,
                purpose: Purpose::TxSpace,
            });
        }
        Some(Op {
            write: false,
            reg: reg::RX_ID,
            value: 0,
            sel: 0xF,
            purpose: Purpose::RxId,
        })
    }

    fn complete(&mut self, cycle: u64, op: Op, data: u32) {
        match op.purpose {
            Purpose::Config | Purpose::Write | Purpose::TxWrite => {}
            Purpose::Explicit => self.reads.push(HostRead {
                cycle,
                reg: op.reg,
                value: data,
            }),
            Purpose::TxSpace => {
                let Some(s) = self.pushing else { return };
                let count = if s.queue == 0 || self.config.one_queue() {
                    get("STATUS", "txq_a_count", data)
                } else {
                    get("STATUS", "txq_b_count", data)
                };
                if count < self.config.tx_queue_depth {
                    let f = s.frame;
                    let data_word = f.data_word();
                    // Registers carry byte 0 in [7:0]; the frame keeps byte 0 first.
                    let d0 = u32::from_le_bytes([f.data[0], f.data[1], f.data[2], f.data[3]]);
                    let d1 = u32::from_le_bytes([f.data[4], f.data[5], f.data[6], f.data[7]]);
                    debug_assert_eq!(data_word.to_be_bytes(), f.data);
                    let id = put("TX_ID", "id", f.id)
                        | put("TX_ID", "ide", f.ide as u32)
                        | put("TX_ID", "rtr", f.rtr as u32);
                    let ctrl = put("TX_CTRL", "dlc", f.dlc as u32)
                        | put("TX_CTRL", "queue", s.queue as u32);
                    for (reg, value) in [
                        (reg::TX_ID, id),
                        (reg::TX_CTRL, ctrl),
                        (reg::TX_DATA0, d0),
                        (reg::TX_DATA1, d1),
                    ] {
                        self.ops.push_back(Op {
                            write: true,
                            reg,
                            value,
                            sel: 0xF,
                            purpose: Purpose::TxWrite,
                        });
                    }
                    self.ops.push_back(Op {
                        write: true,
                        reg: reg::TX_CMD,
                        value: put("TX_CMD", "push", 1),
                        sel: 0xF,
                        purpose: Purpose::TxPush,
                    });
                } else {
                    // Queue full: drain the RX FIFO once, then ask again.
                    self.ops.push_back(Op {
                        write: false,
                        reg: reg::RX_ID,
                        value: 0,
                        sel: 0xF,
                        purpose: Purpose::RxId,
                    });
                }
            }
            Purpose::TxPush => {
                if let Some(s) = self.pushing.take() {
                    self.sent.push(HostTx {
                        cycle,
                        frame: s.frame,
                        queue: s.queue,
                    });
                }
            }
            Purpose::RxId => {
                if RX_READY.get(data) != 0 {
                    self.rx_partial.0 = Frame {
                        id: get("RX_ID", "id", data),
                        ide: get("RX_ID", "ide", data) != 0,
                        rtr: get("RX_ID", "rtr", data) != 0,
                        ..Frame::default()
                    };
                    for (reg, purpose) in [
                        (reg::RX_CTRL, Purpose::RxCtrl),
                        (reg::RX_DATA0, Purpose::RxData0),
                        (reg::RX_DATA1, Purpose::RxData1),
                    ] {
                        self.ops.push_back(Op {
                            write: false,
                            reg,
                            value: 0,
                            sel: 0xF,
                            purpose,
                        });
                    }
                    self.ops.push_back(Op {
                        write: true,
                        reg: reg::RX_CMD,
                        value: put("RX_CMD", "pop", 1),
                        sel: 0xF,
                        purpose: Purpose::RxPop,
                    });
                }
            }
            Purpose::RxCtrl => {
                self.rx_partial.0.dlc = get("RX_CTRL", "dlc", data) as u8;
                self.rx_partial.1 = get("RX_CTRL", "channel", data) as u8;
            }
            Purpose::RxData0 => self.rx_partial.0.data[..4].copy_from_slice(&data.to_le_bytes()),
            Purpose::RxData1 => self.rx_partial.0.data[4..].copy_from_slice(&data.to_le_bytes()),
            Purpose::RxPop => self.received.push(HostRx {
                cycle,
                frame: self.rx_partial.0,
                channel: self.rx_partial.1,
            }),
        }
    }
}
