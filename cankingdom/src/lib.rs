//! # cankingdom
//!
//! The CanKingdom higher-layer protocol for CAN, as defined by the seed
//! paper *"CanKingdom and Dependable CAN systems"* (L.-B. Fredriksson,
//! CanKingdom International), for `no_std` nodes without a heap:
//!
//! - [`letter`]: Envelopes (CAN identifiers), Letters (8-line pages), the
//!   Default Letter (envelope 2031 standard, 8 x `0xAA`), rejection reasons;
//! - [`king_pages`]: King's Pages 0, 1, 2, 5 and 10 (encode and decode);
//! - [`mayor_pages`]: Mayor's Pages 0 (EAN-13) and 1 (serial number);
//! - [`postmaster`]: the controller trait, built on `embedded_can::nb::Can`;
//! - [`mayor`]: a City's state machine (start-up steps 1..3b, King's Letters);
//! - [`king`]: the Capital's start-up driver and membership agreement;
//! - [`tables`]: the City's folder, link and interval tables.
//!
//! Byte `i` of a CAN data field is "Line i" of the seed's forms. Nothing
//! here keeps a clock: `poll` takes the caller's time in microseconds.
//! Nothing panics on received data: a malformed or unstorable letter is
//! rejected whole with a [`Reject`] reason and counted per reason.
//!
//! ## Decisions where the seed is vague or inconsistent
//!
//! 1. **Page 10's number.** Its form prints Line 1 as `00001011` (11) but
//!    labels it "(Page 10)". Line 1 is `0x0A`: the page is named 10, every
//!    other form's Line 1 is its own page number, and 11 is the Circular
//!    Time Base Setup Page that the Page 10 form refers to.
//! 2. **Page 0 bit positions.** `rrrrrAA` / `rrrrrCC`: AA and CC are bits
//!    1..0 of Lines 2 and 3; bits 7..2 are reserved.
//! 3. **Envelope field of Pages 2 and 10** (`ECrxxxxx`): Line 5 bit 7 = E
//!    (extended), bit 6 = C (compressed), bit 5 reserved, bits 4..0 =
//!    envelope bits 28..24; Lines 2..4 the lower bytes. At most 29 bits; a
//!    standard-format number above `0x7FF` is rejected. C is stored only.
//! 4. **Page 1 base number** (`Errxxxxx`): E = bit 7, rr = bits 6..5. All 29
//!    x bits 0 = keep, all 1 = undefined ([`king_pages::BaseNumber`]); E is
//!    ignored for those two. Base numbers 0 and `0x1FFF_FFFF` cannot be set.
//!    A Page 1 asking for a response while leaving the base number unknown,
//!    or asking for a Mayor's page other than 0/1, is rejected whole.
//! 5. **Page 2 table.** An envelope has at most one assignment (transfer
//!    moves "the current assignment"); a folder may hold several envelopes.
//!    Keep/transfer of an unassigned envelope and assign of an envelope
//!    held by another folder are rejected; expel of an unassigned one is a
//!    no-op. Folder numbers of keep/expel are ignored (encoded as 0).
//! 6. **Page 5** Line 5 (`ffffff`) is read as a full 8-bit folder number.
//!    Links are stored and queried; reacting is the City application's job.
//! 7. **Page 10** intervals are stored per envelope (replacing an earlier
//!    one). Their unit, the circular time base of King's Page 11, is out of
//!    scope, so they are not enforced here.
//! 8. **Start-up.** The 200 ms window starts at the Mayor's first `poll`.
//!    During it only the Default Letter is acted upon. Steps 3a/3b follow
//!    2b's wait (where the seed lists them); after 2a the Mayor stays in
//!    Listen Only and answers the King's Page 1 rather than announcing
//!    itself. Any frame the controller delivers counts as "correctly
//!    received" (the controller has checked its CRC).
//! 9. **Modes.** Silent maps to the controller's bus-monitoring mode; Listen
//!    Only and Communicate to normal mode (see [`postmaster`]). A Mayor in
//!    Silent sends nothing: replies due then are dropped and counted
//!    ([`mayor::Mayor::unsent`]). Action Modes and City Modes are recorded
//!    for the City application, whose Founder defines them.
//! 10. **King.** Default Letter every 50 ms during the first 200 ms, then
//!     one *broadcast* Page 1 (the seed derives addresses from reply
//!     envelopes), repeated up to 3 times while a City is missing; Page 0
//!     Run + Communicate only if membership agrees, else the King halts.
//! 11. **Controller errors.** Without naming the `nb` crate, `WouldBlock`
//!     and controller errors are not told apart: a refused transmission is
//!     retried on the next `poll`; a receive error ends that `poll`'s reading.
//! 12. **Groups.** How a City joins a group is not in the seed; the City
//!     Founder lists up to [`mayor::MAX_GROUPS`] group addresses in the config.
//!
//! The time base (King's Page 11), bit-timing download and the other King's
//! pages are not implemented; such letters are rejected as
//! [`Reject::UnknownPage`].
#![cfg_attr(not(test), no_std)]
#![deny(missing_docs)]

pub mod king;
pub mod king_pages;
pub mod letter;
pub mod mayor;
pub mod mayor_pages;
pub mod postmaster;
pub mod tables;

#[cfg(test)]
mod tests;

pub use king::{King, KingConfig};
pub use king_pages::{KingLetter, KingPage};
pub use letter::{Envelope, Letter, Reject};
pub use mayor::{Mayor, MayorConfig};
pub use mayor_pages::MayorPage;
pub use postmaster::{BitRate, CommMode, Postmaster};
