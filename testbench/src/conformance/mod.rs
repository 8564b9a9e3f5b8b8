//! Classical-CAN conformance suite after ISO 16845-1 (items 7.x: the IUT as
//! receiver, 8.x: as transmitter), run on any [`ChannelEngine`].
//!
//! - [`bits`]: the tester's own frame encoder (CRC-15, stuffing), independent of
//!   the reference model.
//! - [`lower_tester`]: the lower tester: exact bit sequences on `rx`, wired-AND bus,
//!   per-bit records of the IUT's `tx`, probes and host events.
//! - [`procedures`]: recurring sequences (receive errors, ACK errors, reaching a
//!   given REC/TEC) with their ISO 11898-1 counter arithmetic.
//! - [`receiver`], [`transmitter`], [`timing`](mod@timing): one public function per ISO 16845-1
//!   item (`iso_7_2_5_crc_error_position`, ...), each taking an IUT factory, plus
//!   [`drcc_fig5_lone_transmitter`] (the DRCC paper's Fig. 5/6 behaviour).
//!
//! Expected values come from ISO 11898-1:2015 (frame format, error detection,
//! 12.1.4.2 counting rules a..l) and the timing contract, never from an engine.
//! The integration test `tests/conformance.rs` runs every item on the model and on
//! the Verilated RTL; `docs/conformance.md` lists the ISO 16845-1 items and their tests.

pub mod bits;
pub mod items;
pub mod lower_tester;
pub mod procedures;
pub mod receiver;
pub mod timing;
pub mod transmitter;

pub use bits::{Field, FrameBits, Options};
pub use lower_tester::{Iut, LowerTester, Lt, Run, Script};
pub use transmitter::drcc_fig5_lone_transmitter;

use drcc_cosim::engine::model::ModelEngine;
use drcc_cosim::engine::verilator::VerilatorEngine;
use drcc_cosim::{BitTiming, ChannelEngine};

/// The message of a missing Verilator (the verilator variants fail with it in CI).
pub const VERILATOR_MISSING: &str =
    "Verilator not found: install it with `apt-get install verilator`";

/// The main timing: brp 0, tseg1 5, tseg2 2, sjw 1 (8 clocks per bit, sample
/// point after 6 of 8 tq).
pub fn timing() -> BitTiming {
    BitTiming {
        brp: 0,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple_sampling: false,
    }
}

/// A timing with a prescaler (brp 1: 2 clocks per tq, 16 clocks per bit).
pub fn timing_brp() -> BitTiming {
    BitTiming {
        brp: 1,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple_sampling: false,
    }
}

/// 10 kbit/s at 100 MHz, as the bit-rate solver picks it: brp 499 (a prescaler
/// past the 6 bits of the SJA1000's BRP), tseg1 15, tseg2 4, sjw 4 (20 tq of 500
/// clocks, 10,000 clocks per bit, sample point 80 %).
pub fn timing_slow() -> BitTiming {
    BitTiming {
        brp: 499,
        tseg1: 15,
        tseg2: 4,
        sjw: 4,
        triple_sampling: false,
    }
}

/// A 16-tq timing with a wide SJW for the resynchronisation items: brp 0,
/// tseg1 11, tseg2 4, sjw 3.
pub fn timing_wide() -> BitTiming {
    BitTiming {
        brp: 0,
        tseg1: 11,
        tseg2: 4,
        sjw: 3,
        triple_sampling: false,
    }
}

/// Factory of reference-model IUTs.
pub fn model_iut() -> Box<dyn ChannelEngine> {
    Box::new(ModelEngine::new())
}

/// Whether a missing Verilator must fail the verilator variants (the one rule
/// of `verilator_sys::required`).
pub use crate::engines::verilator_required;

/// Runs `item` on Verilated IUTs. Without the Verilated model the item fails in CI
/// ([`verilator_required`]) and is skipped with a message elsewhere.
pub fn with_verilator(item: impl FnOnce(&Iut)) {
    match VerilatorEngine::new() {
        Ok(_) => item(&|| -> Box<dyn ChannelEngine> {
            Box::new(VerilatorEngine::new().expect("Verilator engine"))
        }),
        Err(reason) => {
            if verilator_required() {
                panic!("{VERILATOR_MISSING} ({reason})");
            }
            eprintln!("{VERILATOR_MISSING} ({reason}): skipped");
        }
    }
}
