//! # drcc-serve
//!
//! `drcc serve`'s server: a simulated CAN network exposed over the socketcand
//! protocol, so that python-can scripts, cantools, SavvyCAN, Kayak and anything
//! else that speaks socketcand can use it as they would a remote SocketCAN host.
//!
//! - [`Network`]: what the server needs of a simulated network;
//! - [`protocol`]: the socketcand commands and lines (server side);
//! - [`server`]: the TCP server, its threads and the pacing of simulated time.
//!
//! Each node of the network is a bus a client opens by the node's name.
//! `docs/serve.md` is the user's description (conventions, the `fault`
//! extension, pacing); the networks `drcc serve` builds are in the testbench's
//! `served` module.

pub mod protocol;
pub mod server;

use drcc_cosim::traffic::TrafficEvent;
use drcc_cosim::Frame;

pub use server::{bind, serve, Pacing, ServeOptions, ServeSummary, DEFAULT_PORT};

/// A simulated network a server steps and clients use.
pub trait Network {
    /// The node names, which are the bus names clients open.
    fn names(&self) -> &[String];
    /// The clock of every node, in Hz (time = cycle / clock).
    fn clock_hz(&self) -> u64;
    /// Clock cycles stepped so far.
    fn cycle(&self) -> u64;
    /// Clock cycles per bit time.
    fn clocks_per_bit(&self) -> u64;
    /// One clock for the whole network.
    fn step(&mut self);
    /// Node `node` transmits `frame` as soon as it can.
    fn send(&mut self, node: usize, frame: Frame) -> Result<(), String>;
    /// Appends what the nodes delivered since the last call, in order.
    fn poll(&mut self, out: &mut Vec<TrafficEvent>);
    /// Applies a `< fault ... >` command now; returns what was done.
    fn fault(&mut self, args: &[String]) -> Result<String, String>;
    /// One line naming the topology and the engine.
    fn describe(&self) -> String;
}
