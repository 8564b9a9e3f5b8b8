//! Observation: a transparent wrapper around the engines of the first system,
//! logging what each node does clock by clock.

use super::*;

/// One change of a node's probes (recorded from the fault-free cycle on).
#[derive(Clone, Copy, Debug)]
pub(super) struct Mark {
    pub(super) cycle: u64,
    pub(super) field: u8,
    pub(super) err_state: u8,
    pub(super) tec: u16,
    pub(super) rec: u8,
}

/// What one node did, as seen through its outputs.
#[derive(Clone, Debug, Default)]
pub(super) struct NodeLog {
    pub(super) max_tec: u16,
    pub(super) max_rec: u8,
    /// Entries into error passive (from error active).
    pub(super) passive: usize,
    /// Entries into bus-off.
    pub(super) bus_off: usize,
    /// Bus-off -> error active.
    pub(super) recovered: usize,
    /// Error flags started (field becoming ERROR_FLAG).
    pub(super) error_flags: usize,
    /// Overload flags started.
    pub(super) overload_flags: usize,
    /// First fault-free cycle at which the node is idle (and not bus-off).
    pub(super) settled: Option<u64>,
    /// Fault free: every change of field, error state or counters.
    pub(super) trail: Vec<Mark>,
    /// Fault free: cycles at which the node's `rx` had been recessive for more
    /// than 11 bit times (plus the sampling delay) and the node was not idle
    /// (nor bus-off, nor in its 8 suspend bits): (cycle, field).
    pub(super) not_idle: Vec<(u64, u8)>,
}

pub(super) struct Watch {
    pub(super) inner: Box<dyn ChannelEngine>,
    pub(super) log: Rc<RefCell<NodeLog>>,
    pub(super) cycle: u64,
    pub(super) fault_free: u64,
    pub(super) cpb: u64,
    pub(super) prev: Probes,
    pub(super) rx_run: u64,
    pub(super) was_bad: bool,
}

impl ChannelEngine for Watch {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
        let o = self.inner.step(i);
        let c = self.cycle;
        self.cycle += 1;
        let p = o.probes;
        let mut log = self.log.borrow_mut();
        log.max_tec = log.max_tec.max(p.tec);
        log.max_rec = log.max_rec.max(p.rec);
        if p.err_state != self.prev.err_state {
            match (self.prev.err_state, p.err_state) {
                (0, 1) => log.passive += 1,
                (_, 2) => log.bus_off += 1,
                (2, 0) => log.recovered += 1,
                _ => {}
            }
        }
        if p.field != self.prev.field {
            match p.field {
                field::ERROR_FLAG => log.error_flags += 1,
                field::OVERLOAD_FLAG => log.overload_flags += 1,
                _ => {}
            }
        }
        self.rx_run = if i.rx && !i.rst { self.rx_run + 1 } else { 0 };
        if c >= self.fault_free {
            let q = &self.prev;
            if c == self.fault_free
                || (p.field, p.err_state, p.tec, p.rec) != (q.field, q.err_state, q.tec, q.rec)
            {
                log.trail.push(Mark {
                    cycle: c,
                    field: p.field,
                    err_state: p.err_state,
                    tec: p.tec,
                    rec: p.rec,
                });
            }
            if log.settled.is_none() && p.field == field::IDLE && p.err_state != 2 {
                log.settled = Some(c);
            }
            // 11 recessive bits: the 11th is sampled at most one bit plus the
            // two synchronizer clocks after it started.
            let idle_after = 12 * self.cpb + 2;
            let bad = self.rx_run >= idle_after
                && !(p.field == field::IDLE
                    || p.field == field::BUS_OFF
                    || (p.field == field::SUSPEND && self.rx_run < idle_after + 8 * self.cpb));
            if bad && !self.was_bad {
                log.not_idle.push((c, p.field));
            }
            self.was_bad = bad;
        }
        self.prev = p;
        o
    }
}
