//! The register indices live twice on purpose: in the register table
//! `hdl/src/host/registers.rs` (the source of the RTL and of the testbench host
//! `host::reg`, from which `rtl-out/drcc_regs.h` is generated) and in the
//! reference model (`model::drcc::regs`, written from the contract). Independence
//! keeps them apart; this test keeps them equal, reading the generated C header a
//! firmware author would use (`register_maps.rs` checks every field through the
//! model's bus).

use drcc_cosim::host::reg;
use drcc_cosim::model::drcc::regs::idx;
use std::collections::BTreeMap;

fn header_offsets() -> BTreeMap<String, u32> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../rtl-out/drcc_regs.h");
    let text = std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("{path}: {e}; run `cargo run -- generate`"));
    text.lines()
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            (w.next()? == "#define").then_some(())?;
            let name = w.next()?.strip_prefix("DRCC_")?.strip_suffix("_OFFSET")?;
            let v = w.next()?.trim_end_matches('u');
            let v = u32::from_str_radix(v.strip_prefix("0x")?, 16).ok()?;
            Some((name.to_string(), v))
        })
        .collect()
}

#[test]
fn model_host_and_generated_header_agree_on_every_register() {
    let table: &[(&str, u8, u8)] = &[
        ("ID", idx::ID, reg::ID),
        ("CTRL", idx::CTRL, reg::CTRL),
        ("BTR", idx::BTR, reg::BTR),
        ("RMB_CFG", idx::RMB_CFG, reg::RMB_CFG),
        ("DEDUP_CFG", idx::DEDUP_CFG, reg::DEDUP_CFG),
        ("STATUS", idx::STATUS, reg::STATUS),
        ("INT_STATUS", idx::INT_STATUS, reg::INT_STATUS),
        ("INT_ENABLE", idx::INT_ENABLE, reg::INT_ENABLE),
        ("CHAN_A_ERR", idx::CHAN_A_ERR, reg::CHAN_A_ERR),
        ("CHAN_B_ERR", idx::CHAN_B_ERR, reg::CHAN_B_ERR),
        ("AUX_A", idx::AUX_A, reg::AUX_A),
        ("AUX_B", idx::AUX_B, reg::AUX_B),
        ("TX_ID", idx::TX_ID, reg::TX_ID),
        ("TX_CTRL", idx::TX_CTRL, reg::TX_CTRL),
        ("TX_DATA0", idx::TX_DATA0, reg::TX_DATA0),
        ("TX_DATA1", idx::TX_DATA1, reg::TX_DATA1),
        ("TX_CMD", idx::TX_CMD, reg::TX_CMD),
        ("RX_ID", idx::RX_ID, reg::RX_ID),
        ("RX_CTRL", idx::RX_CTRL, reg::RX_CTRL),
        ("RX_DATA0", idx::RX_DATA0, reg::RX_DATA0),
        ("RX_DATA1", idx::RX_DATA1, reg::RX_DATA1),
        ("RX_CMD", idx::RX_CMD, reg::RX_CMD),
        ("STATS0", idx::STATS0, reg::STATS0),
        ("STATS1", idx::STATS1, reg::STATS1),
        ("TIMES", idx::TIMES, reg::TIMES),
        ("DMR_CFG", idx::DMR_CFG, reg::DMR_CFG),
        ("DMR_TIME", idx::DMR_TIME, reg::DMR_TIME),
        ("DMR_CS", idx::DMR_CS, reg::DMR_CS),
        ("DMR_STATUS", idx::DMR_STATUS, reg::DMR_STATUS),
        ("DMR_CS_COUNT", idx::DMR_CS_COUNT, reg::DMR_CS_COUNT),
        ("DMR_RX_STATS", idx::DMR_RX_STATS, reg::DMR_RX_STATS),
        ("MB_SEL", idx::MB_SEL, reg::MB_SEL),
        ("MB_ID", idx::MB_ID, reg::MB_ID),
        ("MB_MASK", idx::MB_MASK, reg::MB_MASK),
        ("MB_CFG", idx::MB_CFG, reg::MB_CFG),
        ("MB_STATE", idx::MB_STATE, reg::MB_STATE),
        ("STAR_STATUS", idx::STAR_STATUS, reg::STAR_STATUS),
        ("OMISSIONS", idx::OMISSIONS, reg::OMISSIONS),
        ("VERSION", idx::VERSION, reg::VERSION),
        ("SIZES", idx::SIZES, reg::SIZES),
        ("CAP_A", idx::CAP_A, reg::CAP_A),
        ("CAP_B", idx::CAP_B, reg::CAP_B),
        ("FILT_ID0", idx::FILT_ID0, reg::FILT_ID0),
        ("FILT_MASK0", idx::FILT_MASK0, reg::FILT_MASK0),
        ("FILT_ID1", idx::FILT_ID1, reg::FILT_ID1),
        ("FILT_MASK1", idx::FILT_MASK1, reg::FILT_MASK1),
        ("RX_TIME", idx::RX_TIME, reg::RX_TIME),
        ("STATS_CLR", idx::STATS_CLR, reg::STATS_CLR),
        ("ECSS_CFG", idx::ECSS_CFG, reg::ECSS_CFG),
        ("ECSS_HB", idx::ECSS_HB, reg::ECSS_HB),
        ("ECSS_PERIOD", idx::ECSS_PERIOD, reg::ECSS_PERIOD),
        ("ECSS_STATUS", idx::ECSS_STATUS, reg::ECSS_STATUS),
    ];
    let header = header_offsets();
    assert_eq!(
        header.len(),
        table.len(),
        "registers in drcc_regs.h: {:?}",
        header.keys().collect::<Vec<_>>()
    );
    for &(name, model, host) in table {
        let off = header
            .get(name)
            .unwrap_or_else(|| panic!("DRCC_{name}_OFFSET missing in drcc_regs.h"));
        assert_eq!(*off, 4 * model as u32, "{name}: header vs model");
        assert_eq!(model, host, "{name}: model vs testbench host");
    }
}
