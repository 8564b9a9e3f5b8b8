//! Test support for the DRCC drivers: two Verilated DRCC nodes on one dual CAN
//! bus ([`DualBus`]) whose register accesses are Wishbone cycles, and the C
//! driver of `drivers/c` compiled in ([`CDriver`]).
//!
//! Line A is the wired-AND of both nodes' `chan_a_tx`, fed back to both
//! `chan_a_rx` (the same for B), one clock later (the transceiver loop). One
//! register access is one classic Wishbone cycle on one node (request clock,
//! acknowledge clock) while both nodes are clocked: the bus has one clock.
//! [`Fault::Cut`] disconnects a node from a line (its receiver hears only its
//! own transmitter, and the others do not hear it).

mod c_driver;

pub use c_driver::{
    c_btr_encode, c_calc_bit_timing, c_call_with_version, c_init_with_version, CBitTiming, CCall,
    CCapture, CChanStatus, CConfig, CDriver, CFrame, CIdent, CIrqResult, CStats, CStatus,
    C_MODE_DMR, C_MODE_NORMAL, C_MODE_REDUNDANCY,
};
pub use verilator_sys::{available, required, unavailable_reason};

use std::cell::RefCell;
use std::rc::Rc;
use verilator_sys::{Drcc, DrccIn, DrccOut};

/// A line fault at one node.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Fault {
    /// Connected.
    #[default]
    None,
    /// Disconnected: the node's receiver hears only its own transmitter and
    /// the other node does not hear it (an open stub).
    Cut,
    /// The node's receiver reads dominant whatever is on the line.
    StuckDominant,
}

/// The two lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Line {
    /// Line A (channel A of both nodes).
    A,
    /// Line B.
    B,
}

/// Two Verilated DRCCs on one dual bus, clocked together.
pub struct DualBus {
    nodes: Vec<Drcc>,
    inputs: [DrccIn; 2],
    outs: [DrccOut; 2],
    faults: [[Fault; 2]; 2],
    clock: u64,
    refused: u64,
}

impl DualBus {
    /// Two nodes, reset held for 4 clocks, both lines idle.
    /// `None` when the Verilated model is not part of this build.
    pub fn new() -> Option<DualBus> {
        let a = Drcc::new().ok()?;
        let b = Drcc::new().ok()?;
        let idle = DrccIn {
            chan_a_rx: 1,
            chan_b_rx: 1,
            wb_sel_i: 0xF,
            ..DrccIn::default()
        };
        let mut bus = DualBus {
            nodes: vec![a, b],
            inputs: [DrccIn { rst: 1, ..idle }; 2],
            outs: [DrccOut::default(); 2],
            faults: [[Fault::None; 2]; 2],
            clock: 0,
            refused: 0,
        };
        bus.tick(4);
        bus.inputs = [idle; 2];
        bus.tick(1);
        Some(bus)
    }

    /// The bus as shared, for register hooks of both nodes.
    pub fn shared() -> Option<Rc<RefCell<DualBus>>> {
        DualBus::new().map(|b| Rc::new(RefCell::new(b)))
    }

    /// Sets the fault of `node` on `line`.
    pub fn set_fault(&mut self, node: usize, line: Line, fault: Fault) {
        self.faults[node][line as usize] = fault;
    }

    fn line_level(&self, line: usize) -> u8 {
        let mut level = 1;
        for (n, out) in self.outs.iter().enumerate() {
            let tx = if line == 0 {
                out.chan_a_tx
            } else {
                out.chan_b_tx
            };
            if self.faults[n][line] != Fault::Cut {
                level &= tx;
            }
        }
        level
    }

    fn rx_of(&self, node: usize, line: usize, level: u8) -> u8 {
        let own = if line == 0 {
            self.outs[node].chan_a_tx
        } else {
            self.outs[node].chan_b_tx
        };
        match self.faults[node][line] {
            Fault::None => level,
            Fault::Cut => own,
            Fault::StuckDominant => 0,
        }
    }

    /// One clock of both nodes.
    pub fn step(&mut self) {
        let (a, b) = (self.line_level(0), self.line_level(1));
        for n in 0..2 {
            self.inputs[n].chan_a_rx = self.rx_of(n, 0, a);
            self.inputs[n].chan_b_rx = self.rx_of(n, 1, b);
        }
        for n in 0..2 {
            self.outs[n] = self.nodes[n].step(&self.inputs[n]);
            if self.outs[n].wb_err_o != 0 {
                self.refused += 1;
            }
        }
        self.clock += 1;
    }

    /// `n` clocks of both nodes.
    pub fn tick(&mut self, n: u64) {
        for _ in 0..n {
            self.step();
        }
    }

    /// One Wishbone cycle on `node` (request clock, then the acknowledge
    /// clock); returns the read data (0 for a write).
    fn cycle(&mut self, node: usize, offset: u32, write: Option<u32>) -> u32 {
        assert!(
            offset.is_multiple_of(4) && offset < 256,
            "byte offset {offset:#x}"
        );
        let req = &mut self.inputs[node];
        req.wb_cyc_i = 1;
        req.wb_stb_i = 1;
        req.wb_adr_i = (offset / 4) as u8;
        req.wb_we_i = u8::from(write.is_some());
        req.wb_dat_i = write.unwrap_or(0);
        req.wb_sel_i = 0xF;
        self.step();
        let out = self.outs[node];
        assert!(
            out.wb_ack_o != 0 || out.wb_err_o != 0,
            "classic Wishbone: ack or err one clock after the request"
        );
        let req = &mut self.inputs[node];
        req.wb_cyc_i = 0;
        req.wb_stb_i = 0;
        req.wb_we_i = 0;
        req.wb_dat_i = 0;
        self.step();
        out.wb_dat_o
    }

    /// Reads the register at byte `offset` of `node`.
    pub fn read32(&mut self, node: usize, offset: u32) -> u32 {
        self.cycle(node, offset, None)
    }

    /// Writes the register at byte `offset` of `node`.
    pub fn write32(&mut self, node: usize, offset: u32, value: u32) {
        self.cycle(node, offset, Some(value));
    }

    /// `irq` of `node` after the last clock.
    pub fn irq(&self, node: usize) -> bool {
        self.outs[node].irq != 0
    }

    /// The outputs of `node` after the last clock.
    pub fn out(&self, node: usize) -> &DrccOut {
        &self.outs[node]
    }

    /// Clocks since the bus was made.
    pub fn clock(&self) -> u64 {
        self.clock
    }

    /// Accesses answered with `wb_err_o` (refused) so far, on either node.
    pub fn refused(&self) -> u64 {
        self.refused
    }
}

/// One node's end of a shared [`DualBus`]: what register hooks hold.
#[derive(Clone)]
pub struct NodePort {
    /// The bus.
    pub bus: Rc<RefCell<DualBus>>,
    /// 0 or 1.
    pub node: usize,
}

impl NodePort {
    /// Reads a register of this node (a Wishbone cycle, both nodes clocked).
    pub fn read32(&self, offset: u32) -> u32 {
        self.bus.borrow_mut().read32(self.node, offset)
    }

    /// Writes a register of this node (a Wishbone cycle, both nodes clocked).
    pub fn write32(&self, offset: u32, value: u32) {
        self.bus.borrow_mut().write32(self.node, offset, value)
    }
}
