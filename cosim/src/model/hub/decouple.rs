//! Decoupling (hub contract §7): `no_twin` counts SAMPLE edges at which no incoming
//! sublink is enabled; after `decouple_bits` of them the hub decouples definitively
//! (sticky: `view = own`, no ACK masking, sublink guards frozen) until the host
//! writes `CTRL.recouple` or enters reset mode. `CTRL.force_decouple` decouples at
//! once. The commands themselves (and what `recouple` does to the sublink guards)
//! are applied by the hub (`super::HubModel`).

/// `no_twin` and `decoupled`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Decoupler {
    /// [0] SAMPLE edges without an enabled sublink, saturating at 65535.
    pub no_twin: u16,
    /// [0] the hub is a star of its own.
    pub decoupled: bool,
}

impl Decoupler {
    /// One SAMPLE edge: `any_sub_enabled` from the enabled registers before the edge.
    /// Returns whether the hub decouples at this edge (`INT_STATUS.decoupled`).
    #[inline]
    pub fn sample(&mut self, any_sub_enabled: bool, decouple_bits: u16) -> bool {
        self.no_twin = if any_sub_enabled {
            0
        } else {
            self.no_twin.saturating_add(1)
        };
        if !self.decoupled && decouple_bits != 0 && self.no_twin >= decouple_bits {
            self.decoupled = true;
            crate::model::coverage::hit("hub: decouple (no sublink left)");
            return true;
        }
        false
    }

    /// `CTRL.force_decouple`.
    pub fn force(&mut self) {
        crate::model::coverage::hit("hub: decouple (forced)");
        self.decoupled = true;
    }

    /// `CTRL.recouple` (the sublink ports are re-enabled by the hub).
    pub fn recouple(&mut self) {
        crate::model::coverage::hit("hub: recouple");
        self.decoupled = false;
        self.no_twin = 0;
    }
}
