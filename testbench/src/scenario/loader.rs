//! Resolving a parsed scenario file: node names, the bit timing, per-node
//! configurations, frames, expectations, aborts, faults and the cycle limit,
//! with an error naming the file, line and field for anything out of range.

use super::*;

pub(super) struct Loader<'a> {
    pub(super) text: &'a str,
    pub(super) file: &'a str,
}

/// The longest node name.
const MAX_NAME_CHARS: usize = 64;

impl Loader<'_> {
    /// The run's length is at most [`MAX_RUN_CYCLES`], and every frame, fault and
    /// abort is due before its end (one scheduled later would never happen, and
    /// the run would still pass).
    fn within_run(
        &self,
        raw: &RawScenario,
        frames: &[ScheduledFrame],
        faults: &[Fault],
        aborts: &[ScheduledAbort],
        max_cycles: u64,
    ) -> Result<(), ScenarioError> {
        let limit = [
            raw.max_cycles.as_ref().map(|s| (s.span(), "max_cycles")),
            raw.max_bits.as_ref().map(|s| (s.span(), "max_bits")),
            raw.max_ms.as_ref().map(|s| (s.span(), "max_ms")),
        ]
        .into_iter()
        .flatten()
        .next();
        if max_cycles > MAX_RUN_CYCLES {
            let (span, key) = limit.unwrap_or((raw.name.span(), "max_cycles"));
            return Err(self.err(
                span,
                key,
                format!(
                    "the run would last {max_cycles} clock cycles, more than the longest run \
                     drcc simulates ({MAX_RUN_CYCLES}): give a shorter limit"
                ),
            ));
        }
        let at_span = |c: &Option<Spanned<u64>>, b: &Option<Spanned<u64>>, whole: Range<usize>| {
            c.as_ref().or(b.as_ref()).map(|s| s.span()).unwrap_or(whole)
        };
        let late = |what: String, at: u64, span: Range<usize>| {
            self.err(
                span,
                &what,
                format!(
                    "due at clock cycle {at}, after the run's end (cycle {max_cycles}): it would \
                     never happen; give an earlier time or a longer max_cycles / max_bits / max_ms"
                ),
            )
        };
        for (i, (f, r)) in frames.iter().zip(&raw.frame).enumerate() {
            if f.at_cycle >= max_cycles {
                let rf = r.get_ref();
                return Err(late(
                    format!("frame[{i}]"),
                    f.at_cycle,
                    at_span(&rf.at_cycle, &rf.at_bit, r.span()),
                ));
            }
        }
        for (i, (f, r)) in faults.iter().zip(&raw.fault).enumerate() {
            if f.start >= max_cycles {
                let rf = r.get_ref();
                return Err(late(
                    format!("fault[{i}]"),
                    f.start,
                    at_span(&rf.at_cycle, &rf.at_bit, r.span()),
                ));
            }
        }
        for (i, (a, r)) in aborts.iter().zip(&raw.abort).enumerate() {
            if a.at_cycle >= max_cycles {
                let ra = r.get_ref();
                return Err(late(
                    format!("abort[{i}]"),
                    a.at_cycle,
                    at_span(&ra.at_cycle, &ra.at_bit, r.span()),
                ));
            }
        }
        Ok(())
    }

    pub(super) fn err(
        &self,
        span: Range<usize>,
        field: &str,
        message: impl Into<String>,
    ) -> ScenarioError {
        ScenarioError {
            file: self.file.to_string(),
            line: Some(line_of(self.text, span.start)),
            field: Some(field.to_string()),
            message: message.into(),
        }
    }

    pub(super) fn node_ref(
        &self,
        v: &Spanned<toml::Value>,
        names: &[String],
        field: &str,
    ) -> Result<usize, ScenarioError> {
        let n = names.len();
        match v.get_ref() {
            toml::Value::Integer(i) if *i >= 0 && (*i as u64) < n as u64 => Ok(*i as usize),
            toml::Value::Integer(i) => Err(self.err(
                v.span(),
                field,
                format!("node {i} does not exist: nodes are 0..={}", n - 1),
            )),
            toml::Value::String(s) => names.iter().position(|x| x == s).ok_or_else(|| {
                self.err(
                    v.span(),
                    field,
                    format!("no node named {s:?} (nodes: {})", names.join(", ")),
                )
            }),
            other => Err(self.err(
                v.span(),
                field,
                format!("expected a node name or index, found {}", other.type_str()),
            )),
        }
    }

    /// The node names: `nodes = N` (named `node0`..) or a list of distinct names.
    fn node_names(&self, raw: &RawScenario) -> Result<Vec<String>, ScenarioError> {
        match raw.nodes.get_ref() {
            toml::Value::Integer(n) if (1..=64).contains(n) => {
                Ok((0..*n).map(|i| format!("node{i}")).collect())
            }
            toml::Value::Integer(n) => Err(self.err(
                raw.nodes.span(),
                "nodes",
                format!("{n} nodes: legal counts are 1..=64"),
            )),
            toml::Value::Array(list) => {
                let mut v = Vec::new();
                for item in list {
                    match item {
                        toml::Value::String(s)
                            if !s.is_empty()
                                && s.chars().count() <= MAX_NAME_CHARS
                                && !s.contains(char::is_whitespace)
                                && !s.contains(char::is_control) =>
                        {
                            if v.contains(s) {
                                return Err(self.err(
                                    raw.nodes.span(),
                                    "nodes",
                                    format!("node name {s:?} appears twice"),
                                ));
                            }
                            v.push(s.clone());
                        }
                        _ => {
                            return Err(self.err(
                                raw.nodes.span(),
                                "nodes",
                                format!(
                                    "node names must be non-empty strings of at most \
                                     {MAX_NAME_CHARS} characters, without spaces or control \
                                     characters"
                                ),
                            ))
                        }
                    }
                }
                if v.is_empty() || v.len() > 64 {
                    return Err(self.err(
                        raw.nodes.span(),
                        "nodes",
                        format!("{} nodes: legal counts are 1..=64", v.len()),
                    ));
                }
                Ok(v)
            }
            other => Err(self.err(
                raw.nodes.span(),
                "nodes",
                format!(
                    "expected a node count or a list of names, found {}",
                    other.type_str()
                ),
            )),
        }
    }

    /// The clock (1 Hz to [`MAX_CLOCK_HZ`]) and the bit timing: `bitrate`, solved
    /// for the clock, or a `[timing]` table, not both.
    fn clock_and_timing(&self, raw: &RawScenario) -> Result<(u64, BitTiming), ScenarioError> {
        let clock_hz = *raw.clock_hz.get_ref();
        if clock_hz == 0 {
            return Err(self.err(raw.clock_hz.span(), "clock_hz", "must be at least 1 Hz"));
        }
        if clock_hz > MAX_CLOCK_HZ {
            return Err(self.err(
                raw.clock_hz.span(),
                "clock_hz",
                format!(
                    "{clock_hz} Hz: give at most {MAX_CLOCK_HZ} (1 GHz), far above any FPGA \
                     clock of a CAN controller; the traces keep every clock edge up to it"
                ),
            ));
        }
        let timing = match (&raw.bitrate, &raw.timing) {
            (Some(_), Some(t)) => Err(self.err(
                t.span(),
                "timing",
                "give either `bitrate` or a [timing] table, not both",
            )),
            (None, None) => Err(ScenarioError {
                file: self.file.to_string(),
                line: None,
                field: Some("bitrate".to_string()),
                message: "missing: give `bitrate` (bit/s) or a [timing] table".to_string(),
            }),
            (Some(b), None) => {
                bitrate::solve(clock_hz, *b.get_ref()).map_err(|e| self.err(b.span(), "bitrate", e))
            }
            (None, Some(t)) => self.timing(t.get_ref(), t.span()),
        };
        Ok((clock_hz, timing?))
    }

    /// Each node's controller configuration: the scenario's keys, then its
    /// `[[node_config]]` overrides (at most one entry per node).
    fn configs(
        &self,
        raw: &RawScenario,
        names: &[String],
    ) -> Result<Vec<ControllerConfig>, ScenarioError> {
        let base = self.config(
            ControllerConfig::default(),
            &raw.mode,
            &raw.ewl,
            raw.single_shot,
            "",
        )?;
        let mut configs = vec![base; names.len()];
        let mut configured: Vec<usize> = Vec::new();
        for (i, nc) in raw.node_config.iter().enumerate() {
            let nc = nc.get_ref();
            let field = format!("node_config[{i}]");
            let node = self.node_ref(&nc.node, names, &format!("{field}.node"))?;
            if configured.contains(&node) {
                return Err(self.err(
                    nc.node.span(),
                    &format!("{field}.node"),
                    format!("node {:?} has two [[node_config]] entries", names[node]),
                ));
            }
            configured.push(node);
            configs[node] = self.config(
                base,
                &nc.mode,
                &nc.ewl,
                nc.single_shot,
                &format!("{field}."),
            )?;
        }
        Ok(configs)
    }

    /// The `[[expect]]` entries (at most one per node, each frame listed once and
    /// existing among the file's `frames`), or every frame to every other node.
    fn expectations(
        &self,
        raw: &RawScenario,
        names: &[String],
        frames: usize,
    ) -> Result<Expectations, ScenarioError> {
        Ok(match &raw.expect {
            None => Expectations::EveryFrameToEveryOtherNode,
            Some(list) => {
                let mut v: Vec<NodeExpectation> = Vec::new();
                for (i, e) in list.iter().enumerate() {
                    let e = e.get_ref();
                    let node = self.node_ref(&e.node, names, &format!("expect[{i}].node"))?;
                    if v.iter().any(|x| x.node == node) {
                        return Err(self.err(
                            e.node.span(),
                            &format!("expect[{i}].node"),
                            format!("node {:?} has two [[expect]] entries", names[node]),
                        ));
                    }
                    let check = |l: &Option<Spanned<Vec<usize>>>, what: &str| {
                        if let Some(l) = l {
                            let list = l.get_ref();
                            if let Some((k, _)) = list
                                .iter()
                                .enumerate()
                                .find(|(k, x)| list[..*k].contains(x))
                            {
                                return Err(self.err(
                                    l.span(),
                                    &format!("expect[{i}].{what}"),
                                    format!(
                                        "frame {} is listed twice: each frame is expected \
                                         exactly once; list it once",
                                        list[k]
                                    ),
                                ));
                            }
                            if let Some(bad) = l.get_ref().iter().find(|&&k| k >= frames) {
                                return Err(self.err(
                                    l.span(),
                                    &format!("expect[{i}].{what}"),
                                    format!(
                                        "frame {bad} does not exist: the file has {} frame(s), numbered from 0 in file order",
                                        frames
                                    ),
                                ));
                            }
                        }
                        Ok(l.as_ref().map(|l| l.get_ref().clone()))
                    };
                    let receives = check(&e.receives, "receives")?;
                    let sends = check(&e.sends, "sends")?;
                    let fails = check(&e.fails, "fails")?;
                    v.push(NodeExpectation {
                        node,
                        receives,
                        sends,
                        fails,
                    });
                }
                Expectations::Explicit(v)
            }
        })
    }

    /// The run's length in clock cycles: at most one of `max_cycles`, `max_bits`
    /// (times `cpb`) and `max_ms`, else long enough for every frame.
    fn max_cycles(
        &self,
        raw: &RawScenario,
        frames: &[ScheduledFrame],
        clock_hz: u64,
        cpb: u64,
    ) -> Result<u64, ScenarioError> {
        let mut limits: Vec<(Range<usize>, &str)> = [
            raw.max_cycles.as_ref().map(|s| (s.span(), "max_cycles")),
            raw.max_bits.as_ref().map(|s| (s.span(), "max_bits")),
            raw.max_ms.as_ref().map(|s| (s.span(), "max_ms")),
        ]
        .into_iter()
        .flatten()
        .collect();
        limits.sort_by_key(|(sp, _)| sp.start);
        if let Some((span, name)) = limits.get(1) {
            return Err(self.err(
                span.clone(),
                name,
                "give at most one of `max_cycles`, `max_bits`, `max_ms`",
            ));
        }
        Ok(if let Some(c) = &raw.max_cycles {
            *c.get_ref()
        } else if let Some(b) = &raw.max_bits {
            b.get_ref().saturating_mul(cpb)
        } else if let Some(ms) = &raw.max_ms {
            let v = *ms.get_ref();
            if !(v.is_finite() && v > 0.0) {
                return Err(self.err(ms.span(), "max_ms", "must be a positive number"));
            }
            (v * clock_hz as f64 / 1000.0).ceil() as u64
        } else {
            Scenario::default_max_cycles(frames, cpb)
        })
    }

    pub(super) fn resolve(&self, raw: RawScenario) -> Result<Scenario, ScenarioError> {
        let names = self.node_names(&raw)?;
        let (clock_hz, timing) = self.clock_and_timing(&raw)?;
        let cpb = timing.clocks_per_bit() as u64;
        let configs = self.configs(&raw, &names)?;
        let mut frames = Vec::new();
        for (i, sf) in raw.frame.iter().enumerate() {
            frames.push(self.frame(i, sf, &names, cpb)?);
        }
        let expect = self.expectations(&raw, &names, frames.len())?;
        // Faults.
        let mut faults = Vec::new();
        for (i, f) in raw.fault.iter().enumerate() {
            faults.push(self.fault(i, f.get_ref(), &names, cpb)?);
        }

        // Aborts.
        let mut aborts = Vec::new();
        for (i, a) in raw.abort.iter().enumerate() {
            let a = a.get_ref();
            let field = format!("abort[{i}]");
            aborts.push(ScheduledAbort {
                node: self.node_ref(&a.node, &names, &format!("{field}.node"))?,
                at_cycle: self.at(&a.at_cycle, &a.at_bit, &field, cpb)?,
            });
        }

        let max_cycles = self.max_cycles(&raw, &frames, clock_hz, cpb)?;
        self.within_run(&raw, &frames, &faults, &aborts, max_cycles)?;
        let reset_cycles = match &raw.reset_cycles {
            Some(r) if (1..=1000).contains(r.get_ref()) => *r.get_ref(),
            Some(r) => return Err(self.err(r.span(), "reset_cycles", "legal values are 1..=1000")),
            None => DEFAULT_RESET_CYCLES,
        };
        let name = raw.name.get_ref().trim().to_string();
        if name.is_empty() {
            return Err(self.err(raw.name.span(), "name", "must not be empty"));
        }
        Ok(Scenario {
            name,
            description: raw.description.unwrap_or_default(),
            source: self.file.to_string(),
            clock_hz,
            timing,
            nodes: names,
            configs,
            frames,
            expect,
            faults,
            aborts,
            max_cycles,
            reset_cycles,
        })
    }
}
