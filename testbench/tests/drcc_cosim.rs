//! Lock-step co-simulation of the DRCC top, reference model vs Verilated RTL, on
//! randomised systems: 3 nodes on a dual bus, each in normal or redundancy mode
//! with a random policy, `dual_tx`, channel modes and bit timing; random frames
//! (base/extended, data/remote, every DLC, bursts that fill the TX queues and
//! overrun RX FIFOs); random register writes at random times, legal and illegal
//! (every address, random values, reset-mode toggles); acceptance filters set in a
//! mid-run reconfiguration, timestamps and statistics clears (DRCC contract §11);
//! random line faults. Every
//! output of every node must agree every clock. The expected values are the model's
//! (the oracle written from the contract), never the RTL's.

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::dual::lockstep::compare;
use drcc_cosim::dual::{DualBusSystem, Line};
use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::engine::drcc_verilator::DrccVerilatorEngine;
use drcc_cosim::host::ecss_config::EcssConfig;
use drcc_cosim::host::{btr, HostConfig, Policy};
use drcc_cosim::Frame;
use drcc_hdl::host::registers as map;
use drcc_testbench::engines::verilator_required;
use drcc_testbench::random::SplitMix64;

fn verilated() -> Option<Box<dyn DrccEngine>> {
    match DrccVerilatorEngine::new() {
        Ok(e) => Some(Box::new(e)),
        Err(e) if verilator_required() => panic!("the Verilated DRCC is required in CI: {e}"),
        Err(e) => {
            eprintln!("skipped outside CI: {e}");
            None
        }
    }
}

fn random_frame(rng: &mut SplitMix64) -> Frame {
    let ide = rng.percent(30);
    let mut data = [0u8; 8];
    for b in data.iter_mut() {
        *b = rng.below(256) as u8;
    }
    let rtr = rng.percent(10);
    let dlc = rng.below(16) as u8;
    let id = if ide {
        rng.below(1 << 29) as u32
    } else {
        rng.below(1 << 11) as u32
    };
    let mut f = Frame {
        id,
        ide,
        rtr,
        dlc,
        data,
    };
    // Bytes past the data length are not sent (a receiver reads them as 0).
    let n = f.data_len();
    for b in f.data[n..].iter_mut() {
        *b = 0;
    }
    f
}

fn random_config(rng: &mut SplitMix64, timing: u32) -> HostConfig {
    let redundancy = rng.percent(60);
    HostConfig {
        btr: timing,
        redundancy,
        policy: match rng.below(4) {
            0 => Policy::None,
            1 => Policy::ErrorPassive,
            _ => Policy::KFailed(1 + rng.below(4) as u8),
        },
        dual_tx: rng.percent(50),
        // Mostly normal; sometimes self-test (no ACK needed) on one channel.
        mode_a: if rng.percent(10) { 2 } else { 0 },
        mode_b: if rng.percent(10) { 2 } else { 0 },
        recovery_bits: 50 + rng.below(400) as u16,
        stall_limit: if rng.percent(50) {
            0
        } else {
            200 + rng.below(400) as u16
        },
        dedup_window: rng.below(3000) as u16,
        int_enable: rng.below(256) as u32,
        dmr: None,
        tx_queue_depth: 8,
        // Drawn last, so the other fields keep their draws; on a dual bus the
        // echo (DRCC contract §4.4) fires only for another node's identical frame.
        star: redundancy && rng.percent(25),
        // Drawn after the rest for the same reason; a channel that goes bus-off
        // then stays held (the random host never writes recover, §11.6).
        busoff_manual: rng.percent(25),
        // Drawn last again: the ECSS bus selection (contract §12) with a random
        // heartbeat; without a master the nodes toggle by silence, so the lock
        // step covers the missed-period clock, the toggles and the bound.
        ecss: (redundancy && rng.percent(30)).then(|| EcssConfig {
            ttoggle: 1 + rng.below(3) as u8,
            ntoggle: rng.below(4) as u8,
            bdefault_b: rng.percent(50),
            hb_id: rng.below(0x800) as u16,
            period_bits: 20 + rng.below(300) as u32,
        }),
    }
}

/// Frames: bursts that can fill the 8-deep queues, the same on both systems.
fn submit_frames(rng: &mut SplitMix64, systems: [&mut DualBusSystem; 2], nodes: usize, cpb: u64) {
    let [model, rtl] = systems;
    for n in 0..nodes {
        let mut t = 50 * cpb;
        for _ in 0..(10 + rng.below(20)) {
            t += rng.below(400) * cpb;
            let f = random_frame(rng);
            let q = rng.below(2) as u8;
            model.node_mut(n).host.submit(t, f, q);
            rtl.node_mut(n).host.submit(t, f, q);
        }
    }
}

/// Up to three faults on either line, the same on both systems.
fn add_faults(
    rng: &mut SplitMix64,
    systems: [&mut DualBusSystem; 2],
    nodes: usize,
    cycles: u64,
    cpb: u64,
) {
    let [model, rtl] = systems;
    for _ in 0..rng.below(4) {
        let line = if rng.percent(50) { Line::A } else { Line::B };
        let target = match rng.below(3) {
            0 => FaultTarget::Bus,
            1 => FaultTarget::Tx(rng.below(nodes as u64) as usize),
            _ => FaultTarget::Rx(rng.below(nodes as u64) as usize),
        };
        let kind = match rng.below(3) {
            0 => FaultKind::StuckDominant,
            1 => FaultKind::StuckRecessive,
            _ => FaultKind::Flip,
        };
        let f = Fault {
            target,
            kind,
            start: rng.below(cycles),
            cycles: 1 + rng.below(300 * cpb),
        };
        model.add_fault(line, f).unwrap();
        rtl.add_fault(line, f).unwrap();
    }
}

/// The hosts' register accesses of a run, drawn after every other choice.
struct HostPlan {
    /// (cycle, node, register, value, byte lanes), in time order.
    writes: Vec<(u64, usize, u8, u32, u8)>,
    /// (cycle, node, register), in time order.
    reads: Vec<(u64, usize, u8)>,
    /// (cycle, node, the four filter words) of a node's reset-mode visit.
    reconf: Vec<(u64, usize, [u32; 4])>,
    /// (cycle, node) of a statistics clear.
    clears: Vec<(u64, usize)>,
}

fn draw_host_plan(rng: &mut SplitMix64, nodes: usize, cycles: u64) -> HostPlan {
    // Register writes at random times: any address, random or edge values,
    // a third of them with random byte lanes (bus_contract.md §1).
    let mut writes: Vec<(u64, usize, u8, u32, u8)> = (0..rng.below(25))
        .map(|_| {
            let value = match rng.below(4) {
                0 => 0,
                1 => u32::MAX,
                _ => rng.next_u64() as u32,
            };
            let sel = if rng.below(3) == 0 {
                rng.below(16) as u8
            } else {
                0xF
            };
            (
                rng.below(cycles),
                rng.below(nodes as u64) as usize,
                rng.below(64) as u8,
                value,
                sel,
            )
        })
        .collect();
    writes.sort();
    // Reads at random times of the registers a driver polls besides the frames:
    // the §10 words (VERSION, SIZES, the captures) and INT_STATUS, so their
    // values are compared on the bus too, not only through irq. Drawn after
    // every other choice, so the rest of each system stays as it was.
    let polled = [
        map::VERSION,
        map::SIZES,
        map::CAP_A,
        map::CAP_B,
        map::INT_STATUS,
        map::CHAN_A_ERR,
        map::RX_TIME,
        map::STATS0,
    ];
    let mut reads: Vec<(u64, usize, u8)> = (0..40)
        .map(|_| {
            (
                rng.below(cycles),
                rng.below(nodes as u64) as usize,
                polled[rng.below(polled.len() as u64) as usize] as u8,
            )
        })
        .collect();
    reads.sort();
    // §11: a node may enter reset mode once, set random acceptance filters and
    // leave it (half of the filters enabled, each comparing a few identifier bits
    // and sometimes IDE, so about half the frames pass), and clear its
    // statistics later. Drawn last as well.
    let mut reconf: Vec<(u64, usize, [u32; 4])> = Vec::new();
    let mut clears: Vec<(u64, usize)> = Vec::new();
    for n in 0..nodes {
        if rng.percent(50) {
            let mut words = [0u32; 4];
            for k in 0..2 {
                let ide = rng.percent(50) as u32;
                words[2 * k] = (rng.next_u64() as u32 & 0x1FFF_FFFF) | (ide << 29);
                let mut mask = 0u32;
                for _ in 0..1 + rng.below(2) {
                    mask |= 1 << rng.below(11);
                }
                if rng.percent(30) {
                    mask |= 1 << 29;
                }
                if rng.percent(50) {
                    mask |= 1 << 31;
                }
                words[2 * k + 1] = mask;
            }
            reconf.push((rng.below(cycles / 2), n, words));
        }
        if rng.percent(50) {
            clears.push((rng.below(cycles), n));
        }
    }
    HostPlan {
        writes,
        reads,
        reconf,
        clears,
    }
}

/// The plan's accesses due at `cycle`, on both systems; `next` and `next_read`
/// are the first write and read not yet made.
fn apply_host_plan(
    plan: &HostPlan,
    cycle: u64,
    configs: &[HostConfig],
    systems: [&mut DualBusSystem; 2],
    next: &mut usize,
    next_read: &mut usize,
) {
    let [model, rtl] = systems;
    while *next < plan.writes.len() && plan.writes[*next].0 == cycle {
        let (_, n, reg, value, sel) = plan.writes[*next];
        model.node_mut(n).host.write_lanes(reg, value, sel);
        rtl.node_mut(n).host.write_lanes(reg, value, sel);
        if reg % 7 == 0 {
            model.node_mut(n).host.read(reg);
            rtl.node_mut(n).host.read(reg);
        }
        *next += 1;
    }
    for &(_, n, words) in plan.reconf.iter().filter(|r| r.0 == cycle) {
        let c = &configs[n];
        for sys in [&mut *model, &mut *rtl] {
            let host = &mut sys.node_mut(n).host;
            host.write(map::CTRL as u8, c.ctrl(true));
            for (k, w) in words.iter().enumerate() {
                host.write((map::FILT_ID0 as usize + k) as u8, *w);
            }
            host.write(map::CTRL as u8, c.ctrl(false));
        }
    }
    for &(_, n) in plan.clears.iter().filter(|r| r.0 == cycle) {
        model.node_mut(n).host.write(map::STATS_CLR as u8, 1);
        rtl.node_mut(n).host.write(map::STATS_CLR as u8, 1);
    }
    while *next_read < plan.reads.len() && plan.reads[*next_read].0 == cycle {
        let (_, n, reg) = plan.reads[*next_read];
        model.node_mut(n).host.read(reg);
        rtl.node_mut(n).host.read(reg);
        *next_read += 1;
    }
}

/// One clock of a system, as the divergence report prints the last ones.
fn clock_line(sys: &DualBusSystem) -> String {
    sys.nodes()
        .iter()
        .map(|n| {
            let p = &n.outputs.probes;
            format!(
                "[st {} ch {} aux {}/{} err {}/{} tec {}/{} wb {}{}{:02}:{:08x}]",
                p.state,
                p.tx_channel as u8,
                p.aux_a_state,
                p.aux_b_state,
                p.chan_a_err_state,
                p.chan_b_err_state,
                p.chan_a_bsp_tx_err_cnt,
                p.chan_b_bsp_tx_err_cnt,
                n.inputs.wb_stb as u8,
                n.inputs.wb_we as u8,
                n.inputs.wb_adr,
                n.inputs.wb_dat_w
            )
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn run_seed(seed: u64, cycles: u64) {
    let Some(_) = verilated() else { return };
    let mut rng = SplitMix64::new(seed);
    // 1 Mbit/s at 8 MHz or 500 kbit/s (BRP 1), 8 tq.
    let brp = rng.below(2) as u16;
    let timing = btr(brp, 5, 2, 1, false, 96);
    let cpb = 8 * (brp as u64 + 1);
    let nodes = 3;
    let configs: Vec<HostConfig> = (0..nodes)
        .map(|_| random_config(&mut rng, timing))
        .collect();
    let build = |verilator: bool| {
        let engines: Vec<Box<dyn DrccEngine>> = (0..nodes)
            .map(|i| {
                if verilator {
                    if let (Ok(path), 0) = (std::env::var("DRCC_DEBUG_VCD"), i) {
                        let mut e = DrccVerilatorEngine::new().unwrap();
                        e.open_vcd(format!("{path}_{seed}.vcd")).unwrap();
                        return Box::new(e) as Box<dyn DrccEngine>;
                    }
                    verilated().expect("checked above")
                } else {
                    Box::new(DrccModelEngine::new()) as Box<dyn DrccEngine>
                }
            })
            .collect();
        DualBusSystem::new(engines, configs.clone()).expect("valid system")
    };
    let mut model = build(false);
    let mut rtl = build(true);
    submit_frames(&mut rng, [&mut model, &mut rtl], nodes, cpb);
    add_faults(&mut rng, [&mut model, &mut rtl], nodes, cycles, cpb);
    let plan = draw_host_plan(&mut rng, nodes, cycles);
    let mut next_read = 0;
    let mut next = 0;
    let mut recent: std::collections::VecDeque<String> = std::collections::VecDeque::new();
    for cycle in 0..cycles {
        apply_host_plan(
            &plan,
            cycle,
            &configs,
            [&mut model, &mut rtl],
            &mut next,
            &mut next_read,
        );
        model.step();
        rtl.step();
        recent.push_back(format!(
            "{cycle}: model {}\n{cycle}: rtl   {}",
            clock_line(&model),
            clock_line(&rtl)
        ));
        if recent.len() > 12 {
            recent.pop_front();
        }
        if let Some(d) = compare(&model, &rtl) {
            let cfg: Vec<String> = configs.iter().map(|c| format!("{c:?}")).collect();
            panic!(
                "seed {seed}: {d} (bit time {})\nconfigs:\n{}\nlast clocks:\n{}",
                d.cycle / cpb,
                cfg.join("\n"),
                recent.iter().cloned().collect::<Vec<_>>().join("\n")
            );
        }
    }
    let delivered: usize = model.nodes().iter().map(|n| n.host.received.len()).sum();
    eprintln!("seed {seed}: {cycles} clocks in lock step, {delivered} frames delivered to hosts");
}

#[test]
fn random_systems_model_vs_verilator() {
    let scale: u64 = std::env::var("DRCC_STRESS_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    for seed in 0..12 * scale {
        run_seed(0xD2CC_0000 + seed, 120_000);
    }
}
