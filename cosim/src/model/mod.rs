#![doc = include_str!("timing_contract.md")]
