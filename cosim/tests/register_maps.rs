//! The reference models against the register tables of drcc-hdl, through the
//! Wishbone bus only. The tables (`drcc_hdl::host::registers`,
//! `drcc_hdl::host::hub_registers`) are the one source of the RTL's map, its
//! documents, C headers and the testbench hosts; the models (`model::drcc`,
//! `model::hub`) keep their own copy written from the contracts and never import
//! drcc-hdl. This test is where the two meet: for every register and field it
//! checks, on the model,
//!
//! - the value read after reset (the table's reset value, every field in place);
//! - a writable field: in reset mode, writing all ones into it and the complement
//!   of its reset value (every legal code for a coded field) and reading it back
//!   gives the same bits at the table's position and touches no other field;
//!   command fields read 0;
//! - a read-only register: a write of all ones is refused (the value is unchanged
//!   and `INT_STATUS.illegal` is set);
//! - `INT_STATUS` (write 1 to clear) stays 0 when ones are written to it.
//!
//! A model and a table that disagree on a position, a width, an access or a reset
//! value fail with the register and field named.

use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs};
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::engine::hub::{HubEngine, HubInputs};
use drcc_cosim::engine::hub_model::HubModelEngine;
use drcc_hdl::host::map::{Access, Field, Register, RegisterMap};
use drcc_hdl::host::{hub_registers, registers};

/// A Wishbone master on one model: two clocks per access (contract §2).
trait Bus {
    fn access(&mut self, we: bool, adr: u32, dat: u32) -> u32;

    fn read(&mut self, adr: u32) -> u32 {
        self.access(false, adr, 0)
    }

    fn write(&mut self, adr: u32, dat: u32) {
        self.access(true, adr, dat);
    }
}

struct Drcc(DrccModelEngine);

impl Drcc {
    fn new() -> Self {
        let mut e = DrccModelEngine::new();
        let rst = DrccInputs {
            rst: true,
            chan_a_rx: true,
            chan_b_rx: true,
            ..Default::default()
        };
        for _ in 0..3 {
            e.step(&rst);
        }
        Drcc(e)
    }
}

impl Bus for Drcc {
    fn access(&mut self, we: bool, adr: u32, dat: u32) -> u32 {
        let mut i = DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr as u8,
            wb_dat_w: dat,
            chan_a_rx: true,
            chan_b_rx: true,
            ..Default::default()
        };
        let out = self.0.step(&i);
        assert!(
            out.wb_ack != out.wb_err,
            "DRCC model: no answer at index {adr}"
        );
        i.wb_cyc = false;
        i.wb_stb = false;
        i.wb_we = false;
        self.0.step(&i);
        out.wb_dat_r
    }
}

struct Hub(HubModelEngine);

impl Hub {
    fn new() -> Self {
        let (n, m) = (hub_registers::N as usize, hub_registers::M as usize);
        let mut e = HubModelEngine::new(n, m).unwrap();
        let rst = HubInputs {
            rst: true,
            uplink: (1 << n) - 1,
            sublink_in: (1 << m) - 1,
            ..Default::default()
        };
        for _ in 0..3 {
            e.step(&rst);
        }
        Hub(e)
    }
}

impl Bus for Hub {
    fn access(&mut self, we: bool, adr: u32, dat: u32) -> u32 {
        let (n, m) = self.0.shape();
        let mut i = HubInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr as u8,
            wb_dat_w: dat,
            uplink: (1 << n) - 1,
            sublink_in: (1 << m) - 1,
            ..Default::default()
        };
        let out = self.0.step(&i);
        assert!(
            out.wb_ack != out.wb_err,
            "hub model: no answer at index {adr}"
        );
        i.wb_cyc = false;
        i.wb_stb = false;
        i.wb_we = false;
        self.0.step(&i);
        out.wb_dat_r
    }
}

/// Every word index a register of the table stands for (the hub's `PORT0` is
/// repeated for each port).
fn indices(map: &RegisterMap, r: &Register) -> Vec<u32> {
    if map.prefix == "HUB" && r.name == "PORT0" {
        (0..hub_registers::N + hub_registers::M)
            .map(|p| r.index + p)
            .collect()
    } else {
        vec![r.index]
    }
}

/// The values a writable field is written with: its codes, or all ones and the
/// complement of its reset value (so every bit is written both ways; clamped
/// minimums of the hub stay below both).
fn test_values(f: &Field) -> Vec<u32> {
    if !f.codes.is_empty() {
        return f.codes.iter().map(|c| c.value).collect();
    }
    let ones = f.get(f.mask());
    let mut v = vec![ones, ones ^ f.reset];
    v.dedup();
    v
}

/// `INT_STATUS.illegal` of the map.
fn illegal(map: &RegisterMap) -> (u32, u32) {
    let r = map.register("INT_STATUS").unwrap();
    (r.index, r.field("illegal").unwrap().mask())
}

/// Checks one model against one table; every step is a fresh model after reset
/// so that one field's write cannot hide another's.
fn check(map: &RegisterMap, mut fresh: impl FnMut() -> Box<dyn Bus>) {
    let (int_status, illegal_bit) = illegal(map);
    let mut bus = fresh();
    for r in map.registers {
        for adr in indices(map, r) {
            assert_eq!(
                bus.read(adr),
                r.reset_value(),
                "{} {} (index {adr}): value after reset, table vs model",
                map.prefix,
                r.name
            );
        }
    }
    for r in map.registers {
        let adr = r.index;
        match r.access {
            Access::Ro => {
                let mut bus = fresh();
                bus.write(adr, u32::MAX);
                assert_eq!(
                    bus.read(adr),
                    r.reset_value(),
                    "{} {}: read-only, a write changed it",
                    map.prefix,
                    r.name
                );
                assert_eq!(
                    bus.read(int_status) & illegal_bit,
                    illegal_bit,
                    "{} {}: read-only, a write was not flagged illegal",
                    map.prefix,
                    r.name
                );
            }
            Access::W1c => {
                let mut bus = fresh();
                bus.write(adr, u32::MAX);
                assert_eq!(bus.read(adr), 0, "{} {}: W1C", map.prefix, r.name);
            }
            Access::Wo => {
                let mut bus = fresh();
                bus.write(adr, 0);
                assert_eq!(
                    bus.read(adr),
                    0,
                    "{} {}: write-only reads 0",
                    map.prefix,
                    r.name
                );
            }
            Access::Rw => {
                for f in r.fields {
                    for v in test_values(f) {
                        let mut bus = fresh();
                        // the reset value with this field replaced: reset mode stays on
                        let word = (r.reset_value() & !f.mask()) | f.put(v);
                        bus.write(adr, word);
                        let back = bus.read(adr);
                        let expect = if f.command { 0 } else { v };
                        assert_eq!(
                            f.get(back),
                            expect,
                            "{} {}.{} ([{}+:{}]): wrote {v:#x}, read {back:#010x}",
                            map.prefix,
                            r.name,
                            f.name,
                            f.lsb,
                            f.width
                        );
                        assert_eq!(
                            back & !f.mask(),
                            r.reset_value() & !f.mask(),
                            "{} {}.{}: the write changed other fields (read {back:#010x})",
                            map.prefix,
                            r.name,
                            f.name
                        );
                        assert_eq!(
                            bus.read(int_status) & illegal_bit,
                            0,
                            "{} {}.{}: a legal write in reset mode was flagged",
                            map.prefix,
                            r.name,
                            f.name
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn drcc_model_agrees_with_the_register_table() {
    registers::MAP.check().unwrap();
    check(&registers::MAP, || Box::new(Drcc::new()));
}

#[test]
fn hub_model_agrees_with_the_register_table() {
    hub_registers::MAP.check().unwrap();
    check(&hub_registers::MAP, || Box::new(Hub::new()));
}

/// The check is not vacuous: a table with one field moved fails it.
#[test]
#[should_panic(expected = "CTRL.dual_tx")]
fn a_moved_field_fails_the_check() {
    let ctrl = registers::MAP.register("CTRL").unwrap();
    let mut fields = ctrl.fields.to_vec();
    let f = fields.iter_mut().find(|f| f.name == "dual_tx").unwrap();
    f.lsb = 6; // a reserved bit of the contract
    let fields: &'static [Field] = fields.leak();
    let regs: Vec<Register> = registers::MAP
        .registers
        .iter()
        .map(|r| {
            if r.name == "CTRL" {
                Register { fields, ..*r }
            } else {
                *r
            }
        })
        .collect();
    let map = RegisterMap {
        registers: regs.leak(),
        ..registers::MAP
    };
    check(&map, || Box::new(Drcc::new()));
}
