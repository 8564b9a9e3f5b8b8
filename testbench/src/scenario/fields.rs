//! The checks of one table each (`[timing]`, `[[node_config]]`, `[[frame]]`,
//! `[[fault]]`, due times): legal ranges from the format's documentation and
//! `BitTiming::validate`.

use super::*;

impl Loader<'_> {
    pub(super) fn timing(
        &self,
        t: &RawTiming,
        span: Range<usize>,
    ) -> Result<BitTiming, ScenarioError> {
        // Legal ranges as BitTiming::validate() states them.
        let field = |v: &Spanned<i64>, name: &str, lo: i64, hi: i64| {
            let x = *v.get_ref();
            if (lo..=hi).contains(&x) {
                Ok(x as u16)
            } else {
                Err(self.err(
                    v.span(),
                    &format!("timing.{name}"),
                    format!(
                        "bit timing field `{name}` = {x} is out of range: legal values are {lo}..={hi}"
                    ),
                ))
            }
        };
        let tseg2 = field(&t.tseg2, "tseg2", 1, 8)? as u8;
        let bt = BitTiming {
            brp: field(&t.brp, "brp", 0, 1023)?,
            tseg1: field(&t.tseg1, "tseg1", 1, 16)? as u8,
            tseg2,
            sjw: match &t.sjw {
                Some(s) => field(s, "sjw", 1, 4)? as u8,
                None => tseg2.clamp(1, 4),
            },
            triple_sampling: t.triple_sampling,
        };
        let field_span = |name: &str| match name {
            "brp" => Some(t.brp.span()),
            "tseg1" => Some(t.tseg1.span()),
            "tseg2" => Some(t.tseg2.span()),
            "sjw" => t.sjw.as_ref().map(|s| s.span()),
            _ => None,
        };
        // validate() also refuses a TSEG1 shorter than 3 clocks, naming `tseg1`.
        if let Err(e) = bt.validate() {
            // The message names the field between backticks.
            let field = e.split('`').nth(1).unwrap_or("").to_string();
            let (sp, f) = match field_span(&field) {
                Some(sp) => (sp, format!("timing.{field}")),
                None => (span, "timing".to_string()),
            };
            return Err(self.err(sp, &f, e));
        }
        Ok(bt)
    }

    /// `base` with the given keys applied; `prefix` is `""` for the scenario keys
    /// or `node_config[i].`.
    pub(super) fn config(
        &self,
        base: ControllerConfig,
        mode: &Option<Spanned<String>>,
        ewl: &Option<Spanned<i64>>,
        single_shot: Option<bool>,
        prefix: &str,
    ) -> Result<ControllerConfig, ScenarioError> {
        let mut c = base;
        if let Some(m) = mode {
            c.mode = match m.get_ref().as_str() {
                "normal" => Mode::Normal,
                "listen_only" => Mode::ListenOnly,
                "self_test" => Mode::SelfTest,
                "loopback" => Mode::Loopback,
                other => {
                    return Err(self.err(
                        m.span(),
                        &format!("{prefix}mode"),
                        format!(
                            "{other:?}: legal modes are normal, listen_only, self_test, loopback"
                        ),
                    ))
                }
            };
        }
        if let Some(e) = ewl {
            let v = *e.get_ref();
            if !(0..=255).contains(&v) {
                return Err(self.err(
                    e.span(),
                    &format!("{prefix}ewl"),
                    format!("{v} is out of range: legal values are 0..=255"),
                ));
            }
            c.ewl = v as u8;
        }
        if let Some(s) = single_shot {
            c.single_shot = s;
        }
        Ok(c)
    }

    pub(super) fn at(
        &self,
        at_cycle: &Option<Spanned<u64>>,
        at_bit: &Option<Spanned<u64>>,
        field: &str,
        cpb: u64,
    ) -> Result<u64, ScenarioError> {
        let (at, span, key) = match (at_cycle, at_bit) {
            (Some(_), Some(b)) => {
                return Err(self.err(
                    b.span(),
                    &format!("{field}.at_bit"),
                    "give either `at_cycle` or `at_bit`, not both",
                ))
            }
            (Some(c), None) => (*c.get_ref(), c.span(), "at_cycle"),
            (None, Some(b)) => (b.get_ref().saturating_mul(cpb), b.span(), "at_bit"),
            (None, None) => return Ok(0),
        };
        if at > MAX_RUN_CYCLES {
            return Err(self.err(
                span,
                &format!("{field}.{key}"),
                format!(
                    "due at clock cycle {at}, beyond the longest run drcc simulates \
                     ({MAX_RUN_CYCLES} cycles): give an earlier time"
                ),
            ));
        }
        Ok(at)
    }

    pub(super) fn frame(
        &self,
        i: usize,
        sf: &Spanned<RawFrame>,
        names: &[String],
        cpb: u64,
    ) -> Result<ScheduledFrame, ScenarioError> {
        let f = sf.get_ref();
        let field = format!("frame[{i}]");
        let node = self.node_ref(&f.node, names, &format!("{field}.node"))?;
        let at_cycle = self.at(&f.at_cycle, &f.at_bit, &field, cpb)?;
        let id = *f.id.get_ref();
        let max_id: i64 = if f.extended { 0x1FFF_FFFF } else { 0x7FF };
        if !(0..=max_id).contains(&id) {
            return Err(self.err(
                f.id.span(),
                &format!("{field}.id"),
                format!(
                    "{} does not fit {} identifier: legal values are 0..=0x{max_id:X}{}",
                    if id < 0 {
                        id.to_string()
                    } else {
                        format!("0x{id:X}")
                    },
                    if f.extended { "a 29-bit" } else { "an 11-bit" },
                    if f.extended {
                        ""
                    } else {
                        " (set `extended = true` for 29-bit identifiers)"
                    }
                ),
            ));
        }
        let data_span = f.data.as_ref().map(|d| d.span()).unwrap_or(sf.span());
        let raw_data: Vec<i64> = f
            .data
            .as_ref()
            .map(|d| d.get_ref().clone())
            .unwrap_or_default();
        if let Some((k, b)) = raw_data
            .iter()
            .enumerate()
            .find(|(_, b)| !(0..=255).contains(*b))
        {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                format!("byte {k} = {b} is out of range: legal values are 0..=255"),
            ));
        }
        let data: Vec<u8> = raw_data.iter().map(|&b| b as u8).collect();
        if f.remote && !data.is_empty() {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                "a remote frame carries no data: remove `data` (use `dlc` for the requested length)",
            ));
        }
        if data.len() > 8 {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                format!("{} bytes: a CAN 2.0 frame carries at most 8", data.len()),
            ));
        }
        let dlc = match &f.dlc {
            Some(d) if !(0..=15).contains(d.get_ref()) => {
                return Err(self.err(
                    d.span(),
                    &format!("{field}.dlc"),
                    format!("{} is out of range: legal values are 0..=15", d.get_ref()),
                ))
            }
            Some(d) => *d.get_ref() as u8,
            None => data.len() as u8,
        };
        let mut frame = Frame {
            id: id as u32,
            ide: f.extended,
            rtr: f.remote,
            dlc,
            data: [0; 8],
        };
        if !f.remote && data.len() != frame.data_len() {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                format!(
                    "{} data bytes, but dlc = {dlc} needs {}",
                    data.len(),
                    frame.data_len()
                ),
            ));
        }
        frame.data[..data.len()].copy_from_slice(&data);
        Ok(ScheduledFrame {
            node,
            at_cycle,
            frame,
            single_shot: f.single_shot,
        })
    }

    pub(super) fn fault(
        &self,
        i: usize,
        f: &RawFault,
        names: &[String],
        cpb: u64,
    ) -> Result<Fault, ScenarioError> {
        let field = format!("fault[{i}]");
        let kind = match f.kind.get_ref().as_str() {
            "stuck_dominant" => FaultKind::StuckDominant,
            "stuck_recessive" => FaultKind::StuckRecessive,
            "flip" => FaultKind::Flip,
            other => {
                return Err(self.err(
                    f.kind.span(),
                    &format!("{field}.kind"),
                    format!("{other:?}: legal kinds are stuck_dominant, stuck_recessive, flip"),
                ))
            }
        };
        let side = f.target.as_ref().map_or("bus", |t| t.get_ref().as_str());
        let node = match &f.node {
            Some(n) => Some(self.node_ref(n, names, &format!("{field}.node"))?),
            None => None,
        };
        let target_span = f.target.as_ref().map(|t| t.span()).unwrap_or(f.kind.span());
        let target = match (side, node) {
            ("bus", None) => FaultTarget::Bus,
            ("tx", Some(n)) => FaultTarget::Tx(n),
            ("rx", Some(n)) => FaultTarget::Rx(n),
            ("bus", Some(_)) => return Err(self.err(
                target_span,
                &format!("{field}.node"),
                "a fault on the bus has no node: set `target = \"tx\"` or `\"rx\"` to hit one node",
            )),
            ("tx" | "rx", None) => {
                return Err(self.err(
                    target_span,
                    &format!("{field}.node"),
                    format!("a fault on a node's {side} needs `node`"),
                ))
            }
            (other, _) => {
                return Err(self.err(
                    target_span,
                    &format!("{field}.target"),
                    format!("{other:?}: legal targets are bus, tx, rx"),
                ))
            }
        };
        let start = self.at(&f.at_cycle, &f.at_bit, &field, cpb)?;
        let cycles = match (&f.cycles, &f.bits) {
            (Some(_), Some(b)) => {
                return Err(self.err(
                    b.span(),
                    &format!("{field}.bits"),
                    "give either `cycles` or `bits`, not both",
                ))
            }
            (Some(c), None) => *c.get_ref(),
            (None, Some(b)) => b.get_ref().saturating_mul(cpb),
            (None, None) => cpb,
        };
        if cycles == 0 {
            let sp = f
                .cycles
                .as_ref()
                .or(f.bits.as_ref())
                .map(|s| s.span())
                .unwrap_or(f.kind.span());
            return Err(self.err(
                sp,
                &format!("{field}.cycles"),
                "a fault lasts at least 1 cycle",
            ));
        }
        Ok(Fault {
            target,
            kind,
            start,
            cycles,
        })
    }
}
