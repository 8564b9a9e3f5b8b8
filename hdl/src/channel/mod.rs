//! One complete ISO 11898-1 classical CAN channel: bus sampling, bit timing
//! logic and the bit stream processor.
pub mod bsp;
pub mod btl;
pub mod bus_sampling;
pub mod can_channel;
pub mod config;
pub mod sized;
