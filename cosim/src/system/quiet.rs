//! Runs that nobody watches clock by clock ([`System::run_for`],
//! [`System::run_until_idle`]): the same clocks and events as [`System::step`],
//! but where the host raises nothing for a while (no reset, request or abort
//! due, nothing changing `tx_pending`) the nodes run through
//! [`ChannelEngine::step_quiet`], which may skip converting outputs nobody
//! looks at, and only the stretch's last sample is kept. Traces and lock-step
//! comparisons use `step`.
//!
//! [`ChannelEngine::step_quiet`]: crate::engine::ChannelEngine::step_quiet
//! [`ChannelEngine::gains_from_quiet`]: crate::engine::ChannelEngine::gains_from_quiet

use super::{RunOutcome, System, IDLE_BITS};
use crate::engine::ChannelInputs;

impl System {
    /// Runs `cycles` clocks with the result of calling [`System::step`] that many
    /// times: the same events and, at the end, the same [`System::sample`]. Where
    /// the host raises nothing for a while (after reset, no request or abort due,
    /// nothing changing `tx_pending`), the nodes run through
    /// [`ChannelEngine::step_quiet`](crate::engine::ChannelEngine::step_quiet),
    /// which may skip converting outputs nobody looks at, and no intermediate
    /// sample is kept. For runs that nobody watches
    /// clock by clock (the benchmark, [`System::run_until_idle`]); traces and
    /// lock-step comparisons use `step`.
    pub fn run_for(&mut self, cycles: u64) {
        if !self.quiet_gains {
            for _ in 0..cycles {
                self.step();
            }
            return;
        }
        let end = self.steps.saturating_add(cycles);
        while self.steps < end {
            let quiet = self.quiet_cycles().min(end - self.steps);
            if quiet == 0 {
                self.step();
            } else {
                self.run_quiet(quiet);
            }
        }
    }

    /// How many clocks from the next one on would [`System::step`] raise no reset,
    /// request or abort, as far as the host's schedule tells (`u64::MAX`: no end);
    /// 0 also when an engine does not gain from quiet stretches
    /// ([`ChannelEngine::gains_from_quiet`](crate::engine::ChannelEngine::gains_from_quiet):
    /// the reference model steps as fast).
    /// A request also needs `tx_pending` low, which only changes with a `tx_done` or
    /// a `tx_failed` (timing contract §8): `run_quiet` ends a stretch there.
    fn quiet_cycles(&self) -> u64 {
        let c = self.steps;
        if c < self.reset_cycles || !self.quiet_gains {
            return 0;
        }
        let mut quiet = u64::MAX;
        for i in 0..self.engines.len() {
            if let Some(&due) = self.aborts[i].front() {
                quiet = quiet.min(due.saturating_sub(c));
            }
            if !self.sample.outputs[i].tx_pending {
                if let Some(head) = self.queues[i].front() {
                    // No request in the clock after one (step's rule).
                    let first = head.due.max(c + self.sample.tx_req[i] as u64);
                    quiet = quiet.min(first - c);
                }
            }
        }
        quiet
    }

    /// Up to `cycles` clocks (at least 1) in which the host raises nothing, as
    /// [`System::step`] would make them; ends after a clock with a pulse
    /// (`rx_valid`, `tx_done`, `arb_lost`, `tx_failed`) or a change of `tx_pending`,
    /// whose events it records. The sample holds the last clock, complete.
    fn run_quiet(&mut self, cycles: u64) {
        let n = self.engines.len();
        self.quiet_inputs.clear();
        for i in 0..n {
            self.quiet_inputs.push(ChannelInputs {
                rst: false,
                rx: true,
                timing: self.timing,
                config: self.config[i],
                tx_req: false,
                tx_frame: self.tx_frame[i],
                tx_abort: false,
                tx_single: false,
                err_reset: false,
                boff_hold: false,
            });
        }
        self.sample.rst = false;
        self.sample.tx_req.fill(false);
        self.sample.tx_abort.fill(false);
        for _ in 0..cycles {
            let cycle = self.steps;
            self.resolve_bus(cycle);
            let mut notable = false;
            for (i, engine) in self.engines.iter_mut().enumerate() {
                let inputs = &mut self.quiet_inputs[i];
                inputs.rx = self.sample.rx[i];
                notable |= engine.step_quiet(inputs, &mut self.sample.outputs[i]);
            }
            self.steps += 1;
            if notable {
                for i in 0..n {
                    self.engines[i].complete_outputs(&mut self.sample.outputs[i]);
                    let out = self.sample.outputs[i];
                    self.record(cycle, i, &out);
                }
                return;
            }
        }
        for (engine, out) in self.engines.iter_mut().zip(&mut self.sample.outputs) {
            engine.complete_outputs(out);
        }
    }

    /// Steps until [`System::is_quiescent`] or until `max_cycles` cycles have been
    /// run in total. Nobody watches single clocks: the quiet stretches run as in
    /// [`System::run_for`], stopping exactly where clock-by-clock stepping would.
    pub fn run_until_idle(&mut self, max_cycles: u64) -> RunOutcome {
        if !self.quiet_gains {
            return self.run_until_idle_stepwise(max_cycles);
        }
        loop {
            if self.is_quiescent() {
                return RunOutcome::Idle { cycle: self.steps };
            }
            if self.steps >= max_cycles {
                return RunOutcome::CycleLimit { cycle: self.steps };
            }
            let mut quiet = self.quiet_cycles().min(max_cycles - self.steps);
            // Within a stretch the queues stay as they are and tx_pending does not
            // change (it ends the stretch), so the system can only become quiescent
            // once the recessive run reaches the idle length: stop there.
            if self.queues.iter().all(|q| q.is_empty())
                && self.sample.outputs.iter().all(|o| !o.tx_pending)
            {
                let idle = IDLE_BITS * self.timing.clocks_per_bit() as u64;
                quiet = quiet.min(idle.saturating_sub(self.recessive_cycles).max(1));
            }
            if quiet == 0 {
                self.step();
            } else {
                self.run_quiet(quiet);
            }
        }
    }
}
