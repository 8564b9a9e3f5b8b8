//! The C driver of `drivers/c` (compiled by build.rs) behind a safe wrapper
//! whose register hooks are Wishbone cycles on one node of a [`DualBus`].
//!
//! [`DualBus`]: crate::DualBus

use crate::NodePort;
use std::ffi::c_void;

/// `drcc_mode` DRCC_MODE_NORMAL.
pub const C_MODE_NORMAL: i32 = 0;
/// `drcc_mode` DRCC_MODE_REDUNDANCY.
pub const C_MODE_REDUNDANCY: i32 = 1;
/// `drcc_mode` DRCC_MODE_DMR.
pub const C_MODE_DMR: i32 = 2;

/// Mirror of the C `drcc_frame`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CFrame {
    /// Identifier, right-aligned.
    pub id: u32,
    /// 1 = extended.
    pub ide: u8,
    /// 1 = remote.
    pub rtr: u8,
    /// Data length code.
    pub dlc: u8,
    /// Received on channel 0 (A) or 1 (B).
    pub channel: u8,
    /// Data bytes.
    pub data: [u8; 8],
    /// Received: RX_TIME.rx_time (bit times).
    pub timestamp: u16,
}

/// Mirror of the C `drcc_capture`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CCapture {
    /// An error was captured.
    pub err_valid: u8,
    /// Error kind (1 bit .. 5 ACK).
    pub err_kind: u8,
    /// Field code of the error.
    pub err_field: u8,
    /// Transmitter at the error.
    pub err_tx: u8,
    /// An arbitration loss was captured.
    pub alc_valid: u8,
    /// Arbitration-lost position.
    pub alc: u8,
}

/// Mirror of the C `drcc_ident`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CIdent {
    /// VERSION.major.
    pub major: u8,
    /// VERSION.minor.
    pub minor: u8,
    /// SIZES.rx_fifo_depth.
    pub rx_fifo_depth: u8,
    /// SIZES.tx_queue_depth.
    pub tx_queue_depth: u8,
    /// SIZES.history.
    pub history: u8,
    /// SIZES.mailboxes.
    pub mailboxes: u8,
    /// SIZES.dmr.
    pub dmr: u8,
    /// SIZES.star.
    pub star: u8,
}

/// Mirror of the C `drcc_stats`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CStats {
    /// STATS0 duplicates.
    pub duplicates: u16,
    /// STATS0 overruns.
    pub overruns: u16,
    /// STATS1 switches.
    pub switches: u16,
    /// STATS1 recoveries.
    pub recoveries: u16,
    /// TIMES last_tx_time.
    pub last_tx_time: u16,
    /// TIMES switch_time.
    pub switch_time: u16,
    /// OMISSIONS of A.
    pub omissions_a: u16,
    /// OMISSIONS of B.
    pub omissions_b: u16,
    /// DMR_STATUS.
    pub dmr_status: u32,
    /// DMR_CS_COUNT.
    pub dmr_cs_count: u32,
    /// DMR_RX_STATS.
    pub dmr_rx_stats: u32,
}

/// Mirror of the C `drcc_chan_status`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CChanStatus {
    /// Transmit error counter.
    pub tec: u16,
    /// Receive error counter.
    pub rec: u8,
    /// 0 error active, 1 error passive, 2 bus-off.
    pub err_state: u8,
    /// TEC or REC >= ewl.
    pub err_warning: u8,
    /// Auxiliary FSM state.
    pub aux_state: u8,
    /// AUX_x causes.
    pub aux_causes: u8,
    /// Failed attempts.
    pub fail_cnt: u8,
    /// Times judged failed.
    pub failures: u8,
    /// Times recovered.
    pub recoveries: u8,
}

/// Mirror of the C `drcc_status`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CStatus {
    /// Main FSM state.
    pub state: u8,
    /// Channel in use.
    pub tx_channel: u8,
    /// CTRL.reset_mode.
    pub reset_mode: u8,
    /// A transmission is in progress.
    pub tx_going_on: u8,
    /// Frames in TX queue A.
    pub txq_a: u8,
    /// Frames in TX queue B.
    pub txq_b: u8,
    /// Frames in the RX FIFO.
    pub rx_count: u8,
    /// Channel A.
    pub a: CChanStatus,
    /// Channel B.
    pub b: CChanStatus,
}

/// Mirror of the C `drcc_bit_timing`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CBitTiming {
    /// Prescaler (clocks per quantum).
    pub brp: u16,
    /// TSEG1 in quanta.
    pub tseg1: u8,
    /// TSEG2 in quanta.
    pub tseg2: u8,
    /// SJW in quanta.
    pub sjw: u8,
    /// Triple sampling.
    pub triple: u8,
}

/// Mirror of the C `drcc_irq_result`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CIrqResult {
    /// INT_STATUS as read and acknowledged.
    pub events: u32,
    /// Frames stored.
    pub frames: usize,
    /// The buffer filled up with frames still in the FIFO.
    pub more: i32,
    /// CAP_A before the acknowledgement.
    pub cap_a: CCapture,
    /// CAP_B before the acknowledgement.
    pub cap_b: CCapture,
}

type Read32 = extern "C" fn(*mut c_void, u32) -> u32;
type Write32 = extern "C" fn(*mut c_void, u32, u32);

extern "C" {
    fn sim_c_open(read32: Read32, write32: Write32, ctx: *mut c_void, rc: *mut i32) -> *mut c_void;
    fn sim_c_close(dev: *mut c_void);
    fn sim_c_example_open(
        read32: Read32,
        write32: Write32,
        ctx: *mut c_void,
        rc: *mut i32,
    ) -> *mut c_void;
    fn sim_c_stats_all(dev: *mut c_void, out: *mut CStats);
    fn sim_c_ident(dev: *const c_void) -> CIdent;
    fn sim_c_set_filter(
        dev: *mut c_void,
        index: u32,
        enable: i32,
        id: u32,
        mask: u32,
        ide: i32,
    ) -> i32;
    fn drcc_clear_filters(dev: *mut c_void) -> i32;
    fn sim_c_init_with_version(version: u32) -> i32;
    fn sim_c_configure_single_shot(
        dev: *mut c_void,
        clock_hz: u32,
        bitrate: u32,
        int_enable: u32,
    ) -> i32;
    fn drcc_now(dev: *mut c_void) -> u16;
    fn drcc_abort(dev: *mut c_void, channels: u32) -> i32;
    fn drcc_recover(dev: *mut c_void, channels: u32) -> i32;
    fn sim_c_status(dev: *mut c_void, out: *mut CStatus);
    fn sim_c_configure_manual(
        dev: *mut c_void,
        clock_hz: u32,
        bitrate: u32,
        mode: i32,
        busoff_manual: i32,
        int_enable: u32,
    ) -> i32;
    fn sim_c_call_with_version(
        version: u32,
        ctrl: u32,
        what: i32,
        channels: u32,
        writes: *mut u32,
        last: *mut [u32; 2],
    ) -> i32;
    fn drcc_clear_stats(dev: *mut c_void);
    fn drcc_get_captures(dev: *mut c_void, a: *mut CCapture, b: *mut CCapture);
    fn drcc_rearm_captures(dev: *mut c_void, errors: i32, arb: i32);
    fn drcc_irq_status(dev: *mut c_void) -> u32;
    fn drcc_irq_ack(dev: *mut c_void, mask: u32);
    fn can_poll(dev: *mut c_void, f: *mut CFrame, tries: std::ffi::c_ulong) -> std::ffi::c_long;
    #[allow(clippy::too_many_arguments)]
    fn sim_c_configure(
        dev: *mut c_void,
        clock_hz: u32,
        bitrate: u32,
        mode: i32,
        policy: u32,
        k: u32,
        dual_tx: i32,
        stall_limit: u16,
        recovery_bits: u16,
        dedup_window: u16,
        int_enable: u32,
    ) -> i32;
    fn sim_c_stats(dev: *mut c_void, duplicates: *mut u32, switches: *mut u32);
    fn drcc_send(dev: *mut c_void, frame: *const CFrame, queue: u32) -> i32;
    fn drcc_receive(dev: *mut c_void, frame: *mut CFrame) -> i32;
    fn drcc_isr(dev: *mut c_void, buf: *mut CFrame, cap: usize) -> CIrqResult;
    fn drcc_calc_bit_timing(clock_hz: u32, bitrate: u32, out: *mut CBitTiming) -> i32;
    fn drcc_btr_encode(bt: *const CBitTiming, ewl: u8) -> u32;
}

extern "C" fn read_hook(ctx: *mut c_void, offset: u32) -> u32 {
    // SAFETY: ctx is the Box<NodePort> CDriver keeps alive while the C side holds it.
    let port = unsafe { &*(ctx as *const NodePort) };
    port.read32(offset)
}

extern "C" fn write_hook(ctx: *mut c_void, offset: u32, value: u32) {
    // SAFETY: as in read_hook.
    let port = unsafe { &*(ctx as *const NodePort) };
    port.write32(offset, value)
}

/// The C driver bound to one node.
pub struct CDriver {
    dev: *mut c_void,
    _port: Box<NodePort>,
}

/// Parameters of [`CDriver::configure`] (the glue's `sim_c_configure`).
#[derive(Clone, Copy, Debug)]
pub struct CConfig {
    /// Module clock in Hz.
    pub clock_hz: u32,
    /// Bit rate.
    pub bitrate: u32,
    /// [`C_MODE_NORMAL`] or [`C_MODE_REDUNDANCY`].
    pub mode: i32,
    /// `DRCC_CTRL_POLICY_*`.
    pub policy: u32,
    /// k of the k-failed policy.
    pub k: u32,
    /// Every message on A, then on B.
    pub dual_tx: bool,
    /// RMB_CFG.stall_limit.
    pub stall_limit: u16,
    /// RMB_CFG.recovery_bits.
    pub recovery_bits: u16,
    /// DEDUP_CFG.window.
    pub dedup_window: u16,
    /// INT_ENABLE.
    pub int_enable: u32,
}

type Opener = unsafe extern "C" fn(Read32, Write32, *mut c_void, *mut i32) -> *mut c_void;

impl CDriver {
    fn open_with(port: NodePort, opener: Opener) -> Result<CDriver, i32> {
        let port = Box::new(port);
        let ctx = &*port as *const NodePort as *mut c_void;
        let mut rc = 0;
        // SAFETY: the hooks and ctx stay valid as long as the returned CDriver.
        let dev = unsafe { opener(read_hook, write_hook, ctx, &mut rc) };
        if dev.is_null() {
            return Err(rc);
        }
        Ok(CDriver { dev, _port: port })
    }

    /// `drcc_init` on `port`; the C result code on failure.
    pub fn open(port: NodePort) -> Result<CDriver, i32> {
        CDriver::open_with(port, sim_c_open)
    }

    /// The README example's `can_start` on `port` (drivers/c/README.md).
    pub fn open_readme_example(port: NodePort) -> Result<CDriver, i32> {
        CDriver::open_with(port, sim_c_example_open)
    }

    /// The README example's `can_poll`: the frame's age in bit times (or -1)
    /// and the frame.
    pub fn readme_poll(&mut self, tries: u32) -> (i64, CFrame) {
        let mut f = CFrame::default();
        // SAFETY: dev is live, f a valid drcc_frame.
        let age = unsafe { can_poll(self.dev, &mut f, tries.into()) };
        // `long` is 32 bits on some targets, 64 on this one.
        #[allow(clippy::useless_conversion)]
        let age = i64::from(age);
        (age, f)
    }

    /// `dev->ident` (VERSION and SIZES read by drcc_init).
    pub fn ident(&self) -> CIdent {
        // SAFETY: dev is live.
        unsafe { sim_c_ident(self.dev) }
    }

    /// `drcc_set_filter` (`None`: disable); the C result code.
    pub fn set_filter(&mut self, index: u32, filter: Option<(u32, u32, bool)>) -> i32 {
        let (id, mask, ide) = filter.unwrap_or((0, 0, false));
        // SAFETY: dev is live.
        unsafe {
            sim_c_set_filter(
                self.dev,
                index,
                i32::from(filter.is_some()),
                id,
                mask,
                i32::from(ide),
            )
        }
    }

    /// `drcc_clear_filters`; the C result code.
    pub fn clear_filters(&mut self) -> i32 {
        // SAFETY: dev is live.
        unsafe { drcc_clear_filters(self.dev) }
    }

    /// `drcc_now`.
    pub fn now(&mut self) -> u16 {
        // SAFETY: dev is live.
        unsafe { drcc_now(self.dev) }
    }

    /// `drcc_abort(channels)` (`DRCC_CH_A` 1, `DRCC_CH_B` 2, both 3); the C
    /// result code.
    pub fn abort(&mut self, channels: u32) -> i32 {
        // SAFETY: dev is live.
        unsafe { drcc_abort(self.dev, channels) }
    }

    /// `drcc_recover(channels)`; the C result code.
    pub fn recover(&mut self, channels: u32) -> i32 {
        // SAFETY: dev is live.
        unsafe { drcc_recover(self.dev, channels) }
    }

    /// `drcc_get_status`.
    pub fn status(&mut self) -> CStatus {
        let mut s = CStatus::default();
        // SAFETY: dev is live, s a valid drcc_status.
        unsafe { sim_c_status(self.dev, &mut s) };
        s
    }

    /// `drcc_configure` in `mode` (`C_MODE_*`, 2 = DMR) with
    /// `busoff_manual`, the rest at `drcc_config_default`; the C result code.
    pub fn configure_manual(
        &mut self,
        clock_hz: u32,
        bitrate: u32,
        mode: i32,
        busoff_manual: bool,
        int_enable: u32,
    ) -> i32 {
        // SAFETY: dev is live.
        unsafe {
            sim_c_configure_manual(
                self.dev,
                clock_hz,
                bitrate,
                mode,
                i32::from(busoff_manual),
                int_enable,
            )
        }
    }

    /// `drcc_clear_stats`.
    pub fn clear_stats(&mut self) {
        // SAFETY: dev is live.
        unsafe { drcc_clear_stats(self.dev) }
    }

    /// `drcc_get_stats`.
    pub fn stats_all(&mut self) -> CStats {
        let mut s = CStats::default();
        // SAFETY: dev is live, s a valid drcc_stats.
        unsafe { sim_c_stats_all(self.dev, &mut s) };
        s
    }

    /// `drcc_get_captures`: (CAP_A, CAP_B).
    pub fn captures(&mut self) -> (CCapture, CCapture) {
        let (mut a, mut b) = (CCapture::default(), CCapture::default());
        // SAFETY: dev is live.
        unsafe { drcc_get_captures(self.dev, &mut a, &mut b) };
        (a, b)
    }

    /// `drcc_rearm_captures`.
    pub fn rearm_captures(&mut self, errors: bool, arb: bool) {
        // SAFETY: dev is live.
        unsafe { drcc_rearm_captures(self.dev, i32::from(errors), i32::from(arb)) }
    }

    /// `drcc_irq_status`.
    pub fn irq_status(&mut self) -> u32 {
        // SAFETY: dev is live.
        unsafe { drcc_irq_status(self.dev) }
    }

    /// `drcc_irq_ack`.
    pub fn irq_ack(&mut self, mask: u32) {
        // SAFETY: dev is live.
        unsafe { drcc_irq_ack(self.dev, mask) }
    }

    /// `drcc_configure` (through the glue); the C result code.
    pub fn configure(&mut self, c: &CConfig) -> i32 {
        // SAFETY: dev is live.
        unsafe {
            sim_c_configure(
                self.dev,
                c.clock_hz,
                c.bitrate,
                c.mode,
                c.policy,
                c.k,
                i32::from(c.dual_tx),
                c.stall_limit,
                c.recovery_bits,
                c.dedup_window,
                c.int_enable,
            )
        }
    }

    /// `drcc_configure` in normal mode with single-shot transmission; the C
    /// result code.
    pub fn configure_single_shot(&mut self, clock_hz: u32, bitrate: u32, int_enable: u32) -> i32 {
        // SAFETY: dev is live.
        unsafe { sim_c_configure_single_shot(self.dev, clock_hz, bitrate, int_enable) }
    }

    /// `drcc_send`; the C result code.
    pub fn send(&mut self, frame: &CFrame, queue: u32) -> i32 {
        // SAFETY: dev is live, frame a valid drcc_frame.
        unsafe { drcc_send(self.dev, frame, queue) }
    }

    /// `drcc_receive`; the frame, or the C result code.
    pub fn receive(&mut self) -> Result<CFrame, i32> {
        let mut f = CFrame::default();
        // SAFETY: dev is live, f a valid drcc_frame.
        match unsafe { drcc_receive(self.dev, &mut f) } {
            0 => Ok(f),
            rc => Err(rc),
        }
    }

    /// `drcc_isr` into `buf`.
    pub fn isr(&mut self, buf: &mut [CFrame]) -> CIrqResult {
        // SAFETY: dev is live; buf holds buf.len() drcc_frames.
        unsafe { drcc_isr(self.dev, buf.as_mut_ptr(), buf.len()) }
    }

    /// (duplicates dropped, channel switches) through `drcc_get_stats`.
    pub fn stats(&mut self) -> (u32, u32) {
        let (mut d, mut s) = (0, 0);
        // SAFETY: dev is live.
        unsafe { sim_c_stats(self.dev, &mut d, &mut s) };
        (d, s)
    }
}

impl Drop for CDriver {
    fn drop(&mut self) {
        // SAFETY: dev came from sim_c_open and is freed once.
        unsafe { sim_c_close(self.dev) }
    }
}

/// `drcc_init` on fake registers whose `VERSION` reads `version` (`ID` reads
/// "DRCC", `SIZES` the default top's); the C result code.
pub fn c_init_with_version(version: u32) -> i32 {
    // SAFETY: plain function on its own fake hooks.
    unsafe { sim_c_init_with_version(version) }
}

/// Which call [`c_call_with_version`] makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CCall {
    /// `drcc_abort(channels)`.
    Abort(u32),
    /// `drcc_recover(channels)`.
    Recover(u32),
    /// `drcc_configure` with `busoff_manual`.
    Configure(bool),
    /// `drcc_configure` in DMR mode with `dmr_first_copy`.
    ConfigureFirstCopy(bool),
}

/// After `drcc_init` on fake registers whose `VERSION` reads `version` and
/// `CTRL` reads `ctrl`: the C result code of `call`, the number of register
/// writes it made and the (offset, value) of the last one ((0, 0) if none).
pub fn c_call_with_version(version: u32, ctrl: u32, call: CCall) -> (i32, u32, (u32, u32)) {
    let (what, arg) = match call {
        CCall::Abort(c) => (0, c),
        CCall::Recover(c) => (1, c),
        CCall::Configure(m) => (2, u32::from(m)),
        CCall::ConfigureFirstCopy(f) => (3, u32::from(f)),
    };
    let mut writes = 0;
    let mut last = [0; 2];
    // SAFETY: plain function on its own fake hooks.
    let rc = unsafe { sim_c_call_with_version(version, ctrl, what, arg, &mut writes, &mut last) };
    (rc, writes, (last[0], last[1]))
}

/// `drcc_calc_bit_timing` of the C driver: the timing or the C result code.
pub fn c_calc_bit_timing(clock_hz: u32, bitrate: u32) -> Result<CBitTiming, i32> {
    let mut t = CBitTiming::default();
    // SAFETY: plain function writing *out.
    match unsafe { drcc_calc_bit_timing(clock_hz, bitrate, &mut t) } {
        0 => Ok(t),
        rc => Err(rc),
    }
}

/// `drcc_btr_encode` of the C driver.
pub fn c_btr_encode(t: &CBitTiming, ewl: u8) -> u32 {
    // SAFETY: plain function reading *bt.
    unsafe { drcc_btr_encode(t, ewl) }
}
