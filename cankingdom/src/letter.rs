//! Envelopes (CAN identifiers), Letters (8-line CAN messages), the Default
//! Letter, and the reasons a received Letter is rejected.

use embedded_can::{ExtendedId, Frame, Id, StandardId};

/// Largest standard (11-bit) envelope number.
pub const MAX_STANDARD: u32 = 0x7FF;
/// Largest extended (29-bit) envelope number.
pub const MAX_EXTENDED: u32 = 0x1FFF_FFFF;

/// An Envelope: a CAN identifier, standard (11-bit) or extended (29-bit).
///
/// The number is always in range for its format (checked by the constructors).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Envelope {
    number: u32,
    extended: bool,
}

impl Envelope {
    /// A standard-format envelope, `None` if `number > 0x7FF`.
    pub const fn standard(number: u32) -> Option<Self> {
        Self::new(number, false)
    }

    /// An extended-format envelope, `None` if `number > 0x1FFF_FFFF`.
    pub const fn extended(number: u32) -> Option<Self> {
        Self::new(number, true)
    }

    /// An envelope of the given format, `None` if the number does not fit it.
    pub const fn new(number: u32, extended: bool) -> Option<Self> {
        let max = if extended { MAX_EXTENDED } else { MAX_STANDARD };
        if number > max {
            None
        } else {
            Some(Self { number, extended })
        }
    }

    /// The envelope number (the CAN identifier value).
    pub const fn number(self) -> u32 {
        self.number
    }

    /// `true` for the extended (29-bit) format.
    pub const fn is_extended(self) -> bool {
        self.extended
    }

    /// This envelope plus `offset`, same format; `None` if it leaves the range.
    pub const fn offset(self, offset: u32) -> Option<Self> {
        match self.number.checked_add(offset) {
            Some(n) => Self::new(n, self.extended),
            None => None,
        }
    }

    /// The `embedded_can` identifier of this envelope.
    pub fn id(self) -> Id {
        if self.extended {
            // In range by construction; ZERO is an unreachable fallback.
            Id::Extended(ExtendedId::new(self.number).unwrap_or(ExtendedId::ZERO))
        } else {
            Id::Standard(StandardId::new(self.number as u16).unwrap_or(StandardId::ZERO))
        }
    }

    /// The envelope of an `embedded_can` identifier.
    pub fn from_id(id: Id) -> Self {
        match id {
            Id::Standard(s) => Self {
                number: u32::from(s.as_raw()),
                extended: false,
            },
            Id::Extended(e) => Self {
                number: e.as_raw(),
                extended: true,
            },
        }
    }
}

/// Envelope 2031 (standard format) of the Default Letter.
pub const DEFAULT_ENVELOPE: Envelope = Envelope {
    number: 2031,
    extended: false,
};

/// The Default Letter's page: all eight lines `0xAA`.
pub const DEFAULT_PAGE: [u8; 8] = [0xAA; 8];

/// The King's envelope by default: 0, standard format.
pub const DEFAULT_KING_ENVELOPE: Envelope = Envelope {
    number: 0,
    extended: false,
};

/// A Letter: an 8-line page (CAN data bytes, byte `i` = "Line i") in an envelope.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Letter {
    /// The envelope (CAN identifier).
    pub envelope: Envelope,
    /// The eight lines of the page.
    pub page: [u8; 8],
}

impl Letter {
    /// The Default Letter: envelope 2031 standard, eight lines of `0xAA`.
    pub const DEFAULT: Letter = Letter {
        envelope: DEFAULT_ENVELOPE,
        page: DEFAULT_PAGE,
    };

    /// `true` if this is the Default Letter.
    pub fn is_default_letter(&self) -> bool {
        *self == Self::DEFAULT
    }

    /// A Letter from a received frame: a data frame of exactly 8 bytes.
    pub fn from_frame<F: Frame>(frame: &F) -> Result<Self, Reject> {
        if frame.is_remote_frame() {
            return Err(Reject::RemoteFrame);
        }
        let page = lines(frame.data())?;
        Ok(Self {
            envelope: Envelope::from_id(frame.id()),
            page,
        })
    }

    /// The frame carrying this Letter (`None` only if the frame type refuses it).
    pub fn to_frame<F: Frame>(&self) -> Option<F> {
        F::new(self.envelope.id(), &self.page)
    }
}

/// The eight lines of a page, or [`Reject::WrongLength`].
pub fn lines(data: &[u8]) -> Result<[u8; 8], Reject> {
    data.try_into().map_err(|_| Reject::WrongLength)
}

/// Why a received Letter was rejected (nothing of it was applied).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Reject {
    /// The page does not have exactly 8 lines (DLC != 8).
    WrongLength,
    /// A remote frame where a page was expected.
    RemoteFrame,
    /// Line 1 names a page this crate does not implement.
    UnknownPage,
    /// A bit the seed's form marks reserved (`r = 0`) is set.
    ReservedBitsSet,
    /// A combination the form calls reserved (King's Page 2 `AAD = 101`).
    ReservedCombination,
    /// A standard-format envelope or base number above `0x7FF`, or
    /// base number + city address outside its format's range.
    EnvelopeOutOfRange,
    /// King's Page 1 asks for a Mayor's page other than 0 or 1.
    UnsupportedResponsePage,
    /// King's Page 1 asks for a response but leaves the base number unknown.
    BaseNumberUnknown,
    /// King's Page 2 keeps or transfers an envelope that has no assignment.
    NotAssigned,
    /// King's Page 2 assigns an envelope already assigned to another folder
    /// (the seed's way to move it is "transfer").
    AlreadyAssigned,
    /// The City's table for this page is full.
    TableFull,
}

impl Reject {
    /// Every reason, in counter order.
    pub const ALL: [Reject; 11] = [
        Reject::WrongLength,
        Reject::RemoteFrame,
        Reject::UnknownPage,
        Reject::ReservedBitsSet,
        Reject::ReservedCombination,
        Reject::EnvelopeOutOfRange,
        Reject::UnsupportedResponsePage,
        Reject::BaseNumberUnknown,
        Reject::NotAssigned,
        Reject::AlreadyAssigned,
        Reject::TableFull,
    ];

    const fn index(self) -> usize {
        self as usize
    }
}

/// A count of rejected letters per [`Reject`] reason (saturating).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RejectCounters {
    counts: [u32; Reject::ALL.len()],
}

impl RejectCounters {
    /// Count one rejection.
    pub fn record(&mut self, reason: Reject) {
        let c = &mut self.counts[reason.index()];
        *c = c.saturating_add(1);
    }

    /// Rejections counted for `reason`.
    pub fn get(&self, reason: Reject) -> u32 {
        self.counts[reason.index()]
    }

    /// Rejections counted for all reasons (saturating).
    pub fn total(&self) -> u32 {
        self.counts.iter().fold(0u32, |a, &c| a.saturating_add(c))
    }
}

/// Why a page could not be encoded (its value has no wire form).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EncodeError {
    /// A base number of 0 or `0x1FFF_FFFF`: on the wire those mean
    /// "keep current setting" and "base number undefined".
    BaseNumberNotExpressible,
    /// A response page of `0xFF`: on the wire it means "no response".
    ResponsePageNotExpressible,
    /// A 40-bit field (EAN, serial number) given a larger value.
    ValueTooLarge,
}

/// An envelope field of King's Pages 2 and 10 (lines 2..5): the envelope
/// and its "compressed" flag.
///
/// Layout decided from the form `ECrxxxxx`: line 5 bit 7 = E (extended),
/// bit 6 = C (compressed), bit 5 reserved (= 0), bits 4..0 = envelope number
/// bits 28..24; lines 2, 3, 4 = bits 7..0, 15..8, 23..16.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EnvelopeSpec {
    /// The envelope.
    pub envelope: Envelope,
    /// C flag: compressed envelope yes/no (stored, not interpreted).
    pub compressed: bool,
}

impl EnvelopeSpec {
    /// A plain (not compressed) envelope spec.
    pub const fn plain(envelope: Envelope) -> Self {
        Self {
            envelope,
            compressed: false,
        }
    }

    /// Write lines 2..5.
    pub(crate) fn encode_into(&self, page: &mut [u8; 8]) {
        let n = self.envelope.number();
        page[2..6].copy_from_slice(&n.to_le_bytes());
        page[5] &= 0x1F;
        if self.envelope.is_extended() {
            page[5] |= 0x80;
        }
        if self.compressed {
            page[5] |= 0x40;
        }
    }

    /// Read lines 2..5.
    pub(crate) fn decode_from(page: &[u8; 8]) -> Result<Self, Reject> {
        if page[5] & 0x20 != 0 {
            return Err(Reject::ReservedBitsSet);
        }
        let n = u32::from_le_bytes([page[2], page[3], page[4], page[5] & 0x1F]);
        let envelope = Envelope::new(n, page[5] & 0x80 != 0).ok_or(Reject::EnvelopeOutOfRange)?;
        Ok(Self {
            envelope,
            compressed: page[5] & 0x40 != 0,
        })
    }
}
