//! Tests of the taps on running systems of the reference model: deliveries come out
//! as the systems record them, and the errors of a transmitter nobody acknowledges
//! come out as ISO 11898-1's counting rules predict.

use super::error::*;
use super::*;
use crate::engine::drcc_model::DrccModelEngine;
use crate::engine::model::ModelEngine;
use crate::engine::{BitTiming, ChannelEngine};
use crate::host::{HostConfig, Policy};
use crate::system::System;

fn model_bus(nodes: usize) -> System {
    let engines: Vec<Box<dyn ChannelEngine>> = (0..nodes)
        .map(|_| Box::new(ModelEngine::new()) as Box<dyn ChannelEngine>)
        .collect();
    System::new(engines, BitTiming::default()).unwrap()
}

fn run_bus(sys: &mut System, cycles: u64) -> Vec<TrafficEvent> {
    let mut tap = ChannelTap::new(sys.nodes());
    let mut events = Vec::new();
    for _ in 0..cycles {
        sys.step();
        tap.poll(sys, &mut events);
        // a clock seen twice counts once
        tap.poll(sys, &mut events);
    }
    events
}

#[test]
fn a_bus_tap_yields_every_delivery_in_order() {
    let mut sys = model_bus(3);
    sys.submit(0, 50, Frame::base(0x123, &[1, 2, 3])).unwrap();
    sys.submit(1, 50, Frame::base(0x0A0, &[4])).unwrap();
    let remote = Frame {
        id: 0x1234_5678,
        ide: true,
        rtr: true,
        dlc: 2,
        data: [0; 8],
    };
    sys.submit(2, 400, remote).unwrap();
    let events = run_bus(&mut sys, 2_000);
    let want: Vec<TrafficEvent> = sys
        .deliveries()
        .iter()
        .map(|d| TrafficEvent {
            cycle: d.cycle,
            node: d.node,
            line: None,
            kind: TrafficKind::Frame(d.frame),
        })
        .collect();
    assert_eq!(want.len(), 6, "three frames, two receivers each");
    assert_eq!(events, want, "an error-free run has frames only");
}

/// A lone transmitter gets an ACK error per attempt: TEC + 8 each time (rule c),
/// the warning limit at 96, error passive at 128, where ACK errors stop counting
/// (rule c, exception 1).
#[test]
fn a_lone_transmitter_reports_ack_errors_warning_and_passive() {
    let mut sys = model_bus(1);
    sys.submit(0, 20, Frame::base(0x555, &[0xAA])).unwrap();
    let events = run_bus(&mut sys, 8 * 60 * 30);
    let errors: Vec<ErrorFrame> = events
        .iter()
        .map(|e| match e.kind {
            TrafficKind::Error(f) => f,
            TrafficKind::Frame(f) => panic!("nobody received {f}"),
        })
        .collect();
    let ack = CAN_ERR_FLAG | CAN_ERR_ACK | CAN_ERR_BUSERROR | CAN_ERR_CNT;
    let crtl = CAN_ERR_FLAG | CAN_ERR_CRTL | CAN_ERR_CNT;
    let mut want = Vec::new();
    for k in 1..=16u8 {
        want.push((ack, 0, 8 * k));
        if k == 12 {
            want.push((crtl, CAN_ERR_CRTL_TX_WARNING, 96));
        }
    }
    want.push((crtl, CAN_ERR_CRTL_TX_PASSIVE, 128));
    want.extend([(ack, 0, 128); 3]);
    let got: Vec<(u32, u8, u8)> = errors
        .iter()
        .take(want.len())
        .map(|f| (f.can_id, f.data[1], f.data[6]))
        .collect();
    assert_eq!(got, want);
}

fn dual(configs: Vec<HostConfig>) -> crate::dual::DualBusSystem {
    let engines = configs
        .iter()
        .map(|_| Box::new(DrccModelEngine::new()) as Box<dyn crate::engine::drcc::DrccEngine>)
        .collect();
    crate::dual::DualBusSystem::new(engines, configs).unwrap()
}

/// Node 1 listens only on line A: node 0's frame gets ACK errors there (flags
/// starting after the ACK slot) until node 0 switches to line B after one failed
/// attempt, where node 1 acknowledges and pops it.
#[test]
fn a_dual_tap_yields_host_frames_and_channel_errors() {
    let node0 = HostConfig {
        policy: Policy::KFailed(1),
        ..HostConfig::default()
    };
    let node1 = HostConfig {
        redundancy: false,
        policy: Policy::None,
        mode_a: 1,
        ..HostConfig::default()
    };
    let mut sys = dual(vec![node0, node1]);
    let f = Frame::base(0x0A5, &[0xAA; 8]);
    sys.node_mut(0).host.submit(40 * 8, f, 0);
    let mut tap = NodeTap::new(2);
    let mut events = Vec::new();
    for _ in 0..8 * 1_500 {
        sys.step();
        tap.poll(&sys, &mut events);
    }
    let frames: Vec<(usize, Option<u8>, Frame, u64)> = events
        .iter()
        .filter_map(|e| match e.kind {
            TrafficKind::Frame(f) => Some((e.node, e.line, f, e.cycle)),
            TrafficKind::Error(_) => None,
        })
        .collect();
    let popped = &sys.node(1).host.received;
    assert_eq!(popped.len(), 1);
    assert_eq!(
        frames,
        [(1, Some(1), f, popped[0].cycle)],
        "node 1 popped it from B"
    );
    let first_error = events
        .iter()
        .find_map(|e| match e.kind {
            TrafficKind::Error(x) => Some((e.node, e.line, x)),
            TrafficKind::Frame(_) => None,
        })
        .unwrap();
    let mut want = ErrorFrame::new(CAN_ERR_PROT | CAN_ERR_BUSERROR).with_counters(8, 0);
    want.data[3] = CAN_ERR_PROT_LOC_ACK;
    assert_eq!(first_error, (0, Some(0), want), "node 0's ACK error on A");
}

/// A node whose receiver is stuck recessive reads back its own dominant SOF as
/// recessive: a bit error "unable to send dominant bit" as transmitter, at the
/// start of frame, TEC 8 (timing contract §4.4).
#[test]
fn a_deaf_transmitter_reports_bit0_at_its_start_of_frame() {
    use crate::bus::{Fault, FaultKind, FaultTarget};
    let mut sys = model_bus(2);
    sys.add_fault(Fault {
        target: FaultTarget::Rx(0),
        kind: FaultKind::StuckRecessive,
        start: 0,
        cycles: u64::MAX,
    })
    .unwrap();
    sys.submit(0, 20, Frame::base(0x100, &[])).unwrap();
    let events = run_bus(&mut sys, 8 * 40);
    let first = events
        .iter()
        .find(|e| e.node == 0)
        .expect("an error of node 0");
    let mut want = ErrorFrame::new(CAN_ERR_PROT | CAN_ERR_BUSERROR).with_counters(8, 0);
    want.data[2] = CAN_ERR_PROT_BIT0 | CAN_ERR_PROT_TX;
    want.data[3] = CAN_ERR_PROT_LOC_SOF;
    assert_eq!(first.kind, TrafficKind::Error(want));
}

/// A ring of three ring nodes (no plain nodes, relays at rest): node 0's frame is
/// popped by nodes 1 and 2, and the ring tap yields exactly those pops, on
/// interface `node<i>` (no line: channel A is a ring node's only connection).
#[test]
fn a_ring_tap_yields_host_frames_without_a_line() {
    use crate::engine::rcm::{RcmEngine, RcmModelEngine};
    use crate::ring::{RingSystem, Shape};
    let config = HostConfig {
        redundancy: false,
        policy: Policy::None,
        ..HostConfig::default()
    };
    let engines = (0..3)
        .map(|_| Box::new(DrccModelEngine::new()) as Box<dyn crate::engine::drcc::DrccEngine>)
        .collect();
    let rcms = (0..3)
        .map(|_| Box::<RcmModelEngine>::default() as Box<dyn RcmEngine>)
        .collect();
    let shape = Shape { plain: vec![0; 3] };
    let mut sys = RingSystem::new(shape, engines, rcms, config, 16).unwrap();
    let f = Frame::base(0x1A5, &[1, 2, 3]);
    sys.node_mut(0).host.submit(40 * 8, f, 0);
    let mut tap = NodeTap::new(3);
    let mut events = Vec::new();
    for _ in 0..8 * 400 {
        sys.step();
        tap.poll(&sys, &mut events);
    }
    let mut want: Vec<TrafficEvent> = (0..3)
        .flat_map(|node| {
            sys.node(node)
                .host
                .received
                .iter()
                .map(move |rx| TrafficEvent {
                    cycle: rx.cycle,
                    node,
                    line: None,
                    kind: TrafficKind::Frame(rx.frame),
                })
        })
        .collect();
    want.sort_by_key(|e| (e.cycle, e.node));
    assert_eq!(want.len(), 2, "nodes 1 and 2 popped the frame");
    assert!(want.iter().all(|e| e.kind == TrafficKind::Frame(f)));
    assert_eq!(events, want, "an error-free ring has its frames only");
    assert_eq!(events[0].interface(), "node1");
}
