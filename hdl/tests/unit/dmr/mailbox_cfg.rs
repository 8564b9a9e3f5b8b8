//! Tests of `drcc_hdl::dmr::mailbox_cfg`.

use drcc_hdl::dmr::mailbox_cfg::*;
use rust_hdl::prelude::*;

#[test]
fn mailbox_cfg_synthesizes() {
    let mut uut = MailboxCfg::default();
    uut.connect_all();
    crate::synth_check::yosys_check("mailbox_cfg", &generate_verilog(&uut));
}
