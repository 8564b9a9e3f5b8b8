//! Lock-step comparison of two replicated-star systems built from different engines:
//! every node's DRCC outputs (pins, Wishbone, the paper's probes) and every hub's
//! outputs (links, Wishbone, probes) must be equal after every clock.

use super::StarSystem;

/// The first difference between two star systems.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StarDivergence {
    pub cycle: u64,
    /// `node 2` or `hub 1`.
    pub unit: String,
    /// Debug rendering of both sides' outputs.
    pub left: String,
    pub right: String,
}

impl std::fmt::Display for StarDivergence {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "divergence at clock {} in {}:\n  {}\n  {}",
            self.cycle, self.unit, self.left, self.right
        )
    }
}

/// Compares the outputs of the last step of `a` and `b`.
pub fn compare(a: &StarSystem, b: &StarSystem) -> Option<StarDivergence> {
    for (i, (x, y)) in a.nodes().iter().zip(b.nodes()).enumerate() {
        if x.outputs != y.outputs {
            return Some(StarDivergence {
                cycle: a.cycle(),
                unit: format!("node {i}"),
                left: format!("{}: {:?}", x.engine.name(), x.outputs),
                right: format!("{}: {:?}", y.engine.name(), y.outputs),
            });
        }
    }
    for h in 0..2 {
        let (x, y) = (a.hub(h), b.hub(h));
        if x.outputs != y.outputs {
            return Some(StarDivergence {
                cycle: a.cycle(),
                unit: format!("hub {}", h + 1),
                left: format!("{}: {:?}", x.engine.name(), x.outputs),
                right: format!("{}: {:?}", y.engine.name(), y.outputs),
            });
        }
    }
    None
}
