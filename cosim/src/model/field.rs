//! Field codes of the `field` probe (timing contract §4.1): the frame field, or the
//! interframe/error state, that the *next* non-stuff bit belongs to.
//!
//! The field names follow ISO 11898-1:2015 clause 10.4 (data, remote, error and
//! overload frames, interframe space) plus the node states of clause 12 (bus
//! integration, bus-off). The numbering is the project's (contract §4.1), not the
//! standard's.

/// Waiting for 11 consecutive recessive bits (bus integration after reset).
pub const INTEGRATING: u8 = 0;
/// Bus idle: a dominant bit is a start of frame.
pub const IDLE: u8 = 1;
/// The 11 base-identifier bits.
pub const ID_A: u8 = 2;
/// RTR of a base frame, SRR of an extended frame.
pub const SRR_RTR: u8 = 3;
/// Identifier extension bit.
pub const IDE: u8 = 4;
/// The 18 identifier-extension bits.
pub const ID_B: u8 = 5;
/// RTR of an extended frame.
pub const RTR_EXT: u8 = 6;
/// Reserved bit r1 (extended frames only).
pub const R1: u8 = 7;
/// Reserved bit r0.
pub const R0: u8 = 8;
/// Data length code (4 bits).
pub const DLC: u8 = 9;
/// Data field: 8 x min(DLC, 8) bits, none for remote frames.
pub const DATA: u8 = 10;
/// CRC sequence (15 bits).
pub const CRC: u8 = 11;
/// CRC delimiter.
pub const CRC_DELIM: u8 = 12;
/// ACK slot.
pub const ACK_SLOT: u8 = 13;
/// ACK delimiter.
pub const ACK_DELIM: u8 = 14;
/// End of frame (7 bits).
pub const EOF: u8 = 15;
/// Intermission (3 bits).
pub const INTERMISSION: u8 = 16;
/// Suspend transmission (8 bits, error-passive transmitter).
pub const SUSPEND: u8 = 17;
/// Active or passive error flag.
pub const ERROR_FLAG: u8 = 18;
/// Error delimiter (including the wait for the first recessive bit).
pub const ERROR_DELIM: u8 = 19;
/// Overload flag.
pub const OVERLOAD_FLAG: u8 = 20;
/// Overload delimiter (including the wait for the first recessive bit).
pub const OVERLOAD_DELIM: u8 = 21;
/// Bus-off: waiting for 128 occurrences of 11 recessive bits.
pub const BUS_OFF: u8 = 22;

/// Human-readable name of a field code (for traces and test messages).
pub fn name(code: u8) -> &'static str {
    match code {
        INTEGRATING => "INTEGRATING",
        IDLE => "IDLE",
        ID_A => "ID_A",
        SRR_RTR => "SRR_RTR",
        IDE => "IDE",
        ID_B => "ID_B",
        RTR_EXT => "RTR_EXT",
        R1 => "R1",
        R0 => "R0",
        DLC => "DLC",
        DATA => "DATA",
        CRC => "CRC",
        CRC_DELIM => "CRC_DELIM",
        ACK_SLOT => "ACK_SLOT",
        ACK_DELIM => "ACK_DELIM",
        EOF => "EOF",
        INTERMISSION => "INTERMISSION",
        SUSPEND => "SUSPEND",
        ERROR_FLAG => "ERROR_FLAG",
        ERROR_DELIM => "ERROR_DELIM",
        OVERLOAD_FLAG => "OVERLOAD_FLAG",
        OVERLOAD_DELIM => "OVERLOAD_DELIM",
        BUS_OFF => "BUS_OFF",
        _ => "?",
    }
}

/// Fields of the arbitration phase (contract §4.4): a transmitter that sends
/// recessive and reads dominant on one of these bits has lost arbitration. IDE
/// counts only in extended frames (the caller checks the bit sent there).
pub fn is_arbitration(code: u8) -> bool {
    matches!(code, ID_A | SRR_RTR | IDE | ID_B | RTR_EXT)
}

/// Fields inside the stuffed region, SOF excluded (contract §4.3): from the first
/// identifier bit up to the CRC delimiter, which may be preceded by a stuff bit.
pub fn is_stuffed(code: u8) -> bool {
    (ID_A..=CRC_DELIM).contains(&code)
}
