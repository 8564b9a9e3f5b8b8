//! The King's Document: King's Pages 0, 1, 2, 5 and 10.
//!
//! Every King's Letter has Line 0 = city or group address (0 = all cities)
//! and Line 1 = page number; Lines 2..7 follow the seed's forms. Bits the
//! forms mark `r` (reserved, `r = 0`) must be 0 on reception.

use crate::letter::{lines, EncodeError, Envelope, EnvelopeSpec, Reject, MAX_EXTENDED};
use crate::postmaster::CommMode;

/// Line 0 address meaning "all cities" (broadcast).
pub const BROADCAST: u8 = 0;

/// Action Mode of King's Page 0 (`AA` = 01, 10, 11; 00 = keep is `None`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Action {
    /// `AA = 01`: Run.
    Run,
    /// `AA = 10`: Freeze.
    Freeze,
    /// `AA = 11`: Reset.
    Reset,
}

/// King's Page 0: runtime control (ends the set-up phase).
///
/// Line 2 `rrrrrrAA` (AA = bits 1..0), Line 3 `rrrrrrCC` (CC = bits 1..0),
/// Line 4 City Mode, Lines 5..7 reserved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct RuntimeControl {
    /// Action Mode; `None` = `AA = 00` keep current mode.
    pub action: Option<Action>,
    /// Communication Mode; `None` = `CC = 00` keep current mode
    /// (`01` Silent, `10` Listen Only, `11` Communicate).
    pub comm: Option<CommMode>,
    /// City Mode; 0 = keep current mode, otherwise per the City specification.
    pub city_mode: u8,
}

/// The base number field of King's Page 1 (Lines 4..7, 29 bits + E flag).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BaseNumber {
    /// All x = 0: keep the current setting (E is ignored).
    Keep,
    /// All x = 1: the base number becomes undefined (E is ignored).
    Undefined,
    /// A base number; its format (E flag) chooses standard or extended
    /// envelopes. 0 and `0x1FFF_FFFF` have no wire form.
    Set(Envelope),
}

/// King's Page 1: the initiating page; base number and response request.
///
/// Line 2 response page (`0xFF` = none), Line 3 reserved, Lines 4..6 base
/// number bits 7..0, 15..8, 23..16, Line 7 `Errxxxxx`: E = bit 7,
/// rr = bits 6..5 (reserved), bits 4..0 = base number bits 28..24.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Initiation {
    /// The Mayor's page to respond with; `None` = `0xFF`, no response.
    pub response: Option<u8>,
    /// The base number.
    pub base: BaseNumber,
}

/// What King's Page 2 does with its envelope (Line 7 `rrrrrAAD`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AssignAction {
    /// `AA = 00`: keep the current assignment; D enables/disables the envelope.
    Keep {
        /// D.
        enable: bool,
    },
    /// `AA = 01`: assign to `folder`, in parallel with other envelopes there.
    Assign {
        /// Line 6.
        folder: u8,
        /// D.
        enable: bool,
    },
    /// `AA = 11`: transfer the envelope's assignment to `folder`.
    Transfer {
        /// Line 6.
        folder: u8,
        /// D.
        enable: bool,
    },
    /// `AAD = 100`: expel the envelope from any assignment.
    Expel,
}

/// King's Page 2: assign an envelope to a folder or expel it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EnvelopeAssignment {
    /// Lines 2..5.
    pub envelope: EnvelopeSpec,
    /// Lines 6..7.
    pub action: AssignAction,
}

/// King's Page 5: link an Action page to a Reaction page.
///
/// Line 2 action folder, Line 3 action form, Line 4 reserved, Line 5
/// reaction folder (all 8 bits; the form's `ffffff` is read as a typo),
/// Line 6 reaction form, Line 7 reserved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ActionReaction {
    /// Folder of the acting document.
    pub action_folder: u8,
    /// Form (page) of the acting document.
    pub action_form: u8,
    /// Folder of the reacting document.
    pub reaction_folder: u8,
    /// Form (page) of the reacting document.
    pub reaction_form: u8,
}

/// King's Page 10: minimum time between two transmissions of an envelope.
///
/// Lines 2..5 envelope (as Page 2), Line 6 segments, Line 7 revolutions,
/// in units of the circular time base of King's Page 11 (not implemented).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct MinInterval {
    /// Lines 2..5.
    pub envelope: EnvelopeSpec,
    /// Line 6: number of segments.
    pub segments: u8,
    /// Line 7: number of revolutions.
    pub revolutions: u8,
}

/// One of the King's pages this crate implements.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum KingPage {
    /// Page 0, runtime control.
    Page0(RuntimeControl),
    /// Page 1, initiation (base number, response request).
    Page1(Initiation),
    /// Page 2, envelope assignment.
    Page2(EnvelopeAssignment),
    /// Page 5, action/reaction link.
    Page5(ActionReaction),
    /// Page 10, minimum transmission interval.
    Page10(MinInterval),
}

impl KingPage {
    /// The page number written in Line 1.
    ///
    /// Page 10 is `0x0A`: the seed's form prints `00001011` (11) but labels
    /// it "(Page 10)"; every other form's Line 1 is its page number and 11
    /// is the Circular Time Base Setup Page the form itself refers to.
    pub const fn number(&self) -> u8 {
        match self {
            KingPage::Page0(_) => 0,
            KingPage::Page1(_) => 1,
            KingPage::Page2(_) => 2,
            KingPage::Page5(_) => 5,
            KingPage::Page10(_) => 10,
        }
    }
}

/// A King's Letter's content: address (Line 0) and page.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct KingLetter {
    /// Line 0: city or group address, 0 = all cities.
    pub address: u8,
    /// Lines 1..7.
    pub page: KingPage,
}

const fn comm_bits(c: Option<CommMode>) -> u8 {
    match c {
        None => 0b00,
        Some(CommMode::Silent) => 0b01,
        Some(CommMode::ListenOnly) => 0b10,
        Some(CommMode::Communicate) => 0b11,
    }
}

const fn action_bits(a: Option<Action>) -> u8 {
    match a {
        None => 0b00,
        Some(Action::Run) => 0b01,
        Some(Action::Freeze) => 0b10,
        Some(Action::Reset) => 0b11,
    }
}

impl KingLetter {
    /// The eight lines of this letter.
    pub fn encode(&self) -> Result<[u8; 8], EncodeError> {
        let mut p = [0u8; 8];
        p[0] = self.address;
        p[1] = self.page.number();
        match self.page {
            KingPage::Page0(rc) => {
                p[2] = action_bits(rc.action);
                p[3] = comm_bits(rc.comm);
                p[4] = rc.city_mode;
            }
            KingPage::Page1(init) => {
                p[2] = match init.response {
                    None => 0xFF,
                    Some(0xFF) => return Err(EncodeError::ResponsePageNotExpressible),
                    Some(page) => page,
                };
                let (n, e) = match init.base {
                    BaseNumber::Keep => (0, false),
                    BaseNumber::Undefined => (MAX_EXTENDED, false),
                    BaseNumber::Set(env) => {
                        if env.number() == 0 || env.number() == MAX_EXTENDED {
                            return Err(EncodeError::BaseNumberNotExpressible);
                        }
                        (env.number(), env.is_extended())
                    }
                };
                p[4..8].copy_from_slice(&n.to_le_bytes());
                if e {
                    p[7] |= 0x80;
                }
            }
            KingPage::Page2(a) => {
                a.envelope.encode_into(&mut p);
                let (folder, aad) = match a.action {
                    AssignAction::Keep { enable } => (0, u8::from(enable)),
                    AssignAction::Assign { folder, enable } => (folder, 0b010 | u8::from(enable)),
                    AssignAction::Transfer { folder, enable } => (folder, 0b110 | u8::from(enable)),
                    AssignAction::Expel => (0, 0b100),
                };
                p[6] = folder;
                p[7] = aad;
            }
            KingPage::Page5(l) => {
                p[2] = l.action_folder;
                p[3] = l.action_form;
                p[5] = l.reaction_folder;
                p[6] = l.reaction_form;
            }
            KingPage::Page10(m) => {
                m.envelope.encode_into(&mut p);
                p[6] = m.segments;
                p[7] = m.revolutions;
            }
        }
        Ok(p)
    }

    /// Decode a King's Letter from its data bytes (must be exactly 8).
    pub fn decode(data: &[u8]) -> Result<Self, Reject> {
        let p = lines(data)?;
        let page = match p[1] {
            0 => KingPage::Page0(decode_page0(&p)?),
            1 => KingPage::Page1(decode_page1(&p)?),
            2 => KingPage::Page2(decode_page2(&p)?),
            5 => {
                if p[4] != 0 || p[7] != 0 {
                    return Err(Reject::ReservedBitsSet);
                }
                KingPage::Page5(ActionReaction {
                    action_folder: p[2],
                    action_form: p[3],
                    reaction_folder: p[5],
                    reaction_form: p[6],
                })
            }
            10 => KingPage::Page10(MinInterval {
                envelope: EnvelopeSpec::decode_from(&p)?,
                segments: p[6],
                revolutions: p[7],
            }),
            _ => return Err(Reject::UnknownPage),
        };
        Ok(Self {
            address: p[0],
            page,
        })
    }
}

fn decode_page0(p: &[u8; 8]) -> Result<RuntimeControl, Reject> {
    if p[2] & !0b11 != 0 || p[3] & !0b11 != 0 || p[5] != 0 || p[6] != 0 || p[7] != 0 {
        return Err(Reject::ReservedBitsSet);
    }
    let action = match p[2] & 0b11 {
        0b01 => Some(Action::Run),
        0b10 => Some(Action::Freeze),
        0b11 => Some(Action::Reset),
        _ => None,
    };
    let comm = match p[3] & 0b11 {
        0b01 => Some(CommMode::Silent),
        0b10 => Some(CommMode::ListenOnly),
        0b11 => Some(CommMode::Communicate),
        _ => None,
    };
    Ok(RuntimeControl {
        action,
        comm,
        city_mode: p[4],
    })
}

fn decode_page1(p: &[u8; 8]) -> Result<Initiation, Reject> {
    if p[3] != 0 || p[7] & 0x60 != 0 {
        return Err(Reject::ReservedBitsSet);
    }
    let response = if p[2] == 0xFF { None } else { Some(p[2]) };
    let n = u32::from_le_bytes([p[4], p[5], p[6], p[7] & 0x1F]);
    let base = match n {
        0 => BaseNumber::Keep,
        MAX_EXTENDED => BaseNumber::Undefined,
        _ => BaseNumber::Set(Envelope::new(n, p[7] & 0x80 != 0).ok_or(Reject::EnvelopeOutOfRange)?),
    };
    Ok(Initiation { response, base })
}

fn decode_page2(p: &[u8; 8]) -> Result<EnvelopeAssignment, Reject> {
    if p[7] & 0xF8 != 0 {
        return Err(Reject::ReservedBitsSet);
    }
    let envelope = EnvelopeSpec::decode_from(p)?;
    let enable = p[7] & 1 != 0;
    let folder = p[6];
    let action = match p[7] & 0b111 {
        0b000 | 0b001 => AssignAction::Keep { enable },
        0b010 | 0b011 => AssignAction::Assign { folder, enable },
        0b110 | 0b111 => AssignAction::Transfer { folder, enable },
        0b100 => AssignAction::Expel,
        _ => return Err(Reject::ReservedCombination), // AAD = 101
    };
    Ok(EnvelopeAssignment { envelope, action })
}
