//! The socketcand server loop of `drcc serve`: one thread accepts connections, one
//! reader thread per client splits its bytes into elements, one writer thread per
//! client sends its lines, and the calling thread owns the network: it applies the
//! clients' commands between clocks, steps the network and hands every delivered
//! frame and error frame to the clients that opened that node in raw mode.
//!
//! The network is stepped only by the calling thread, so an engine need not be
//! `Send` (Verilator's is not), and a client's commands take effect in the order
//! they were read.

use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream, UdpSocket};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::Arc;
use std::thread;
use std::time::{Duration, Instant};

use drcc_cosim::traffic::{TrafficEvent, TrafficKind};

use crate::protocol::{self, Command, Framer};
use crate::Network;

/// The socketcand default port.
pub const DEFAULT_PORT: u16 = 29536;

/// The socketcand discovery beacon's UDP port.
pub const BEACON_PORT: u16 = 42000;

/// The interval between two beacons (socketcand: at most 3 s).
pub const BEACON_INTERVAL: Duration = Duration::from_secs(2);

/// After `< ok >` to `< rawmode >`, frames wait this long before they are sent, so
/// that the `< ok >` arrives alone: python-can reads it with one `recv` and
/// compares the whole buffer with `< ok >`.
pub const RAW_GRACE: Duration = Duration::from_millis(100);

/// How simulated time relates to the wall clock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pacing {
    /// As fast as the engine allows.
    Fast,
    /// Simulated time follows the wall clock (as far as the engine keeps up).
    Realtime,
}

/// How the server runs.
#[derive(Clone, Debug)]
pub struct ServeOptions {
    /// Pacing of simulated time.
    pub pacing: Pacing,
    /// Send the discovery beacon.
    pub beacon: bool,
    /// Stop after this much wall time (None: until stopped).
    pub stop_after: Option<Duration>,
    /// Print a status line this often (None: never).
    pub progress: Option<Duration>,
}

/// What one run of the server did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ServeSummary {
    /// Clock cycles stepped.
    pub cycles: u64,
    /// Frames delivered by the nodes.
    pub frames: u64,
    /// Error frames signalled.
    pub errors: u64,
    /// Connections accepted.
    pub clients: u64,
}

/// Binds the server's port; a port in use is refused with a message naming it.
pub fn bind(addr: SocketAddr) -> Result<TcpListener, String> {
    TcpListener::bind(addr).map_err(|e| {
        if e.kind() == std::io::ErrorKind::AddrInUse {
            format!(
                "port {} is already in use on {}: stop the other server or give another \
                 port with --port",
                addr.port(),
                addr.ip()
            )
        } else {
            format!("cannot listen on {addr}: {e}")
        }
    })
}

/// A message from the connection threads to the network's thread.
enum Msg {
    Connected(u64, TcpStream),
    Element(u64, Result<String, String>),
    Gone(u64, usize),
}

/// What a client opened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    NoBus,
    Bcm,
    /// Raw mode since the instant given.
    Raw(Instant),
}

struct Client {
    out: Sender<String>,
    node: Option<usize>,
    mode: Mode,
    /// Lines held during [`RAW_GRACE`].
    held: Vec<String>,
}

impl Client {
    fn say(&self, line: String) {
        let _ = self.out.send(line);
    }
}

fn accept_loop(listener: TcpListener, tx: Sender<Msg>, stop: Arc<AtomicBool>) {
    let _ = listener.set_nonblocking(true);
    let mut next = 0u64;
    while !stop.load(Ordering::Relaxed) {
        match listener.accept() {
            Ok((stream, _)) => {
                let _ = stream.set_nonblocking(false);
                let _ = stream.set_nodelay(true);
                next += 1;
                if tx.send(Msg::Connected(next, stream)).is_err() {
                    return;
                }
            }
            Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => {
                thread::sleep(Duration::from_millis(5));
            }
            Err(_) => thread::sleep(Duration::from_millis(5)),
        }
    }
}

fn reader(id: u64, mut stream: TcpStream, tx: Sender<Msg>) {
    let mut framer = Framer::default();
    let mut buf = [0u8; 4096];
    loop {
        match stream.read(&mut buf) {
            Ok(0) | Err(_) => {
                let _ = tx.send(Msg::Gone(id, framer.pending()));
                return;
            }
            Ok(k) => {
                for e in framer.push(&buf[..k]) {
                    if tx.send(Msg::Element(id, e)).is_err() {
                        return;
                    }
                }
            }
        }
    }
}

fn writer(mut stream: TcpStream, rx: Receiver<String>) {
    for line in rx {
        if stream.write_all(line.as_bytes()).is_err() {
            return;
        }
    }
    let _ = stream.shutdown(std::net::Shutdown::Both);
}

/// The beacon text (socketcand's `CANBeacon` XML) for `buses` at `url`.
pub fn beacon_text(buses: &[String], url: &str) -> String {
    let mut s = format!(
        "<CANBeacon name=\"drcc\" type=\"SocketCAN\" description=\"drcc serve: a \
         simulated CAN network\"><URL>{url}</URL>"
    );
    for b in buses {
        s.push_str(&format!("<Bus name=\"{b}\"/>"));
    }
    s.push_str("</CANBeacon>");
    s
}

/// Sends the beacon every [`BEACON_INTERVAL`]: to 127.0.0.1 when the server
/// listens on a loopback address (the only place its URL works), else as a
/// broadcast on the local network.
fn beacon_loop(text: String, local: SocketAddr, stop: Arc<AtomicBool>) {
    let Ok(sock) = UdpSocket::bind("0.0.0.0:0") else {
        eprintln!("drcc serve: cannot open a UDP socket for the beacon; no beacon sent");
        return;
    };
    let to: SocketAddr = if local.ip().is_loopback() {
        SocketAddr::from(([127, 0, 0, 1], BEACON_PORT))
    } else {
        let _ = sock.set_broadcast(true);
        SocketAddr::from(([255, 255, 255, 255], BEACON_PORT))
    };
    let mut last: Option<Instant> = None;
    while !stop.load(Ordering::Relaxed) {
        if last.is_none_or(|t| t.elapsed() >= BEACON_INTERVAL) {
            let _ = sock.send_to(text.as_bytes(), to);
            last = Some(Instant::now());
        }
        thread::sleep(Duration::from_millis(50));
    }
}

/// The network's side of the server.
struct Hub<'a> {
    net: &'a mut dyn Network,
    clients: BTreeMap<u64, Client>,
    summary: ServeSummary,
}

impl Hub<'_> {
    fn time_ns(&self, cycle: u64) -> u64 {
        (cycle as u128 * 1_000_000_000 / self.net.clock_hz() as u128) as u64
    }

    fn handle(&mut self, msg: Msg) {
        match msg {
            Msg::Connected(id, stream) => {
                let (out, rx) = channel();
                let Ok(w) = stream.try_clone() else {
                    return;
                };
                thread::spawn(move || writer(w, rx));
                let _ = out.send("< hi >".to_string());
                self.clients.insert(
                    id,
                    Client {
                        out,
                        node: None,
                        mode: Mode::NoBus,
                        held: Vec::new(),
                    },
                );
                self.summary.clients += 1;
            }
            Msg::Gone(id, pending) => {
                if pending > 0 {
                    eprintln!(
                        "drcc serve: client {id} closed in the middle of an element ({pending} \
                         bytes dropped)"
                    );
                }
                self.clients.remove(&id);
            }
            Msg::Element(id, Err(why)) => {
                if let Some(c) = self.clients.get(&id) {
                    c.say(protocol::refusal(&why));
                }
            }
            Msg::Element(id, Ok(text)) => {
                let answer = match protocol::parse(&text) {
                    Ok(cmd) => self.command(id, cmd),
                    Err(why) => Err(why),
                };
                if let (Some(c), Some(line)) = (
                    self.clients.get(&id),
                    answer.unwrap_or_else(|why| Some(protocol::refusal(&why))),
                ) {
                    c.say(line);
                }
            }
        }
    }

    /// Applies one command; returns the answer line, if any.
    fn command(&mut self, id: u64, cmd: Command) -> Result<Option<String>, String> {
        let names = self.net.names().to_vec();
        let Some(c) = self.clients.get_mut(&id) else {
            return Ok(None);
        };
        let ok = Ok(Some("< ok >".to_string()));
        match cmd {
            Command::Echo => Ok(Some("< echo >".to_string())),
            Command::Open(bus) => {
                if c.node.is_some() {
                    return Err("a bus is open already: one bus per connection".into());
                }
                let node = names.iter().position(|n| *n == bus).ok_or_else(|| {
                    format!(
                        "unknown bus `{}`: the buses are {}",
                        protocol::printable(&bus),
                        names.join(", ")
                    )
                })?;
                c.node = Some(node);
                c.mode = Mode::Bcm;
                ok
            }
            Command::RawMode | Command::BcmMode if c.node.is_none() => {
                Err("open a bus first: `open node0`".into())
            }
            Command::RawMode => {
                c.mode = Mode::Raw(Instant::now());
                ok
            }
            Command::BcmMode => {
                c.mode = Mode::Bcm;
                c.held.clear();
                ok
            }
            Command::Send(frame) => {
                let node = c.node.ok_or("open a bus first: `open node0`".to_string())?;
                self.net.send(node, frame)?;
                Ok(None)
            }
            Command::Fault(args) => {
                let done = self.net.fault(&args)?;
                eprintln!(
                    "drcc serve: {} s: fault: {done}",
                    protocol::timestamp(self.time_ns(self.net.cycle()))
                );
                ok
            }
        }
    }

    /// Hands the events to the raw-mode clients of their node.
    fn dispatch(&mut self, events: &[TrafficEvent]) {
        for ev in events {
            let t = self.time_ns(ev.cycle);
            let line = match &ev.kind {
                TrafficKind::Frame(f) => {
                    self.summary.frames += 1;
                    protocol::frame_line(f, t)
                }
                TrafficKind::Error(e) => {
                    self.summary.errors += 1;
                    protocol::error_line(e.can_id, t)
                }
            };
            for c in self.clients.values_mut() {
                if c.node != Some(ev.node) {
                    continue;
                }
                if let Mode::Raw(since) = c.mode {
                    if since.elapsed() < RAW_GRACE {
                        c.held.push(line.clone());
                    } else {
                        c.say(line.clone());
                    }
                }
            }
        }
    }

    /// Sends the lines held during a client's raw-mode grace once it is over.
    fn release_held(&mut self) {
        for c in self.clients.values_mut() {
            if let Mode::Raw(since) = c.mode {
                if !c.held.is_empty() && since.elapsed() >= RAW_GRACE {
                    for line in std::mem::take(&mut c.held) {
                        let _ = c.out.send(line);
                    }
                }
            }
        }
    }
}

/// Serves `net` on `listener` until `stop` is set (or `opts.stop_after` passed);
/// `sink` sees every event, in batches (the traffic export). Clocks are stepped one bit time at
/// a time, and the clients' commands applied between them.
pub fn serve(
    net: &mut dyn Network,
    listener: TcpListener,
    opts: &ServeOptions,
    stop: Arc<AtomicBool>,
    mut sink: impl FnMut(&[TrafficEvent]) -> Result<(), String>,
) -> Result<ServeSummary, String> {
    let local = listener
        .local_addr()
        .map_err(|e| format!("cannot read the listening address: {e}"))?;
    let (tx, rx) = channel::<Msg>();
    let mut threads = Vec::new();
    {
        let tx = tx.clone();
        let stop = stop.clone();
        threads.push(thread::spawn(move || accept_loop(listener, tx, stop)));
    }
    if opts.beacon {
        let text = beacon_text(net.names(), &format!("can://{local}"));
        let stop = stop.clone();
        threads.push(thread::spawn(move || beacon_loop(text, local, stop)));
    }
    // Readers get their own sender per connection, made from this one.
    let reader_tx = tx;
    let mut hub = Hub {
        net,
        clients: BTreeMap::new(),
        summary: ServeSummary::default(),
    };
    let started = Instant::now();
    let sim_start = hub.net.cycle();
    let mut last_progress = Instant::now();
    let mut warned_slow = false;
    let mut events = Vec::new();
    let batch = hub.net.clocks_per_bit().max(1);
    let result = loop {
        if stop.load(Ordering::Relaxed) || opts.stop_after.is_some_and(|d| started.elapsed() >= d) {
            break Ok(());
        }
        // Running fast with no client connected, nothing can be observed: wait for
        // one (in real time the clock runs on, as it would on a real bus).
        let first = if hub.clients.is_empty() && opts.pacing == Pacing::Fast {
            match rx.recv_timeout(Duration::from_millis(50)) {
                Ok(m) => Some(m),
                Err(RecvTimeoutError::Timeout) => continue,
                Err(RecvTimeoutError::Disconnected) => break Ok(()),
            }
        } else {
            None
        };
        for msg in first.into_iter().chain(rx.try_iter()) {
            if let Msg::Connected(id, stream) = &msg {
                if let Ok(r) = stream.try_clone() {
                    let (id, tx) = (*id, reader_tx.clone());
                    thread::spawn(move || reader(id, r, tx));
                }
            }
            hub.handle(msg);
        }
        for _ in 0..batch {
            hub.net.step();
        }
        events.clear();
        hub.net.poll(&mut events);
        if !events.is_empty() {
            if let Err(e) = sink(&events) {
                break Err(e);
            }
        }
        hub.dispatch(&events);
        hub.release_held();
        let sim_ns = hub.time_ns(hub.net.cycle() - sim_start);
        if opts.pacing == Pacing::Realtime {
            let wall_ns = started.elapsed().as_nanos() as u64;
            if sim_ns > wall_ns {
                thread::sleep(Duration::from_nanos((sim_ns - wall_ns).min(50_000_000)));
            } else if wall_ns - sim_ns > 500_000_000 && !warned_slow {
                warned_slow = true;
                eprintln!(
                    "drcc serve: the engine is slower than real time ({:.0} % of it): \
                     simulated time falls behind the wall clock",
                    100.0 * sim_ns as f64 / wall_ns as f64
                );
            }
        }
        if let Some(every) = opts.progress {
            if last_progress.elapsed() >= every {
                last_progress = Instant::now();
                eprintln!(
                    "drcc serve: {} s simulated, {} frames delivered, {} error frames, {} \
                     clients connected",
                    protocol::timestamp(sim_ns),
                    hub.summary.frames,
                    hub.summary.errors,
                    hub.clients.len()
                );
            }
        }
    };
    stop.store(true, Ordering::Relaxed);
    hub.summary.cycles = hub.net.cycle() - sim_start;
    let summary = hub.summary.clone();
    drop(hub);
    for t in threads {
        let _ = t.join();
    }
    result.map(|()| summary)
}
