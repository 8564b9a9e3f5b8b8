//! The DRCC core's host-view interface (PeliCAN contract §14) in lock step. The
//! SJA1000 view's reference model drives its model core; the same drive, edge by
//! edge, drives the RTL core (`drcc_hdl::drcc_core::DrccCore` in rust-hdl's
//! simulator), and every core output a view reads is compared clock by clock:
//! the CAN pins, the DRCC probes, each channel's transmit and error outputs,
//! the RX writer's stores and overruns, and the RX FIFO's state and head. The
//! scenarios are the view model's own tests (`model_pelican/`, whose expected
//! values come from the contract and the data sheet), run again here with the
//! RTL core beside the model; a `Net` a scenario clones runs without it.

#[path = "model_support/mod.rs"]
mod support;

#[path = "model_pelican/acceptance.rs"]
mod acceptance;
#[path = "model_pelican/busoff.rs"]
mod busoff;
#[path = "model_pelican/drivers.rs"]
mod drivers;
#[path = "model_pelican/harness.rs"]
mod harness;
#[path = "model_pelican/map.rs"]
mod map;

/// The RTL core beside the model.
mod shadow {
    use drcc_cosim::engine::drcc_core_rusthdl::{CoreViewOutputs, DrccCoreViewEngine, ViewChannel};
    use drcc_cosim::model::pelican::{PelicanInputs, PelicanModel, PelicanParams};
    use drcc_cosim::ChannelOutputs;
    use drcc_hdl::config::DrccConfig;

    enum Engine {
        M16(DrccCoreViewEngine<16>),
        M0(DrccCoreViewEngine<0>),
    }

    /// The RTL core, `None` in a cloned `Net`.
    pub struct Shadow {
        eng: Option<Engine>,
        clock: u64,
    }

    impl Clone for Shadow {
        fn clone(&self) -> Self {
            Shadow {
                eng: None,
                clock: self.clock,
            }
        }
    }

    /// What the RTL's channel outputs must be, from the model's.
    fn expected_channel(o: &ChannelOutputs) -> ViewChannel {
        ViewChannel {
            tx_done: o.tx_done,
            tx_failed: o.tx_failed,
            tx_pending: o.tx_pending,
            is_tx: o.probes.is_tx,
            boff_runs: o.probes.boff_runs,
            err_warning: o.diag.err_warning,
            tec: o.probes.tec,
            err_valid: o.diag.err_valid,
            err_kind: o.diag.err_kind,
            err_field: o.diag.err_field,
            err_tx: o.diag.err_tx,
            arb_lost: o.arb_lost,
            alc: o.diag.alc,
        }
    }

    impl Shadow {
        pub fn new(p: &PelicanParams) -> Self {
            let c = &p.core;
            let cfg = DrccConfig {
                mailboxes: c.mailboxes,
                rx_fifo_depth: c.rx_fifo_depth as usize,
                tx_queue_depth: c.tx_queue_depth as usize,
                history: c.history as usize,
                dmr: c.dmr,
                star: c.star,
            };
            let eng = match c.mailboxes {
                16 => Engine::M16(DrccCoreViewEngine::with_config(&cfg)),
                0 => Engine::M0(DrccCoreViewEngine::with_config(&cfg)),
                m => panic!("no RTL core generated with {m} mailboxes here"),
            };
            Shadow {
                eng: Some(eng),
                clock: 0,
            }
        }

        /// Step the RTL core with the model's last core edge and compare.
        pub fn edge(&mut self, _: &PelicanInputs, dut: &PelicanModel) {
            let k = self.clock;
            self.clock += 1;
            let e = *dut.last_core_edge();
            let o: CoreViewOutputs = match self.eng.as_mut() {
                None => return,
                Some(Engine::M16(x)) => x.step(e.rst, e.rx, &e.drive),
                Some(Engine::M0(x)) => x.step(e.rst, e.rx, &e.drive),
            };
            let core = dut.core();
            let m = core.outputs();
            assert_eq!(
                (o.top.chan_a_tx, o.top.chan_b_tx),
                (m.chan_a_tx, m.chan_b_tx),
                "CAN pins, clock {k}"
            );
            assert_eq!(o.top.probes, m.probes, "DRCC probes, clock {k}");
            let v = core.core_view();
            for x in 0..2 {
                assert_eq!(
                    o.chan[x],
                    expected_channel(v.chan[x]),
                    "channel {x}, clock {k}"
                );
            }
            let ev = dut.core_events();
            assert_eq!(
                (o.stored, o.overrun),
                (ev.stored, ev.overrun),
                "RX writer store / overrun, clock {k}"
            );
            assert_eq!(
                (o.rx_ready, o.rx_count),
                (v.rx_ready, v.rx_count),
                "RX FIFO, clock {k}"
            );
            // The head as the contract's timing (§15) lets a view read it: from
            // an access taken two edges after a pop (the RTL's read port runs
            // one entry ahead at the pop edge, `memory/rx_fifo.rs`), and while
            // `rx_ready` (one edge after a store into an empty FIFO).
            if v.rx_ready && !e.drive.pop {
                assert_eq!(
                    (o.head, o.head_ch),
                    (v.head, v.head_ch & 1),
                    "RX FIFO head, clock {k}"
                );
            }
        }
    }
}
