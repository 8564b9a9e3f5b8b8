//! The run: the configurations' episodes in lock step, their totals, and the
//! final idle check.

use super::*;

/// Totals of a configuration.
#[derive(Clone, Debug, Default)]
pub(super) struct Totals {
    pub(super) timing: String,
    pub(super) bits: u64,
    pub(super) cycles: u64,
    pub(super) frames: usize,
    pub(super) deliveries: usize,
    pub(super) faults: usize,
    pub(super) events: usize,
    pub(super) error_flags: usize,
    pub(super) overload_flags: usize,
    pub(super) passive: usize,
    pub(super) bus_off: usize,
    pub(super) recovered: usize,
    pub(super) max_tec: u16,
    pub(super) max_rec: u8,
    /// Longest time from the end of the faults until every node was idle / all
    /// nodes were idle together, in bit times.
    pub(super) settle_bits: u64,
    pub(super) quiet_bits: u64,
    /// Frames sent after all nodes were idle together (checked delivered).
    pub(super) synchronised_frames: usize,
}

/// A numeric environment variable (soak runs), or `default`.
pub(super) fn env_u64(name: &str, default: u64) -> u64 {
    match std::env::var(name) {
        Ok(v) => v
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v:?} is not a number")),
        Err(_) => default,
    }
}

pub(super) fn stress(spec: &Stress, other: EngineKind) {
    let t0 = Instant::now();
    // Soak runs: DRCC_STRESS_SCALE=k runs k times the episodes, and
    // DRCC_STRESS_SEED=s shifts every seed by s << 16 (other traffic and faults).
    let scale = env_u64("DRCC_STRESS_SCALE", 1).max(1);
    let shift = env_u64("DRCC_STRESS_SEED", 0) << 16;
    let spec = &Stress {
        episodes: spec.episodes * scale,
        min_bits: spec.min_bits * scale,
        seed: spec.seed + shift,
        ..*spec
    };
    let mut tot = Totals::default();
    let mut problems = Vec::new();
    for e in 0..spec.episodes {
        episode(spec, spec.seed + e, other, &mut tot, &mut problems);
    }
    // The faults did something (over the configuration: single episodes may be
    // unlucky).
    if tot.error_flags < tot.events / 4 {
        problems.push(format!(
            "FAULTS INEFFECTIVE: only {} error flags for {} fault events",
            tot.error_flags, tot.events
        ));
    }
    if tot.passive < spec.episodes as usize / 2 {
        problems.push(format!(
            "FAULTS INEFFECTIVE: only {} entries into error passive in {} episodes with long \
             stuck-dominant windows",
            tot.passive, spec.episodes
        ));
    }
    if tot.bus_off < spec.episodes as usize / 2 {
        problems.push(format!(
            "FAULTS INEFFECTIVE: only {} bus-off entries in {} episodes that force one",
            tot.bus_off, spec.episodes
        ));
    }
    if tot.bits < spec.min_bits {
        problems.push(format!(
            "the configuration covered only {} bit times, less than the {} it is counted for",
            tot.bits, spec.min_bits
        ));
    }
    eprintln!(
        "[{}] model vs {}: {} episodes, {} bit times ({} cycles), {} nodes, {} Hz, {} bit/s, \
         {}; {} frames, {} deliveries; {} faults ({} events); error flags {}, \
         overload flags {}, error passive {}, bus-off {} (recovered {}), max tec {} rec {}; \
         after the faults every node idle within {} bits, all together within {} bits, then {} \
         frames sent and delivered everywhere; {:.1} s",
        spec.name,
        other.name(),
        spec.episodes,
        tot.bits,
        tot.cycles,
        spec.nodes,
        spec.clock_hz,
        spec.bitrate,
        tot.timing,
        tot.frames,
        tot.deliveries,
        tot.faults,
        tot.events,
        tot.error_flags,
        tot.overload_flags,
        tot.passive,
        tot.bus_off,
        tot.recovered,
        tot.max_tec,
        tot.max_rec,
        tot.settle_bits,
        tot.quiet_bits,
        tot.synchronised_frames,
        t0.elapsed().as_secs_f64()
    );
    assert!(
        problems.is_empty(),
        "{}: {} problem(s), no divergence:\n  {}",
        spec.name,
        problems.len(),
        problems
            .iter()
            .take(40)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n  ")
    );
}

/// One episode: model vs `other` in lock step, then every check. A divergence
/// panics at once (with the VCDs and the scenario left in the printed directory);
/// other problems are collected.
pub(super) fn episode(
    spec: &Stress,
    seed: u64,
    other: EngineKind,
    tot: &mut Totals,
    all: &mut Vec<String>,
) {
    let (sc, fp) = build(spec, seed);
    let cpb = sc.clocks_per_bit();
    let fault_free = fp.end;
    let logs: Vec<Rc<RefCell<NodeLog>>> = (0..spec.nodes)
        .map(|_| Rc::new(RefCell::new(NodeLog::default())))
        .collect();
    let mut a = build_system_with(&sc, |i| {
        Ok(Box::new(Watch {
            inner: make_engine(EngineKind::Model)?,
            log: logs[i].clone(),
            cycle: 0,
            fault_free,
            cpb,
            prev: Probes::default(),
            rx_run: 0,
            was_bad: false,
        }) as Box<dyn ChannelEngine>)
    })
    .unwrap();
    let mut b = build_system_with(&sc, |_| make_engine(other)).unwrap();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "error-stress-{}-{seed:#x}-model-{}",
        spec.name,
        other.name()
    ));
    let opts = CosimOptions {
        max_cycles: sc.max_cycles,
        clock_hz: sc.clock_hz,
        vcd_dir: Some(dir.clone()),
        before: (60 * cpb as usize).max(2000),
        after: (20 * cpb).max(200),
    };
    let report = match lockstep(&mut a, &mut b, &opts) {
        Ok(r) => r,
        Err(e) => {
            let _ = std::fs::create_dir_all(&dir);
            let toml = dir.join("scenario.toml");
            let _ = std::fs::write(&toml, sc.to_toml());
            let when = match &e {
                CosimError::Divergence(d) if d.cycle < fault_free => "while faults are injected",
                CosimError::Divergence(_) => "after the faults stopped",
                CosimError::Setup(_) => "at setup",
            };
            panic!(
                "DIVERGENCE in {} ({}), {when} (faults until cycle {fault_free}, bit {}):\n{e}\n\
                 files in {}\nreproduce: drcc cosim {} --engines model,{} --vcd-dir {}",
                spec.name,
                sc.description,
                fault_free / cpb,
                dir.display(),
                toml.display(),
                other.name(),
                dir.display()
            );
        }
    };
    let mut problems = Vec::new();
    let end = report.outcome.cycles();
    if !report.outcome.is_idle() {
        let mut why = Vec::new();
        for n in 0..a.nodes() {
            let o = &a.sample().outputs[n];
            why.push(format!(
                "node{n}: {} queued, pending {}, field {} ({}), err_state {}, tec {}, rec {}",
                a.queued(n),
                o.tx_pending,
                o.probes.field,
                field::name(o.probes.field),
                o.probes.err_state,
                o.probes.tec,
                o.probes.rec
            ));
        }
        problems.push(format!(
            "LOCKUP: the run did not end within {} bit times ({} after the faults stopped): {}",
            end / cpb,
            end.saturating_sub(fault_free) / cpb,
            why.join("; ")
        ));
    } else {
        final_idle_check(&mut a, &mut b, cpb, &mut problems);
    }
    let logs: Vec<NodeLog> = logs.iter().map(|l| l.borrow().clone()).collect();
    check(&sc, &fp, &a, &logs, tot, &mut problems);
    tot.timing = format!("{:?}", sc.timing);
    tot.bits += end / cpb;
    tot.cycles += end;
    tot.frames += sc.frames.len();
    tot.deliveries += a.deliveries().len();
    tot.faults += fp.faults.len();
    tot.events += fp.events.len();
    for l in &logs {
        tot.error_flags += l.error_flags;
        tot.overload_flags += l.overload_flags;
        tot.passive += l.passive;
        tot.bus_off += l.bus_off;
        tot.recovered += l.recovered;
        tot.max_tec = tot.max_tec.max(l.max_tec);
        tot.max_rec = tot.max_rec.max(l.max_rec);
    }
    if !problems.is_empty() {
        let _ = std::fs::create_dir_all(&dir);
        let toml = dir.join("scenario.toml");
        let _ = std::fs::write(&toml, sc.to_toml());
        all.push(format!(
            "episode {seed:#x} ({}; scenario with its faults: {}):",
            sc.description,
            toml.display()
        ));
        all.extend(problems.into_iter().map(|p| format!("  {p}")));
    }
}

/// After the run ended idle (nothing pending, the bus recessive for 11 bit
/// times), keeps both systems in lock step for 10 more bits: right away every
/// node is idle, or in the 8 bits of suspend transmission of an error-passive
/// transmitter; 10 bits later every node is idle.
pub(super) fn final_idle_check(
    a: &mut System,
    b: &mut System,
    cpb: u64,
    problems: &mut Vec<String>,
) {
    for k in 1..=10 * cpb {
        a.step();
        b.step();
        if let Some((node, signal, va, vb)) = compare_samples(a.sample(), b.sample()) {
            problems.push(format!(
                "divergence after the end of the run, cycle {} (bit {}), node{node} `{signal}`: \
                 {} {va}, {} {vb}",
                a.sample().cycle,
                a.sample().cycle / cpb,
                a.engine_label(),
                b.engine_label()
            ));
            return;
        }
        if k == 2 * cpb || k == 10 * cpb {
            for (n, o) in a.sample().outputs.iter().enumerate() {
                let p = o.probes;
                let ok = p.field == field::IDLE
                    || (k == 2 * cpb && p.field == field::SUSPEND && p.err_state == 1);
                if !ok {
                    problems.push(format!(
                        "node{n} is not idle {} bit times after the bus went idle at the end \
                         (cycle {}): field {} ({}), err_state {}",
                        11 + k / cpb,
                        a.sample().cycle,
                        p.field,
                        field::name(p.field),
                        p.err_state
                    ));
                }
            }
        }
    }
}
