//! Tests of `drcc_hdl::dmr::if_mailboxes`.

use drcc_hdl::dmr::if_mailboxes::*;
use rust_hdl::prelude::*;

#[test]
fn holds_one_block_with_mailboxes_and_none_without() {
    assert_eq!(IfMailboxes::<DFF<Bit>, 16>::default().len(), 1);
    assert_eq!(IfMailboxes::<DFF<Bit>, 1>::default().len(), 1);
    assert_eq!(IfMailboxes::<DFF<Bit>, 0>::default().len(), 0);
}
