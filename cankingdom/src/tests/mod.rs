//! Test doubles: a frame type, a recording Postmaster, a broadcast bus.

mod king;
mod mayor;
mod mayor_reject;
mod pages;
mod system;

use std::collections::VecDeque;
use std::vec::Vec;

use embedded_can::{ErrorKind, ExtendedId, Frame, Id, StandardId};

use crate::postmaster::{BitRate, CommMode, Postmaster};

/// A classical CAN frame.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TestFrame {
    id: Id,
    data: [u8; 8],
    dlc: usize,
    remote: bool,
}

impl Frame for TestFrame {
    fn new(id: impl Into<Id>, data: &[u8]) -> Option<Self> {
        if data.len() > 8 {
            return None;
        }
        let mut d = [0; 8];
        d[..data.len()].copy_from_slice(data);
        Some(Self {
            id: id.into(),
            data: d,
            dlc: data.len(),
            remote: false,
        })
    }
    fn new_remote(id: impl Into<Id>, dlc: usize) -> Option<Self> {
        (dlc <= 8).then(|| Self {
            id: id.into(),
            data: [0; 8],
            dlc,
            remote: true,
        })
    }
    fn is_extended(&self) -> bool {
        matches!(self.id, Id::Extended(_))
    }
    fn is_remote_frame(&self) -> bool {
        self.remote
    }
    fn id(&self) -> Id {
        self.id
    }
    fn dlc(&self) -> usize {
        self.dlc
    }
    fn data(&self) -> &[u8] {
        if self.remote {
            &[]
        } else {
            &self.data[..self.dlc]
        }
    }
}

/// A standard-format data frame.
pub fn std_frame(id: u16, data: &[u8]) -> TestFrame {
    TestFrame::new(StandardId::new(id).unwrap(), data).unwrap()
}

/// An extended-format data frame.
pub fn ext_frame(id: u32, data: &[u8]) -> TestFrame {
    TestFrame::new(ExtendedId::new(id).unwrap(), data).unwrap()
}

/// The raw standard identifier of a frame (panics on extended: tests only).
pub fn std_id(f: &TestFrame) -> u16 {
    match f.id() {
        Id::Standard(s) => s.as_raw(),
        Id::Extended(_) => panic!("extended frame"),
    }
}

/// A Postmaster that records everything done to it.
#[derive(Debug, Default)]
pub struct FakePost {
    /// Frames waiting to be received.
    pub rx: VecDeque<TestFrame>,
    /// Frames transmitted (delivered to the bus by the test).
    pub tx: Vec<TestFrame>,
    /// Every `set_comm_mode`, in order.
    pub modes: Vec<CommMode>,
    /// Every `set_bit_rate`, in order.
    pub rates: Vec<BitRate>,
    /// While true, `transmit` answers `WouldBlock`.
    pub busy: bool,
    /// Transmissions attempted while Silent or before any mode was set.
    pub silent_violations: u32,
}

impl FakePost {
    /// The current mode.
    pub fn mode(&self) -> Option<CommMode> {
        self.modes.last().copied()
    }
    /// The current bit rate.
    pub fn rate(&self) -> Option<BitRate> {
        self.rates.last().copied()
    }
}

impl embedded_can::nb::Can for FakePost {
    type Frame = TestFrame;
    type Error = ErrorKind;

    fn transmit(&mut self, frame: &TestFrame) -> nb::Result<Option<TestFrame>, ErrorKind> {
        if self.busy {
            return Err(nb::Error::WouldBlock);
        }
        if matches!(self.mode(), None | Some(CommMode::Silent)) {
            self.silent_violations += 1;
        }
        self.tx.push(frame.clone());
        Ok(None)
    }

    fn receive(&mut self) -> nb::Result<TestFrame, ErrorKind> {
        self.rx.pop_front().ok_or(nb::Error::WouldBlock)
    }
}

impl Postmaster for FakePost {
    fn set_comm_mode(&mut self, mode: CommMode) {
        self.modes.push(mode);
    }
    fn set_bit_rate(&mut self, rate: BitRate) {
        self.rates.push(rate);
    }
}

/// An in-memory broadcast bus: every transmitted frame goes to every other
/// node at the same bit rate. A node that transmits while Silent is a
/// protocol violation (counted by its FakePost, and the frame is dropped).
#[derive(Debug, Default)]
pub struct Bus {
    /// One Postmaster per node.
    pub posts: Vec<FakePost>,
    /// Every frame that went on the bus, with its sender.
    pub log: Vec<(usize, TestFrame)>,
}

impl Bus {
    /// A bus with `n` nodes.
    pub fn new(n: usize) -> Self {
        Self {
            posts: (0..n).map(|_| FakePost::default()).collect(),
            log: Vec::new(),
        }
    }

    /// Deliver what node `from` transmitted.
    pub fn deliver(&mut self, from: usize) {
        let frames = std::mem::take(&mut self.posts[from].tx);
        let silent = matches!(self.posts[from].mode(), None | Some(CommMode::Silent));
        if silent {
            return;
        }
        let rate = self.posts[from].rate();
        for f in frames {
            for (j, p) in self.posts.iter_mut().enumerate() {
                if j != from && p.rate() == rate {
                    p.rx.push_back(f.clone());
                }
            }
            self.log.push((from, f));
        }
    }

    /// Total protocol violations.
    pub fn violations(&self) -> u32 {
        self.posts.iter().map(|p| p.silent_violations).sum()
    }
}
