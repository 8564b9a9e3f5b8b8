//! The frame field the next non-stuff bit belongs to (timing contract §4.1).
//! The declaration order is the encoding of the `field` probe (0..=22), shared
//! with the reference model; do not reorder.

use rust_hdl::prelude::*;

/// Frame fields and the protocol states between frames (ISO 11898-1, 10.4).
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum Field {
    Integrating,
    Idle,
    IdA,
    SrrRtr,
    Ide,
    IdB,
    RtrExt,
    R1,
    R0,
    Dlc,
    Data,
    Crc,
    CrcDelim,
    AckSlot,
    AckDelim,
    Eof,
    Intermission,
    Suspend,
    ErrorFlag,
    ErrorDelim,
    OverloadFlag,
    OverloadDelim,
    BusOff,
}
