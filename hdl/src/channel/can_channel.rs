//! The `can_channel` top: one complete classical CAN 2.0B channel (ISO 11898-1)
//! made of the rx synchronizer, the bit timing logic and the bit stream
//! processor. Ports are grouped by interface: clock/reset, bit-timing
//! configuration, CAN pins, host transmit, host receive, probes.

use super::bsp::field::Field;
use super::bsp::protocol::ProtocolController;
use super::btl::BitTimingLogic;
use super::bus_sampling::synchronizer::RxSynchronizer;
use super::config::ChannelConfig;
use super::BRP_BITS;
use rust_hdl::prelude::*;

/// One CAN channel: BTL + BSP.
#[derive(LogicBlock)]
pub struct CanChannel<const RX_HOLD: u64 = 1> {
    // clock and reset
    /// Clock. Every register changes at its rising edge; the bit timing is counted
    /// in its periods (a time quantum is `cfg_brp + 1` clocks).
    pub clk: Signal<In, Clock>,
    /// Synchronous reset, active high: at an edge with `rst = 1` every register takes
    /// its reset value and the `cfg_*` inputs are captured (contract §1, §6).
    pub rst: Signal<In, Bit>,
    // bit-timing configuration (ISO 11898-1 11.3): captured at every edge where
    // `rst = 1`, held while `rst = 0` (contract §6)
    /// Baud-rate prescaler BRP, 0..1023, taken as is (not a minus-one code): a
    /// time quantum lasts `cfg_brp + 1` clocks. Captured while `rst = 1`.
    pub cfg_brp: Signal<In, Bits<BRP_BITS>>,
    /// TSEG1 minus one: PROP_SEG + PHASE_SEG1 lasts `cfg_tseg1 + 1` tq (1..16),
    /// lengthened if needed so a bit has at least 8 tq and TSEG1 at least 3 clocks
    /// (contract §6). Captured while `rst = 1`.
    pub cfg_tseg1: Signal<In, Bits<4>>,
    /// TSEG2 minus one: PHASE_SEG2 lasts `cfg_tseg2 + 1` tq (1..8). Captured while
    /// `rst = 1`.
    pub cfg_tseg2: Signal<In, Bits<3>>,
    /// SJW minus one: the resynchronisation jump width is `min(cfg_sjw + 1, TSEG2)`
    /// tq (1..4). Captured while `rst = 1`.
    pub cfg_sjw: Signal<In, Bits<2>>,
    /// Triple sampling, 1 = on: the sample is the majority of the bus value at the
    /// sample point and at the two time quanta before it. Captured while `rst = 1`.
    pub cfg_triple: Signal<In, Bit>,
    // controller configuration: captured at every edge where `rst = 1` (contract §6)
    /// Operating mode (contract §7): 0 normal, 1 listen-only (never drives the bus),
    /// 2 self-test (no ACK needed), 3 loop-back (hears only itself, `tx` stays 1).
    /// Captured while `rst = 1`.
    pub cfg_mode: Signal<In, Bits<2>>,
    /// Error warning limit EWL (ISO 11898-1 default 96): `err_warning` is
    /// `tec >= cfg_ewl || rec >= cfg_ewl`. Captured while `rst = 1`.
    pub cfg_ewl: Signal<In, Bits<8>>,
    /// 1 = single shot, no automatic retransmission: an attempt that loses
    /// arbitration or meets an error drops the frame (`tx_failed`, contract §8).
    /// Captured while `rst = 1`.
    pub cfg_single_shot: Signal<In, Bit>,
    // CAN pins, to and from the transceiver (1 = recessive, 0 = dominant)
    /// CAN receive pin, 1 = recessive. May be asynchronous: it passes a two
    /// flip-flop synchronizer, so a change is seen 2 clocks later (contract §2).
    pub rx: Signal<In, Bit>,
    /// CAN transmit pin, 1 = recessive. A register, recessive after reset and
    /// constant 1 in loop-back mode; it changes only at the start of a bit.
    pub tx: Signal<Out, Bit>,
    // host transmit interface: one frame at a time (contract §4.4, §8)
    /// Transmit request, a one-clock pulse: at that edge `tx_id`, `tx_ide`, `tx_rtr`,
    /// `tx_dlc` and `tx_data` are latched and `tx_pending` rises. Ignored while
    /// `tx_pending = 1`; refused with `tx_failed` in listen-only mode.
    pub tx_req: Signal<In, Bit>,
    /// Identifier to send, right-aligned: a base frame uses `[10:0]` (`[28:11]`
    /// ignored), an extended frame `[28:0]`, whose base part `[28:18]` goes first
    /// on the bus. Latched by `tx_req`.
    pub tx_id: Signal<In, Bits<29>>,
    /// Identifier extension: 1 = extended frame (29-bit identifier), 0 = base frame
    /// (11 bits). Latched by `tx_req`.
    pub tx_ide: Signal<In, Bit>,
    /// 1 = remote frame (no data field; `tx_dlc` is still sent). Latched by `tx_req`.
    pub tx_rtr: Signal<In, Bit>,
    /// Data length code as sent, 0..15; 9..15 carry 8 bytes. Latched by `tx_req`.
    pub tx_dlc: Signal<In, Bits<4>>,
    /// Data bytes, byte 0 (the first on the bus) in `[63:56]`, byte 7 in `[7:0]`: the
    /// data field leaves MSB first from bit 63 down. Bytes past `min(tx_dlc, 8)` are
    /// not sent. Latched by `tx_req`.
    pub tx_data: Signal<In, Bits<64>>,
    /// Abort request, a one-clock pulse: drops the pending frame at once while the
    /// node is not transmitting it (and `tx` is recessive), else when the attempt in
    /// progress fails; a successful attempt still ends with `tx_done` (contract §8).
    pub tx_abort: Signal<In, Bit>,
    /// 1 = the frame of this `tx_req` is single shot, as with `cfg_single_shot`
    /// but for this frame only. Latched by `tx_req` (contract §8).
    pub tx_single: Signal<In, Bit>,
    // ---- error control ----
    /// Error counter reset: at an edge with `err_reset = 1` a node that is not
    /// bus-off ends with TEC = REC = 0, error active; it stays on the bus (no
    /// re-integration, unlike `rst`). 0 in normal use (contract §4.5).
    pub err_reset: Signal<In, Bit>,
    /// Bus-off hold: while 1, a bus-off node does not count its recovery (128
    /// runs of 11 recessive bits); it stays bus-off until the host lets it go.
    /// 0 in normal use (contract §4.5).
    pub boff_hold: Signal<In, Bit>,
    /// A frame is latched and not yet sent or dropped: 1 from the `tx_req` edge
    /// until `tx_done` or `tx_failed`.
    pub tx_pending: Signal<Out, Bit>,
    /// One-clock pulse: the pending frame was dropped (single-shot attempt failed,
    /// abort carried out, or `tx_req` in listen-only mode); `tx_pending` clears.
    pub tx_failed: Signal<Out, Bit>,
    /// One-clock pulse: the pending frame was sent (7th EOF bit recessive, ISO
    /// 11898-1 8.1.5); `tx_pending` clears.
    pub tx_done: Signal<Out, Bit>,
    /// One-clock pulse: arbitration lost (the bit position is in `alc`); the frame
    /// stays pending and is retried, unless `cfg_single_shot`.
    pub arb_lost: Signal<Out, Bit>,
    // host receive interface: the last frame received, held until the next one
    /// One-clock pulse: a frame was received (6th EOF bit recessive, not sent by this
    /// node except in loop-back mode); `rx_id` .. `rx_data` are updated at that edge.
    pub rx_valid: Signal<Out, Bit>,
    /// Received identifier, aligned as `tx_id`: base frame in `[10:0]` with `[28:11]`
    /// zero, extended frame in `[28:0]`. Held until the next `rx_valid`.
    pub rx_id: Signal<Out, Bits<29>>,
    /// Received frame is extended (1) or base (0). Held until the next `rx_valid`.
    pub rx_ide: Signal<Out, Bit>,
    /// Received frame is a remote frame. Held until the next `rx_valid`.
    pub rx_rtr: Signal<Out, Bit>,
    /// Received data length code as sent on the bus, 0..15. Held until the next
    /// `rx_valid`.
    pub rx_dlc: Signal<Out, Bits<4>>,
    /// Received data, byte 0 in `[63:56]` as `tx_data`; bytes past `min(rx_dlc, 8)`
    /// and every byte of a remote frame are 0. Held until the next `rx_valid`.
    pub rx_data: Signal<Out, Bits<64>>,
    // probes (contract §3, §4)
    /// One-clock pulse, the clock after each sample point of the bit timing logic.
    pub sample_point: Signal<Out, Bit>,
    /// Bus value taken at the last sample point, 1 = recessive.
    pub sampled_bit: Signal<Out, Bit>,
    /// Field of the next non-stuff bit (contract §4.1): 0 integrating, 1 idle, 2 base
    /// ID, 3 SRR/RTR, 4 IDE, 5 extension ID, 6 extended RTR, 7 r1, 8 r0, 9 DLC, 10 data,
    /// 11 CRC, 12 CRC delimiter, 13 ACK slot, 14 ACK delimiter, 15 EOF, 16
    /// intermission, 17 suspend, 18 error flag, 19 error delimiter, 20 overload flag,
    /// 21 overload delimiter, 22 bus-off.
    pub field: Signal<Out, Field>,
    /// Transmit error counter TEC (ISO 11898-1 12.1.4); above 255 the node is
    /// bus-off.
    pub tec: Signal<Out, Bits<9>>,
    /// Receive error counter REC, saturating at 255.
    pub rec: Signal<Out, Bits<8>>,
    /// Fault confinement state: 0 error active, 1 error passive, 2 bus-off.
    pub err_state: Signal<Out, Bits<2>>,
    /// The node is transmitter of the frame on the bus: from the SOF it starts
    /// until it loses arbitration, the end of the intermission after its frame,
    /// or bus-off (contract §4.5, "Roles").
    pub is_tx: Signal<Out, Bit>,
    /// Completed runs of 11 recessive bits in the current bus-off (0..127), 0
    /// outside bus-off (contract §4.5).
    pub boff_runs: Signal<Out, Bits<7>>,
    // diagnostics, host-visible registers (contract §9)
    /// `tec >= cfg_ewl || rec >= cfg_ewl` (error warning limit reached).
    pub err_warning: Signal<Out, Bit>,
    /// One-clock pulse: an error was detected; `err_kind`, `err_field` and `err_tx`
    /// are loaded at that edge.
    pub err_valid: Signal<Out, Bit>,
    /// Kind of the last error: 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK (0 none since
    /// reset). Held until the next error.
    pub err_kind: Signal<Out, Bits<3>>,
    /// `field` code of the bit in error at the last error. Held until the next error.
    pub err_field: Signal<Out, Field>,
    /// 1 = the node was transmitter at the last error. Held until the next error.
    pub err_tx: Signal<Out, Bit>,
    /// Arbitration-lost capture, loaded with `arb_lost`: base-ID bit i (0 = first,
    /// most significant) is i, SRR/RTR 11, IDE 12, extension bit j is 13 + j, the
    /// RTR of an extended frame 31.
    pub alc: Signal<Out, Bits<5>>,
    /// Bit errors counted since reset, saturating at 255.
    pub cnt_bit: Signal<Out, Bits<8>>,
    /// Stuff errors counted since reset, saturating at 255.
    pub cnt_stuff: Signal<Out, Bits<8>>,
    /// CRC errors counted since reset, saturating at 255.
    pub cnt_crc: Signal<Out, Bits<8>>,
    /// Form errors counted since reset, saturating at 255.
    pub cnt_form: Signal<Out, Bits<8>>,
    /// ACK errors counted since reset, saturating at 255.
    pub cnt_ack: Signal<Out, Bits<8>>,
    // blocks
    cfg_regs: ChannelConfig,
    rx_sync: RxSynchronizer,
    btl: BitTimingLogic,
    bsp: ProtocolController<RX_HOLD>,
    loopback_mode: Constant<Bits<2>>,
}

impl<const RX_HOLD: u64> Default for CanChannel<RX_HOLD> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            cfg_brp: Default::default(),
            cfg_tseg1: Default::default(),
            cfg_tseg2: Default::default(),
            cfg_sjw: Default::default(),
            cfg_triple: Default::default(),
            cfg_mode: Default::default(),
            cfg_ewl: Default::default(),
            cfg_single_shot: Default::default(),
            rx: Default::default(),
            tx: Default::default(),
            tx_req: Default::default(),
            tx_id: Default::default(),
            tx_ide: Default::default(),
            tx_rtr: Default::default(),
            tx_dlc: Default::default(),
            tx_data: Default::default(),
            tx_abort: Default::default(),
            tx_single: Default::default(),
            err_reset: Default::default(),
            boff_hold: Default::default(),
            tx_pending: Default::default(),
            tx_failed: Default::default(),
            tx_done: Default::default(),
            arb_lost: Default::default(),
            rx_valid: Default::default(),
            rx_id: Default::default(),
            rx_ide: Default::default(),
            rx_rtr: Default::default(),
            rx_dlc: Default::default(),
            rx_data: Default::default(),
            sample_point: Default::default(),
            sampled_bit: Default::default(),
            field: Default::default(),
            tec: Default::default(),
            rec: Default::default(),
            err_state: Default::default(),
            is_tx: Default::default(),
            boff_runs: Default::default(),
            err_warning: Default::default(),
            err_valid: Default::default(),
            err_kind: Default::default(),
            err_field: Default::default(),
            err_tx: Default::default(),
            alc: Default::default(),
            cnt_bit: Default::default(),
            cnt_stuff: Default::default(),
            cnt_crc: Default::default(),
            cnt_form: Default::default(),
            cnt_ack: Default::default(),
            cfg_regs: Default::default(),
            rx_sync: Default::default(),
            btl: Default::default(),
            bsp: Default::default(),
            loopback_mode: Constant::new(3.into()),
        }
    }
}

impl<const RX_HOLD: u64> Logic for CanChannel<RX_HOLD> {
    #[hdl_gen]
    fn update(&mut self) {
        self.cfg_regs.clk.next = self.clk.val();
        self.cfg_regs.rst.next = self.rst.val();
        self.cfg_regs.cfg_brp.next = self.cfg_brp.val();
        self.cfg_regs.cfg_tseg1.next = self.cfg_tseg1.val();
        self.cfg_regs.cfg_tseg2.next = self.cfg_tseg2.val();
        self.cfg_regs.cfg_sjw.next = self.cfg_sjw.val();
        self.cfg_regs.cfg_triple.next = self.cfg_triple.val();
        self.cfg_regs.cfg_mode.next = self.cfg_mode.val();
        self.cfg_regs.cfg_ewl.next = self.cfg_ewl.val();
        self.cfg_regs.cfg_single_shot.next = self.cfg_single_shot.val();

        // Loop-back mode (contract §7): the receiver hears the node's own tx
        // register and the pin stays recessive.
        self.rx_sync.clk.next = self.clk.val();
        self.rx_sync.rst.next = self.rst.val();
        if self.cfg_regs.mode.val() == self.loopback_mode.val() {
            self.rx_sync.rx.next = self.bsp.tx.val();
            self.tx.next = true;
        } else {
            self.rx_sync.rx.next = self.rx.val();
            self.tx.next = self.bsp.tx.val();
        }

        self.btl.clk.next = self.clk.val();
        self.btl.rst.next = self.rst.val();
        self.btl.cfg_brp_next.next = self.cfg_regs.brp_next.val();
        self.btl.cfg_tseg1_len.next = self.cfg_regs.tseg1_len.val();
        self.btl.cfg_tseg2_len.next = self.cfg_regs.tseg2_len.val();
        self.btl.cfg_sjw_len.next = self.cfg_regs.sjw_len.val();
        self.btl.cfg_triple.next = self.cfg_regs.triple.val();
        self.btl.rx_s.next = self.rx_sync.rx_s.val();
        self.btl.tx.next = self.bsp.tx.val();
        self.btl.hard_sync_enable.next = self.bsp.hard_sync_enable.val();

        self.bsp.clk.next = self.clk.val();
        self.bsp.rst.next = self.rst.val();
        self.bsp.sample.next = self.btl.sample.val();
        self.bsp.sampled.next = self.btl.sampled.val();
        self.bsp.bit_start.next = self.btl.bit_start.val();
        self.bsp.hard_sync.next = self.btl.hard_sync.val();
        self.bsp.tx_req.next = self.tx_req.val();
        self.bsp.tx_id.next = self.tx_id.val();
        self.bsp.tx_ide.next = self.tx_ide.val();
        self.bsp.tx_rtr.next = self.tx_rtr.val();
        self.bsp.tx_dlc.next = self.tx_dlc.val();
        self.bsp.tx_data.next = self.tx_data.val();
        self.bsp.tx_abort.next = self.tx_abort.val();
        self.bsp.tx_single.next = self.tx_single.val();
        self.bsp.err_reset.next = self.err_reset.val();
        self.bsp.boff_hold.next = self.boff_hold.val();
        self.bsp.mode.next = self.cfg_regs.mode.val();
        self.bsp.ewl.next = self.cfg_regs.ewl.val();
        self.bsp.single_shot.next = self.cfg_regs.single_shot.val();

        self.tx_pending.next = self.bsp.tx_pending.val();
        self.tx_done.next = self.bsp.tx_done.val();
        self.arb_lost.next = self.bsp.arb_lost.val();
        self.rx_valid.next = self.bsp.rx_valid.val();
        self.rx_id.next = self.bsp.rx_id.val();
        self.rx_ide.next = self.bsp.rx_ide.val();
        self.rx_rtr.next = self.bsp.rx_rtr.val();
        self.rx_dlc.next = self.bsp.rx_dlc.val();
        self.rx_data.next = self.bsp.rx_data.val();
        self.sample_point.next = self.btl.sample_point.val();
        self.sampled_bit.next = self.btl.last_sample.val();
        self.field.next = self.bsp.field.val();
        self.tec.next = self.bsp.tec.val();
        self.rec.next = self.bsp.rec.val();
        self.err_state.next = self.bsp.err_state.val();
        self.is_tx.next = self.bsp.is_tx.val();
        self.boff_runs.next = self.bsp.boff_runs.val();
        self.tx_failed.next = self.bsp.tx_failed.val();
        self.err_warning.next = self.bsp.err_warning.val();
        self.err_valid.next = self.bsp.err_valid.val();
        self.err_kind.next = self.bsp.err_kind.val();
        self.err_field.next = self.bsp.err_field.val();
        self.err_tx.next = self.bsp.err_tx.val();
        self.alc.next = self.bsp.alc.val();
        self.cnt_bit.next = self.bsp.cnt_bit.val();
        self.cnt_stuff.next = self.bsp.cnt_stuff.val();
        self.cnt_crc.next = self.bsp.cnt_crc.val();
        self.cnt_form.next = self.bsp.cnt_form.val();
        self.cnt_ack.next = self.bsp.cnt_ack.val();
    }
}
