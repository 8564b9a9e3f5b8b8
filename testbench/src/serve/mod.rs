//! `drcc serve`: a simulated CAN network exposed over the socketcand protocol, so
//! that python-can scripts, cantools, SavvyCAN, Kayak and anything else that speaks
//! socketcand can use it as they would a remote SocketCAN host.
//!
//! - [`protocol`]: the socketcand commands and lines (server side);
//! - [`network`]: the networks served (a scenario's bus of channels, a dual bus of
//!   DRCC nodes, a replicated star) behind one interface;
//! - [`server`]: the TCP server, its threads and the pacing of simulated time.
//!
//! Each node of the network is a bus a client opens by the node's name. docs/serve.md
//! is the user's description (conventions, the `fault` extension, pacing).

pub mod network;
pub mod protocol;
pub mod server;

pub use network::{BusNetwork, DualNetwork, Network, StarNetwork};
pub use server::{bind, serve, Pacing, ServeOptions, ServeSummary, DEFAULT_PORT};
