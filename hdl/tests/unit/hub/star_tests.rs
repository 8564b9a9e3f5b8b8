//! The two emitted hubs (`Hub4x2` = hub A, `HubB4x2` = hub B) wired into a
//! replicated star in rust-hdl's simulator, with idle nodes: NRAP (hub contract
//! §9) brings both to the same outcome, `RUN` when the interlinks come back and
//! `SPLIT` when they stay cut, and a hub that never saw its twin's forcing joins
//! the twin's exchange. Node 0 of each hub acknowledges every frame (it drives
//! dominant while its hub's tracker is in the ACK slot), the other nodes are
//! silent. These are smoke tests of the RTL's structure; the clock-by-clock check
//! is the lock-step comparison with the reference model.

use drcc_hdl::host::hub_registers::{self as map, NrapPhase};
use drcc_hdl::hub::hub::Hub;
use rust_hdl::prelude::*;

/// One hub, its nodes and its host.
struct Side<const H: usize> {
    uut: Box<Hub<4, 2, 6, H>>,
    /// Node 0 acknowledges every frame.
    acks: bool,
    /// Phases seen, in order (without repetitions).
    phases: Vec<u64>,
}

impl<const H: usize> Side<H> {
    fn new() -> Self {
        let mut uut = Box::<Hub<4, 2, 6, H>>::default();
        uut.connect_all();
        uut.uplink.next = 0xF.into();
        uut.sublink_in.next = 0x3.into();
        Side {
            uut,
            acks: true,
            phases: vec![0],
        }
    }

    /// One clock with these link inputs; node 0 acknowledges if `acks` (from the
    /// outputs before the clock).
    fn clock(&mut self, sublink_in: u64) {
        let u = &mut self.uut;
        let ack_slot = self.acks && u.trk_state.val().to_u64() == 2;
        u.uplink.next = (if ack_slot { 0xE } else { 0xF }).into();
        u.sublink_in.next = sublink_in.into();
        u.clk.next = Clock::from(false);
        assert!(simulate(u.as_mut(), 200));
        u.clk.next = Clock::from(true);
        assert!(simulate(u.as_mut(), 200));
        let p = u.nrap_phase.val().to_u64();
        if *self.phases.last().unwrap() != p {
            self.phases.push(p);
        }
    }

    fn bus(&mut self, we: bool, adr: u32, dat: u32, sublink_in: u64) -> u64 {
        let u = &mut self.uut;
        u.wb_cyc_i.next = true;
        u.wb_stb_i.next = true;
        u.wb_we_i.next = we;
        u.wb_adr_i.next = (adr as u64).into();
        u.wb_dat_i.next = (dat as u64).into();
        u.wb_sel_i.next = 0xF.into();
        self.clock(sublink_in);
        // a refused write ends with ERR instead (bus_contract.md §1)
        assert!(self.uut.wb_ack_o.val() != self.uut.wb_err_o.val());
        let r = self.uut.wb_dat_o.val().to_u64();
        self.uut.wb_cyc_i.next = false;
        self.uut.wb_stb_i.next = false;
        self.uut.wb_we_i.next = false;
        self.clock(sublink_in);
        r
    }
}

/// Hub A and hub B; each direction of the interlinks wired, or cut: stuck at
/// the given level (`Some(0)` dominant, `Some(3)` recessive).
struct Star {
    a: Side<0>,
    b: Side<1>,
    to_a: Option<u64>,
    to_b: Option<u64>,
}

impl Star {
    /// Both hubs out of `rst`, configured (short NRAP times) and running.
    fn new() -> Self {
        let mut s = Star {
            a: Side::new(),
            b: Side::new(),
            to_a: None,
            to_b: None,
        };
        s.a.uut.rst.next = true;
        s.b.uut.rst.next = true;
        s.clock();
        s.a.uut.rst.next = false;
        s.b.uut.rst.next = false;
        let ncfg = 64 | (2 << 12) | (2 << 16) | (2 << 20);
        let ntime = 600 | (600 << 16);
        for (adr, dat) in [
            (map::BTR, BTR),
            (map::NRAP_CFG, ncfg),
            (map::NRAP_TIME, ntime),
            (map::NRAP_DDSP, 300),
            (map::CTRL, 0x300),
        ] {
            s.a.bus(true, adr, dat, 0x3);
            s.b.bus(true, adr, dat, 0x3);
        }
        s
    }

    /// Both directions stuck dominant (`true`) or both wired.
    fn cut(&mut self, cut: bool) {
        let level = if cut { Some(0) } else { None };
        self.to_a = level;
        self.to_b = level;
    }

    /// One clock of both hubs; each one's `sublink_in` is the other's
    /// `sublink_out` of the previous clock, or the level of a cut.
    fn clock(&mut self) {
        let to_a = self
            .to_a
            .unwrap_or_else(|| self.b.uut.sublink_out.val().to_u64());
        let to_b = self
            .to_b
            .unwrap_or_else(|| self.a.uut.sublink_out.val().to_u64());
        self.a.clock(to_a);
        self.b.clock(to_b);
    }

    fn run(&mut self, clocks: usize) {
        for _ in 0..clocks {
            self.clock();
        }
    }

    /// Runs until hub A is in `phase` (at most `clocks`).
    fn until_a(&mut self, phase: NrapPhase, clocks: usize) -> bool {
        for _ in 0..clocks {
            if self.a.uut.nrap_phase.val().to_u64() == phase.code() as u64 {
                return true;
            }
            self.clock();
        }
        false
    }

    /// Runs until both hubs are in `phase` (at most `clocks`).
    fn until(&mut self, phase: NrapPhase, clocks: usize) -> bool {
        for _ in 0..clocks {
            if self.a.uut.nrap_phase.val().to_u64() == phase.code() as u64
                && self.b.uut.nrap_phase.val().to_u64() == phase.code() as u64
            {
                return true;
            }
            self.clock();
        }
        false
    }
}

/// `BTR`: BRP 2, TSEG1 5, TSEG2 2, so 24 clocks per bit and the sample point 18
/// clocks in. An ACK from the twin hub comes back 8 clocks after the bit start
/// (4 edges each way: `sublink_out`, two synchronizers, `coupled_q`), later than
/// the sample point of the reset `BTR` (8 clocks per bit, sampled at 6).
const BTR: u32 = 2 | (4 << 6) | (1 << 10);

/// Clocks per bit with [`BTR`].
const BIT: usize = 24;

fn codes(phases: &[NrapPhase]) -> Vec<u64> {
    phases.iter().map(|p| p.code() as u64).collect()
}

#[test]
fn interlinks_that_come_back_recouple_both_hubs() {
    use NrapPhase::*;
    let mut s = Star::new();
    assert_eq!(s.a.bus(false, map::ID, 0, 0x3), 0x4855_0402);
    assert_eq!(s.b.bus(false, map::ID, 0, 0x3), 0x4855_1402);
    s.run(20 * BIT);
    // both interlinks stuck dominant: each hub isolates its sublinks (rule SD)
    // and starts NRAP; then they are wired again
    s.cut(true);
    assert!(s.until(SrpForce, 40 * BIT));
    s.cut(false);
    assert!(
        s.until(Run, 3000 * BIT),
        "a: {:?} b: {:?}",
        s.a.phases,
        s.b.phases
    );
    let path = codes(&[Run, SrpForce, SrpExchange, Nrp, Run]);
    assert_eq!(s.a.phases, path);
    assert_eq!(s.b.phases, path);
    for (name, st) in [
        ("a", s.a.bus(false, map::NRAP_STATUS, 0, 0x3)),
        ("b", s.b.bus(false, map::NRAP_STATUS, 0, 0x3)),
    ] {
        assert_eq!(st & 0xFF, 0x18, "{name}: RUN, outcome 1, one run");
    }
    // coupled again: every port of both hubs enabled (the silent nodes too),
    // not decoupled
    s.run(4);
    assert_eq!(s.a.uut.port_enabled.val().to_u64(), 0x3F);
    assert_eq!(s.b.uut.port_enabled.val().to_u64(), 0x3F);
    assert!(!s.a.uut.decoupled.val() && !s.b.uut.decoupled.val());
    // INT_STATUS.nrap was raised
    assert_ne!(s.a.bus(false, map::INT_STATUS, 0, 0x3) & 0x20, 0);
}

#[test]
fn interlinks_that_stay_cut_split_both_hubs() {
    use NrapPhase::*;
    let mut s = Star::new();
    s.run(20 * BIT);
    s.cut(true);
    assert!(
        s.until(Split, 3000 * BIT),
        "a: {:?} b: {:?}",
        s.a.phases,
        s.b.phases
    );
    let path = codes(&[Run, SrpForce, SrpExchange, DdspForce, DdspSend, Split]);
    assert_eq!(s.a.phases, path);
    assert_eq!(s.b.phases, path);
    assert!(s.a.uut.decoupled.val() && s.b.uut.decoupled.val());
    // each star keeps its nodes
    assert_eq!(s.a.uut.port_enabled.val().to_u64() & 0xF, 0xF);
    assert_eq!(s.b.uut.port_enabled.val().to_u64() & 0xF, 0xF);
    // a hub that decided on definitive decoupling keeps its sublinks recessive
    assert_eq!(s.a.uut.sublink_out.val().to_u64(), 0x3);
    let st = s.a.bus(false, map::NRAP_STATUS, 0, 0);
    assert_eq!(st & 0xFF, 0x16, "SPLIT, outcome 0, one run");
    // CTRL.recouple ends SPLIT in RUN
    s.cut(false);
    s.a.bus(true, map::CTRL, 0x304, 0x3);
    assert_eq!(s.a.uut.nrap_phase.val().to_u64(), Run.code() as u64);
    assert!(!s.a.uut.decoupled.val());
    // a command given in SPLIT leaves `outcome`
    let st = s.a.bus(false, map::NRAP_STATUS, 0, 0x3);
    assert_eq!(st & 0xFF, 0x10, "RUN, outcome 0, one run");
}

/// §9.2: a command that ends an active phase sets `outcome` (`recouple` → 1,
/// `force_decouple` → 0).
#[test]
fn a_command_that_ends_nrap_sets_the_outcome() {
    use NrapPhase::*;
    let mut s = Star::new();
    s.run(20 * BIT);
    s.cut(true);
    assert!(s.until(SrpExchange, 400 * BIT));
    s.a.bus(true, map::CTRL, 0x304, 0);
    s.b.bus(true, map::CTRL, 0x302, 0);
    let a = s.a.bus(false, map::NRAP_STATUS, 0, 0);
    let b = s.b.bus(false, map::NRAP_STATUS, 0, 0);
    assert_eq!(a & 0xFF, 0x18, "a: RUN, outcome 1, one run");
    assert_eq!(b & 0xFF, 0x16, "b: SPLIT, outcome 0, one run");
}

/// Only B -> A fails (stuck dominant): A isolates its sublinks and forces, but
/// its forcing never reaches B (A -> B stuck recessive), so B stays in `RUN`;
/// when the interlinks come back B joins at the ACK slot of A's identification
/// frame (§9.2 Joining). Its ports stay as they are, and that ACK slot counts for
/// the pairs as in `SRP_EXCHANGE`: with B's nodes acknowledging it (they are
/// coupled in `RUN`), B's `half` is set like A's, so both hubs count the same
/// pairs and end `NRP` at the ACK slot of the same frame of hub B; without an
/// acknowledgement from B's nodes both hubs see the bus acknowledgement of A's
/// node 0 alike.
fn missed_forcing_joins(b_acks: bool) {
    use NrapPhase::*;
    let mut s = Star::new();
    s.b.acks = b_acks;
    s.run(20 * BIT);
    s.to_a = Some(0);
    s.to_b = Some(3);
    assert!(s.until_a(SrpExchange, 400 * BIT));
    assert_eq!(s.b.phases, codes(&[Run]));
    // the interlinks come back: B hears A's identification frame and joins,
    // keeping its ports
    s.cut(false);
    let before = s.b.uut.port_enabled.val().to_u64();
    let mut joined = false;
    let mut ends = [None, None];
    for t in 0..3000 * BIT {
        let pb = s.b.uut.nrap_phase.val().to_u64();
        if !joined && pb == SrpExchange.code() as u64 {
            joined = true;
            assert_eq!(s.b.uut.port_enabled.val().to_u64(), before, "ports kept");
        }
        let sides = [
            (s.a.uut.nrap_phase.val().to_u64(), s.a.phases.len()),
            (pb, s.b.phases.len()),
        ];
        for (k, (p, seen)) in sides.into_iter().enumerate() {
            // back in RUN after NRAP
            if ends[k].is_none() && p == Run.code() as u64 && seen > 1 {
                ends[k] = Some(t);
            }
        }
        if ends.iter().all(Option::is_some) {
            break;
        }
        s.clock();
    }
    assert!(joined);
    assert_eq!(
        s.a.phases,
        codes(&[Run, SrpForce, SrpExchange, Nrp, Run]),
        "a: {:?} b: {:?}",
        s.a.phases,
        s.b.phases
    );
    assert_eq!(s.b.phases, codes(&[Run, SrpExchange, Nrp, Run]));
    // both end NRP at the ACK slot of the same frame (a few clocks of link delay
    // apart, far less than a frame)
    let (ta, tb) = (ends[0].unwrap(), ends[1].unwrap());
    assert!(ta.abs_diff(tb) < BIT, "a ends at {ta}, b at {tb}");
    let st = s.b.bus(false, map::NRAP_STATUS, 0, 0x3);
    assert_eq!(st & 0xFF, 0x18, "RUN, outcome 1, one run");
    s.run(4);
    assert_eq!(s.a.uut.port_enabled.val().to_u64(), 0x3F);
    assert_eq!(s.b.uut.port_enabled.val().to_u64(), 0x3F);
}

#[test]
fn a_hub_that_missed_the_forcing_joins_the_exchange() {
    missed_forcing_joins(false);
}

/// The half-pair skew of the first NRAP RTL: B's own nodes acknowledge A's frame
/// at B's joining ACK slot.
#[test]
fn a_joining_hub_counts_the_joining_frame_for_the_pairs() {
    missed_forcing_joins(true);
}

/// §8 / §9.5: the NRAP registers take writes only in reset mode, with their
/// clamps; `NRAP_STATUS` is read-only; `CTRL.nrap_on` is cfg.
#[test]
fn nrap_registers_clamp_and_refuse() {
    let mut a = Side::<0>::new();
    a.uut.rst.next = true;
    a.clock(0x3);
    a.uut.rst.next = false;
    let read = |a: &mut Side<0>, adr: u32| a.bus(false, adr, 0, 0x3);
    // reset values
    assert_eq!(
        read(&mut a, map::NRAP_CFG),
        64 | (2 << 12) | (2 << 16) | (8 << 20)
    );
    assert_eq!(read(&mut a, map::NRAP_TIME), 1024 | (1024 << 16));
    assert_eq!(read(&mut a, map::NRAP_DDSP), 1024 | (16 << 16));
    assert_eq!(read(&mut a, map::CTRL), 0x301);
    // clamps (reset mode)
    a.bus(true, map::NRAP_CFG, 0, 0x3);
    assert_eq!(
        read(&mut a, map::NRAP_CFG),
        64 | (1 << 12) | (1 << 16) | (1 << 20)
    );
    a.bus(true, map::NRAP_CFG, 63 | (15 << 12), 0x3);
    assert_eq!(
        read(&mut a, map::NRAP_CFG),
        64 | (15 << 12) | (1 << 16) | (1 << 20)
    );
    a.bus(true, map::NRAP_CFG, 1023 | (3 << 16) | (9 << 20), 0x3);
    assert_eq!(
        read(&mut a, map::NRAP_CFG),
        1023 | (1 << 12) | (3 << 16) | (9 << 20)
    );
    a.bus(true, map::NRAP_TIME, 255 | (256 << 16), 0x3);
    assert_eq!(read(&mut a, map::NRAP_TIME), 256 | (256 << 16));
    for (block, stored) in [(0, 0), (1, 4), (3, 4), (4, 4), (31, 31)] {
        a.bus(true, map::NRAP_DDSP, 7 | (block << 16), 0x3);
        assert_eq!(read(&mut a, map::NRAP_DDSP), 256 | (stored << 16));
    }
    // nrap_on is cfg: taken in reset mode, refused (illegal) outside it
    a.bus(true, map::CTRL, 0x101, 0x3);
    assert_eq!(read(&mut a, map::CTRL), 0x101);
    a.bus(true, map::CTRL, 0x100, 0x3);
    assert_eq!(read(&mut a, map::INT_STATUS) & 0x8, 0);
    a.bus(true, map::CTRL, 0x300, 0x3);
    assert_eq!(
        read(&mut a, map::CTRL),
        0x100,
        "nrap_on changed outside reset mode"
    );
    assert_ne!(read(&mut a, map::INT_STATUS) & 0x8, 0, "illegal");
    a.bus(true, map::INT_STATUS, 0x3F, 0x3);
    // outside reset mode the cfg registers and NRAP_STATUS refuse writes
    for adr in [
        map::NRAP_CFG,
        map::NRAP_TIME,
        map::NRAP_DDSP,
        map::NRAP_STATUS,
    ] {
        let before = read(&mut a, adr);
        a.bus(true, adr, 0xFFFF_FFFF, 0x3);
        assert_eq!(read(&mut a, adr), before);
        assert_ne!(read(&mut a, map::INT_STATUS) & 0x8, 0, "illegal");
        a.bus(true, map::INT_STATUS, 0x3F, 0x3);
    }
    // force_decouple with NRAP off: decoupled, the phase stays RUN
    a.bus(true, map::CTRL, 0x102, 0x3);
    assert!(a.uut.decoupled.val());
    assert_eq!(a.uut.nrap_phase.val().to_u64(), 0);
}
