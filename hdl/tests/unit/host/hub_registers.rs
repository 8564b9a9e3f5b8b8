//! Tests of `drcc_hdl::host::hub_registers`.

use drcc_hdl::host::hub_registers::*;

mod tests {
    use super::*;

    #[test]
    fn table_is_consistent() {
        MAP.check().unwrap();
        for w in REGISTERS.windows(2) {
            assert!(w[0].index < w[1].index, "{} is out of order", w[1].name);
        }
        // reset values of contract §8
        assert_eq!(register("ID").unwrap().reset_value(), 0x4855_0402);
        assert_eq!(register("BTR").unwrap().reset_value(), (4 << 6) | (1 << 10));
        assert_eq!(
            register("GUARD_CFG").unwrap().reset_value(),
            14 | (28 << 8) | (8 << 16)
        );
        assert_eq!(register("BF_CFG").unwrap().reset_value(), 32 | (64 << 8));
        assert_eq!(
            register("RESTORE_CFG").unwrap().reset_value(),
            1408 | (4096 << 16)
        );
        assert_eq!(register("CTRL").unwrap().reset_value(), 0x301);
        assert_eq!(id_value(1, N, M), 0x4855_1402);
        // contract §9.5
        assert_eq!(
            register("NRAP_CFG").unwrap().reset_value(),
            64 | (2 << 12) | (2 << 16) | (8 << 20)
        );
        assert_eq!(
            register("NRAP_TIME").unwrap().reset_value(),
            1024 | (1024 << 16)
        );
        assert_eq!(
            register("NRAP_DDSP").unwrap().reset_value(),
            1024 | (16 << 16)
        );
        assert_eq!(register("INT_ENABLE").unwrap().defined(), 0x3F);
        let h = c_header();
        assert!(h.contains("#define HUB_PORT0_OFFSET 0x40u"));
        assert!(h.contains("#define HUB_PORT_OFFSET(p)"));
        assert!(h.contains("#define HUB_STATUS_TRK_ACK_SLOT 2u"));
        assert!(h.trim_end().ends_with("#endif /* HUB_REGS_H */"));
        assert!(markdown().contains("| 16 | 0x40 | [`PORT0`]"));
    }
}
