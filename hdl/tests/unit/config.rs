//! Tests of `drcc_hdl::config`.

use drcc_hdl::config::*;

mod tests {
    use super::*;

    #[test]
    fn named_configurations_are_offered() {
        for (name, c) in DrccConfig::NAMED {
            c.check().unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }

    #[test]
    fn sizes_outside_the_offer_are_refused_by_name() {
        let c = DrccConfig {
            history: 12,
            ..DrccConfig::DEFAULT
        };
        let e = c.check().unwrap_err();
        assert!(
            e.contains("history = 12") && e.contains("4, 8, 16, 32"),
            "{e}"
        );
        let c = DrccConfig {
            tx_queue_depth: 16,
            ..DrccConfig::DEFAULT
        };
        assert!(c.check().unwrap_err().contains("tx_queue_depth"));
    }
}
