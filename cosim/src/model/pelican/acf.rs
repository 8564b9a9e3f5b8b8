//! The SJA1000 acceptance filter (PeliCAN contract P-ACF-1, DS 6.4.15).

use crate::frame::Frame;

/// `ACR0..3`, `AMR0..3` and `MOD.AFM`: a function of the frame only (P-RX-5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Acf {
    pub acr: [u8; 4],
    pub amr: [u8; 4],
    /// `MOD.AFM`: single filter.
    pub single: bool,
}

/// `m(c, k, x)`: every bit not masked (`AMR` 0 = compare) equal.
fn m(c: u8, k: u8, x: u8) -> bool {
    (c ^ x) & !k == 0
}

impl Acf {
    /// The frame passes (P-ACF-1).
    pub fn accepts(&self, f: &Frame) -> bool {
        let (a, k) = (self.acr, self.amr);
        let rtr = f.rtr as u8;
        if f.ide {
            let id = f.id;
            let b = [(id >> 21) as u8, (id >> 13) as u8, (id >> 5) as u8];
            let b3 = ((id as u8 & 0x1F) << 3) | (rtr << 2);
            if self.single {
                m(a[0], k[0], b[0])
                    && m(a[1], k[1], b[1])
                    && m(a[2], k[2], b[2])
                    && m(a[3] & 0xFC, k[3] | 0x03, b3)
            } else {
                (m(a[0], k[0], b[0]) && m(a[1], k[1], b[1]))
                    || (m(a[2], k[2], b[0]) && m(a[3], k[3], b[1]))
            }
        } else {
            let hi = (f.id >> 3) as u8;
            // {id[2:0], rtr} in bits [7:4].
            let lo = ((f.id as u8 & 7) << 5) | (rtr << 4);
            let nb0 = f.rtr || f.dlc == 0;
            let nb1 = f.rtr || f.dlc < 2;
            let (d1, d2) = (f.data[0], f.data[1]);
            if self.single {
                m(a[0], k[0], hi)
                    && m(a[1], k[1] | 0x0F, lo)
                    && (nb0 || m(a[2], k[2], d1))
                    && (nb1 || m(a[3], k[3], d2))
            } else {
                let f1 = m(a[0], k[0], hi)
                    && m(a[1], k[1] | 0x0F, lo)
                    && (nb0 || m((a[1] << 4) | (a[3] & 0x0F), (k[1] << 4) | (k[3] & 0x0F), d1));
                let f2 = m(a[2], k[2], hi) && m(a[3], k[3] | 0x0F, lo);
                f1 || f2
            }
        }
    }
}
