//! Tests of `drcc_hdl::dmr::mailbox_state`.

use drcc_hdl::dmr::mailbox_state::*;
use rust_hdl::prelude::*;

#[test]
fn mailbox_state_synthesizes() {
    let mut uut = MailboxState::<16>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("mailbox_state", &generate_verilog(&uut));
}
