//! The electrical abstraction of a REDCAN ring (`ring_contract.md` §1): bus
//! sections as wired-AND lines, relays joining them, terminations making bus ends,
//! and the section faults of §3. It knows nothing of controllers: it maps the
//! relay states in force and the nodes' `tx` to what every node reads, and judges
//! whether a bus is well formed.
//!
//! Geometry: ring node `i` sits between section `i - 1` (its left) and section `i`
//! (its right), indices mod N. Section `s` holds `plain[s]` plain nodes; an open
//! circuit at point `p` of section `s` (after its `p`-th plain node) cuts it into a
//! left piece (towards ring node `s`) and a right piece (towards ring node `s + 1`).

/// The relay state of one RCM as applied to the wires (its contacts).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Relay {
    /// Relay closed: left and right sections joined, the node on them.
    Transparent,
    /// Relay open, the node on the left section (Fig. 4).
    Left,
    /// Relay open, the node on the right section.
    Right,
}

impl Relay {
    /// From the RCM's `mode` output (1 left, 2 right, 3 transparent).
    pub fn from_mode(mode: u8) -> Relay {
        match mode {
            1 => Relay::Left,
            2 => Relay::Right,
            _ => Relay::Transparent,
        }
    }
}

/// The shape of a ring: `plain[s]` plain nodes on section `s`; the ring has
/// `plain.len()` ring nodes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shape {
    /// Plain nodes per section.
    pub plain: Vec<usize>,
}

impl Shape {
    /// Ring nodes (= sections).
    pub fn ring_nodes(&self) -> usize {
        self.plain.len()
    }

    /// All nodes: ring nodes `0..N`, then the plain nodes section by section.
    pub fn nodes(&self) -> usize {
        self.plain.len() + self.plain.iter().sum::<usize>()
    }

    /// Node index of plain node `k` of section `s`.
    pub fn plain_node(&self, s: usize, k: usize) -> usize {
        self.plain.len() + self.plain[..s].iter().sum::<usize>() + k
    }

    /// Section and position of node `node` if it is a plain node.
    pub fn plain_of(&self, node: usize) -> Option<(usize, usize)> {
        let mut idx = node.checked_sub(self.plain.len())?;
        for (s, &n) in self.plain.iter().enumerate() {
            if idx < n {
                return Some((s, idx));
            }
            idx -= n;
        }
        None
    }
}

/// Section faults in force (§3); node faults (babbling, crash) act on `tx` and the
/// relay and are applied by the caller.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SectionFaults {
    /// `(section, point)`: the section is broken after its `point`-th plain node.
    pub open: Vec<(usize, usize)>,
    /// Sections stuck dominant.
    pub short: Vec<usize>,
}

/// One bus end: where the line stops, and how many terminations it has there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// At RCM `i`'s open relay, on its left or right side: terminated once.
    Module { rcm: usize, right_side: bool },
    /// At an open circuit inside section `s`: unterminated.
    Break { section: usize },
}

impl End {
    /// Terminations at this end (§1: an open relay terminates, a break does not).
    pub fn terminations(&self) -> usize {
        match self {
            End::Module { .. } => 1,
            End::Break { .. } => 0,
        }
    }
}

/// The shape of one bus.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BusShape {
    /// A line with two ends.
    Line([End; 2]),
    /// A closed ring: no end, no termination.
    Ring,
}

impl BusShape {
    /// A line with both ends terminated exactly once (§1).
    pub fn well_formed(&self) -> bool {
        match self {
            BusShape::Line(ends) => ends.iter().all(|e| e.terminations() == 1),
            BusShape::Ring => false,
        }
    }
}

/// The wiring: which bus every node is on, for given relay states and faults.
#[derive(Clone, Debug)]
pub struct Wiring {
    shape: Shape,
    /// Piece index of every node (`None`: on no section, e.g. never).
    node_piece: Vec<usize>,
    /// Bus index of every piece.
    piece_bus: Vec<usize>,
    /// Pieces stuck dominant.
    piece_short: Vec<bool>,
    buses: usize,
    /// For each piece: (section, is the right part of a broken section).
    pieces: Vec<(usize, bool)>,
    relays: Vec<Relay>,
    faults: SectionFaults,
}

impl Wiring {
    /// The wiring of `shape` with every relay transparent and no fault.
    pub fn new(shape: Shape) -> Result<Wiring, String> {
        let n = shape.ring_nodes();
        if !(3..=10).contains(&n) {
            return Err(format!(
                "a REDCAN ring of {n} ring nodes: give 3..=10 (the paper's range)"
            ));
        }
        let mut w = Wiring {
            relays: vec![Relay::Transparent; n],
            shape,
            node_piece: Vec::new(),
            piece_bus: Vec::new(),
            piece_short: Vec::new(),
            buses: 0,
            pieces: Vec::new(),
            faults: SectionFaults::default(),
        };
        w.rebuild();
        Ok(w)
    }

    /// The shape.
    pub fn shape(&self) -> &Shape {
        &self.shape
    }

    /// Sets the section faults (checked against the shape).
    pub fn set_faults(&mut self, faults: SectionFaults) -> Result<(), String> {
        let n = self.shape.ring_nodes();
        for &(s, p) in &faults.open {
            if s >= n || p > self.shape.plain[s] {
                return Err(format!(
                    "an open circuit at section {s} point {p}: sections are 0..{n}, points 0..=plain nodes of the section"
                ));
            }
        }
        if let Some(&s) = faults.short.iter().find(|&&s| s >= n) {
            return Err(format!(
                "a short circuit on section {s}: sections are 0..{n}"
            ));
        }
        self.faults = faults;
        self.rebuild();
        Ok(())
    }

    /// Applies relay states (one per ring node); recomputes the buses if any changed.
    pub fn set_relays(&mut self, relays: &[Relay]) {
        if relays != self.relays.as_slice() {
            self.relays.copy_from_slice(relays);
            self.rebuild();
        }
    }

    /// The relays in force.
    pub fn relays(&self) -> &[Relay] {
        &self.relays
    }

    fn open_point(&self, s: usize) -> Option<usize> {
        self.faults
            .open
            .iter()
            .find(|&&(sec, _)| sec == s)
            .map(|&(_, p)| p)
    }

    /// First and last piece of section `s`.
    fn section_pieces(&self, s: usize) -> (usize, usize) {
        let first = self.pieces.iter().position(|&(sec, _)| sec == s).unwrap();
        let last = if self.open_point(s).is_some() {
            first + 1
        } else {
            first
        };
        (first, last)
    }

    fn rebuild(&mut self) {
        let n = self.shape.ring_nodes();
        self.pieces.clear();
        for s in 0..n {
            self.pieces.push((s, false));
            if self.open_point(s).is_some() {
                self.pieces.push((s, true));
            }
        }
        let np = self.pieces.len();
        // Union-find over pieces; closed relays join section i-1's last piece with
        // section i's first.
        let mut parent: Vec<usize> = (0..np).collect();
        fn find(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        for i in 0..n {
            if self.relays[i] == Relay::Transparent {
                let (_, left_last) = self.section_pieces((i + n - 1) % n);
                let (right_first, _) = self.section_pieces(i);
                let (a, b) = (find(&mut parent, left_last), find(&mut parent, right_first));
                parent[a] = b;
            }
        }
        let mut bus_of_root = vec![usize::MAX; np];
        self.piece_bus = vec![0; np];
        self.buses = 0;
        for p in 0..np {
            let r = find(&mut parent, p);
            if bus_of_root[r] == usize::MAX {
                bus_of_root[r] = self.buses;
                self.buses += 1;
            }
            self.piece_bus[p] = bus_of_root[r];
        }
        self.piece_short = self
            .pieces
            .iter()
            .map(|&(s, _)| self.faults.short.contains(&s))
            .collect();
        // Nodes: ring node i on its left or right piece (transparent: both are one
        // bus, take the right); plain node k of section s on the piece its point
        // falls in.
        let total = self.shape.nodes();
        self.node_piece = vec![0; total];
        for i in 0..n {
            let (_, left_last) = self.section_pieces((i + n - 1) % n);
            let (right_first, _) = self.section_pieces(i);
            self.node_piece[i] = match self.relays[i] {
                Relay::Left => left_last,
                Relay::Right | Relay::Transparent => right_first,
            };
        }
        for s in 0..n {
            let (first, last) = self.section_pieces(s);
            for k in 0..self.shape.plain[s] {
                let piece = match self.open_point(s) {
                    Some(p) if k >= p => last,
                    _ => first,
                };
                self.node_piece[self.shape.plain_node(s, k)] = piece;
            }
        }
    }

    /// Number of buses (connected sets of pieces).
    pub fn buses(&self) -> usize {
        self.buses
    }

    /// The bus node `node` is on.
    pub fn bus_of(&self, node: usize) -> usize {
        self.piece_bus[self.node_piece[node]]
    }

    /// What every node reads, given every node's `tx` (1 = recessive): the AND over
    /// its bus, dominant if a shorted piece is on it. Writes into `rx`.
    pub fn resolve(&self, tx: &[bool], rx: &mut [bool]) {
        let mut bus = vec![true; self.buses];
        for (p, &short) in self.piece_short.iter().enumerate() {
            if short {
                bus[self.piece_bus[p]] = false;
            }
        }
        for (node, &t) in tx.iter().enumerate() {
            if !t {
                bus[self.bus_of(node)] = false;
            }
        }
        for (node, r) in rx.iter_mut().enumerate() {
            *r = bus[self.bus_of(node)];
        }
    }

    /// The shape of bus `b`: walk the ring of pieces and relays, find the arc the
    /// bus covers, and name its two ends.
    pub fn bus_shape(&self, b: usize) -> BusShape {
        let n = self.shape.ring_nodes();
        // Junctions in ring order: after piece p comes either a break (within a
        // section) or ring node (s+1)'s relay (after a section's last piece).
        // Walk right from a piece of bus b until leaving it, then left likewise.
        let np = self.pieces.len();
        let Some(start) = (0..np).find(|&p| self.piece_bus[p] == b) else {
            return BusShape::Ring;
        };
        // The junction to the right of piece p.
        let right_end = |p: usize| -> Option<End> {
            let (s, _) = self.pieces[p];
            let (_, last) = self.section_pieces(s);
            if p != last {
                return Some(End::Break { section: s });
            }
            let rcm = (s + 1) % n;
            (self.relays[rcm] != Relay::Transparent).then_some(End::Module {
                rcm,
                right_side: false,
            })
        };
        let left_end = |p: usize| -> Option<End> {
            let (s, _) = self.pieces[p];
            let (first, _) = self.section_pieces(s);
            if p != first {
                return Some(End::Break { section: s });
            }
            (self.relays[s] != Relay::Transparent).then_some(End::Module {
                rcm: s,
                right_side: true,
            })
        };
        let mut p = start;
        let mut right = None;
        for _ in 0..np {
            if let Some(e) = right_end(p) {
                right = Some(e);
                break;
            }
            p = (p + 1) % np;
        }
        let Some(right) = right else {
            return BusShape::Ring;
        };
        let mut p = start;
        let mut left = None;
        for _ in 0..np {
            if let Some(e) = left_end(p) {
                left = Some(e);
                break;
            }
            p = (p + np - 1) % np;
        }
        BusShape::Line([left.expect("a line has two ends"), right])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(plain: &[usize]) -> Wiring {
        Wiring::new(Shape {
            plain: plain.to_vec(),
        })
        .unwrap()
    }

    #[test]
    fn all_transparent_is_one_closed_ring_which_is_not_well_formed() {
        let w = ring(&[1, 0, 2]);
        assert_eq!(w.buses(), 1);
        assert_eq!(w.bus_shape(0), BusShape::Ring);
        assert!(!w.bus_shape(0).well_formed());
    }

    #[test]
    fn one_open_relay_makes_a_line_terminated_at_both_sides_of_it() {
        let mut w = ring(&[1, 0, 2]);
        w.set_relays(&[Relay::Left, Relay::Transparent, Relay::Transparent]);
        assert_eq!(w.buses(), 1);
        let shape = w.bus_shape(0);
        assert_eq!(
            shape,
            BusShape::Line([
                End::Module {
                    rcm: 0,
                    right_side: true
                },
                End::Module {
                    rcm: 0,
                    right_side: false
                }
            ])
        );
        assert!(shape.well_formed());
        // Every node reads every node's dominant bit.
        let mut tx = vec![true; w.shape().nodes()];
        tx[5] = false;
        let mut rx = vec![true; tx.len()];
        w.resolve(&tx, &mut rx);
        assert!(rx.iter().all(|&r| !r));
    }

    #[test]
    fn two_open_relays_partition_the_ring() {
        let mut w = ring(&[1, 1, 1]);
        w.set_relays(&[Relay::Right, Relay::Transparent, Relay::Left]);
        assert_eq!(w.buses(), 2);
        // Ring node 0 (right side: section 0) and ring node 1 share a bus with the
        // plain nodes of sections 0 and 1; ring node 2 (left: section 1) too; the
        // plain node of section 2 is alone between the two open relays.
        let p2 = w.shape().plain_node(2, 0);
        assert_ne!(w.bus_of(0), w.bus_of(p2));
        assert_eq!(w.bus_of(0), w.bus_of(2));
    }

    #[test]
    fn an_open_circuit_leaves_unterminated_ends_until_relays_isolate_it() {
        let mut w = ring(&[0, 2, 0]);
        w.set_relays(&[Relay::Left, Relay::Transparent, Relay::Transparent]);
        w.set_faults(SectionFaults {
            open: vec![(1, 1)],
            short: vec![],
        })
        .unwrap();
        // The ring opened at node 0 and broken in section 1: two buses, each with
        // one unterminated end.
        assert_eq!(w.buses(), 2);
        for b in 0..2 {
            assert!(!w.bus_shape(b).well_formed());
        }
        // Node 1 connects left, node 2 connects right, node 0 goes transparent:
        // one well-formed bus of the ring nodes; the broken section's plain nodes
        // are each alone on a piece.
        w.set_relays(&[Relay::Transparent, Relay::Left, Relay::Right]);
        let b = w.bus_of(0);
        assert_eq!(w.bus_of(1), b);
        assert_eq!(w.bus_of(2), b);
        assert!(w.bus_shape(b).well_formed());
        let (p0, p1) = (w.shape().plain_node(1, 0), w.shape().plain_node(1, 1));
        assert_ne!(w.bus_of(p0), b);
        assert_ne!(w.bus_of(p1), b);
    }

    #[test]
    fn a_short_makes_its_bus_dominant_until_isolated() {
        let mut w = ring(&[0, 0, 0]);
        w.set_relays(&[Relay::Left, Relay::Transparent, Relay::Transparent]);
        w.set_faults(SectionFaults {
            open: vec![],
            short: vec![1],
        })
        .unwrap();
        let tx = vec![true; 3];
        let mut rx = vec![true; 3];
        w.resolve(&tx, &mut rx);
        assert_eq!(rx, [false; 3]);
        // Isolate section 1 (between ring nodes 1 and 2).
        w.set_relays(&[Relay::Transparent, Relay::Left, Relay::Right]);
        w.resolve(&tx, &mut rx);
        assert_eq!(rx, [true; 3]);
        assert!(w.bus_shape(w.bus_of(0)).well_formed());
    }

    #[test]
    fn shapes_outside_the_papers_range_and_bad_faults_are_refused() {
        assert!(Wiring::new(Shape { plain: vec![0; 2] }).is_err());
        assert!(Wiring::new(Shape { plain: vec![0; 11] }).is_err());
        let mut w = ring(&[1, 0, 0]);
        assert!(w
            .set_faults(SectionFaults {
                open: vec![(0, 2)],
                short: vec![]
            })
            .is_err());
        assert!(w
            .set_faults(SectionFaults {
                open: vec![],
                short: vec![3]
            })
            .is_err());
    }
}
