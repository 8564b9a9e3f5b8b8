//! Tests of `drcc_hdl::host::status_words`.

use drcc_hdl::host::registers::{self as map, MAP};
use drcc_hdl::host::status_words::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    #[test]
    fn status_words_synthesizes() {
        let mut uut = StatusWords::<16>::default();
        uut.connect_all();
        crate::synth_check::yosys_check("status_words", &generate_verilog(&uut));
    }

    /// Every field of STATUS lands where the table puts it: each input is driven
    /// with all ones in turn and the word must be exactly the field's mask.
    #[test]
    fn status_fields_sit_at_their_table_positions() {
        let mut uut = StatusWords::<16>::default();
        uut.connect_all();
        uut.adr.next = (map::STATUS as u64).into();
        type Drive = fn(&mut StatusWords<16>, bool);
        let fields: [(&str, Drive); 11] = [
            ("state", |u, on| {
                u.state.next = if on { 0xF.into() } else { 0.into() }
            }),
            ("tx_channel", |u, on| u.tx_channel.next = on),
            ("aux_a_state", |u, on| {
                u.aux_a_state.next = if on { 3.into() } else { 0.into() }
            }),
            ("aux_b_state", |u, on| {
                u.aux_b_state.next = if on { 3.into() } else { 0.into() }
            }),
            ("err_state_a", |u, on| {
                u.es_a.next = if on { 3.into() } else { 0.into() }
            }),
            ("err_state_b", |u, on| {
                u.es_b.next = if on { 3.into() } else { 0.into() }
            }),
            ("reset_mode", |u, on| u.reset_mode.next = on),
            ("tx_going_on", |u, on| u.tx_going_on.next = on),
            ("txq_a_count", |u, on| {
                u.txq_a.next = if on { 0xF.into() } else { 0.into() }
            }),
            ("txq_b_count", |u, on| {
                u.txq_b.next = if on { 0xF.into() } else { 0.into() }
            }),
            ("rx_count", |u, on| {
                u.rx_count.next = if on { 0x3F.into() } else { 0.into() }
            }),
        ];
        for (name, drive) in fields {
            drive(&mut uut, true);
            assert!(simulate(&mut uut, 10));
            let mask = MAP.field("STATUS", name).mask() as u64;
            assert_eq!(uut.word.val().to_u64(), mask, "STATUS.{name}");
            drive(&mut uut, false);
        }
    }
}
