//! Redundancy management block (DRCC paper section III, Table 1): the main FSM,
//! one auxiliary FSM per channel with the switch policy it judges by, the
//! nominal bit tick they count with, and the echo of a replicated star node
//! with the hubs' identification frames it follows, and the ECSS bus selection
//! by the redundancy master's heartbeat.
pub mod aux_fsm;
pub mod bit_tick;
pub mod echo;
pub mod ecss;
pub mod main_fsm;
pub mod star;
pub mod stats;
pub mod switch_policy;
