//! Identification frames of NRAP (ReCANcentrate paper section 5; hub contract
//! §9.1, §9.3): the two ROMs, built at generation time, and the hub's
//! transmitter and recogniser.
//!
//! - ROMs (§9.1): [`id_frame`] builds the bus bits of a base data frame with
//!   identifier `id` and DLC 0 (SOF, identifier, RTR, IDE, r0, DLC, CRC-15 over
//!   SOF..DLC, stuffed after 5 equal bits over SOF..CRC, then the recessive CRC
//!   delimiter). Hub `H` (0 = A, 1 = B) holds `ROM_OWN` = frame `H` and `ROM_TWIN`
//!   = frame `1 - H` as constants of the netlist (`Bits<64>`, bit k = bus bit k);
//!   nothing computes a CRC at run time, and only `ROM_OWN` feeds the transmitter.
//! - Transmitter (§9.3): `tx_q` (reset 1), `tx_on`, `tx_idx`, `ack_due`, `acking`
//!   and `quiet`, the recessive samples in a row (`quiet = b ? min(quiet + 1, 15)
//!   : 0` at every SAMPLE edge). At a `bit_start` edge of the hub's BTL (values
//!   before it): a hard sync while sending does nothing (it restarts the SOF bit);
//!   else the next ROM bit; after the CRC delimiter `tx_q = 1` and `tx_on = 0`;
//!   else a due ACK of the twin's frame (one dominant bit); else a SOF when `send`
//!   and `quiet >= 11` (the first bit of bus idle). At a SAMPLE edge a sent bit
//!   that differs from the bus (`b`) stops the transmitter (`tx_on = 0`, `tx_q =
//!   1`). At every edge where `hush` (`!active` or a FORCE phase, registers)
//!   `tx_on`, `ack_due`, `acking` clear and `tx_q = 1`.
//! - Recogniser (§9.3): at `SOF_PORTS` `r_idx = 1`, `r_own = r_twin = 1`; at
//!   `FRAME_PORTS` each flag stays 1 while the bus bit matches its ROM at `r_idx`
//!   (`r_idx < L`), `r_idx = min(r_idx + 1, 63)`; `own_frame = r_own & r_idx ==
//!   L_OWN`, `twin_frame = r_twin & r_idx == L_TWIN` (registers, read by the NRAP
//!   phase rules at `ACK_PORTS`); `in_id = r_own | r_twin` (the erring rule of
//!   `NRP` and `DDSP_SEND` looks only inside identification frames). `ack_due = 1` at a `FRAME_PORTS` edge where the
//!   new `r_twin` is 1 and the new `r_idx == L_TWIN` (the twin's CRC delimiter)
//!   and `ack_en` (phase `SRP_EXCHANGE`, `NRP` or `DDSP_SEND`).
//!
//! `rst` (the hub's `rst | reset_mode`) holds every register at its reset value.

use crate::pins::RecessiveReg;
use rust_hdl::prelude::*;

/// The CAN CRC-15 generator polynomial (ISO 11898-1 10.4.2.6).
const CRC15_POLY: u16 = 0x4599;

/// The identification frame of base identifier `id`, DLC 0, as it appears on the
/// bus from SOF to the CRC delimiter inclusive (stuff bits included), index 0 =
/// SOF; `true` = recessive. Hub A's (`id` 0) is 41 bits, hub B's (`id` 1) 38.
pub fn id_frame(id: u16) -> Vec<bool> {
    assert!(id < 0x800, "a base identifier has 11 bits");
    // SOF, identifier MSB first, RTR = 0, IDE = 0, r0 = 0, DLC = 0000
    let mut raw = vec![false];
    raw.extend((0..11).rev().map(|k| (id >> k) & 1 == 1));
    raw.extend([false; 3 + 4]);
    // CRC-15 over SOF..DLC (initial value 0)
    let mut crc: u16 = 0;
    for &b in &raw {
        let next = b ^ ((crc >> 14) & 1 == 1);
        crc = (crc << 1) & 0x7FFF;
        if next {
            crc ^= CRC15_POLY;
        }
    }
    raw.extend((0..15).rev().map(|k| (crc >> k) & 1 == 1));
    // bit stuffing over SOF..CRC: after 5 equal bits the complement, which counts
    // as the first bit of the next run (a stuff bit after the last CRC bit too)
    let mut bus = Vec::with_capacity(raw.len() + raw.len() / 4 + 2);
    let (mut last, mut run) = (true, 0);
    for b in raw {
        if run == 5 {
            bus.push(!last);
            last = !last;
            run = 1;
        }
        if b == last {
            run += 1;
        } else {
            last = b;
            run = 1;
        }
        bus.push(b);
    }
    if run == 5 {
        bus.push(!last);
    }
    // CRC delimiter
    bus.push(true);
    bus
}

/// The ROM of identifier `id`: bit k of the word = bus bit k of [`id_frame`],
/// and the frame's length `L`.
pub fn id_rom(id: u16) -> (u64, usize) {
    let bits = id_frame(id);
    assert!(
        bits.len() < 64,
        "an identification frame fits a 6-bit index"
    );
    let word = bits
        .iter()
        .enumerate()
        .fold(0u64, |w, (k, &b)| w | (u64::from(b) << k));
    (word, bits.len())
}

/// The transmitter and recogniser of hub `H` (0 = hub A, 1 = hub B).
#[derive(LogicBlock)]
pub struct IdFrame<const H: usize> {
    // ---- clock and reset ----
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// `rst | reset_mode` (value before the edge): every register to its reset
    /// value (`tx_q` = 1, the rest 0).
    pub rst: Signal<In, Bit>,
    // ---- from the hub's bit timing logic ----
    /// `BitStart` edge of the hub's BTL (§C.3): the transmitter may change.
    pub bit_start: Signal<In, Bit>,
    /// This bit start is a hard synchronisation.
    pub hard: Signal<In, Bit>,
    /// SAMPLE edge of the hub's BTL.
    pub sample: Signal<In, Bit>,
    /// `coupled_q`: the bus value sampled at a SAMPLE edge.
    pub b: Signal<In, Bit>,
    // ---- from the tracker (§5; events valid in the clock of the SAMPLE edge) ----
    /// `SOF_PORTS`.
    pub ev_sof: Signal<In, Bit>,
    /// `FRAME_PORTS`: every sampled bit of `FRAME`.
    pub ev_frame: Signal<In, Bit>,
    // ---- from the NRAP phase (registers, §9.2/§9.3) ----
    /// `send`: the transmitter may start an identification frame.
    pub send: Signal<In, Bit>,
    /// The phase is `SRP_EXCHANGE`, `NRP` or `DDSP_SEND`: the twin's frame is
    /// acknowledged.
    pub ack_en: Signal<In, Bit>,
    /// `!active | forcing`: the transmitter is held silent at this edge.
    pub hush: Signal<In, Bit>,
    // ---- outputs ----
    /// `tx_q`: the hub's transmitter, 1 = recessive.
    pub tx: Signal<Out, Bit>,
    /// `r_own & r_idx == L_OWN`: the frame that just ended is the own one.
    pub own_frame: Signal<Out, Bit>,
    /// `r_twin & r_idx == L_TWIN`: the frame that just ended is the twin's.
    pub twin_frame: Signal<Out, Bit>,
    /// `r_own | r_twin`: the frame so far is an identification frame.
    pub in_id: Signal<Out, Bit>,
    // ---- transmitter ----
    /// The transmitter's pin register: recessive from configuration on.
    tx_q: RecessiveReg<Bit>,
    tx_on: DFF<Bit>,
    tx_idx: DFF<Bits<6>>,
    ack_due: DFF<Bit>,
    acking: DFF<Bit>,
    quiet: DFF<Bits<4>>,
    // ---- recogniser ----
    r_idx: DFF<Bits<6>>,
    r_own: DFF<Bit>,
    r_twin: DFF<Bit>,
    r_own_n: Signal<Local, Bit>,
    r_twin_n: Signal<Local, Bit>,
    // ---- the ROMs (§9.1) ----
    rom_own: Constant<Bits<64>>,
    rom_twin: Constant<Bits<64>>,
    l_own: Constant<Bits<6>>,
    l_twin: Constant<Bits<6>>,
    l_twin_m1: Constant<Bits<6>>,
    zero6: Constant<Bits<6>>,
    one6: Constant<Bits<6>>,
    max6: Constant<Bits<6>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    eleven4: Constant<Bits<4>>,
    max4: Constant<Bits<4>>,
}

impl<const H: usize> Default for IdFrame<H> {
    fn default() -> Self {
        assert!(H <= 1, "hub: HUB_ID is 0 (hub A) or 1 (hub B)");
        let (own, l_own) = id_rom(H as u16);
        let (twin, l_twin) = id_rom(1 - H as u16);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            bit_start: Default::default(),
            hard: Default::default(),
            sample: Default::default(),
            b: Default::default(),
            ev_sof: Default::default(),
            ev_frame: Default::default(),
            send: Default::default(),
            ack_en: Default::default(),
            hush: Default::default(),
            tx: Default::default(),
            own_frame: Default::default(),
            twin_frame: Default::default(),
            in_id: Default::default(),
            tx_q: Default::default(),
            tx_on: Default::default(),
            tx_idx: Default::default(),
            ack_due: Default::default(),
            acking: Default::default(),
            quiet: Default::default(),
            r_idx: Default::default(),
            r_own: Default::default(),
            r_twin: Default::default(),
            r_own_n: Default::default(),
            r_twin_n: Default::default(),
            rom_own: Constant::new(own.into()),
            rom_twin: Constant::new(twin.into()),
            l_own: Constant::new((l_own as u64).into()),
            l_twin: Constant::new((l_twin as u64).into()),
            l_twin_m1: Constant::new((l_twin as u64 - 1).into()),
            zero6: Constant::new(0.into()),
            one6: Constant::new(1.into()),
            max6: Constant::new(63.into()),
            zero4: Constant::new(0.into()),
            one4: Constant::new(1.into()),
            eleven4: Constant::new(11.into()),
            max4: Constant::new(15.into()),
        }
    }
}

impl<const H: usize> Logic for IdFrame<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tx_q, tx_on, tx_idx, ack_due, acking, quiet, r_idx, r_own, r_twin);

        // ---- transmitter at a BitStart edge (§9.3) ----
        if self.bit_start.val() {
            if self.tx_on.q.val() & self.hard.val() {
                // a hard sync restarts the SOF bit: nothing
            } else if self.tx_on.q.val() & (self.tx_idx.q.val() < self.l_own.val()) {
                self.tx_q.d.next = self.rom_own.val().get_bit(self.tx_idx.q.val().index());
                self.tx_idx.d.next = self.tx_idx.q.val() + self.one6.val();
            } else if self.tx_on.q.val() {
                // after the CRC delimiter: listen
                self.tx_q.d.next = true;
                self.tx_on.d.next = false;
            } else if self.ack_due.q.val() {
                // acknowledge the twin's frame
                self.tx_q.d.next = false;
                self.ack_due.d.next = false;
                self.acking.d.next = true;
            } else if self.acking.q.val() {
                self.tx_q.d.next = true;
                self.acking.d.next = false;
            } else if self.send.val() & (self.quiet.q.val() >= self.eleven4.val()) {
                // SOF at the first bit of bus idle
                self.tx_q.d.next = false;
                self.tx_on.d.next = true;
                self.tx_idx.d.next = self.one6.val();
            }
        }
        // ---- transmitter at a SAMPLE edge: arbitration lost or a bit error ----
        if self.sample.val() & self.tx_on.q.val() & (self.b.val() != self.tx_q.q.val()) {
            self.tx_on.d.next = false;
            self.tx_q.d.next = true;
        }
        // recessive samples in a row
        if self.sample.val() {
            if !self.b.val() {
                self.quiet.d.next = self.zero4.val();
            } else if self.quiet.q.val() != self.max4.val() {
                self.quiet.d.next = self.quiet.q.val() + self.one4.val();
            }
        }

        // ---- recogniser (§9.3), from the tracker's events ----
        self.r_own_n.next = self.r_own.q.val()
            & (self.r_idx.q.val() < self.l_own.val())
            & (self.b.val() == self.rom_own.val().get_bit(self.r_idx.q.val().index()));
        self.r_twin_n.next = self.r_twin.q.val()
            & (self.r_idx.q.val() < self.l_twin.val())
            & (self.b.val() == self.rom_twin.val().get_bit(self.r_idx.q.val().index()));
        if self.ev_sof.val() {
            self.r_idx.d.next = self.one6.val();
            self.r_own.d.next = true;
            self.r_twin.d.next = true;
        }
        if self.ev_frame.val() {
            self.r_own.d.next = self.r_own_n.val();
            self.r_twin.d.next = self.r_twin_n.val();
            if self.r_idx.q.val() != self.max6.val() {
                self.r_idx.d.next = self.r_idx.q.val() + self.one6.val();
            }
            // the twin's CRC delimiter has just been sampled, right: ACK it
            if self.r_twin_n.val()
                & (self.r_idx.q.val() == self.l_twin_m1.val())
                & self.ack_en.val()
            {
                self.ack_due.d.next = true;
            }
        }

        // ---- silent outside NRAP and while forcing ----
        if self.hush.val() {
            self.tx_on.d.next = false;
            self.ack_due.d.next = false;
            self.acking.d.next = false;
            self.tx_q.d.next = true;
        }
        if self.rst.val() {
            self.tx_q.d.next = true;
            self.tx_on.d.next = false;
            self.tx_idx.d.next = self.zero6.val();
            self.ack_due.d.next = false;
            self.acking.d.next = false;
            self.quiet.d.next = self.zero4.val();
            self.r_idx.d.next = self.zero6.val();
            self.r_own.d.next = false;
            self.r_twin.d.next = false;
        }

        // ---- outputs ----
        self.tx.next = self.tx_q.q.val();
        self.own_frame.next = self.r_own.q.val() & (self.r_idx.q.val() == self.l_own.val());
        self.twin_frame.next = self.r_twin.q.val() & (self.r_idx.q.val() == self.l_twin.val());
        self.in_id.next = self.r_own.q.val() | self.r_twin.q.val();
    }
}
