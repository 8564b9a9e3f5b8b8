//! The software of each ring node's host, polled once per bit time: ring node 0
//! runs the King (the Capital of seed 002), then, once the kingdom runs, the
//! REDCAN master (centralized) or a distributed node; every other node runs a
//! City's Mayor, and on a ring node the REDCAN slave or a distributed node. The
//! algorithms are the `redcan` crate's; they reach the DRCC through the
//! CanKingdom adapter of `post`.

use super::app::RingState;
use super::post::{CkFrame, DrccPost};
use super::{ean_of, Algorithm, RingReport, APP_BASE, MS};
use cankingdom::king::{ExpectedCity, KingPhase, Membership};
use cankingdom::king_pages::Action;
use cankingdom::{Envelope, King, KingConfig, Mayor, MayorConfig};
use drcc_cosim::Frame;
use redcan::central::{self, CentralTiming, Master, Slave, BASE};
use redcan::distributed::{DistNode, DistTiming};

/// What every host's algorithm is run with.
pub(super) struct Hosts {
    /// Which REDCAN algorithm the ring runs.
    pub algorithm: Algorithm,
    /// Ring nodes (`0..n`) and all nodes (`n..total` are the plain nodes).
    pub n: usize,
    pub total: usize,
    /// The centralized algorithm's times.
    pub central: CentralTiming,
    /// The distributed algorithm's times.
    pub dist: DistTiming,
}

/// The Capital's King behind one object type (its City count is a const generic).
pub(super) trait Capital {
    fn poll(&mut self, now: u64, post: &mut DrccPost, other: &mut dyn FnMut(&CkFrame));
    fn phase(&self) -> KingPhase;
    fn membership(&self) -> Membership;
}

impl<const N: usize> Capital for King<N> {
    fn poll(&mut self, now: u64, post: &mut DrccPost, other: &mut dyn FnMut(&CkFrame)) {
        self.poll_with(now, post, |f| other(f));
    }
    fn phase(&self) -> KingPhase {
        King::phase(self)
    }
    fn membership(&self) -> Membership {
        King::membership(self)
    }
}

fn capital(cities: &[ExpectedCity]) -> Result<Box<dyn Capital>, String> {
    let base = Envelope::standard(BASE).expect("an 11-bit base");
    macro_rules! kings {
        ($($n:literal)*) => {
            match cities.len() {
                $($n => {
                    let c: [ExpectedCity; $n] = cities.try_into().expect("length checked");
                    Ok(Box::new(King::<$n>::new(KingConfig::new(c, base)).map_err(|e| format!("{e:?}"))?))
                })*
                n => Err(format!("a kingdom of {n} Cities: the ring runs 2..=40")),
            }
        };
    }
    kings!(2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 36 37 38 39 40)
}

/// One node's software.
pub(super) enum App {
    /// Ring node 0: the King, then the REDCAN master.
    King {
        king: Box<dyn Capital>,
        master: Option<Master<CkFrame>>,
        dist: Option<DistNode<CkFrame>>,
    },
    /// A City: its Mayor, and on a ring node the REDCAN slave.
    City {
        mayor: Box<Mayor>,
        slave: Option<Slave>,
        dist: Option<DistNode<CkFrame>>,
        ring: bool,
    },
}

/// The hosts' software at power-up: the King on node 0 (expecting every other
/// node as a City), a Mayor on every other node (the ring nodes in the ring
/// group of the heartbeat).
pub(super) fn host_apps(h: &Hosts) -> Result<Vec<App>, String> {
    let cities: Vec<ExpectedCity> = (1..h.total)
        .map(|i| ExpectedCity {
            address: i as u8,
            ean: ean_of(i as u8),
        })
        .collect();
    let mut apps: Vec<App> = Vec::with_capacity(h.total);
    apps.push(App::King {
        king: capital(&cities)?,
        master: None,
        dist: None,
    });
    for i in 1..h.total {
        let mut cfg = MayorConfig::new(i as u8, ean_of(i as u8), 1000 + i as u64);
        cfg.king_envelope = Envelope::standard(central::KING_ENVELOPE).expect("0");
        if i < h.n {
            cfg.groups[0] = central::RING_GROUP;
        }
        apps.push(App::City {
            mayor: Box::new(Mayor::new(cfg).map_err(|e| format!("{e:?}"))?),
            slave: None,
            dist: None,
            ring: i < h.n,
        });
    }
    Ok(apps)
}

impl App {
    /// One poll of node `i`'s host at `now`: the CanKingdom side, then the REDCAN
    /// algorithm once it runs, with the frames received since the last poll; the
    /// detection and the kingdom's start go into `report`. Returns the RCM command
    /// to write, if any.
    pub(super) fn poll(
        &mut self,
        i: usize,
        now: u64,
        post: &mut DrccPost,
        h: &Hosts,
        report: &mut RingReport,
    ) -> Result<Option<u8>, String> {
        let mut other: Vec<Frame> = Vec::new();
        Ok(match self {
            App::King { dist: Some(d), .. } => {
                while let Ok(f) = embedded_can::nb::Can::receive(post) {
                    other.push(f.0);
                }
                dist_step(d, now, &other, post, i, report)
            }
            App::King { king, master, dist } => {
                if let Some(m) = master {
                    while let Ok(f) = embedded_can::nb::Can::receive(post) {
                        other.push(f.0);
                    }
                    m.poll(now, &letters(&other));
                    // The flush first: the poll's letters are for the side the
                    // relay is still on.
                    if std::mem::take(&mut m.flush) {
                        post.flush();
                    }
                    for f in m.outbox.drain(..) {
                        post.host.submit(now, f.0, 0);
                    }
                    if let Some(t) = m.detected_at {
                        report.detected.get_or_insert((i, t));
                    }
                    m.command.take()
                } else {
                    king.poll(now, post, &mut |f| other.push(f.0));
                    match king.phase() {
                        KingPhase::Running if king.membership() == Membership::Agreed => {
                            report.kingdom_at.get_or_insert(now);
                            match h.algorithm {
                                Algorithm::Centralized => {
                                    *master = Some(Master::new(
                                        h.n,
                                        h.total - 1,
                                        APP_BASE,
                                        h.central,
                                        now + 10 * MS,
                                    ))
                                }
                                Algorithm::Distributed => {
                                    *dist = Some(DistNode::new(
                                        0,
                                        h.n,
                                        h.total,
                                        APP_BASE,
                                        h.dist,
                                        now + 10 * MS,
                                    ))
                                }
                            }
                        }
                        KingPhase::Halted => {
                            return Err(format!(
                                "the King's start-up did not agree: {:?}",
                                king.membership()
                            ))
                        }
                        _ => {}
                    }
                    None
                }
            }
            App::City {
                mayor,
                slave,
                dist,
                ring,
            } => {
                mayor.poll_with(now, post, |f| other.push(f.0));
                let started = slave.is_some() || dist.is_some();
                if *ring && !started && mayor.action() == Some(Action::Run) {
                    match h.algorithm {
                        Algorithm::Centralized => {
                            *slave = Some(Slave::new(i as u8, h.central, now))
                        }
                        Algorithm::Distributed => {
                            *dist = Some(DistNode::new(i, h.n, h.total, APP_BASE, h.dist, now))
                        }
                    }
                }
                if let Some(d) = dist {
                    dist_step(d, now, &other, post, i, report)
                } else if let Some(sl) = slave {
                    sl.poll(now, mayor, &letters(&other));
                    if std::mem::take(&mut sl.flush) {
                        post.flush();
                    }
                    if let Some(t) = sl.detected_at {
                        if report.detected.is_none_or(|(_, d)| t < d) {
                            report.detected = Some((i, t));
                        }
                    }
                    sl.command.take()
                } else {
                    None
                }
            }
        })
    }
}

/// What a node's REDCAN says of its application frames (`app`).
pub(super) fn ring_state(app: &App) -> RingState {
    let (master, slave, dist) = match app {
        App::King { master, dist, .. } => (master.as_ref(), None, dist.as_ref()),
        App::City { slave, dist, .. } => (None, slave.as_ref(), dist.as_ref()),
    };
    let rebuilding = master.is_some_and(|m| !m.running())
        || slave.is_some_and(|s| !s.running())
        || dist.is_some_and(|d| !d.settled());
    if rebuilding {
        RingState::Rebuilding
    } else if master.is_some() || slave.is_some() || dist.is_some() {
        RingState::Settled
    } else {
        RingState::Plain
    }
}

/// One poll of a node's distributed REDCAN: its letters (after a flush when it
/// has just detected), its detection time, its RCM command.
fn dist_step(
    d: &mut DistNode<CkFrame>,
    now: u64,
    rx: &[Frame],
    post: &mut DrccPost,
    i: usize,
    report: &mut RingReport,
) -> Option<u8> {
    d.poll(now, &letters(rx));
    if std::mem::take(&mut d.flush) {
        post.flush();
    }
    for f in d.outbox.drain(..) {
        post.host.submit(now, f.0, 0);
    }
    if let Some(t) = d.detected_at {
        if report.detected.is_none_or(|(_, e)| t < e) {
            report.detected = Some((i, t));
        }
    }
    d.command.take()
}

/// The frames a host received, as the `redcan` algorithms take them.
fn letters(rx: &[Frame]) -> Vec<CkFrame> {
    rx.iter().map(|&f| CkFrame(f)).collect()
}
