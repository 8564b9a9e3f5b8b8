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
}

type Read32 = extern "C" fn(*mut c_void, u32) -> u32;
type Write32 = extern "C" fn(*mut c_void, u32, u32);

extern "C" {
    fn sim_c_open(read32: Read32, write32: Write32, ctx: *mut c_void, rc: *mut i32) -> *mut c_void;
    fn sim_c_close(dev: *mut c_void);
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

impl CDriver {
    /// `drcc_init` on `port`; the C result code on failure.
    pub fn open(port: NodePort) -> Result<CDriver, i32> {
        let port = Box::new(port);
        let ctx = &*port as *const NodePort as *mut c_void;
        let mut rc = 0;
        // SAFETY: the hooks and ctx stay valid as long as the returned CDriver.
        let dev = unsafe { sim_c_open(read_hook, write_hook, ctx, &mut rc) };
        if dev.is_null() {
            return Err(rc);
        }
        Ok(CDriver { dev, _port: port })
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
