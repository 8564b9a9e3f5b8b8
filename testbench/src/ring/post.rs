//! The `cankingdom` crate's controller trait ([`Postmaster`]) over the DRCC's host
//! interface: the simulated host of a ring node runs the same CanKingdom code a
//! microcontroller would, through this adapter (`ring_contract.md` §4).
//!
//! - transmit: the frame is pushed to TX queue A (normal mode) at this clock;
//! - receive: the frames the host popped from the RX FIFO, in order;
//! - Silent = `LISTEN_ONLY` (timing contract §7: no ACK, no error frame, never
//!   transmits); Listen Only and Communicate = `NORMAL`. A mode change is two
//!   `CTRL` writes (reset mode with the new `mode_a`, then out of reset mode): the
//!   channel re-integrates, as a controller does after a mode change;
//! - bit rate: the simulated clock makes 125 kbit/s with 8 time quanta of one clock
//!   (`btr(0, 5, 2, 1)`); any other rate is set as 62.5 kbit/s (BRP 1), a rate the
//!   125 kbit/s bus cannot be heard at: a City with a wrong presumed rate stays out.

use cankingdom::postmaster::{BitRate, CommMode, Postmaster};
use drcc_cosim::host::{btr, reg, HostConfig, HostDriver};
use drcc_cosim::Frame;
use embedded_can::{ErrorKind, ExtendedId, Id, StandardId};

/// A CAN frame as `embedded_can` sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CkFrame(pub Frame);

impl embedded_can::Frame for CkFrame {
    fn new(id: impl Into<Id>, data: &[u8]) -> Option<Self> {
        if data.len() > 8 {
            return None;
        }
        let (id, ide) = match id.into() {
            Id::Standard(s) => (s.as_raw() as u32, false),
            Id::Extended(e) => (e.as_raw(), true),
        };
        let mut d = [0u8; 8];
        d[..data.len()].copy_from_slice(data);
        Some(CkFrame(Frame {
            id,
            ide,
            rtr: false,
            dlc: data.len() as u8,
            data: d,
        }))
    }

    fn new_remote(id: impl Into<Id>, dlc: usize) -> Option<Self> {
        let mut f = Self::new(id, &[])?;
        f.0.rtr = true;
        f.0.dlc = dlc.min(15) as u8;
        Some(f)
    }

    fn is_extended(&self) -> bool {
        self.0.ide
    }

    fn is_remote_frame(&self) -> bool {
        self.0.rtr
    }

    fn id(&self) -> Id {
        if self.0.ide {
            Id::Extended(ExtendedId::new(self.0.id & 0x1FFF_FFFF).expect("29 bits"))
        } else {
            Id::Standard(StandardId::new((self.0.id & 0x7FF) as u16).expect("11 bits"))
        }
    }

    fn dlc(&self) -> usize {
        self.0.dlc as usize
    }

    fn data(&self) -> &[u8] {
        if self.0.rtr {
            &[]
        } else {
            &self.0.data[..(self.0.dlc as usize).min(8)]
        }
    }
}

/// The only error: nothing to receive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Empty;

impl embedded_can::Error for Empty {
    fn kind(&self) -> ErrorKind {
        ErrorKind::Other
    }
}

/// What the adapter keeps between polls of one node.
#[derive(Clone, Debug)]
pub struct PostState {
    /// Next index of `HostDriver::received` to hand out.
    pub rx_next: usize,
    /// The controller's channel A mode code in force (§C.7).
    pub mode_a: u8,
    /// The `BTR` value in force.
    pub btr: u32,
    config: HostConfig,
}

impl PostState {
    /// For a host configured with `config`.
    pub fn new(config: HostConfig) -> Self {
        PostState {
            rx_next: 0,
            mode_a: config.mode_a,
            btr: config.btr,
            config,
        }
    }
}

/// The adapter for one poll of one node at clock `now`.
pub struct DrccPost<'a> {
    pub host: &'a mut HostDriver,
    pub state: &'a mut PostState,
    pub now: u64,
}

impl DrccPost<'_> {
    /// Gives up every frame queued and not yet sent: the host's backlog, and the
    /// DRCC's TX queues, which entering reset mode empties (DRCC contract §9).
    pub fn flush(&mut self) {
        self.host.drop_submissions();
        self.reconfigure();
    }

    fn reconfigure(&mut self) {
        let c = HostConfig {
            btr: self.state.btr,
            mode_a: self.state.mode_a,
            ..self.state.config
        };
        self.host.write(reg::CTRL, c.ctrl(true));
        self.host.write(reg::BTR, c.btr);
        self.host.write(reg::CTRL, c.ctrl(false));
    }
}

impl embedded_can::nb::Can for DrccPost<'_> {
    type Frame = CkFrame;
    type Error = Empty;

    fn transmit(&mut self, frame: &CkFrame) -> nb::Result<Option<CkFrame>, Empty> {
        self.host.submit(self.now, frame.0, 0);
        Ok(None)
    }

    fn receive(&mut self) -> nb::Result<CkFrame, Empty> {
        match self.host.received.get(self.state.rx_next) {
            Some(r) => {
                self.state.rx_next += 1;
                Ok(CkFrame(r.frame))
            }
            None => Err(nb::Error::WouldBlock),
        }
    }
}

impl Postmaster for DrccPost<'_> {
    fn set_comm_mode(&mut self, mode: CommMode) {
        let code = match mode {
            CommMode::Silent => 1,
            CommMode::ListenOnly | CommMode::Communicate => 0,
        };
        if code != self.state.mode_a {
            self.state.mode_a = code;
            self.reconfigure();
        }
    }

    fn set_bit_rate(&mut self, rate: BitRate) {
        let value = match rate {
            BitRate::Kbit125 => ring_btr(),
            _ => btr(1, 5, 2, 1, false, 96),
        };
        if value != self.state.btr {
            self.state.btr = value;
            self.reconfigure();
        }
    }
}

/// The ring's bit timing: 8 time quanta of one clock (125 kbit/s at 1 MHz).
pub fn ring_btr() -> u32 {
    btr(0, 5, 2, 1, false, 96)
}
