//! The algorithms' rules against the seed and the ring contract, on a frame type
//! of the tests' own (any `embedded_can::Frame` will do).

use crate::central::{answer_of, decide, BASE};
use crate::distributed::{DistNode, DistTiming, ALIVE_BASE, DETECT_ENVELOPE};
use crate::{CONNECT_LEFT, CONNECT_RIGHT, TRANSPARENT};
use alloc::vec;
use alloc::vec::Vec;
use embedded_can::{ExtendedId, Frame, Id, StandardId};

#[derive(Clone, Debug, PartialEq)]
struct TestFrame {
    id: Id,
    rtr: bool,
    data: Vec<u8>,
}

impl Frame for TestFrame {
    fn new(id: impl Into<Id>, data: &[u8]) -> Option<Self> {
        (data.len() <= 8).then(|| TestFrame {
            id: id.into(),
            rtr: false,
            data: data.to_vec(),
        })
    }
    fn new_remote(id: impl Into<Id>, _dlc: usize) -> Option<Self> {
        Some(TestFrame {
            id: id.into(),
            rtr: true,
            data: Vec::new(),
        })
    }
    fn is_extended(&self) -> bool {
        matches!(self.id, Id::Extended(_))
    }
    fn is_remote_frame(&self) -> bool {
        self.rtr
    }
    fn id(&self) -> Id {
        self.id
    }
    fn dlc(&self) -> usize {
        self.data.len()
    }
    fn data(&self) -> &[u8] {
        &self.data
    }
}

fn std_frame(id: u16, data: &[u8]) -> TestFrame {
    TestFrame::new(StandardId::new(id).unwrap(), data).unwrap()
}

/// Seed 000, Table 1 (centralized): both sides reached -> transparent; only the
/// left -> connect left; neither -> connect right (awaiting the scan from the
/// left); and the row the table lacks, only the right -> connect right.
#[test]
fn slave_decisions_follow_table_1() {
    assert_eq!(decide(true, true), TRANSPARENT);
    assert_eq!(decide(true, false), CONNECT_LEFT);
    assert_eq!(decide(false, false), CONNECT_RIGHT);
    assert_eq!(decide(false, true), CONNECT_RIGHT);
}

/// A City's answer is a Mayor's Page on `BASE + address`; anything else on those
/// envelopes (a remote frame, an extended one, a malformed page) is not.
#[test]
fn answers_are_mayors_pages_on_the_city_envelope() {
    // Mayor's Page 0 (seed 002's form): Line 1 = page 0, Lines 2..6 the EAN-13.
    let page0 = [0u8, 0, 0x07, 0x00, 0x11, 0x47, 0x00, 0];
    assert_eq!(answer_of(&std_frame((BASE + 7) as u16, &page0)), Some(7));
    let page9 = [0u8, 9, 0x07, 0x00, 0x11, 0x47, 0x00, 0];
    assert_eq!(answer_of(&std_frame((BASE + 7) as u16, &page9)), None);
    assert_eq!(answer_of(&std_frame(BASE as u16, &page0)), None);
    let remote = TestFrame::new_remote(StandardId::new((BASE + 7) as u16).unwrap(), 8).unwrap();
    assert_eq!(answer_of(&remote), None);
    let ext = TestFrame::new(ExtendedId::new(BASE + 7).unwrap(), &page0).unwrap();
    assert_eq!(answer_of(&ext), None);
}

/// Ring contract §6, Run: an alive letter every Ta; a ring node silent for more
/// than 2 Ta starts the rebuild with a D letter of its own, giving up what it
/// queued.
#[test]
fn distributed_node_detects_a_silent_neighbour_after_two_alive_periods() {
    let t = DistTiming::standard(3_000);
    let mut node: DistNode<TestFrame> = DistNode::new(1, 3, 3, 0x500, t, 0);
    node.poll(0, &[]);
    assert_eq!(node.outbox, vec![std_frame(ALIVE_BASE as u16 + 1, &[1])]);
    node.outbox.clear();
    // Node 2 keeps talking; node 0 falls silent after time 0.
    let alive2 = std_frame(ALIVE_BASE as u16 + 2, &[2]);
    let mut now = 0;
    while now <= 2 * t.ta {
        now += 1_000;
        node.poll(now, core::slice::from_ref(&alive2));
        if now <= 2 * t.ta {
            assert!(
                node.settled(),
                "detected at {now} us, before 2 Ta of silence"
            );
        }
    }
    assert!(!node.settled(), "no detection after 2 Ta + 1 ms of silence");
    assert_eq!(node.detected_at, Some(now));
    assert!(node.flush);
    assert!(node
        .outbox
        .contains(&std_frame(DETECT_ENVELOPE as u16, &[1])));
}

/// The D letter of another node starts the rebuild at once; the same envelope in
/// an extended or a remote frame is no letter.
#[test]
fn a_detect_letter_starts_the_rebuild_only_as_a_base_data_frame() {
    let t = DistTiming::standard(3_000);
    let mut node: DistNode<TestFrame> = DistNode::new(2, 3, 3, 0x500, t, 0);
    let ext = TestFrame::new(ExtendedId::new(DETECT_ENVELOPE).unwrap(), &[0]).unwrap();
    let remote =
        TestFrame::new_remote(StandardId::new(DETECT_ENVELOPE as u16).unwrap(), 1).unwrap();
    node.poll(100, &[ext, remote]);
    assert!(node.settled());
    node.poll(200, &[std_frame(DETECT_ENVELOPE as u16, &[0])]);
    assert!(!node.settled());
    assert_eq!(node.detected_at, Some(200));
}
