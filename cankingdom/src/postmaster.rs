//! The Postmaster: what this crate needs from a CAN controller.
//!
//! A [`Postmaster`] is an [`embedded_can::nb::Can`] (non-blocking transmit
//! and receive of [`embedded_can::Frame`]s) that can also change its
//! communication mode and its bit rate.
//!
//! Mapping of the seed's Communication Modes to a classical CAN controller
//! (ISO 11898-1):
//!
//! | [`CommMode`] | controller setting | Mayor's own rule |
//! |---|---|---|
//! | [`CommMode::Silent`] | bus-monitoring / listen-only mode: receives, never drives the bus (no ACK bit, no error or overload frames, no transmissions): "completely silent" | sends nothing |
//! | [`CommMode::ListenOnly`] | normal mode: acknowledges and signals errors | sends Letters only upon the King's request (the reply to King's Page 1) |
//! | [`CommMode::Communicate`] | normal mode | normal communication |
//!
//! Note the naming clash: the seed's "Listen Only" is *not* the controller
//! feature many datasheets call "listen-only"; that one is the seed's Silent.

use embedded_can::nb::Can;

use crate::letter::Letter;

/// The seed's Communication Modes (see the module table for the mapping).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CommMode {
    /// Receive only; no ACK, no error or overload frames, no transmission.
    Silent,
    /// Fully active controller (ACK, error signalling); the Mayor sends
    /// Letters only upon the King's request.
    ListenOnly,
    /// Normal communication.
    Communicate,
}

/// Bit-timing register settings (classical CAN, one sample point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BitTiming {
    /// Baud-rate prescaler (time quanta per controller clock division).
    pub prescaler: u16,
    /// Time segment 1 (propagation + phase segment 1), in time quanta.
    pub tseg1: u8,
    /// Time segment 2 (phase segment 2), in time quanta.
    pub tseg2: u8,
    /// Synchronisation jump width, in time quanta.
    pub sjw: u8,
}

/// A bit rate for the Postmaster.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BitRate {
    /// 125 kbit/s, the start-up default every City uses for its first 200 ms.
    Kbit125,
    /// 250 kbit/s.
    Kbit250,
    /// 500 kbit/s.
    Kbit500,
    /// 1 Mbit/s.
    Kbit1000,
    /// Register settings chosen by the City Founder ("presumed Kingdom and
    /// location"); their meaning depends on the controller's clock.
    Custom(BitTiming),
}

/// A CAN controller as the Mayor and the King use it.
///
/// Both methods are commands; a controller that needs time to switch does
/// so internally (the protocol keeps no clock of its own).
pub trait Postmaster: Can {
    /// Put the controller into a Communication Mode (see the module docs).
    fn set_comm_mode(&mut self, mode: CommMode);
    /// Load the bit-timing settings for `rate`.
    fn set_bit_rate(&mut self, rate: BitRate);
}

/// Frames read from the controller in one `poll`, at most (bounds the work
/// of one call even if the controller never runs dry).
pub(crate) const MAX_RX_PER_POLL: usize = 64;

/// A small FIFO of Letters waiting for the controller.
#[derive(Debug, Clone)]
pub(crate) struct Outbox<const N: usize> {
    slots: [Option<Letter>; N],
    head: usize,
    len: usize,
}

impl<const N: usize> Outbox<N> {
    pub(crate) const fn new() -> Self {
        Self {
            slots: [None; N],
            head: 0,
            len: 0,
        }
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Queue a letter; gives it back if the queue is full.
    pub(crate) fn push(&mut self, letter: Letter) -> Result<(), Letter> {
        if self.len >= N {
            return Err(letter);
        }
        self.slots[(self.head + self.len) % N] = Some(letter);
        self.len += 1;
        Ok(())
    }

    fn front(&self) -> Option<Letter> {
        if self.len == 0 {
            None
        } else {
            self.slots[self.head]
        }
    }

    fn pop(&mut self) {
        if self.len > 0 {
            self.slots[self.head] = None;
            self.head = (self.head + 1) % N;
            self.len -= 1;
        }
    }

    /// Drop everything queued; returns how many letters were dropped.
    pub(crate) fn clear(&mut self) -> usize {
        let n = self.len;
        *self = Self::new();
        n
    }

    /// Hand queued letters to the controller until it refuses one.
    ///
    /// Any `Err` from `transmit` (`WouldBlock` or a controller error) leaves
    /// the letter queued for the next call. A frame the controller displaces
    /// is queued again (if it is a Letter and there is room). Returns the
    /// number of letters the controller accepted.
    pub(crate) fn flush<P: Postmaster>(&mut self, post: &mut P) -> usize {
        let mut sent = 0;
        // Each accepted letter may displace one frame that we re-queue, so
        // bound the loop rather than rely on the queue shrinking.
        for _ in 0..(2 * N + 1) {
            let Some(letter) = self.front() else { break };
            let Some(frame) = letter.to_frame::<P::Frame>() else {
                self.pop(); // the frame type refuses it: never sendable
                continue;
            };
            match post.transmit(&frame) {
                Ok(displaced) => {
                    self.pop();
                    sent += 1;
                    if let Some(old) = displaced {
                        if let Ok(l) = Letter::from_frame(&old) {
                            let _ = self.push(l);
                        }
                    }
                }
                Err(_) => break,
            }
        }
        sent
    }
}
