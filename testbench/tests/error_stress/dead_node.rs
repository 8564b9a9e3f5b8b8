//! Fault confinement of a node whose transceiver dies: bus-off by bit
//! monitoring, the others communicate.

use super::*;

/// A node whose receiver reads recessive for good (a broken transceiver RXD)
/// sends its SOF and reads it back recessive. ISO 11898-1 bit monitoring: a node
/// sending a bit detects a bit error when it reads another value; the only
/// exceptions are a recessive bit read dominant in arbitration or in the ACK
/// slot and a passive error flag. So the SOF is a bit error (rule c: TEC + 8), its
/// active error flag reads back recessive (rule d: + 8 per flag), and after at
/// most 32 errors (a few hundred bit times) the node is bus-off: it sends
/// recessive only, and the other nodes communicate again although the fault
/// persists (this is what fault confinement is for).
#[test]
fn dead_receiver_is_confined_by_bus_off() {
    dead_node_is_confined(FaultTarget::Rx(0));
}

/// A node whose transmitter cannot drive dominant (a broken transceiver TXD)
/// reads its own SOF recessive: bit errors at every attempt and in its own flags,
/// bus-off after at most 32 of them (ISO 11898-1 bit monitoring, rules c and d).
#[test]
fn dead_transmitter_goes_bus_off() {
    dead_node_is_confined(FaultTarget::Tx(0));
}

fn dead_node_is_confined(target: FaultTarget) {
    let mut kinds = vec![EngineKind::Model, EngineKind::RustHdl];
    if verilator_present() {
        kinds.push(EngineKind::Verilator);
    }
    let timing = drcc_testbench::bitrate::solve(8_000_000, 1_000_000).unwrap();
    let cpb = timing.clocks_per_bit() as u64;
    let frame = |id: u32| Frame {
        id,
        ide: false,
        rtr: false,
        dlc: 2,
        data: [0xA5, 0x5A, 0, 0, 0, 0, 0, 0],
    };
    let mut problems = Vec::new();
    for kind in kinds {
        let engines = (0..3).map(|_| make_engine(kind).unwrap()).collect();
        let mut sys = System::new(engines, timing).unwrap();
        // Node 0 has a frame to send when its transceiver breaks (bit 20, for
        // 4000 bits). By ISO 11898-1 it is bus-off a few hundred bits later (16
        // bit errors in its active flags, then 16 attempts of about 26 bits as
        // an error-passive transmitter); nodes 1 and 2 send a frame every 150 bits
        // from bit 1300 on.
        sys.submit(0, 30 * cpb, frame(0x100)).unwrap();
        for k in 0..12u64 {
            let node = 1 + (k % 2) as usize;
            sys.submit(node, (1300 + 150 * k) * cpb, frame(0x200 + k as u32))
                .unwrap();
        }
        sys.add_fault(Fault {
            target,
            kind: FaultKind::StuckRecessive,
            start: 20 * cpb,
            cycles: 4000 * cpb,
        })
        .unwrap();
        let mut bus_off_at = None;
        let mut max_tec = 0;
        while sys.cycle() < 3200 * cpb {
            let s = sys.step();
            let p = s.outputs[0].probes;
            max_tec = max_tec.max(p.tec);
            if p.err_state == 2 && bus_off_at.is_none() {
                bus_off_at = Some(s.cycle / cpb);
            }
        }
        let others = sys.tx_done().iter().filter(|e| e.node != 0).count();
        let o = sys.sample().outputs[0];
        let state = format!(
            "{kind}: node0 {:?} stuck recessive from bit 20: max tec {max_tec}, bus-off at bit \
             {bus_off_at:?}; at bit 3200 field {} ({}), tx {}, tx_pending {}; nodes 1 and 2 sent \
             {others} of their 12 frames (due from bit 1300 on) by bit 3200",
            target,
            o.probes.field,
            field::name(o.probes.field),
            o.tx,
            o.tx_pending
        );
        if bus_off_at.is_none_or(|b| b > 1200) {
            problems.push(format!("node0 not bus-off by bit 1200 -- {state}"));
        }
        if others < 6 {
            problems.push(format!(
                "nodes 1 and 2 do not communicate while node0 is confined -- {state}"
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
