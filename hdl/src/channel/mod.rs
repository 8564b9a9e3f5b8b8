//! One complete ISO 11898-1 classical CAN channel: bus sampling, bit timing
//! logic and the bit stream processor.
/// Width of the baud-rate prescaler BRP (a time quantum is `BRP + 1` clocks,
/// BRP 0..1023): 10 kbit/s at 100 MHz needs BRP 399 (25 tq of 400 clocks), and
/// 1 Mbit/s at 8 MHz BRP 0 (timing contract §1).
pub const BRP_BITS: usize = 10;

pub mod bsp;
pub mod btl;
pub mod bus_sampling;
pub mod can_channel;
pub mod config;
pub mod sized;
