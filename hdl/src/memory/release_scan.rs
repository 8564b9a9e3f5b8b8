//! The release scan's choice (DMR contract §8, `RSCAN`): among the waiting
//! frames of the new ACL, the one with the largest age wins, the first found
//! among equal ages (`rel_found`, `rel_e`, `rel_age`).
//!
//! Timing: the age of an entry is taken from the timestamp RAM read one entry
//! ahead (`dedup.rs`), for the `now` of the judging edge (`now + tick`: `now`
//! counts `tick`s), and registered in `age_q`. At the judging edge the choice
//! therefore compares two registers (`age_q > rel_age`), off the RAM path.

use rust_hdl::prelude::*;

/// Oldest-candidate tracker of the release scan.
#[derive(LogicBlock)]
pub struct ReleaseScan {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or reset mode: the choice is forgotten.
    pub clear: Signal<In, Bit>,
    // ---- scan control ----
    /// The idle -> `RSCAN` edge: a new scan starts with no candidate.
    pub start: Signal<In, Bit>,
    /// The entry judged at this edge is a candidate by its flags (valid, not
    /// expired, not used, not delivered, received on the ACL).
    pub cand: Signal<In, Bit>,
    /// Index of the entry judged at this edge.
    pub scan_e: Signal<In, Bits<5>>,
    // ---- age of the entry judged at the next edge ----
    /// `now - ts` of the entry read one ahead, for this clock's `now`.
    pub next_age: Signal<In, Bits<16>>,
    /// Bit tick: `now` advances at this edge.
    pub tick: Signal<In, Bit>,
    // ---- the choice ----
    /// A candidate was found at an earlier edge of this scan (registered; with
    /// the candidate judged at this edge, `found | cand`, as `take` would be).
    pub found: Signal<Out, Bit>,
    /// Entry chosen so far (registered).
    pub rel_e: Signal<Out, Bits<5>>,
    age_q: DFF<Bits<16>>,
    rel_found: DFF<Bit>,
    rel_e_q: DFF<Bits<5>>,
    rel_age: DFF<Bits<16>>,
    take: Signal<Local, Bit>,
    zero5: Constant<Bits<5>>,
    zero16: Constant<Bits<16>>,
}

impl Default for ReleaseScan {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            clear: Default::default(),
            start: Default::default(),
            cand: Default::default(),
            scan_e: Default::default(),
            next_age: Default::default(),
            tick: Default::default(),
            found: Default::default(),
            rel_e: Default::default(),
            age_q: Default::default(),
            rel_found: Default::default(),
            rel_e_q: Default::default(),
            rel_age: Default::default(),
            take: Default::default(),
            zero5: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
        }
    }
}

impl Logic for ReleaseScan {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, age_q, rel_found, rel_e_q, rel_age);
        // the judging edge's age: now + tick - ts
        self.age_q.d.next = self.next_age.val() + bit_cast::<16, 1>(self.tick.val().into());
        // §8: the largest age wins; a strict compare keeps the first among equals
        self.take.next = self.cand.val()
            & (!self.rel_found.q.val() | (self.age_q.q.val() > self.rel_age.q.val()));
        self.rel_found.d.next = self.rel_found.q.val() | self.take.val();
        self.rel_e_q.d.next = self.rel_e_q.q.val();
        self.rel_age.d.next = self.rel_age.q.val();
        if self.take.val() {
            self.rel_e_q.d.next = self.scan_e.val();
            self.rel_age.d.next = self.age_q.q.val();
        }
        if self.start.val() {
            self.rel_found.d.next = false;
        }
        if self.clear.val() {
            self.rel_found.d.next = false;
            self.rel_e_q.d.next = self.zero5.val();
            self.rel_age.d.next = self.zero16.val();
        }
        self.found.next = self.rel_found.q.val();
        self.rel_e.next = self.rel_e_q.q.val();
    }
}
