//! The comparisons of the DMR control lock-step (§4.1 events, every register and
//! output against the model's) and the coverage counts.

use super::bench::{key30, Bench};
use drcc_cosim::model::drcc::dmr::engine::Raised;
use drcc_cosim::model::drcc::dmr::mailboxes::Key;
use drcc_cosim::model::drcc::dmr::{DmrBlock, DmrEvents, DmrInputs};
use drcc_cosim::model::drcc::regs::idx;

/// How often each path was reached (asserted non-zero at the end).
#[derive(Debug, Default)]
pub struct Coverage {
    pub edges: u64,
    pub holds: u64,
    pub rsts: u64,
    pub dmr_ticks: u64,
    pub host_req: [u64; 2],
    pub cs_req: [u64; 2],
    pub periodic_cs: u64,
    pub first_copies: u64,
    pub pops: u64,
    pub cs_success: u64,
    pub recoveries: u64,
    pub cs_failed: u64,
    pub busoff: u64,
    pub eval_tx: u64,
    pub eval_rx: u64,
    pub eval_rx_ignored: u64,
    pub deletion_abort: u64,
    pub cs_abort: u64,
    pub returns: u64,
    pub restarts: u64,
    pub acl_switches: u64,
    pub state: [u64; 4],
    pub cs_good: u64,
    pub cs_bad: u64,
    pub raise_tx: u64,
    pub raise_rx: u64,
    pub raise_req: u64,
    pub raise_eval: u64,
}

impl Bench {
    /// §4.1 events from the model's registers before the edge (`c`), against the
    /// block's raises.
    pub fn check_raises(
        &self,
        c: &DmrBlock,
        i: &DmrInputs,
        raised: &Raised,
        ev: &DmrEvents,
        at: &str,
    ) {
        for l in 0..2 {
            let o = 1 - l;
            let rx =
                (i.rx_valid[l] && !c.is_cs_frame(&i.rx_frame[l])).then(|| Key::of(&i.rx_frame[l]));
            assert_eq!(
                rx.is_some(),
                ev.rx_deliver[l],
                "{at}: RX({l}) vs the model's rx_deliver"
            );
            assert_eq!(raised.rx[l], rx, "{at}: RX({l})");
            let req = c.req[l].then(|| Key::of(&i.rd));
            assert_eq!(raised.req[l], req, "{at}: REQ({l})");
            let tx = (i.done[l] && !c.cs_busy[l] && c.busy[l] && !c.tx_fault[l] && !c.tx_fault[o])
                .then_some(c.key_sent[l]);
            assert_eq!(raised.tx[l], tx, "{at}: TX({l})");
        }
        assert_eq!(raised.eval, c.dmr_tick, "{at}: eval");
    }

    /// Every register of the model against the block's.
    pub fn check_registers(&self, at: &str) {
        let m = &self.model;
        let u = &self.uut;
        let tb = &u.time_base;
        assert_eq!(tb.tb_cnt.q.val().to_u64(), m.tb_cnt as u64, "{at}: tb_cnt");
        assert_eq!(tb.tick_q.q.val(), m.dmr_tick, "{at}: dmr_tick");
        assert_eq!(u.dmr_tick.val(), m.dmr_tick, "{at}: dmr_tick out");
        assert_eq!(u.raise_eval.val(), m.dmr_tick, "{at}: raise_eval");
        assert_eq!(
            tb.period_cnt.q.val().to_u64(),
            m.period_cnt as u64,
            "{at}: period_cnt"
        );
        let offs = [u.off_dcl.val().to_u64(), u.off_rcl.val().to_u64()];
        let tx_req = [u.tx_req_dcl.val(), u.tx_req_rcl.val()];
        let cs_req = [u.cs_req_dcl.val(), u.cs_req_rcl.val()];
        let abort = [u.tx_abort_dcl.val(), u.tx_abort_rcl.val()];
        let restart = [u.restart_dcl.val(), u.restart_rcl.val()];
        let tx_fault = [u.dcl_tx_fault.val(), u.rcl_tx_fault.val()];
        let rx_fault = [u.dcl_rx_fault.val(), u.rcl_rx_fault.val()];
        for (l, line) in [&u.dcl, &u.rcl].into_iter().enumerate() {
            assert_eq!(offs[l], m.off[l] as u64, "{at}: off[{l}]");
            assert_eq!(tx_req[l], m.tx_req(l), "{at}: tx_req[{l}]");
            assert_eq!(cs_req[l], m.cs_req[l], "{at}: cs_req[{l}]");
            assert_eq!(abort[l], m.abort[l], "{at}: abort[{l}]");
            assert_eq!(restart[l], m.restart[l], "{at}: restart[{l}]");
            assert_eq!(tx_fault[l], m.tx_fault[l], "{at}: tx_fault[{l}]");
            assert_eq!(rx_fault[l], m.rx_fault[l], "{at}: rx_fault[{l}]");
            assert_eq!(line.req_q.q.val(), m.req[l], "{at}: req[{l}]");
            assert_eq!(line.busy_q.q.val(), m.busy[l], "{at}: busy[{l}]");
            assert_eq!(line.cs_busy_q.q.val(), m.cs_busy[l], "{at}: cs_busy[{l}]");
            assert_eq!(line.cs_live_q.q.val(), m.cs_live[l], "{at}: cs_live[{l}]");
            assert_eq!(line.cs_due_q.q.val(), m.cs_due[l], "{at}: cs_due[{l}]");
            assert_eq!(
                line.rec_pending_q.q.val(),
                m.rec_pending[l],
                "{at}: rec_pending[{l}]"
            );
            assert_eq!(line.busoff_q.q.val(), m.busoff_q[l], "{at}: busoff_q[{l}]");
            assert_eq!(
                line.key_sent_q.q.val().to_u64(),
                key30(&m.key_sent[l]),
                "{at}: key_sent[{l}]"
            );
            // One timer per line: the CS timer while an attempt is live, else the
            // recovery timer (the model keeps two; a live attempt has rec_timer 0).
            assert!(
                !m.cs_live[l] || m.rec_timer[l] == 0,
                "{at}: cs_live with rec_timer"
            );
            let t = if m.cs_busy[l] && m.cs_live[l] {
                m.cs_timer[l]
            } else {
                m.rec_timer[l]
            };
            assert_eq!(line.timer_q.q.val().to_u64(), t as u64, "{at}: timer[{l}]");
        }
        assert_eq!(u.acl.val(), m.acl != 0, "{at}: acl");
        assert_eq!(
            u.dmr_state.val().to_u64(),
            m.dmr_state as u64,
            "{at}: dmr_state"
        );
        let st = &u.status;
        assert_eq!(st.cause_q.q.val().to_u64(), m.cause as u64, "{at}: cause");
        assert_eq!(
            st.cause_line_q.q.val(),
            m.cause_line != 0,
            "{at}: cause_line"
        );
        assert_eq!(
            st.cause_mb_q.q.val().to_u64(),
            m.cause_mb as u64,
            "{at}: cause_mb"
        );
        let read = |adr| m.read(adr, false, 0).unwrap() as u64;
        assert_eq!(
            u.status_word.val().to_u64(),
            read(idx::DMR_STATUS),
            "{at}: DMR_STATUS"
        );
        assert_eq!(
            u.cs_count_word.val().to_u64(),
            read(idx::DMR_CS_COUNT),
            "{at}: DMR_CS_COUNT"
        );
    }

    pub fn coverage(&mut self, c: &DmrBlock, i: &DmrInputs, ev: &DmrEvents, rst: bool, hold: bool) {
        let m = &self.model;
        let v = &mut self.cov;
        v.edges += 1;
        if rst {
            v.rsts += 1;
            return;
        }
        if hold {
            v.holds += 1;
            return;
        }
        v.dmr_ticks += m.dmr_tick as u64;
        v.first_copies += ev.tx_done as u64;
        v.pops += (ev.pop > 0) as u64;
        v.acl_switches += ev.acl_switch as u64;
        v.state[m.dmr_state as usize] += 1;
        v.raise_eval += c.dmr_tick as u64;
        for l in 0..2 {
            v.host_req[l] += m.req[l] as u64;
            v.cs_req[l] += m.cs_req[l] as u64;
            v.restarts += m.restart[l] as u64;
            if c.cs_busy[l] && !m.cs_busy[l] && c.cs_live[l] && !m.tx_fault[l] && !m.rx_fault[l] {
                v.cs_success += 1;
                if c.tx_fault[l] || c.rx_fault[l] {
                    v.recoveries += 1;
                }
            }
            if m.abort[l] && c.busy[l] && m.tx_fault[l] && !c.tx_fault[l] {
                v.deletion_abort += 1;
            }
            if m.abort[l] && c.cs_busy[l] {
                v.cs_abort += 1;
            }
            // return: the line sends again while the other one sends
            if c.tx_fault[l] && !m.tx_fault[l] && !c.tx_fault[1 - l] && !m.tx_fault[1 - l] {
                v.returns += 1;
            }
            if !c.cs_due[l] && m.cs_due[l] && !c.tx_fault[l] && !c.rx_fault[l] {
                v.periodic_cs += 1;
            }
            v.cs_good += (m.cs_count[2 * l] > c.cs_count[2 * l]) as u64;
            v.cs_bad += (m.cs_count[2 * l + 1] > c.cs_count[2 * l + 1]) as u64;
        }
        for l in 0..2 {
            // the model's own conditions on its pre-edge registers (§6, §7)
            if c.cs_busy[l] && c.cs_live[l] && c.dmr_tick && c.cs_timer[l] == 1 {
                v.cs_failed += 1;
            }
            if !c.busoff_q[l] && i.err_state[l] == 2 {
                v.busoff += 1;
            }
        }
    }
}
