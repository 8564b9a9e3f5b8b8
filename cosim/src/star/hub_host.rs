//! The host side of one hub: a Wishbone B4 classic master that writes the start-up
//! configuration (reset mode, `BTR`, guard thresholds, restoration and decoupling
//! times, `INT_ENABLE`, then reset mode cleared) and afterwards performs the register
//! reads and writes a test asks for, the way a supervisor CPU next to the hub would.
//!
//! Register indices and field positions come from drcc-hdl's hub register table
//! (the one source of the map, which also generates `rtl-out/hub_regs.h`); the
//! reference model keeps its own copy, checked by `cosim/tests/register_maps.rs`.
//! The driver reacts only to the outputs of the previous clock, so two engines that
//! agree clock by clock get identical stimulus.

use crate::engine::hub::{HubInputs, HubOutputs};
use drcc_hdl::host::hub_registers::MAP;
use std::collections::VecDeque;

/// Word indices and `CTRL` bits of the hub registers, from the register table of
/// drcc-hdl (`drcc_hdl::host::hub_registers`, contract §8).
pub mod hub_reg {
    use drcc_hdl::host::hub_registers::{self as map, REGISTERS};
    use drcc_hdl::host::map::find;
    pub const ID: u8 = map::ID as u8;
    pub const CTRL: u8 = map::CTRL as u8;
    pub const BTR: u8 = map::BTR as u8;
    pub const GUARD_CFG: u8 = map::GUARD_CFG as u8;
    pub const BF_CFG: u8 = map::BF_CFG as u8;
    pub const RESTORE_CFG: u8 = map::RESTORE_CFG as u8;
    pub const STATUS: u8 = map::STATUS as u8;
    pub const INT_STATUS: u8 = map::INT_STATUS as u8;
    pub const INT_ENABLE: u8 = map::INT_ENABLE as u8;
    pub const STATS: u8 = map::STATS as u8;
    pub const ACK_UNIT: u8 = map::ACK_UNIT as u8;
    /// `PORT_p` is at `PORT0 + p`.
    pub const PORT0: u8 = map::PORT0 as u8;
    /// `CTRL` bits.
    pub const CTRL_RESET_MODE: u32 = find(REGISTERS, "CTRL", "reset_mode").mask();
    pub const CTRL_FORCE_DECOUPLE: u32 = find(REGISTERS, "CTRL", "force_decouple").mask();
    pub const CTRL_RECOUPLE: u32 = find(REGISTERS, "CTRL", "recouple").mask();
    pub const CTRL_ACK_INTERDEP: u32 = find(REGISTERS, "CTRL", "ack_interdep").mask();
    pub const NRAP_STATUS: u8 = map::NRAP_STATUS as u8;
}

/// `reg.field` placed in a register word (positions from the table).
fn put(reg: &str, field: &str, value: u32) -> u32 {
    MAP.field(reg, field).put(value)
}

/// What the hub's host writes at start-up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HubConfig {
    /// `BTR` (the DRCC's layout; `triple` and `ewl` are not used by the hub).
    pub btr: u32,
    /// ACK interdependence (paper section 4).
    pub ack_interdep: bool,
    /// Dominant run that isolates a node port / an incoming sublink (>= 14).
    pub sd_run_up: u8,
    pub sd_run_sub: u8,
    /// Consecutive silent frames that isolate a port (0 = off).
    pub sr_frames: u8,
    /// Port error counter limits (node ports / sublinks).
    pub bf_up: u8,
    pub bf_sub: u8,
    /// Symptom-free bit times before an isolated port is restored (0 = never).
    pub restore_bits: u16,
    /// Bit times without any enabled sublink before definitive decoupling (0 = never).
    pub decouple_bits: u16,
    pub int_enable: u32,
    /// Fault injection (`CTRL.fi_ack_leak`, hub contract §4.1): the coupler passes
    /// its own nodes' ACK while coupled, and the ACK unit must stop it.
    pub fi_ack_leak: bool,
    /// Fault injection (`CTRL.fi_no_twin`, hub contract §9.6): the coupler ignores
    /// the twin's contribution.
    pub fi_no_twin: bool,
    /// The Network Reconfiguration Agreement Protocol (`CTRL.nrap_on`, §9).
    pub nrap_on: bool,
}

impl Default for HubConfig {
    /// The contract's reset values, with guarding switched on.
    fn default() -> Self {
        HubConfig {
            btr: MAP.register("BTR").map_or(0, |r| r.reset_value()),
            ack_interdep: true,
            sd_run_up: 14,
            sd_run_sub: 28,
            sr_frames: 8,
            bf_up: 32,
            bf_sub: 64,
            restore_bits: 1408,
            decouple_bits: 4096,
            // every interrupt
            int_enable: MAP.register("INT_ENABLE").map_or(0, |r| r.defined()),
            fi_ack_leak: false,
            fi_no_twin: false,
            nrap_on: true,
        }
    }
}

impl HubConfig {
    /// `CTRL` value with the given reset-mode bit.
    pub fn ctrl(&self, reset_mode: bool) -> u32 {
        put("CTRL", "reset_mode", reset_mode as u32)
            | put("CTRL", "ack_interdep", self.ack_interdep as u32)
            | put("CTRL", "fi_ack_leak", self.fi_ack_leak as u32)
            | put("CTRL", "fi_no_twin", self.fi_no_twin as u32)
            | put("CTRL", "nrap_on", self.nrap_on as u32)
    }

    /// `GUARD_CFG` value.
    pub fn guard_cfg(&self) -> u32 {
        put("GUARD_CFG", "sd_run_up", self.sd_run_up as u32)
            | put("GUARD_CFG", "sd_run_sub", self.sd_run_sub as u32)
            | put("GUARD_CFG", "sr_frames", self.sr_frames as u32)
    }

    /// `BF_CFG` value.
    pub fn bf_cfg(&self) -> u32 {
        put("BF_CFG", "bf_up", self.bf_up as u32) | put("BF_CFG", "bf_sub", self.bf_sub as u32)
    }

    /// `RESTORE_CFG` value.
    pub fn restore_cfg(&self) -> u32 {
        put("RESTORE_CFG", "restore_bits", self.restore_bits as u32)
            | put("RESTORE_CFG", "decouple_bits", self.decouple_bits as u32)
    }
}

/// A register read asked for by a test, and its result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HubRead {
    pub cycle: u64,
    pub reg: u8,
    pub value: u32,
}

#[derive(Clone, Copy, Debug)]
struct Op {
    write: bool,
    reg: u8,
    value: u32,
    config: bool,
}

/// One hub's host.
#[derive(Clone, Debug)]
pub struct HubHost {
    config: HubConfig,
    ops: VecDeque<Op>,
    current: Option<Op>,
    /// Reads done so far.
    pub reads: Vec<HubRead>,
    configured: bool,
}

impl HubHost {
    /// A host that configures the hub with `config` after reset.
    pub fn new(config: HubConfig) -> Self {
        let c = config;
        let ops = [
            (hub_reg::CTRL, c.ctrl(true)),
            (hub_reg::BTR, c.btr),
            (hub_reg::GUARD_CFG, c.guard_cfg()),
            (hub_reg::BF_CFG, c.bf_cfg()),
            (hub_reg::RESTORE_CFG, c.restore_cfg()),
            (hub_reg::INT_ENABLE, c.int_enable),
            (hub_reg::CTRL, c.ctrl(false)),
        ]
        .into_iter()
        .map(|(reg, value)| Op {
            write: true,
            reg,
            value,
            config: true,
        })
        .collect();
        HubHost {
            config,
            ops,
            current: None,
            reads: Vec::new(),
            configured: false,
        }
    }

    /// The configuration written at start-up.
    pub fn config(&self) -> &HubConfig {
        &self.config
    }

    /// Whether the start-up configuration has been written.
    pub fn configured(&self) -> bool {
        self.configured
    }

    /// Whether nothing is left to do.
    pub fn is_idle(&self) -> bool {
        self.ops.is_empty() && self.current.is_none()
    }

    /// Asks for one register read (result in [`HubHost::reads`]).
    pub fn read(&mut self, reg: u8) {
        self.ops.push_back(Op {
            write: false,
            reg,
            value: 0,
            config: false,
        });
    }

    /// Asks for one register write.
    pub fn write(&mut self, reg: u8, value: u32) {
        self.ops.push_back(Op {
            write: true,
            reg,
            value,
            config: false,
        });
    }

    /// Wishbone inputs for clock `cycle`, given the hub's outputs of the previous
    /// clock (`prev`).
    pub fn drive(&mut self, cycle: u64, prev: &HubOutputs, rst: bool, inputs: &mut HubInputs) {
        inputs.wb_cyc = false;
        inputs.wb_stb = false;
        inputs.wb_we = false;
        inputs.wb_adr = 0;
        inputs.wb_dat_w = 0;
        if rst {
            return;
        }
        if let Some(op) = self.current {
            if prev.wb_ack || prev.wb_err {
                self.current = None;
                if !op.write {
                    self.reads.push(HubRead {
                        cycle,
                        reg: op.reg,
                        value: prev.wb_dat_r,
                    });
                }
            }
        }
        if self.current.is_none() {
            self.current = self.ops.pop_front();
            if !self.current.is_some_and(|o| o.config) {
                self.configured = true;
            }
        }
        if let Some(op) = self.current {
            inputs.wb_cyc = true;
            inputs.wb_stb = true;
            inputs.wb_we = op.write;
            inputs.wb_adr = op.reg;
            inputs.wb_dat_w = op.value;
        }
    }
}
