//! The bit sequences the lower tester plays: [`Script`] of [`SBit`]s (what the
//! tester drives, what it expects on the IUT's `tx`), with builders for the frame
//! fields, flags, delimiters, intermission and suspend of ISO 11898-1.

use super::*;

/// One bit of a [`Script`].
#[derive(Clone, Debug)]
pub struct SBit {
    /// The tester's drive.
    pub drive: Lt,
    /// Expected IUT `tx` at its sample point (None: not checked).
    pub expect: Option<bool>,
    /// Name of the bit in failure reports and for [`Run::find`].
    pub label: String,
    /// Request this frame (`tx_req`) at the first clock of the bit.
    pub request: Option<Frame>,
    /// Before this bit, wait (recessive) up to this many bit times for the IUT's
    /// SOF; the bit then starts at the clock the IUT's dominant reaches the bus.
    pub await_sof: Option<u32>,
    /// Instead of one bit time of `drive`: these `(drive, clocks)` segments (the
    /// bit-timing items lengthen, shorten and cut bits). The sample point inside a
    /// shaped bit is not checked against the grid; the bits after it are.
    pub shape: Option<Vec<(Lt, u32)>>,
}

/// Bits to play, with the IUT's expected `tx`.
#[derive(Clone, Debug, Default)]
pub struct Script {
    /// The bits.
    pub bits: Vec<SBit>,
}

fn expect_of(v: bool) -> Option<bool> {
    Some(v)
}

impl Script {
    /// An empty script.
    pub fn new() -> Self {
        Script::default()
    }

    /// Number of bits.
    pub fn len(&self) -> usize {
        self.bits.len()
    }

    /// No bits.
    pub fn is_empty(&self) -> bool {
        self.bits.is_empty()
    }

    /// One bit.
    pub fn push(&mut self, drive: Lt, expect: Option<bool>, label: impl Into<String>) -> &mut Self {
        self.bits.push(SBit {
            drive,
            expect,
            label: label.into(),
            request: None,
            await_sof: None,
            shape: None,
        });
        self
    }

    /// One bit made of `(drive, clocks)` segments (see [`SBit::shape`]).
    pub fn push_shaped(
        &mut self,
        segs: &[(Lt, u32)],
        expect: Option<bool>,
        label: impl Into<String>,
    ) -> &mut Self {
        self.push(segs[0].0, expect, label);
        self.bits.last_mut().unwrap().shape = Some(segs.to_vec());
        self
    }

    /// `n` equal bits labelled `label 1` .. `label n`.
    pub fn repeat(&mut self, n: usize, drive: Lt, expect: Option<bool>, label: &str) -> &mut Self {
        for i in 1..=n {
            self.push(drive, expect, format!("{label} {i}"));
        }
        self
    }

    /// Requests `frame` at the start of the next bit pushed.
    pub fn request_at(&mut self, idx: usize, frame: Frame) -> &mut Self {
        self.bits[idx].request = Some(frame);
        self
    }

    /// The tester transmits bits `range` of `fb`; the IUT is a receiver and is
    /// expected recessive everywhere except in the ACK slot, where it sends its ACK
    /// iff `iut_acks`.
    pub fn receive(&mut self, fb: &FrameBits, range: Range<usize>, iut_acks: bool) -> &mut Self {
        for i in range {
            let b = fb.bits[i];
            let expect = !(b.field == Field::AckSlot && iut_acks);
            self.push(Lt::from_value(b.value), expect_of(expect), fb.name(i));
        }
        self
    }

    /// The IUT transmits bits `range` of `fb`; the tester drives recessive except
    /// in the ACK slot, which it makes dominant iff `ack`. When the range starts
    /// with the SOF, the tester waits up to `sof_within` bit times for it.
    pub fn transmit(
        &mut self,
        fb: &FrameBits,
        range: Range<usize>,
        ack: bool,
        sof_within: u32,
    ) -> &mut Self {
        let first = self.bits.len();
        let starts_at_sof = range.start == 0;
        for i in range {
            let b = fb.bits[i];
            let drive = if b.field == Field::AckSlot && ack {
                Lt::D
            } else {
                Lt::R
            };
            self.push(drive, expect_of(b.value), fb.name(i));
        }
        if starts_at_sof {
            self.bits[first].await_sof = Some(sof_within);
        }
        self
    }

    /// The IUT's active error flag, observed with a recessive tester.
    pub fn active_flag(&mut self, label: &str) -> &mut Self {
        self.repeat(6, Lt::R, Some(false), label)
    }

    /// The IUT's passive error flag with a recessive tester.
    pub fn passive_flag(&mut self, label: &str) -> &mut Self {
        self.repeat(6, Lt::R, Some(true), label)
    }

    /// An error flag of the IUT, active or passive.
    pub fn error_flag(&mut self, active: bool) -> &mut Self {
        if active {
            self.active_flag("ErrFlag")
        } else {
            self.passive_flag("ErrFlag")
        }
    }

    /// Error delimiter: 8 recessive bits.
    pub fn error_delim(&mut self) -> &mut Self {
        self.repeat(8, Lt::R, Some(true), "ErrDelim")
    }

    /// The IUT's overload flag with a recessive tester.
    pub fn overload_flag(&mut self) -> &mut Self {
        self.repeat(6, Lt::R, Some(false), "OvlFlag")
    }

    /// Overload delimiter: 8 recessive bits.
    pub fn overload_delim(&mut self) -> &mut Self {
        self.repeat(8, Lt::R, Some(true), "OvlDelim")
    }

    /// Intermission: 3 recessive bits.
    pub fn intermission(&mut self) -> &mut Self {
        self.repeat(3, Lt::R, Some(true), "Intermission")
    }

    /// Suspend transmission: 8 recessive bits.
    pub fn suspend(&mut self) -> &mut Self {
        self.repeat(8, Lt::R, Some(true), "Suspend")
    }

    /// `n` recessive bits of bus idle.
    pub fn idle(&mut self, n: usize) -> &mut Self {
        self.repeat(n, Lt::R, Some(true), "Idle")
    }

    /// Appends another script.
    pub fn append(&mut self, other: &Script) -> &mut Self {
        self.bits.extend(other.bits.iter().cloned());
        self
    }
}
