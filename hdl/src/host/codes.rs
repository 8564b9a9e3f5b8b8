//! The named codes of the DRCC register map: modes, policies and states, each
//! written once (`register_enum!`) and used by the RTL, the testbench host and
//! the generated documents (`super::registers` re-exports them).

use crate::register_enum;

register_enum! {
    /// `CTRL.redundancy`: how the two channels are used (DRCC paper section III).
    pub enum Mode {
        /// two independent controllers
        Normal = 0 => "NORMAL",
        /// one redundant channel pair, the main FSM switches between them
        Redundancy = 1 => "REDUNDANCY",
    }
}

register_enum! {
    /// `CTRL.policy`: when an auxiliary FSM judges its channel failed (DRCC paper
    /// section III; contract §5).
    pub enum SwitchPolicy {
        /// never (the main FSM stays on its channel)
        None = 0 => "NONE",
        /// when the channel is error passive (the paper's policy)
        ErrorPassive = 1 => "ERROR_PASSIVE",
        /// after `k` failed attempts since the last success
        KFailed = 2 => "K_FAILED",
        /// when the channel's TEC or REC reaches the warning limit `BTR.ewl`
        Warning = 3 => "WARNING",
    }
}

register_enum! {
    /// `CTRL.mode_a`/`mode_b`: operating mode of one channel (contract §C.7).
    pub enum ChannelMode {
        /// ISO 11898-1 operation
        Normal = 0 => "NORMAL",
        /// receive only, never drives dominant (bus monitoring, ISO 11898-1 10.14)
        ListenOnly = 1 => "LISTEN_ONLY",
        /// a frame is successful without an acknowledgement
        SelfTest = 2 => "SELF_TEST",
        /// the channel hears its own transmit output only
        Loopback = 3 => "LOOPBACK",
    }
}

register_enum! {
    /// `CHAN_x_ERR.err_state`: fault confinement state (ISO 11898-1 12.1.4).
    pub enum ErrState {
        ErrorActive = 0 => "ERROR_ACTIVE",
        ErrorPassive = 1 => "ERROR_PASSIVE",
        BusOff = 2 => "BUS_OFF",
    }
}

register_enum! {
    /// Auxiliary FSM state (`AUX_x.state`, `STATUS.aux_x_state`; contract §5).
    pub enum AuxState {
        Valid = 0 => "VALID",
        Failed = 1 => "FAILED",
        Restart = 2 => "RESTART",
        Probation = 3 => "PROBATION",
    }
}

register_enum! {
    /// `STAR_STATUS.last_a` / `last_b`: whose identification frame a channel
    /// received last (contract §4.5).
    pub enum StarLast {
        None = 0 => "NONE",
        /// hub A's (identifier 0x000)
        HubA = 1 => "HUB_A",
        /// hub B's (identifier 0x001)
        HubB = 2 => "HUB_B",
    }
}

register_enum! {
    /// Main FSM state (`STATUS.state`; DRCC paper Table 1).
    pub enum MainState {
        Idle1 = 0 => "IDLE1",
        Wait1 = 1 => "WAIT1",
        Ch1 = 2 => "CH1",
        Abort1 = 3 => "ABORT1",
        Wait2 = 4 => "WAIT2",
        Idle2 = 5 => "IDLE2",
        Wait3 = 6 => "WAIT3",
        Ch2 = 7 => "CH2",
        Abort2 = 8 => "ABORT2",
        Wait4 = 9 => "WAIT4",
    }
}

register_enum! {
    /// `DMR_STATUS.dmr_state`: the CiA 701 DMR state (seed Figure 6; DMR contract §6).
    pub enum DmrState {
        /// both lines fully operational
        RedundancyActive = 0 => "REDUNDANCY_ACTIVE",
        /// a fault was found on reception; both lines transmit
        RedundancyPassive = 1 => "REDUNDANCY_PASSIVE",
        /// one line cannot transmit
        RedundancyDisabled = 2 => "REDUNDANCY_DISABLED",
        /// neither line can transmit
        NetworkDisconnected = 3 => "NETWORK_DISCONNECTED",
    }
}

register_enum! {
    /// `DMR_STATUS.cause`: why the last DMR fault was set (DMR contract §6).
    pub enum DmrCause {
        /// a mailbox timer expired with the counter out of balance (seed Figure 4)
        Timeout = 0 => "TIMEOUT",
        /// a mailbox counter exceeded its deviation limit (seed Figure 4)
        Deviation = 1 => "DEVIATION",
        /// the line's channel entered bus-off
        BusOff = 2 => "BUS_OFF",
        /// the line's connection service frame was not sent in time
        CsFailed = 3 => "CS_FAILED",
    }
}
