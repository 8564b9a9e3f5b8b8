//! Tests of `drcc_hdl::dmr`.

mod control;
mod cs_rx;
mod engine;
mod if_mailboxes;
mod line;
mod mailbox_cfg;
mod mailbox_state;
mod offsets;
mod sat_count;
mod status;
mod time_base;
