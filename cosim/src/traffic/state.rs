//! Fault-confinement state changes as SocketCAN error frames, the way the Linux
//! CAN driver core reports them (`can_change_state` and `can_restart` in
//! `drivers/net/can/dev/dev.c`): a change of the node's state (error active, error
//! warning, error passive, bus-off) becomes one error frame naming the counter that
//! caused it; leaving bus-off is a restart.

use super::error::*;

/// A fault-confinement state, ordered by severity. "Warning" is ISO 11898-1's
/// error warning limit (a counter at or above the configured EWL) while still
/// error active.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord)]
enum Level {
    #[default]
    Active,
    Warning,
    Passive,
    BusOff,
}

/// The state one counter puts the node in (rules i, j of ISO 11898-1 12.1.4.2:
/// error passive above 127; warning at the error warning limit).
fn level(count: u16, ewl: u8) -> Level {
    if count >= 128 {
        Level::Passive
    } else if count >= ewl as u16 {
        Level::Warning
    } else {
        Level::Active
    }
}

/// The state one channel was last seen in; [`Confinement::update`] reports changes.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Confinement {
    level: Level,
}

impl Confinement {
    /// Takes the channel's counters, `err_state` probe (0 active, 1 passive, 2
    /// bus-off) and error warning limit; returns the error frame of a state change.
    ///
    /// To bus-off: [`CAN_ERR_BUSOFF`]. From bus-off: [`CAN_ERR_RESTARTED`]. Else
    /// [`CAN_ERR_CRTL`] with `data[1]` naming the new state of the counter that is
    /// worse (both when they are equally bad): TX/RX warning, TX/RX passive, or
    /// [`CAN_ERR_CRTL_ACTIVE`] for a return to error active. Every one carries the
    /// counters ([`CAN_ERR_CNT`]).
    pub(super) fn update(
        &mut self,
        tec: u16,
        rec: u8,
        err_state: u8,
        ewl: u8,
    ) -> Option<ErrorFrame> {
        let (tx, rx) = (level(tec, ewl), level(rec as u16, ewl));
        let from_probe = match err_state {
            0 => Level::Active,
            1 => Level::Passive,
            _ => Level::BusOff,
        };
        let new = tx.max(rx).max(from_probe);
        let old = std::mem::replace(&mut self.level, new);
        if new == old {
            return None;
        }
        let frame = if new == Level::BusOff {
            ErrorFrame::new(CAN_ERR_BUSOFF)
        } else if old == Level::BusOff {
            ErrorFrame::new(CAN_ERR_RESTARTED)
        } else {
            let mut f = ErrorFrame::new(CAN_ERR_CRTL);
            if tx >= rx {
                f.data[1] |= tx_bits(tx);
            }
            if rx >= tx {
                f.data[1] |= rx_bits(rx);
            }
            f
        };
        Some(frame.with_counters(tec, rec))
    }
}

/// `data[1]` for the transmit counter's state (`can_tx_state_to_frame`).
fn tx_bits(l: Level) -> u8 {
    match l {
        Level::Active => CAN_ERR_CRTL_ACTIVE,
        Level::Warning => CAN_ERR_CRTL_TX_WARNING,
        _ => CAN_ERR_CRTL_TX_PASSIVE,
    }
}

/// `data[1]` for the receive counter's state (`can_rx_state_to_frame`).
fn rx_bits(l: Level) -> u8 {
    match l {
        Level::Active => CAN_ERR_CRTL_ACTIVE,
        Level::Warning => CAN_ERR_CRTL_RX_WARNING,
        _ => CAN_ERR_CRTL_RX_PASSIVE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_transmitter_climbing_to_bus_off_and_back() {
        let mut c = Confinement::default();
        assert_eq!(c.update(88, 0, 0, 96), None, "below the warning limit");
        let w = c.update(96, 0, 0, 96).unwrap();
        // CAN_ERR_FLAG | CRTL | CNT, data[1] = TX_WARNING, TEC 96 in data[6].
        assert_eq!(w.can_id, 0x2000_0204);
        assert_eq!(w.data, [0, 0x08, 0, 0, 0, 0, 96, 0]);
        let p = c.update(128, 0, 1, 96).unwrap();
        assert_eq!((p.can_id, p.data[1]), (0x2000_0204, 0x20));
        assert_eq!(c.update(136, 0, 1, 96), None, "still passive");
        let off = c.update(256, 0, 2, 96).unwrap();
        assert_eq!(
            (off.can_id, off.data),
            (0x2000_0240, [0, 0, 0, 0, 0, 0, 255, 0])
        );
        let back = c.update(0, 0, 0, 96).unwrap();
        assert_eq!((back.can_id, back.data[1]), (0x2000_0300, 0));
    }

    #[test]
    fn the_worse_counter_is_named_and_recovery_is_active() {
        let mut c = Confinement::default();
        let rx = c.update(8, 130, 1, 96).unwrap();
        assert_eq!(rx.data[1], 0x10, "RX passive, the TEC is only active");
        let both = c.update(130, 130, 1, 96);
        assert_eq!(both, None, "passive either way: no change");
        let active = c.update(0, 0, 0, 96).unwrap();
        assert_eq!(active.data[1], 0x40);
        assert_eq!(active.data[6..], [0, 0]);
    }
}
