//! The lower tester (LT) of the conformance suite: it drives one implementation
//! under test (IUT, any [`ChannelEngine`]) with exact bit sequences on `rx` and
//! records, bit by bit, what the IUT does.
//!
//! **Bus.** The IUT's `rx` in clock n is the wired-AND of the IUT's own `tx`
//! returned by step n-1 and the tester's drive ([`Lt::R`] lets the IUT's `tx`
//! through, [`Lt::D`] pulls the bus dominant). [`Lt::ForceR`] forces the bus
//! recessive whatever the IUT sends: that is how the LT corrupts a dominant bit of
//! the IUT (ISO 16845-1 lower testers do the same; on a real bus it stands for a
//! disturbance).
//!
//! **Bit grid.** The tester sends bits of exactly `clocks_per_bit` clocks, back to
//! back, from an origin: the first dominant bit it drives (the IUT hard-synchronises
//! on that SOF edge, contract §3), or the IUT's own SOF ([`SBit::await_sof`]: the
//! tester waits with a recessive bus until the IUT pulls it dominant and starts a
//! new grid at that clock, because the IUT hard-synchronises on its own SOF edge).
//! Every tester edge on that grid falls into the IUT's SYNC_SEG (the IUT's 2-clock
//! synchronizer delays all edges alike), so the IUT samples every tester bit at
//! the same clock of the bit (clock 5 of 8, counted from 0, with 8 tq of one
//! clock); the tester learns that clock at the origin and reports a lost
//! synchronisation at the first bit where it moves.
//!
//! **Records.** For every bit the tester records ([`BitRecord`]): its drive, the bus
//! value and the IUT's `tx` at the IUT's sample point, the probes right after that
//! sample point (field, TEC, REC, error state, sampled bit) and the host events of
//! the bit (`rx_valid` with `rx_frame`, `tx_done`, `arb_lost`). A SAMPLE edge (and
//! the pulses it raises) belongs to the bit whose bus clock it read, two clocks
//! before the edge ([`SampleEvent`]).
//!
//! **Scripts.** A [`Script`] lists bits with the tester's drive and the expected
//! IUT `tx`; [`LowerTester::run`] plays it and fails with a table around the first
//! bit where the IUT's `tx` differs from the expectation.

use std::collections::VecDeque;
use std::fmt::Write as _;
use std::ops::Range;

use drcc_cosim::{BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs, Frame, Probes};

use super::bits::{Field, FrameBits};

mod play;
mod records;
mod report;
mod script;
pub use records::*;
use report::{table, val};
pub use script::*;

/// A factory of fresh IUTs (the conformance items take one, so each item can start
/// from reset as often as it needs).
pub type Iut = dyn Fn() -> Box<dyn ChannelEngine>;

/// Field codes of the `field` probe (timing contract §4.1).
pub mod field {
    /// Waiting for 11 recessive bits after reset.
    pub const INTEGRATING: u8 = 0;
    /// Bus idle.
    pub const IDLE: u8 = 1;
    /// Base identifier.
    pub const ID_A: u8 = 2;
    /// ACK slot.
    pub const ACK_SLOT: u8 = 13;
    /// End of frame.
    pub const EOF: u8 = 15;
    /// Intermission.
    pub const INTERMISSION: u8 = 16;
    /// Suspend transmission.
    pub const SUSPEND: u8 = 17;
    /// Error flag.
    pub const ERROR_FLAG: u8 = 18;
    /// Error delimiter.
    pub const ERROR_DELIM: u8 = 19;
    /// Overload flag.
    pub const OVERLOAD_FLAG: u8 = 20;
    /// Overload delimiter.
    pub const OVERLOAD_DELIM: u8 = 21;
    /// Bus-off.
    pub const BUS_OFF: u8 = 22;

    /// Name of a field code.
    pub fn name(code: u8) -> &'static str {
        const NAMES: [&str; 23] = [
            "INTEGRATING",
            "IDLE",
            "ID_A",
            "SRR_RTR",
            "IDE",
            "ID_B",
            "RTR_EXT",
            "R1",
            "R0",
            "DLC",
            "DATA",
            "CRC",
            "CRC_DELIM",
            "ACK_SLOT",
            "ACK_DELIM",
            "EOF",
            "INTERMISSION",
            "SUSPEND",
            "ERROR_FLAG",
            "ERROR_DELIM",
            "OVERLOAD_FLAG",
            "OVERLOAD_DELIM",
            "BUS_OFF",
        ];
        NAMES.get(code as usize).copied().unwrap_or("?")
    }
}

/// `err_state` probe values.
pub mod state {
    /// Error active.
    pub const ACTIVE: u8 = 0;
    /// Error passive.
    pub const PASSIVE: u8 = 1;
    /// Bus-off.
    pub const BUS_OFF: u8 = 2;
}

/// What the tester drives during one bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lt {
    /// Recessive: the bus carries the IUT's own `tx`.
    R,
    /// Dominant.
    D,
    /// Recessive whatever the IUT sends (corrupts a dominant bit of the IUT).
    ForceR,
}

impl Lt {
    /// `R` for `true` (recessive), `D` for `false`.
    pub fn from_value(recessive: bool) -> Lt {
        if recessive {
            Lt::R
        } else {
            Lt::D
        }
    }

    /// The bus value with this drive and the IUT's `tx`.
    pub fn bus(self, iut_tx: bool) -> bool {
        match self {
            Lt::R => iut_tx,
            Lt::D => false,
            Lt::ForceR => true,
        }
    }

    fn symbol(self) -> &'static str {
        match self {
            Lt::R => "R",
            Lt::D => "D",
            Lt::ForceR => "R!",
        }
    }
}

/// The lower tester driving one IUT.
pub struct LowerTester {
    iut: Box<dyn ChannelEngine>,
    inputs: ChannelInputs,
    /// The IUT's `tx` returned by the last step: on the bus in the next clock.
    tx: bool,
    last: ChannelOutputs,
    clock: u64,
    /// (bus, IUT tx on the bus) of the last clocks, newest last.
    history: VecDeque<(bool, bool)>,
    /// Every SAMPLE edge and host pulse so far.
    pub events: Vec<SampleEvent>,
    /// The bit grid is established (the IUT is synchronised to the tester).
    synced: bool,
    sample_offset: Option<u32>,
    request: Option<Frame>,
    /// Every frame the IUT delivered (`rx_valid`), in order.
    pub received: Vec<Frame>,
    /// Number of `tx_done` pulses.
    pub tx_done: u32,
    /// Number of `arb_lost` pulses.
    pub arb_lost: u32,
    /// Optional per-clock trace (timing items).
    pub trace: Option<Vec<ClockRecord>>,
    context: String,
}

impl LowerTester {
    /// A tester on a fresh IUT: reset for 2 clocks, then recessive until the IUT
    /// has integrated (11 recessive bits, contract §4.1) and is idle.
    pub fn new(iut: Box<dyn ChannelEngine>, timing: BitTiming) -> Self {
        timing.validate().expect("conformance bit timing");
        let mut lt = LowerTester {
            iut,
            inputs: ChannelInputs {
                rst: true,
                rx: true,
                timing,
                ..ChannelInputs::default()
            },
            tx: true,
            last: ChannelOutputs::default(),
            clock: 0,
            history: VecDeque::with_capacity(4),
            events: Vec::new(),
            synced: false,
            sample_offset: None,
            request: None,
            received: Vec::new(),
            tx_done: 0,
            arb_lost: 0,
            trace: None,
            context: String::new(),
        };
        for _ in 0..2 {
            lt.last = lt.iut.step(&lt.inputs);
        }
        lt.inputs.rst = false;
        lt.tx = lt.last.tx;
        let cpb = lt.cpb() as u64;
        for _ in 0..13 * cpb {
            lt.clock(Lt::R);
        }
        assert_eq!(
            lt.last.probes.field,
            field::IDLE,
            "{}: IUT not idle after reset and 13 recessive bits (field {})",
            lt.iut.name(),
            field::name(lt.last.probes.field)
        );
        lt
    }

    /// A tester on a fresh IUT from `factory`.
    pub fn start(factory: &Iut, timing: BitTiming) -> Self {
        Self::new(factory(), timing)
    }

    /// A text printed with every failure (e.g. the elementary test).
    pub fn set_context(&mut self, ctx: impl Into<String>) {
        self.context = ctx.into();
    }

    /// The IUT's engine name.
    pub fn name(&self) -> &'static str {
        self.iut.name()
    }

    /// Clocks per bit.
    pub fn cpb(&self) -> u32 {
        self.inputs.timing.clocks_per_bit()
    }

    /// The bit timing.
    pub fn timing(&self) -> BitTiming {
        self.inputs.timing
    }

    /// Clocks run so far.
    pub fn now(&self) -> u64 {
        self.clock
    }

    /// The outputs of the last clock.
    pub fn outputs(&self) -> &ChannelOutputs {
        &self.last
    }

    /// The probes of the last clock.
    pub fn probes(&self) -> Probes {
        self.last.probes
    }

    /// (TEC, REC, error state) now.
    pub fn counters(&self) -> (u16, u8, u8) {
        let p = self.last.probes;
        (p.tec, p.rec, p.err_state)
    }

    /// Requests `frame` (`tx_req` during the next clock).
    pub fn request(&mut self, frame: Frame) {
        self.request = Some(frame);
    }

    /// The next bit starts a new grid (e.g. after moving the edges on purpose).
    pub fn resync_grid(&mut self) {
        self.sample_offset = None;
    }

    /// One clock with the tester driving `drive`.
    pub fn clock(&mut self, drive: Lt) -> ClockRecord {
        let iut_tx = self.tx;
        let bus = drive.bus(iut_tx);
        self.inputs.rx = bus;
        match self.request.take() {
            Some(f) => {
                self.inputs.tx_req = true;
                self.inputs.tx_frame = f;
            }
            None => self.inputs.tx_req = false,
        }
        let out = self.iut.step(&self.inputs);
        self.tx = out.tx;
        self.last = out;
        self.clock += 1;
        if self.history.len() == 3 {
            self.history.pop_front();
        }
        self.history.push_back((bus, iut_tx));
        if out.rx_valid {
            self.received.push(out.rx_frame);
        }
        if out.probes.sample_point || out.rx_valid || out.tx_done || out.arb_lost {
            // The SAMPLE edge used rx_s = the bus two clocks before this edge.
            let (b, t) = if self.history.len() >= 3 {
                self.history[0]
            } else {
                (bus, iut_tx)
            };
            self.events.push(SampleEvent {
                rx_clock: (self.clock - 1).saturating_sub(2),
                sample: out.probes.sample_point,
                bus: b,
                tx: t,
                probes: out.probes,
                rx_frame: out.rx_valid.then_some(out.rx_frame),
                tx_done: out.tx_done,
                arb_lost: out.arb_lost,
            });
        }
        self.tx_done += out.tx_done as u32;
        self.arb_lost += out.arb_lost as u32;
        let rec = ClockRecord {
            clock: self.clock - 1,
            bus,
            tx: iut_tx,
            out,
        };
        if let Some(t) = self.trace.as_mut() {
            t.push(rec);
        }
        rec
    }

    /// `n` clocks of the same drive.
    pub fn clocks(&mut self, drive: Lt, n: u32) -> Vec<ClockRecord> {
        (0..n).map(|_| self.clock(drive)).collect()
    }

    /// One bit time of the tester, with its record (as known at its end).
    pub fn bit(&mut self, drive: Lt, label: &str) -> BitRecord {
        let segs = [(drive, self.cpb())];
        self.shaped_bit(&segs, label)
    }

    /// One tester bit made of `(drive, clocks)` segments (need not add up to one
    /// bit time: the timing items lengthen and shorten bits). The record holds what
    /// is known when the bit ends (see [`LowerTester::fill`]).
    pub fn shaped_bit(&mut self, segs: &[(Lt, u32)], label: &str) -> BitRecord {
        let start = self.clock;
        if segs.iter().any(|s| s.0 == Lt::D) {
            self.synced = true;
        }
        for &(drive, n) in segs {
            for _ in 0..n {
                self.clock(drive);
            }
        }
        let mut rec = BitRecord {
            label: label.to_string(),
            drive: segs[0].0,
            bus: true,
            tx: true,
            sample_offset: None,
            probes: self.last.probes,
            rx_valid: false,
            rx_frame: None,
            tx_done: false,
            arb_lost: false,
            waited: None,
            start,
            end: self.clock,
        };
        self.fill(&mut rec);
        rec
    }

    /// Fills `rec` from the events whose sampled bus clock lies in the bit: the
    /// last sample point, and every host pulse. A sample point late in a bit may
    /// come up to two clocks after the bit's end, so a record is complete once
    /// two more clocks have run.
    pub fn fill(&self, rec: &mut BitRecord) {
        let from = self.events.partition_point(|e| e.rx_clock < rec.start);
        for e in self.events[from..]
            .iter()
            .take_while(|e| e.rx_clock < rec.end)
        {
            if e.sample {
                rec.bus = e.bus;
                rec.tx = e.tx;
                rec.sample_offset = Some((e.rx_clock - rec.start) as u32);
                rec.probes = e.probes;
            }
            if let Some(f) = e.rx_frame {
                rec.rx_valid = true;
                rec.rx_frame = Some(f);
            }
            rec.tx_done |= e.tx_done;
            rec.arb_lost |= e.arb_lost;
        }
    }

    /// The last sample point that read a bus clock in `start..end`.
    pub fn sample_in(&self, start: u64, end: u64) -> Option<SampleEvent> {
        self.events
            .iter()
            .rev()
            .find(|e| e.sample && e.rx_clock >= start && e.rx_clock < end)
            .copied()
    }

    /// Waits, recessive, up to `max_bits` bit times (plus half a bit for the loop
    /// delay: with 0 the SOF must come at this very bit) for the IUT to pull the
    /// bus dominant; returns the clocks waited. The next clock is
    /// then the first clock of the IUT's SOF on the bus and starts a new grid.
    pub fn await_sof(&mut self, max_bits: u32) -> u32 {
        let limit = max_bits * self.cpb() + self.cpb() / 2 + 2;
        let mut waited = 0;
        while self.tx {
            assert!(
                waited < limit,
                "{}: {}the IUT did not start a frame within {max_bits} bit times \
                 (field {}, TEC {}, REC {}, state {})",
                self.iut.name(),
                self.ctx(),
                field::name(self.last.probes.field),
                self.last.probes.tec,
                self.last.probes.rec,
                self.last.probes.err_state
            );
            self.clock(Lt::R);
            waited += 1;
        }
        self.synced = true;
        waited
    }

    fn ctx(&self) -> String {
        if self.context.is_empty() {
            String::new()
        } else {
            format!("[{}] ", self.context)
        }
    }
}
