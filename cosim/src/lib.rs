//! drcc-cosim: everything that runs a design — the reference model, the engines,
//! the bus, co-simulation and traces.

pub mod bus;
pub mod cosim;
pub mod dual;
pub mod engine;
pub mod frame;
pub mod host;
pub mod model;
pub mod ring;
pub mod star;
pub mod system;
pub mod trace;
pub mod traffic;

pub use engine::{
    BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs, ControllerConfig, Diagnostics, Mode,
    Probes,
};
pub use frame::Frame;
