//! The lower tester's own frame encoder: the exact bit sequence of a classical CAN
//! frame on the bus, SOF to the last EOF bit, with stuff bits, written from
//! ISO 11898-1:2015 clause 10 independently of the reference model (nothing of
//! `drcc_cosim::model` is used here).
//!
//! - CRC-15, polynomial 0x4599, initial value 0, over the destuffed bits from SOF
//!   to the end of the data field (ISO 11898-1 10.4.2.6).
//! - Bit stuffing from SOF through the CRC sequence: after five equal consecutive
//!   bits (stuff bits included) the complement is inserted, also after the last
//!   CRC bit (10.5). CRC delimiter, ACK field and EOF are never stuffed.
//! - Every bit carries its field and its index inside the field, so tests can name
//!   positions ("the 3rd DLC bit", "the 2nd stuff bit") and corrupt them.

use drcc_cosim::Frame;

/// The fields of a data or remote frame as they appear on the bus.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// Start of frame.
    Sof,
    /// The 11 base identifier bits.
    IdA,
    /// RTR of a base frame, SRR of an extended frame.
    SrrRtr,
    /// Identifier extension bit.
    Ide,
    /// The 18 identifier extension bits.
    IdB,
    /// RTR of an extended frame.
    RtrExt,
    /// Reserved bit r1 (extended frames).
    R1,
    /// Reserved bit r0.
    R0,
    /// Data length code.
    Dlc,
    /// Data field.
    Data,
    /// CRC sequence.
    Crc,
    /// CRC delimiter.
    CrcDelim,
    /// ACK slot.
    AckSlot,
    /// ACK delimiter.
    AckDelim,
    /// End of frame.
    Eof,
}

impl Field {
    /// Fields in which a recessive bit overwritten by a dominant one means lost
    /// arbitration for the transmitter.
    pub fn is_arbitration(self) -> bool {
        matches!(
            self,
            Field::IdA | Field::SrrRtr | Field::Ide | Field::IdB | Field::RtrExt
        )
    }
}

/// One bit on the bus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BusBit {
    /// `true` = recessive.
    pub value: bool,
    /// The field the bit belongs to (a stuff bit: the field of the bit before it).
    pub field: Field,
    /// Index of the bit inside its field (a stuff bit: the index of the bit before it).
    pub index: u8,
    /// A stuff bit.
    pub stuff: bool,
}

/// Bits a frame may carry that [`Frame`] does not describe (ISO 16845-1 7.1.4 /
/// 7.1.5: receivers accept either value of SRR, r1, r0), and deliberate errors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    /// SRR of an extended frame (nominally recessive).
    pub srr: bool,
    /// r1 of an extended frame (nominally dominant).
    pub r1: bool,
    /// r0 (nominally dominant).
    pub r0: bool,
    /// XORed onto the computed CRC before it is sent (0: a correct CRC).
    pub crc_xor: u16,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            srr: true,
            r1: false,
            r0: false,
            crc_xor: 0,
        }
    }
}

/// CRC-15/CAN of a bit string (ISO 11898-1 10.4.2.6): polynomial 0x4599, initial 0.
pub fn crc15(bits: &[bool]) -> u16 {
    let mut crc: u16 = 0;
    for &b in bits {
        let feedback = b ^ (crc & 0x4000 != 0);
        crc = (crc << 1) & 0x7FFF;
        if feedback {
            crc ^= 0x4599;
        }
    }
    crc
}

/// The bits of bytes, MSB first.
pub fn bytes_to_bits(bytes: &[u8]) -> Vec<bool> {
    bytes
        .iter()
        .flat_map(|&byte| (0..8).rev().map(move |i| byte >> i & 1 == 1))
        .collect()
}

/// A frame as it appears on the bus, from SOF to the last EOF bit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FrameBits {
    /// The frame as the host sees it.
    pub frame: Frame,
    /// Bits of the frame; the ACK slot is recessive (as the transmitter sends it).
    pub bits: Vec<BusBit>,
    /// The CRC that was sent.
    pub crc: u16,
}

impl FrameBits {
    /// The frame with nominal SRR/r1/r0 and a correct CRC.
    pub fn new(frame: &Frame) -> Self {
        Self::with(frame, Options::default())
    }

    /// The frame with the given options.
    pub fn with(frame: &Frame, opt: Options) -> Self {
        let f = frame.normalized();
        // Unstuffed bits covered by the CRC, with their field and index.
        let mut raw: Vec<(bool, Field, u8)> = Vec::with_capacity(128);
        let push = |raw: &mut Vec<(bool, Field, u8)>, value: u64, n: u8, field: Field| {
            for i in 0..n {
                raw.push((value >> (n - 1 - i) & 1 == 1, field, i));
            }
        };
        push(&mut raw, 0, 1, Field::Sof);
        if f.ide {
            push(&mut raw, (f.id >> 18) as u64, 11, Field::IdA);
            push(&mut raw, opt.srr as u64, 1, Field::SrrRtr);
            push(&mut raw, 1, 1, Field::Ide);
            push(&mut raw, (f.id & 0x3FFFF) as u64, 18, Field::IdB);
            push(&mut raw, f.rtr as u64, 1, Field::RtrExt);
            push(&mut raw, opt.r1 as u64, 1, Field::R1);
        } else {
            push(&mut raw, f.id as u64, 11, Field::IdA);
            push(&mut raw, f.rtr as u64, 1, Field::SrrRtr);
            push(&mut raw, 0, 1, Field::Ide);
        }
        push(&mut raw, opt.r0 as u64, 1, Field::R0);
        push(&mut raw, f.dlc as u64, 4, Field::Dlc);
        for (i, b) in bytes_to_bits(&f.data[..f.data_len()])
            .into_iter()
            .enumerate()
        {
            raw.push((b, Field::Data, i as u8));
        }
        let covered: Vec<bool> = raw.iter().map(|r| r.0).collect();
        let crc = crc15(&covered) ^ (opt.crc_xor & 0x7FFF);
        push(&mut raw, crc as u64, 15, Field::Crc);

        // Stuffing, SOF through the last CRC bit.
        let mut bits = Vec::with_capacity(160);
        let (mut last, mut run) = (true, 0u8);
        for (value, field, index) in raw {
            bits.push(BusBit {
                value,
                field,
                index,
                stuff: false,
            });
            if value == last {
                run += 1;
            } else {
                last = value;
                run = 1;
            }
            if run == 5 {
                last = !last;
                run = 1;
                bits.push(BusBit {
                    value: last,
                    field,
                    index,
                    stuff: true,
                });
            }
        }
        let mut fixed = |field: Field, n: u8| {
            for index in 0..n {
                bits.push(BusBit {
                    value: true,
                    field,
                    index,
                    stuff: false,
                });
            }
        };
        fixed(Field::CrcDelim, 1);
        fixed(Field::AckSlot, 1);
        fixed(Field::AckDelim, 1);
        fixed(Field::Eof, 7);
        FrameBits {
            frame: f,
            bits,
            crc,
        }
    }

    /// Number of bits, SOF to the last EOF bit.
    pub fn len(&self) -> usize {
        self.bits.len()
    }

    /// Never true (a frame has at least 44 bits); for clippy.
    pub fn is_empty(&self) -> bool {
        self.bits.is_empty()
    }

    /// The bit values.
    pub fn values(&self) -> Vec<bool> {
        self.bits.iter().map(|b| b.value).collect()
    }

    /// Position of the `index`-th (non-stuff) bit of `field`.
    pub fn pos(&self, field: Field, index: u8) -> usize {
        self.bits
            .iter()
            .position(|b| !b.stuff && b.field == field && b.index == index)
            .unwrap_or_else(|| panic!("frame {} has no bit {field:?}[{index}]", self.frame))
    }

    /// Positions of every stuff bit.
    pub fn stuff_positions(&self) -> Vec<usize> {
        (0..self.len()).filter(|&i| self.bits[i].stuff).collect()
    }

    /// Whether bit `i` lies in the arbitration field (ISO 11898-1:2015 10.4.2.3:
    /// identifier and RTR in base format; base identifier, SRR, IDE, identifier
    /// extension and RTR in extended format; IDE of a base frame belongs to the
    /// control field). A stuff bit belongs to the field of the bit before it.
    pub fn in_arbitration(&self, i: usize) -> bool {
        match self.bits[i].field {
            Field::IdA | Field::SrrRtr | Field::IdB | Field::RtrExt => true,
            Field::Ide => self.frame.ide,
            _ => false,
        }
    }

    /// Position of the ACK slot.
    pub fn ack_slot(&self) -> usize {
        self.pos(Field::AckSlot, 0)
    }

    /// Position of the CRC delimiter.
    pub fn crc_delim(&self) -> usize {
        self.pos(Field::CrcDelim, 0)
    }

    /// Position of EOF bit `n` (1..=7).
    pub fn eof(&self, n: u8) -> usize {
        self.pos(Field::Eof, n - 1)
    }

    /// A short name of bit `i`, e.g. `Dlc[2]` or `stuff after Crc[14]`.
    pub fn name(&self, i: usize) -> String {
        let b = &self.bits[i];
        if b.stuff {
            format!("stuff after {:?}[{}]", b.field, b.index)
        } else {
            format!("{:?}[{}]", b.field, b.index)
        }
    }
}

/// Small deterministic generator (SplitMix64) for the frame searches below.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// What a stuff bit follows: the field of the bit before it, or "after the last
/// CRC bit" (the stuff bit right before the CRC delimiter).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StuffSite {
    /// A stuff bit after a bit of this field.
    After(Field),
    /// The stuff bit after the 15th CRC bit.
    AfterLastCrcBit,
}

impl FrameBits {
    /// Where this frame's stuff bits are.
    pub fn stuff_sites(&self) -> Vec<StuffSite> {
        self.bits
            .iter()
            .filter(|b| b.stuff)
            .map(|b| {
                if b.field == Field::Crc && b.index == 14 {
                    StuffSite::AfterLastCrcBit
                } else {
                    StuffSite::After(b.field)
                }
            })
            .collect()
    }
}

/// Every place a stuff bit can occur in a base (`ide` false) or extended frame.
pub fn stuff_site_set(ide: bool) -> Vec<StuffSite> {
    let fields: &[Field] = if ide {
        &[
            Field::IdA,
            Field::SrrRtr,
            Field::Ide,
            Field::IdB,
            Field::RtrExt,
            Field::R1,
            Field::R0,
            Field::Dlc,
            Field::Data,
            Field::Crc,
        ]
    } else {
        &[
            Field::IdA,
            Field::SrrRtr,
            Field::Ide,
            Field::R0,
            Field::Dlc,
            Field::Data,
            Field::Crc,
        ]
    };
    let mut v: Vec<StuffSite> = fields.iter().map(|&f| StuffSite::After(f)).collect();
    v.push(StuffSite::AfterLastCrcBit);
    v
}

/// A small set of frames (ISO 16845-1 7.1.10 / 7.1.11, 8.1.6 / 8.1.7: critical
/// stuffing) whose stuff bits together occur after every field that can be
/// followed by one ([`stuff_site_set`]), found by a deterministic search; the
/// all-dominant and all-recessive frames come first.
pub fn stuffing_frames(ide: bool) -> Vec<Frame> {
    let mask = if ide { 0x1FFF_FFFF } else { 0x7FF };
    let mut frames = vec![
        Frame {
            id: 0,
            ide,
            dlc: 8,
            ..Frame::default()
        },
        Frame {
            id: mask,
            ide,
            dlc: 8,
            data: [0xFF; 8],
            ..Frame::default()
        },
    ];
    let want = stuff_site_set(ide);
    let mut have: Vec<StuffSite> = frames
        .iter()
        .flat_map(|f| FrameBits::new(f).stuff_sites())
        .collect();
    let patterns = [0x00, 0xFF, 0x0F, 0xF0, 0x1F, 0xF8, 0x83, 0x7C];
    let mut rng = Rng(if ide { 0xE0E0 } else { 0xB0B0 });
    for _ in 0..100_000 {
        if want.iter().all(|w| have.contains(w)) {
            return frames;
        }
        let r = rng.next();
        let mut f = Frame {
            id: (rng.next() as u32) & mask,
            ide,
            rtr: r.is_multiple_of(8),
            dlc: ((r >> 8) % 9) as u8,
            data: [0; 8],
        };
        for b in f.data.iter_mut() {
            let x = rng.next();
            *b = if x.is_multiple_of(3) {
                (x >> 8) as u8
            } else {
                patterns[((x >> 8) % 8) as usize]
            };
        }
        let f = f.normalized();
        let sites = FrameBits::new(&f).stuff_sites();
        if sites.iter().any(|s| want.contains(s) && !have.contains(s)) {
            have.extend(sites);
            frames.push(f);
        }
    }
    panic!("no frame set covers every stuff site");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc15_check_value() {
        // CRC-15/CAN check value over ASCII "123456789".
        assert_eq!(crc15(&bytes_to_bits(b"123456789")), 0x059E);
    }

    #[test]
    fn base_frame_layout_and_stuffing() {
        // ID 0, DLC 0: SOF + 11 dominant ID bits need stuff bits after 5 equal bits.
        let fb = FrameBits::new(&Frame::default());
        let v = fb.values();
        assert_eq!(&v[..7], &[false, false, false, false, false, true, false]);
        assert!(fb.bits[5].stuff);
        // No six equal bits anywhere up to the CRC delimiter.
        let end = fb.crc_delim();
        for w in v[..end].windows(6) {
            assert!(w.iter().any(|&b| b != w[0]), "six equal bits in {v:?}");
        }
        assert_eq!(fb.len() - fb.crc_delim(), 10);
        assert_eq!(fb.eof(7), fb.len() - 1);
    }

    #[test]
    fn stuffing_frames_cover_every_site() {
        for ide in [false, true] {
            let frames = stuffing_frames(ide);
            let sites: Vec<StuffSite> = frames
                .iter()
                .flat_map(|f| FrameBits::new(f).stuff_sites())
                .collect();
            for w in stuff_site_set(ide) {
                assert!(sites.contains(&w), "{w:?} not covered");
            }
            assert!(frames.len() < 20, "{} frames", frames.len());
        }
    }

    #[test]
    fn unstuffed_lengths() {
        let ext = Frame {
            id: 0x1555_5555,
            ide: true,
            dlc: 8,
            data: [0x55; 8],
            ..Frame::default()
        };
        let fb = FrameBits::new(&ext);
        // 1 + 11 + 1 + 1 + 18 + 1 + 1 + 1 + 4 + 64 + 15 destuffed bits, then 10 fixed.
        let n = fb.bits.iter().filter(|b| !b.stuff).count();
        assert_eq!(n, 118 + 10);
    }
}
