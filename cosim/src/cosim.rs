//! Co-simulation: two systems running the same scenario on different engines, in
//! lock step, compared every clock.
//!
//! Every clock, every node's outputs (`tx`, `tx_pending`, `tx_done`, `arb_lost`,
//! `tx_failed`, `rx_valid`, `rx_frame`), every probe and every diagnostics
//! register (`err_warning`, `err_valid`, `err_kind`, `err_field`, `err_tx`, `alc`,
//! `cnt_*`) are compared ([`OUTPUT_SIGNALS`]), and so are the inputs the systems
//! applied (`rx`, `tx_req`, `tx_abort`), which can only differ if the scenarios
//! differ.
//! The first divergence is an error ([`CosimError::Divergence`]) reporting the
//! cycle, the bit time (cycle / clocks per bit), the node, the signal and both
//! values. If a VCD directory is given, the last [`CosimOptions::before`] cycles
//! before the divergence and [`CosimOptions::after`] cycles after it are written
//! there: one file per system (`divergence_<engine>.vcd`, top scope `tb`, ready for
//! `drcc wave-diff`) and one with both systems side by side (`divergence.vcd`,
//! top scopes `a_<engine>` and `b_<engine>`).

use std::fmt;
use std::path::{Path, PathBuf};

use crate::system::{RunOutcome, Sample, System};
use crate::trace::{format_value, History, VcdWriter, OUTPUT_SIGNALS};

/// Options of a co-simulation run.
#[derive(Clone, Debug)]
pub struct CosimOptions {
    /// Stop (successfully) after this many cycles even if the systems are not idle.
    pub max_cycles: u64,
    /// Clock frequency, for the VCD time base.
    pub clock_hz: u64,
    /// Where to write the VCDs around a divergence (none: no VCD, no history kept).
    pub vcd_dir: Option<PathBuf>,
    /// Cycles kept before a divergence.
    pub before: usize,
    /// Cycles run and traced after a divergence.
    pub after: u64,
}

impl Default for CosimOptions {
    fn default() -> Self {
        CosimOptions {
            max_cycles: 10_000_000,
            clock_hz: 8_000_000,
            vcd_dir: None,
            before: 2000,
            after: 200,
        }
    }
}

/// A successful (divergence-free) run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CosimReport {
    /// How the run ended (both systems end alike).
    pub outcome: RunOutcome,
    /// Engines of the first system.
    pub engine_a: String,
    /// Engines of the second system.
    pub engine_b: String,
}

/// The first clock at which the systems differ.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Divergence {
    /// Clock cycle.
    pub cycle: u64,
    /// Clocks per bit of the shared bit timing.
    pub clocks_per_bit: u32,
    /// Node index.
    pub node: usize,
    /// Node name.
    pub node_name: String,
    /// Signal name (as in the VCD: `tx`, `rx_frame_id`, `field`, ...).
    pub signal: String,
    /// Engines of the first system.
    pub engine_a: String,
    /// Engines of the second system.
    pub engine_b: String,
    /// Value in the first system.
    pub value_a: String,
    /// Value in the second system.
    pub value_b: String,
    /// VCD files written around the divergence.
    pub vcd_files: Vec<PathBuf>,
    /// Why the VCDs could not be written, if they could not.
    pub vcd_error: Option<String>,
}

impl Divergence {
    /// Bit time: whole bits since cycle 0.
    pub fn bit(&self) -> u64 {
        self.cycle / self.clocks_per_bit.max(1) as u64
    }
    /// Clock within the bit time.
    pub fn clock_in_bit(&self) -> u64 {
        self.cycle % self.clocks_per_bit.max(1) as u64
    }
}

impl fmt::Display for Divergence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "divergence at cycle {} (bit time {} + {}/{} clocks), node {} (`{}`), signal `{}`:",
            self.cycle,
            self.bit(),
            self.clock_in_bit(),
            self.clocks_per_bit,
            self.node,
            self.node_name,
            self.signal
        )?;
        writeln!(f, "  {:<10} {}", self.engine_a, self.value_a)?;
        write!(f, "  {:<10} {}", self.engine_b, self.value_b)?;
        if !self.vcd_files.is_empty() {
            write!(f, "\n  VCDs around it:")?;
            for p in &self.vcd_files {
                write!(f, " {}", p.display())?;
            }
        }
        if let Some(e) = &self.vcd_error {
            write!(f, "\n  (no VCD: {e})")?;
        }
        Ok(())
    }
}

/// Why a co-simulation failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CosimError {
    /// The two systems cannot be compared (different node counts or timing).
    Setup(String),
    /// The systems diverged.
    Divergence(Box<Divergence>),
}

impl fmt::Display for CosimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CosimError::Setup(s) => write!(f, "co-simulation setup: {s}"),
            CosimError::Divergence(d) => d.fmt(f),
        }
    }
}

impl std::error::Error for CosimError {}

/// The first signal that differs between two samples of the same cycle:
/// `(node, signal, value a, value b)`.
pub fn compare_samples(a: &Sample, b: &Sample) -> Option<(usize, String, String, String)> {
    for (node, (oa, ob)) in a.outputs.iter().zip(&b.outputs).enumerate() {
        if oa == ob {
            continue;
        }
        for s in OUTPUT_SIGNALS {
            let (va, vb) = ((s.get)(oa), (s.get)(ob));
            if va != vb {
                return Some((
                    node,
                    s.name.to_string(),
                    format_value(s.width, va),
                    format_value(s.width, vb),
                ));
            }
        }
        return Some((
            node,
            "outputs".to_string(),
            format!("{oa:?}"),
            format!("{ob:?}"),
        ));
    }
    for node in 0..a.outputs.len().min(b.outputs.len()) {
        let pairs = [
            ("rx", a.rx.get(node), b.rx.get(node)),
            ("tx_req", a.tx_req.get(node), b.tx_req.get(node)),
            ("tx_abort", a.tx_abort.get(node), b.tx_abort.get(node)),
        ];
        for (name, va, vb) in pairs {
            if va != vb {
                let show = |v: Option<&bool>| v.map_or("-".to_string(), |&v| (v as u8).to_string());
                return Some((node, name.to_string(), show(va), show(vb)));
            }
        }
    }
    None
}

/// Runs both systems in lock step until both are idle or `max_cycles` is reached,
/// comparing every clock. The systems must have the same node count, timing and
/// configurations, and the same frames and aborts submitted.
pub fn lockstep(
    a: &mut System,
    b: &mut System,
    opts: &CosimOptions,
) -> Result<CosimReport, CosimError> {
    lockstep_observed(a, b, opts, &mut |_| {})
}

/// [`lockstep`], calling `observe` with the first system after every clock that
/// both systems agree on (traffic taps, `crate::traffic`).
pub fn lockstep_observed(
    a: &mut System,
    b: &mut System,
    opts: &CosimOptions,
    observe: &mut dyn FnMut(&System),
) -> Result<CosimReport, CosimError> {
    if a.nodes() != b.nodes() {
        return Err(CosimError::Setup(format!(
            "the systems have {} and {} nodes",
            a.nodes(),
            b.nodes()
        )));
    }
    if a.timing() != b.timing() {
        return Err(CosimError::Setup(format!(
            "the systems have different bit timings: {:?} and {:?}",
            a.timing(),
            b.timing()
        )));
    }
    if a.configs() != b.configs() {
        return Err(CosimError::Setup(format!(
            "the systems have different controller configurations: {:?} and {:?}",
            a.configs(),
            b.configs()
        )));
    }
    if a.cycle() != b.cycle() {
        return Err(CosimError::Setup(
            "the systems are at different cycles".to_string(),
        ));
    }
    let keep = opts.before + opts.after as usize + 1;
    let mut hist = opts
        .vcd_dir
        .as_ref()
        .map(|_| (History::new(keep), History::new(keep)));
    loop {
        let (qa, qb) = (a.is_quiescent(), b.is_quiescent());
        if qa && qb {
            return Ok(report(a, b, RunOutcome::Idle { cycle: a.cycle() }));
        }
        if a.cycle() >= opts.max_cycles {
            return Ok(report(a, b, RunOutcome::CycleLimit { cycle: a.cycle() }));
        }
        a.step();
        b.step();
        if let Some((ha, hb)) = hist.as_mut() {
            ha.push(a.sample());
            hb.push(b.sample());
        }
        let found = compare_samples(a.sample(), b.sample()).or_else(|| {
            // Equal samples but one side idle and the other not: queues differ.
            (qa != qb).then(|| {
                (
                    0,
                    "idle".to_string(),
                    (qa as u8).to_string(),
                    (qb as u8).to_string(),
                )
            })
        });
        if let Some((node, signal, value_a, value_b)) = found {
            let cycle = a.sample().cycle;
            let mut d = Divergence {
                cycle,
                clocks_per_bit: a.timing().clocks_per_bit(),
                node,
                node_name: a.names().get(node).cloned().unwrap_or_default(),
                signal,
                engine_a: a.engine_label(),
                engine_b: b.engine_label(),
                value_a,
                value_b,
                vcd_files: Vec::new(),
                vcd_error: None,
            };
            if let (Some(dir), Some((mut ha, mut hb))) = (opts.vcd_dir.as_ref(), hist.take()) {
                for _ in 0..opts.after {
                    a.step();
                    b.step();
                    ha.push(a.sample());
                    hb.push(b.sample());
                }
                match write_divergence_vcds(dir, opts.clock_hz, &d, &ha, &hb) {
                    Ok(files) => d.vcd_files = files,
                    Err(e) => d.vcd_error = Some(e),
                }
            }
            return Err(CosimError::Divergence(Box::new(d)));
        }
        observe(a);
    }
}

fn report(a: &System, b: &System, outcome: RunOutcome) -> CosimReport {
    CosimReport {
        outcome,
        engine_a: a.engine_label(),
        engine_b: b.engine_label(),
    }
}

/// Writes `divergence_<a>.vcd`, `divergence_<b>.vcd` and `divergence.vcd` (both).
fn write_divergence_vcds(
    dir: &Path,
    clock_hz: u64,
    d: &Divergence,
    ha: &History,
    hb: &History,
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create VCD directory {}: {e}", dir.display()))?;
    let nodes = ha.iter().next().map_or(0, |s| s.outputs.len());
    let comment = |who: &str| {
        format!(
            "drcc cosim divergence at cycle {} node{} {}: {}; clock_hz={clock_hz}",
            d.cycle, d.node, d.signal, who
        )
    };
    let (mut na, mut nb) = (d.engine_a.replace('+', "_"), d.engine_b.replace('+', "_"));
    if na == nb {
        na.push_str("_a");
        nb.push_str("_b");
    }
    let fa = dir.join(format!("divergence_{na}.vcd"));
    let fb = dir.join(format!("divergence_{nb}.vcd"));
    let fboth = dir.join("divergence.vcd");
    VcdWriter::write_file(
        &fa,
        clock_hz,
        &[("tb", nodes)],
        &comment(&d.engine_a),
        ha.iter().map(|s| vec![s]),
    )?;
    VcdWriter::write_file(
        &fb,
        clock_hz,
        &[("tb", nodes)],
        &comment(&d.engine_b),
        hb.iter().map(|s| vec![s]),
    )?;
    let (sa, sb) = (format!("a_{na}"), format!("b_{nb}"));
    VcdWriter::write_file(
        &fboth,
        clock_hz,
        &[(sa.as_str(), nodes), (sb.as_str(), nodes)],
        &comment(&format!("{} (a) and {} (b)", d.engine_a, d.engine_b)),
        ha.iter().zip(hb.iter()).map(|(x, y)| vec![x, y]),
    )?;
    Ok(vec![fa, fb, fboth])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs};
    use crate::frame::Frame;
    use crate::system::tests::Ideal;

    /// An `Ideal` engine whose outputs go wrong at one cycle (`tec` = 8 unless
    /// `spoil` says otherwise).
    struct Broken {
        inner: Box<dyn ChannelEngine>,
        at: u64,
        n: u64,
        spoil: fn(&mut ChannelOutputs),
    }

    impl ChannelEngine for Broken {
        fn name(&self) -> &'static str {
            "broken"
        }
        fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
            let mut o = self.inner.step(i);
            if self.n == self.at {
                (self.spoil)(&mut o);
            }
            self.n += 1;
            o
        }
    }

    fn system(broken_at: Option<u64>) -> System {
        system_spoiled(broken_at, |o| o.probes.tec = 8)
    }

    fn system_spoiled(broken_at: Option<u64>, spoil: fn(&mut ChannelOutputs)) -> System {
        let engines: Vec<Box<dyn ChannelEngine>> = (0..3)
            .map(|i| match broken_at {
                Some(at) if i == 2 => Box::new(Broken {
                    inner: Ideal::boxed(),
                    at,
                    n: 0,
                    spoil,
                }) as Box<dyn ChannelEngine>,
                _ => Ideal::boxed(),
            })
            .collect();
        let mut s = System::new(engines, BitTiming::default()).unwrap();
        for (node, at, dlc) in [(0, 5, 3u8), (1, 200, 4), (0, 5, 2)] {
            let f = Frame {
                dlc,
                ..Default::default()
            };
            s.submit(node, at, f).unwrap();
        }
        s
    }

    #[test]
    fn equal_systems_do_not_diverge() {
        let (mut a, mut b) = (system(None), system(None));
        let r = lockstep(&mut a, &mut b, &CosimOptions::default()).unwrap();
        assert!(r.outcome.is_idle());
        assert_eq!(a.deliveries().len(), 6);
    }

    #[test]
    fn diagnostics_and_tx_failed_are_compared() {
        type Case = (fn(&mut ChannelOutputs), &'static str, &'static str);
        let cases: [Case; 4] = [
            (|o| o.tx_failed = true, "tx_failed", "1"),
            (|o| o.diag.err_kind = 5, "err_kind", "0x5 (5)"),
            (|o| o.diag.alc = 31, "alc", "0x1F (31)"),
            (|o| o.diag.cnt_ack = 1, "cnt_ack", "0x1 (1)"),
        ];
        for (spoil, signal, value) in cases {
            let (mut a, mut b) = (system(None), system_spoiled(Some(33), spoil));
            let CosimError::Divergence(d) =
                lockstep(&mut a, &mut b, &CosimOptions::default()).unwrap_err()
            else {
                panic!("expected a divergence in {signal}");
            };
            assert_eq!((d.cycle, d.node, d.signal.as_str()), (33, 2, signal));
            assert_eq!(d.value_b, value);
        }
        // Different configurations cannot be compared.
        let (mut a, mut b) = (system(None), system(None));
        b.set_node_config(
            1,
            crate::engine::ControllerConfig {
                single_shot: true,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(matches!(
            lockstep(&mut a, &mut b, &CosimOptions::default()),
            Err(CosimError::Setup(_))
        ));
    }

    #[test]
    fn divergence_is_reported_with_vcds() {
        let dir = std::env::temp_dir().join(format!("drcc-cosim-test-{}", std::process::id()));
        let (mut a, mut b) = (system(None), system(Some(40)));
        let opts = CosimOptions {
            vcd_dir: Some(dir.clone()),
            before: 20,
            after: 5,
            ..Default::default()
        };
        let err = lockstep(&mut a, &mut b, &opts).unwrap_err();
        let CosimError::Divergence(d) = err else {
            panic!("expected a divergence");
        };
        assert_eq!((d.cycle, d.node, d.signal.as_str()), (40, 2, "tec"));
        assert_eq!((d.bit(), d.clock_in_bit()), (5, 0));
        assert_eq!(d.value_b, "0x8 (8)");
        assert_eq!(d.vcd_files.len(), 3, "{:?}", d.vcd_error);
        let ta = crate::trace::read_vcd(&d.vcd_files[0]).unwrap();
        let tb = crate::trace::read_vcd(&d.vcd_files[1]).unwrap();
        let rep = crate::trace::first_difference(&ta, &tb, &[]).unwrap();
        let first = rep.first.unwrap();
        assert_eq!(first.signal, "tb.node2.tec[8:0]");
        assert_eq!(first.cycle, Some(40));
        let text = d.to_string();
        assert!(
            text.contains("cycle 40") && text.contains("`tec`"),
            "{text}"
        );
        let both = crate::trace::read_vcd(&d.vcd_files[2]).unwrap();
        assert!(both.signal("a_ideal.node0.tx").is_some());
        assert!(both.signal("b_ideal_broken.node2.tx").is_some());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
