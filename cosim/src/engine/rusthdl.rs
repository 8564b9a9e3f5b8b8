//! The `rust-hdl` engine: the hdl blocks run in rust-hdl's own event-driven
//! simulator. It runs the same Rust description the Verilog is emitted from, so
//! comparing it with the Verilated RTL checks that the emitted Verilog means what
//! the Rust means, and it is the fallback engine when Verilator is absent.
//!
//! One `step`: with `clk` low, apply the inputs and settle; raise `clk` and
//! settle; read the outputs (inputs change away from the clock edge, as the
//! conventions of `docs/design.md` require).

use super::{ChannelEngine, ChannelInputs, ChannelOutputs, Diagnostics, Probes};
use crate::frame::Frame;
use drcc_hdl::channel::can_channel::CanChannel;
use rust_hdl::prelude::*;

/// Settling budget per half clock; the channel settles in a handful of passes.
const MAX_SETTLE_ITERS: usize = 200;

/// The can_channel block in rust-hdl's simulator.
pub struct RustHdlEngine {
    uut: Box<CanChannel>,
}

impl Default for RustHdlEngine {
    fn default() -> Self {
        Self::new()
    }
}

/// Lets a rust-hdl block settle after its inputs or its clock changed, within
/// `iters` delta cycles. One that does not has a combinational loop, a design bug
/// rust-hdl's checks catch at generation time: reported loudly rather than hung on.
/// Shared by the rust-hdl engines and the block-level lock-step tests.
pub fn settle<B: Block>(uut: &mut B, iters: usize, what: &str) {
    if !simulate(uut, iters) {
        panic!("rust-hdl engine: {what} did not settle (combinational loop?)");
    }
}

impl RustHdlEngine {
    /// A fresh channel, clock low, not yet reset (drive `rst` for a few steps).
    pub fn new() -> Self {
        let mut uut = Box::<CanChannel>::default();
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        simulate(uut.as_mut(), MAX_SETTLE_ITERS);
        RustHdlEngine { uut }
    }

    fn settle(&mut self) {
        settle(self.uut.as_mut(), MAX_SETTLE_ITERS, "can_channel");
    }
}

impl ChannelEngine for RustHdlEngine {
    fn name(&self) -> &'static str {
        "rust-hdl"
    }

    fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.rst.next = i.rst;
        u.rx.next = i.rx;
        u.cfg_brp.next = (i.timing.brp.min(1023) as u64).into();
        u.cfg_tseg1.next = (i.timing.tseg1.clamp(1, 16) as u64 - 1).into();
        u.cfg_tseg2.next = (i.timing.tseg2.clamp(1, 8) as u64 - 1).into();
        u.cfg_sjw.next = (i.timing.sjw.clamp(1, 4) as u64 - 1).into();
        u.cfg_triple.next = i.timing.triple_sampling;
        u.cfg_mode.next = (i.config.mode.code() as u64).into();
        u.cfg_ewl.next = (i.config.ewl as u64).into();
        u.cfg_single_shot.next = i.config.single_shot;
        u.tx_req.next = i.tx_req;
        u.tx_id.next = ((i.tx_frame.id & 0x1FFF_FFFF) as u64).into();
        u.tx_ide.next = i.tx_frame.ide;
        u.tx_rtr.next = i.tx_frame.rtr;
        u.tx_dlc.next = ((i.tx_frame.dlc & 0xF) as u64).into();
        u.tx_data.next = i.tx_frame.data_word().into();
        u.tx_abort.next = i.tx_abort;
        u.tx_single.next = i.tx_single;
        u.err_reset.next = i.err_reset;
        u.boff_hold.next = i.boff_hold;
        self.settle();
        self.uut.clk.next = Clock::from(true);
        self.settle();
        let u = &self.uut;
        let rx_frame = Frame {
            id: u.rx_id.val().to_u64() as u32,
            ide: u.rx_ide.val(),
            rtr: u.rx_rtr.val(),
            dlc: u.rx_dlc.val().to_u64() as u8,
            data: [0; 8],
        }
        .with_data_word(u.rx_data.val().to_u64());
        ChannelOutputs {
            tx: u.tx.val(),
            tx_pending: u.tx_pending.val(),
            tx_done: u.tx_done.val(),
            arb_lost: u.arb_lost.val(),
            tx_failed: u.tx_failed.val(),
            rx_valid: u.rx_valid.val(),
            rx_frame,
            probes: Probes {
                sample_point: u.sample_point.val(),
                sampled_bit: u.sampled_bit.val(),
                field: field_code(&u.field.val()),
                tec: u.tec.val().to_u64() as u16,
                rec: u.rec.val().to_u64() as u8,
                err_state: u.err_state.val().to_u64() as u8,
                is_tx: u.is_tx.val(),
                boff_runs: u.boff_runs.val().to_u64() as u8,
            },
            diag: Diagnostics {
                err_warning: u.err_warning.val(),
                err_valid: u.err_valid.val(),
                err_kind: u.err_kind.val().to_u64() as u8,
                err_field: field_code(&u.err_field.val()),
                err_tx: u.err_tx.val(),
                alc: u.alc.val().to_u64() as u8,
                cnt_bit: u.cnt_bit.val().to_u64() as u8,
                cnt_stuff: u.cnt_stuff.val().to_u64() as u8,
                cnt_crc: u.cnt_crc.val().to_u64() as u8,
                cnt_form: u.cnt_form.val().to_u64() as u8,
                cnt_ack: u.cnt_ack.val().to_u64() as u8,
            },
        }
    }
}

/// The probe encoding of a field (`field`, `err_field`): its declaration index
/// (timing contract §4.1), as in the emitted Verilog.
pub(crate) fn field_code(f: &drcc_hdl::channel::bsp::field::Field) -> u8 {
    use drcc_hdl::channel::bsp::field::Field::*;
    match f {
        Integrating => 0,
        Idle => 1,
        IdA => 2,
        SrrRtr => 3,
        Ide => 4,
        IdB => 5,
        RtrExt => 6,
        R1 => 7,
        R0 => 8,
        Dlc => 9,
        Data => 10,
        Crc => 11,
        CrcDelim => 12,
        AckSlot => 13,
        AckDelim => 14,
        Eof => 15,
        Intermission => 16,
        Suspend => 17,
        ErrorFlag => 18,
        ErrorDelim => 19,
        OverloadFlag => 20,
        OverloadDelim => 21,
        BusOff => 22,
    }
}
