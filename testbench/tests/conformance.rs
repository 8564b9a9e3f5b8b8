//! The classical-CAN conformance suite (ISO 16845-1 items 7.x receiver, 8.x
//! transmitter, plus the DRCC paper's Fig. 5/6 behaviour), each item twice:
//! `<item>_model` on the reference model and `<item>_verilator` on the Verilated
//! RTL. Without the Verilated model the verilator variants fail when `CI` is set
//! and are skipped (with a message) otherwise. The items themselves live in
//! `drcc_testbench::conformance`; `docs/conformance.md` lists the ISO 16845-1 items
//! and their tests.
//!
//! Run: `cargo test --release -p drcc-testbench --test suite conformance::` (the
//! tests end in `_model` or `_verilator`, one per engine).

use drcc_testbench::conformance::{model_iut, receiver, timing, transmitter, with_verilator};

/// `item_model, item_verilator => module::item`: the item on both engines.
macro_rules! conformance {
    ($($model:ident, $verilator:ident => $module:ident :: $func:ident;)*) => {
        $(
            #[test]
            fn $model() {
                $module::$func(&model_iut);
            }

            #[test]
            fn $verilator() {
                with_verilator(|iut| $module::$func(iut));
            }
        )*
    };
}

conformance! {
    iso_7_1_1_base_frames_model,
    iso_7_1_1_base_frames_verilator => receiver::iso_7_1_1_base_frames;
    iso_7_1_2_extended_frames_model,
    iso_7_1_2_extended_frames_verilator => receiver::iso_7_1_2_extended_frames;
    iso_7_1_3_receives_while_losing_arbitration_model,
    iso_7_1_3_receives_while_losing_arbitration_verilator => receiver::iso_7_1_3_receives_while_losing_arbitration;
    iso_7_1_4_base_r0_recessive_model,
    iso_7_1_4_base_r0_recessive_verilator => receiver::iso_7_1_4_base_r0_recessive;
    iso_7_1_5_extended_srr_r1_r0_model,
    iso_7_1_5_extended_srr_r1_r0_verilator => receiver::iso_7_1_5_extended_srr_r1_r0;
    iso_7_1_8_dlc_greater_than_8_model,
    iso_7_1_8_dlc_greater_than_8_verilator => receiver::iso_7_1_8_dlc_greater_than_8;
    iso_7_1_9_back_to_back_frames_model,
    iso_7_1_9_back_to_back_frames_verilator => receiver::iso_7_1_9_back_to_back_frames;
    iso_7_1_10_stuffing_base_model,
    iso_7_1_10_stuffing_base_verilator => receiver::iso_7_1_10_stuffing_base;
    iso_7_1_11_stuffing_extended_model,
    iso_7_1_11_stuffing_extended_verilator => receiver::iso_7_1_11_stuffing_extended;
    iso_7_1_12_valid_at_eof6_overload_at_eof7_model,
    iso_7_1_12_valid_at_eof6_overload_at_eof7_verilator => receiver::iso_7_1_12_valid_at_eof6_overload_at_eof7;
    iso_7_2_1_ack_bit_error_model,
    iso_7_2_1_ack_bit_error_verilator => receiver::iso_7_2_1_ack_bit_error;
    iso_7_2_2_stuff_error_base_model,
    iso_7_2_2_stuff_error_base_verilator => receiver::iso_7_2_2_stuff_error_base;
    iso_7_2_3_stuff_error_extended_model,
    iso_7_2_3_stuff_error_extended_verilator => receiver::iso_7_2_3_stuff_error_extended;
    iso_7_2_4_stuff_error_data_patterns_model,
    iso_7_2_4_stuff_error_data_patterns_verilator => receiver::iso_7_2_4_stuff_error_data_patterns;
    iso_7_2_5_crc_error_position_model,
    iso_7_2_5_crc_error_position_verilator => receiver::iso_7_2_5_crc_error_position;
    iso_7_2_6_crc_and_form_error_one_flag_model,
    iso_7_2_6_crc_and_form_error_one_flag_verilator => receiver::iso_7_2_6_crc_and_form_error_one_flag;
    iso_7_2_7_form_error_crc_delimiter_model,
    iso_7_2_7_form_error_crc_delimiter_verilator => receiver::iso_7_2_7_form_error_crc_delimiter;
    iso_7_2_9_form_error_ack_delimiter_model,
    iso_7_2_9_form_error_ack_delimiter_verilator => receiver::iso_7_2_9_form_error_ack_delimiter;
    iso_7_2_10_form_error_eof_model,
    iso_7_2_10_form_error_eof_verilator => receiver::iso_7_2_10_form_error_eof;
    iso_7_2_11_dominant_eof6_invalid_model,
    iso_7_2_11_dominant_eof6_invalid_verilator => receiver::iso_7_2_11_dominant_eof6_invalid;
    iso_7_3_1_dominant_bits_after_active_flag_model,
    iso_7_3_1_dominant_bits_after_active_flag_verilator => receiver::iso_7_3_1_dominant_bits_after_active_flag;
    iso_7_3_2_sof_at_intermission_bit_3_model,
    iso_7_3_2_sof_at_intermission_bit_3_verilator => receiver::iso_7_3_2_sof_at_intermission_bit_3;
    iso_7_3_3_bit_error_in_active_flag_model,
    iso_7_3_3_bit_error_in_active_flag_verilator => receiver::iso_7_3_3_bit_error_in_active_flag;
    iso_7_3_4_form_error_in_error_delimiter_model,
    iso_7_3_4_form_error_in_error_delimiter_verilator => receiver::iso_7_3_4_form_error_in_error_delimiter;
    iso_7_4_1_overload_at_intermission_model,
    iso_7_4_1_overload_at_intermission_verilator => receiver::iso_7_4_1_overload_at_intermission;
    iso_7_4_6_overload_at_intermission_after_error_frame_model,
    iso_7_4_6_overload_at_intermission_after_error_frame_verilator => receiver::iso_7_4_6_overload_at_intermission_after_error_frame;
    iso_7_4_7_overload_at_intermission_after_overload_frame_model,
    iso_7_4_7_overload_at_intermission_after_overload_frame_verilator => receiver::iso_7_4_7_overload_at_intermission_after_overload_frame;
    iso_7_4_2_overload_at_last_eof_bit_model,
    iso_7_4_2_overload_at_last_eof_bit_verilator => receiver::iso_7_4_2_overload_at_last_eof_bit;
    iso_7_4_3_overload_at_delimiter_bit_8_model,
    iso_7_4_3_overload_at_delimiter_bit_8_verilator => receiver::iso_7_4_3_overload_at_delimiter_bit_8;
    iso_7_4_4_bit_error_in_overload_flag_model,
    iso_7_4_4_bit_error_in_overload_flag_verilator => receiver::iso_7_4_4_bit_error_in_overload_flag;
    iso_7_4_5_form_error_in_overload_delimiter_model,
    iso_7_4_5_form_error_in_overload_delimiter_verilator => receiver::iso_7_4_5_form_error_in_overload_delimiter;
    iso_7_5_1_passive_flag_six_equal_bits_model,
    iso_7_5_1_passive_flag_six_equal_bits_verilator => receiver::iso_7_5_1_passive_flag_six_equal_bits;
    iso_7_5_2_passive_sof_at_intermission_bit_3_model,
    iso_7_5_2_passive_sof_at_intermission_bit_3_verilator => receiver::iso_7_5_2_passive_sof_at_intermission_bit_3;
    iso_7_5_3_passive_dominant_bits_after_flag_model,
    iso_7_5_3_passive_dominant_bits_after_flag_verilator => receiver::iso_7_5_3_passive_dominant_bits_after_flag;
    iso_7_5_4_stays_passive_model,
    iso_7_5_4_stays_passive_verilator => receiver::iso_7_5_4_stays_passive;
    iso_7_5_5_passive_flag_restarts_model,
    iso_7_5_5_passive_flag_restarts_verilator => receiver::iso_7_5_5_passive_flag_restarts;
    iso_7_5_6_passive_form_error_in_delimiter_model,
    iso_7_5_6_passive_form_error_in_delimiter_verilator => receiver::iso_7_5_6_passive_form_error_in_delimiter;
    iso_7_5_7_active_to_passive_model,
    iso_7_5_7_active_to_passive_verilator => receiver::iso_7_5_7_active_to_passive;
    iso_7_6_1_rec_bit_error_in_active_flag_model,
    iso_7_6_1_rec_bit_error_in_active_flag_verilator => receiver::iso_7_6_1_rec_bit_error_in_active_flag;
    iso_7_6_2_rec_bit_error_in_overload_flag_model,
    iso_7_6_2_rec_bit_error_in_overload_flag_verilator => receiver::iso_7_6_2_rec_bit_error_in_overload_flag;
    iso_7_6_3_rec_dominant_after_active_flag_model,
    iso_7_6_3_rec_dominant_after_active_flag_verilator => receiver::iso_7_6_3_rec_dominant_after_active_flag;
    iso_7_6_4_rec_dominant_after_overload_flag_model,
    iso_7_6_4_rec_dominant_after_overload_flag_verilator => receiver::iso_7_6_4_rec_dominant_after_overload_flag;
    iso_7_6_5_rec_ack_bit_error_model,
    iso_7_6_5_rec_ack_bit_error_verilator => receiver::iso_7_6_5_rec_ack_bit_error;
    iso_7_6_6_rec_form_error_crc_delimiter_model,
    iso_7_6_6_rec_form_error_crc_delimiter_verilator => receiver::iso_7_6_6_rec_form_error_crc_delimiter;
    iso_7_6_7_rec_form_error_ack_delimiter_model,
    iso_7_6_7_rec_form_error_ack_delimiter_verilator => receiver::iso_7_6_7_rec_form_error_ack_delimiter;
    iso_7_6_8_rec_form_error_eof_model,
    iso_7_6_8_rec_form_error_eof_verilator => receiver::iso_7_6_8_rec_form_error_eof;
    iso_7_6_9_rec_stuff_error_model,
    iso_7_6_9_rec_stuff_error_verilator => receiver::iso_7_6_9_rec_stuff_error;
    iso_7_6_10_rec_crc_error_model,
    iso_7_6_10_rec_crc_error_verilator => receiver::iso_7_6_10_rec_crc_error;
    iso_7_6_11_rec_dominant_first_bit_after_flag_model,
    iso_7_6_11_rec_dominant_first_bit_after_flag_verilator => receiver::iso_7_6_11_rec_dominant_first_bit_after_flag;
    iso_7_6_12_rec_form_error_error_delimiter_model,
    iso_7_6_12_rec_form_error_error_delimiter_verilator => receiver::iso_7_6_12_rec_form_error_error_delimiter;
    iso_7_6_13_rec_form_error_overload_delimiter_model,
    iso_7_6_13_rec_form_error_overload_delimiter_verilator => receiver::iso_7_6_13_rec_form_error_overload_delimiter;
    iso_7_6_14_rec_valid_frame_model,
    iso_7_6_14_rec_valid_frame_verilator => receiver::iso_7_6_14_rec_valid_frame;
    iso_7_6_15_rec_above_127_valid_frame_model,
    iso_7_6_15_rec_above_127_valid_frame_verilator => receiver::iso_7_6_15_rec_above_127_valid_frame;
    iso_7_6_16_rec_unchanged_dominant_last_eof_bit_model,
    iso_7_6_16_rec_unchanged_dominant_last_eof_bit_verilator => receiver::iso_7_6_16_rec_unchanged_dominant_last_eof_bit;
    iso_7_6_17_rec_unchanged_13_bit_overload_flag_model,
    iso_7_6_17_rec_unchanged_13_bit_overload_flag_verilator => receiver::iso_7_6_17_rec_unchanged_13_bit_overload_flag;
    iso_7_6_18_rec_13_bit_error_flag_model,
    iso_7_6_18_rec_13_bit_error_flag_verilator => receiver::iso_7_6_18_rec_13_bit_error_flag;
    iso_7_6_19_rec_unchanged_error_delimiter_bit_8_model,
    iso_7_6_19_rec_unchanged_error_delimiter_bit_8_verilator => receiver::iso_7_6_19_rec_unchanged_error_delimiter_bit_8;
    iso_7_6_20_rec_unchanged_overload_delimiter_bit_8_model,
    iso_7_6_20_rec_unchanged_overload_delimiter_bit_8_verilator => receiver::iso_7_6_20_rec_unchanged_overload_delimiter_bit_8;
    iso_7_6_21_rec_unchanged_by_own_transmission_model,
    iso_7_6_21_rec_unchanged_by_own_transmission_verilator => receiver::iso_7_6_21_rec_unchanged_by_own_transmission;
    iso_7_7_1_sample_point_model,
    iso_7_7_1_sample_point_verilator => timing::iso_7_7_1_sample_point;
    iso_7_7_2_hard_synchronisation_model,
    iso_7_7_2_hard_synchronisation_verilator => timing::iso_7_7_2_hard_synchronisation;
    iso_7_7_3_positive_phase_error_within_sjw_model,
    iso_7_7_3_positive_phase_error_within_sjw_verilator => timing::iso_7_7_3_positive_phase_error_within_sjw;
    iso_7_7_4_positive_phase_error_beyond_sjw_model,
    iso_7_7_4_positive_phase_error_beyond_sjw_verilator => timing::iso_7_7_4_positive_phase_error_beyond_sjw;
    iso_7_7_5_negative_phase_error_within_sjw_model,
    iso_7_7_5_negative_phase_error_within_sjw_verilator => timing::iso_7_7_5_negative_phase_error_within_sjw;
    iso_7_7_6_negative_phase_error_beyond_sjw_model,
    iso_7_7_6_negative_phase_error_beyond_sjw_verilator => timing::iso_7_7_6_negative_phase_error_beyond_sjw;
    iso_7_7_7_one_synchronisation_per_bit_model,
    iso_7_7_7_one_synchronisation_per_bit_verilator => timing::iso_7_7_7_one_synchronisation_per_bit;
    iso_7_7_8_one_synchronisation_after_early_edge_model,
    iso_7_7_8_one_synchronisation_after_early_edge_verilator => timing::iso_7_7_8_one_synchronisation_after_early_edge;
    iso_7_7_9_1_glitch_not_sof_model,
    iso_7_7_9_1_glitch_not_sof_verilator => timing::iso_7_7_9_1_glitch_not_sof;
    iso_7_7_9_2_no_resync_after_hard_sync_model,
    iso_7_7_9_2_no_resync_after_hard_sync_verilator => timing::iso_7_7_9_2_no_resync_after_hard_sync;
    iso_7_7_10_no_sync_after_dominant_sample_model,
    iso_7_7_10_no_sync_after_dominant_sample_verilator => timing::iso_7_7_10_no_sync_after_dominant_sample;
    iso_7_7_11_ack_timing_model,
    iso_7_7_11_ack_timing_verilator => timing::iso_7_7_11_ack_timing;
    iso_8_1_1_base_frames_model,
    iso_8_1_1_base_frames_verilator => transmitter::iso_8_1_1_base_frames;
    iso_8_1_2_extended_frames_model,
    iso_8_1_2_extended_frames_verilator => transmitter::iso_8_1_2_extended_frames;
    iso_8_1_3_arbitration_lost_base_model,
    iso_8_1_3_arbitration_lost_base_verilator => transmitter::iso_8_1_3_arbitration_lost_base;
    iso_8_1_4_arbitration_lost_extended_model,
    iso_8_1_4_arbitration_lost_extended_verilator => transmitter::iso_8_1_4_arbitration_lost_extended;
    iso_8_1_5_valid_at_end_of_eof_model,
    iso_8_1_5_valid_at_end_of_eof_verilator => transmitter::iso_8_1_5_valid_at_end_of_eof;
    iso_8_1_6_stuffing_base_model,
    iso_8_1_6_stuffing_base_verilator => transmitter::iso_8_1_6_stuffing_base;
    iso_8_1_7_stuffing_extended_model,
    iso_8_1_7_stuffing_extended_verilator => transmitter::iso_8_1_7_stuffing_extended;
    iso_8_1_8_sof_at_intermission_bit_3_model,
    iso_8_1_8_sof_at_intermission_bit_3_verilator => transmitter::iso_8_1_8_sof_at_intermission_bit_3;
    iso_8_2_1_bit_error_base_model,
    iso_8_2_1_bit_error_base_verilator => transmitter::iso_8_2_1_bit_error_base;
    iso_8_2_2_bit_error_extended_model,
    iso_8_2_2_bit_error_extended_verilator => transmitter::iso_8_2_2_bit_error_extended;
    iso_8_2_3_stuff_bit_errors_base_model,
    iso_8_2_3_stuff_bit_errors_base_verilator => transmitter::iso_8_2_3_stuff_bit_errors_base;
    iso_8_2_4_stuff_bit_errors_extended_model,
    iso_8_2_4_stuff_bit_errors_extended_verilator => transmitter::iso_8_2_4_stuff_bit_errors_extended;
    iso_8_2_5_form_errors_tx_model,
    iso_8_2_5_form_errors_tx_verilator => transmitter::iso_8_2_5_form_errors_tx;
    iso_8_2_6_ack_error_model,
    iso_8_2_6_ack_error_verilator => transmitter::iso_8_2_6_ack_error;
    iso_8_2_8_stuff_bit_errors_data_patterns_model,
    iso_8_2_8_stuff_bit_errors_data_patterns_verilator => transmitter::iso_8_2_8_stuff_bit_errors_data_patterns;
    iso_8_3_1_dominant_bits_after_flag_tx_model,
    iso_8_3_1_dominant_bits_after_flag_tx_verilator => transmitter::iso_8_3_1_dominant_bits_after_flag_tx;
    iso_8_3_2_sof_at_intermission_bit_3_tx_model,
    iso_8_3_2_sof_at_intermission_bit_3_tx_verilator => transmitter::iso_8_3_2_sof_at_intermission_bit_3_tx;
    iso_8_3_3_bit_error_in_flag_tx_model,
    iso_8_3_3_bit_error_in_flag_tx_verilator => transmitter::iso_8_3_3_bit_error_in_flag_tx;
    iso_8_3_4_form_error_in_delimiter_tx_model,
    iso_8_3_4_form_error_in_delimiter_tx_verilator => transmitter::iso_8_3_4_form_error_in_delimiter_tx;
    iso_8_4_1_overload_after_own_frame_model,
    iso_8_4_1_overload_after_own_frame_verilator => transmitter::iso_8_4_1_overload_after_own_frame;
    iso_8_4_2_overload_at_delimiter_bit_8_tx_model,
    iso_8_4_2_overload_at_delimiter_bit_8_tx_verilator => transmitter::iso_8_4_2_overload_at_delimiter_bit_8_tx;
    iso_8_4_3_dominant_intermission_3_is_sof_model,
    iso_8_4_3_dominant_intermission_3_is_sof_verilator => transmitter::iso_8_4_3_dominant_intermission_3_is_sof;
    iso_8_4_4_bit_error_in_overload_flag_tx_model,
    iso_8_4_4_bit_error_in_overload_flag_tx_verilator => transmitter::iso_8_4_4_bit_error_in_overload_flag_tx;
    iso_8_4_5_form_error_in_overload_delimiter_tx_model,
    iso_8_4_5_form_error_in_overload_delimiter_tx_verilator => transmitter::iso_8_4_5_form_error_in_overload_delimiter_tx;
    iso_8_5_1_passive_flag_with_active_flag_from_others_model,
    iso_8_5_1_passive_flag_with_active_flag_from_others_verilator => transmitter::iso_8_5_1_passive_flag_with_active_flag_from_others;
    iso_8_5_2_passive_receives_after_error_frame_model,
    iso_8_5_2_passive_receives_after_error_frame_verilator => transmitter::iso_8_5_2_passive_receives_after_error_frame;
    iso_8_5_3_passive_dominant_bits_in_delimiter_model,
    iso_8_5_3_passive_dominant_bits_in_delimiter_verilator => transmitter::iso_8_5_3_passive_dominant_bits_in_delimiter;
    iso_8_5_4_passive_receives_during_suspend_model,
    iso_8_5_4_passive_receives_during_suspend_verilator => transmitter::iso_8_5_4_passive_receives_during_suspend;
    iso_8_5_5_suspend_after_error_frame_model,
    iso_8_5_5_suspend_after_error_frame_verilator => transmitter::iso_8_5_5_suspend_after_error_frame;
    iso_8_5_6_suspend_after_overload_frame_model,
    iso_8_5_6_suspend_after_overload_frame_verilator => transmitter::iso_8_5_6_suspend_after_overload_frame;
    iso_8_5_7_suspend_after_own_frame_model,
    iso_8_5_7_suspend_after_own_frame_verilator => transmitter::iso_8_5_7_suspend_after_own_frame;
    iso_8_5_8_no_suspend_after_arbitration_lost_model,
    iso_8_5_8_no_suspend_after_arbitration_lost_verilator => transmitter::iso_8_5_8_no_suspend_after_arbitration_lost;
    iso_8_5_9_passive_never_transmits_without_sof_model,
    iso_8_5_9_passive_never_transmits_without_sof_verilator => transmitter::iso_8_5_9_passive_never_transmits_without_sof;
    iso_8_5_10_bus_off_no_transmission_model,
    iso_8_5_10_bus_off_no_transmission_verilator => transmitter::iso_8_5_10_bus_off_no_transmission;
    iso_8_5_11_bus_off_recovery_model,
    iso_8_5_11_bus_off_recovery_verilator => transmitter::iso_8_5_11_bus_off_recovery;
    iso_8_5_12_passive_flag_tx_six_equal_bits_model,
    iso_8_5_12_passive_flag_tx_six_equal_bits_verilator => transmitter::iso_8_5_12_passive_flag_tx_six_equal_bits;
    iso_8_5_13_passive_form_error_in_delimiter_tx_model,
    iso_8_5_13_passive_form_error_in_delimiter_tx_verilator => transmitter::iso_8_5_13_passive_form_error_in_delimiter_tx;
    iso_8_5_14_retransmission_within_31_bits_model,
    iso_8_5_14_retransmission_within_31_bits_verilator => transmitter::iso_8_5_14_retransmission_within_31_bits;
    iso_8_5_15_turning_passive_retransmits_after_25_bits_model,
    iso_8_5_15_turning_passive_retransmits_after_25_bits_verilator => transmitter::iso_8_5_15_turning_passive_retransmits_after_25_bits;
    iso_8_6_1_tec_bit_error_in_active_flag_model,
    iso_8_6_1_tec_bit_error_in_active_flag_verilator => transmitter::iso_8_6_1_tec_bit_error_in_active_flag;
    iso_8_6_2_tec_bit_error_in_overload_flag_model,
    iso_8_6_2_tec_bit_error_in_overload_flag_verilator => transmitter::iso_8_6_2_tec_bit_error_in_overload_flag;
    iso_8_6_3_tec_dominant_after_active_flag_model,
    iso_8_6_3_tec_dominant_after_active_flag_verilator => transmitter::iso_8_6_3_tec_dominant_after_active_flag;
    iso_8_6_4_tec_dominant_after_passive_flag_model,
    iso_8_6_4_tec_dominant_after_passive_flag_verilator => transmitter::iso_8_6_4_tec_dominant_after_passive_flag;
    iso_8_6_5_tec_dominant_after_overload_flag_model,
    iso_8_6_5_tec_dominant_after_overload_flag_verilator => transmitter::iso_8_6_5_tec_dominant_after_overload_flag;
    iso_8_6_6_tec_bit_error_model,
    iso_8_6_6_tec_bit_error_verilator => transmitter::iso_8_6_6_tec_bit_error;
    iso_8_6_7_tec_form_error_model,
    iso_8_6_7_tec_form_error_verilator => transmitter::iso_8_6_7_tec_form_error;
    iso_8_6_8_ack_error_active_model,
    iso_8_6_8_ack_error_active_verilator => transmitter::iso_8_6_8_ack_error_active;
    iso_8_6_9_tec_error_delimiter_form_error_model,
    iso_8_6_9_tec_error_delimiter_form_error_verilator => transmitter::iso_8_6_9_tec_error_delimiter_form_error;
    iso_8_6_10_tec_overload_delimiter_form_error_model,
    iso_8_6_10_tec_overload_delimiter_form_error_verilator => transmitter::iso_8_6_10_tec_overload_delimiter_form_error;
    iso_8_6_11_tec_successful_transmission_active_model,
    iso_8_6_11_tec_successful_transmission_active_verilator => transmitter::iso_8_6_11_tec_successful_transmission_active;
    iso_8_6_12_tec_successful_transmission_passive_model,
    iso_8_6_12_tec_successful_transmission_passive_verilator => transmitter::iso_8_6_12_tec_successful_transmission_passive;
    iso_8_6_13_tec_13_bit_overload_flag_model,
    iso_8_6_13_tec_13_bit_overload_flag_verilator => transmitter::iso_8_6_13_tec_13_bit_overload_flag;
    iso_8_6_14_tec_13_bit_error_flag_model,
    iso_8_6_14_tec_13_bit_error_flag_verilator => transmitter::iso_8_6_14_tec_13_bit_error_flag;
    iso_8_6_15_tec_unchanged_overload_delimiter_bit_8_model,
    iso_8_6_15_tec_unchanged_overload_delimiter_bit_8_verilator => transmitter::iso_8_6_15_tec_unchanged_overload_delimiter_bit_8;
    iso_8_6_16_tec_unchanged_error_delimiter_bit_8_model,
    iso_8_6_16_tec_unchanged_error_delimiter_bit_8_verilator => transmitter::iso_8_6_16_tec_unchanged_error_delimiter_bit_8;
    iso_8_6_17_tec_unchanged_passive_ack_error_model,
    iso_8_6_17_tec_unchanged_passive_ack_error_verilator => transmitter::iso_8_6_17_tec_unchanged_passive_ack_error;
    iso_8_6_18_tec_passive_ack_error_then_dominant_model,
    iso_8_6_18_tec_passive_ack_error_then_dominant_verilator => transmitter::iso_8_6_18_tec_passive_ack_error_then_dominant;
    iso_8_6_19_tec_unchanged_stuff_error_in_arbitration_model,
    iso_8_6_19_tec_unchanged_stuff_error_in_arbitration_verilator => transmitter::iso_8_6_19_tec_unchanged_stuff_error_in_arbitration;
    iso_8_6_20_tec_unchanged_by_reception_model,
    iso_8_6_20_tec_unchanged_by_reception_verilator => transmitter::iso_8_6_20_tec_unchanged_by_reception;
    iso_8_6_21_tec_unchanged_error_after_arbitration_lost_model,
    iso_8_6_21_tec_unchanged_error_after_arbitration_lost_verilator => transmitter::iso_8_6_21_tec_unchanged_error_after_arbitration_lost;
    iso_8_7_1_sample_point_tx_model,
    iso_8_7_1_sample_point_tx_verilator => timing::iso_8_7_1_sample_point_tx;
    iso_8_7_2_hard_sync_sof_before_sample_point_tx_model,
    iso_8_7_2_hard_sync_sof_before_sample_point_tx_verilator => timing::iso_8_7_2_hard_sync_sof_before_sample_point_tx;
    iso_8_7_3_hard_sync_sof_after_sample_point_tx_model,
    iso_8_7_3_hard_sync_sof_after_sample_point_tx_verilator => timing::iso_8_7_3_hard_sync_sof_after_sample_point_tx;
    iso_8_7_4_negative_phase_error_within_sjw_tx_model,
    iso_8_7_4_negative_phase_error_within_sjw_tx_verilator => timing::iso_8_7_4_negative_phase_error_within_sjw_tx;
    iso_8_7_5_negative_phase_error_beyond_sjw_tx_model,
    iso_8_7_5_negative_phase_error_beyond_sjw_tx_verilator => timing::iso_8_7_5_negative_phase_error_beyond_sjw_tx;
    iso_8_7_6_one_synchronisation_per_bit_tx_model,
    iso_8_7_6_one_synchronisation_per_bit_tx_verilator => timing::iso_8_7_6_one_synchronisation_per_bit_tx;
    iso_8_7_7_no_resync_while_sending_dominant_model,
    iso_8_7_7_no_resync_while_sending_dominant_verilator => timing::iso_8_7_7_no_resync_while_sending_dominant;
    iso_8_7_8_edge_after_sample_point_within_sjw_tx_model,
    iso_8_7_8_edge_after_sample_point_within_sjw_tx_verilator => timing::iso_8_7_8_edge_after_sample_point_within_sjw_tx;
    iso_8_7_9_edge_after_sample_point_beyond_sjw_tx_model,
    iso_8_7_9_edge_after_sample_point_beyond_sjw_tx_verilator => timing::iso_8_7_9_edge_after_sample_point_beyond_sjw_tx;
    drcc_fig5_lone_transmitter_model,
    drcc_fig5_lone_transmitter_verilator => transmitter::drcc_fig5_lone_transmitter;
    iso_8_6_19_base_ide_stuff_bit_is_not_arbitration_model,
    iso_8_6_19_base_ide_stuff_bit_is_not_arbitration_verilator => transmitter::iso_8_6_19_base_ide_stuff_bit_is_not_arbitration;
}

/// The coverage collection (`drcc coverage`) runs every item of this file on the
/// model from `drcc_testbench::conformance::items::ITEMS`: the two lists must be
/// the same.
#[test]
fn every_item_is_in_the_coverage_table() {
    let src = include_str!("conformance.rs");
    let mut here: Vec<&str> = src
        .split("=>")
        .skip(1)
        .filter_map(|rest| {
            let path = rest.split(';').next()?.trim();
            let (_, func) = path.split_once("::")?;
            Some(func.trim())
        })
        .filter(|f| f.starts_with("iso_") || f.starts_with("drcc_"))
        .collect();
    let mut table: Vec<&str> = drcc_testbench::conformance::items::ITEMS
        .iter()
        .map(|(name, _)| *name)
        .collect();
    here.sort_unstable();
    table.sort_unstable();
    assert!(here.len() >= 140, "{} items", here.len());
    assert_eq!(
        here, table,
        "tests/conformance.rs and conformance::items::ITEMS differ"
    );
}
