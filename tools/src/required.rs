//! The one rule that decides whether a missing Verilator is an error or a skip.
//!
//! Shared by every test that needs an external tool ([`crate::need`]) and by
//! verilator-sys's build script, so the build, the tests and the tools all read
//! `CI` and `DRCC_REQUIRE_VERILATOR` the same way. Standard library only.

/// The variables that make Verilator required, in the order they are read.
pub const REQUIRE_VARS: [&str; 2] = ["DRCC_REQUIRE_VERILATOR", "CI"];

/// Whether a missing Verilator (or any other external tool the tests need) must
/// fail instead of being skipped.
///
/// Rule: required iff `DRCC_REQUIRE_VERILATOR` or `CI` is set to a value other
/// than empty, `0`, `false`, `no` or `off` (case-insensitive, surrounding blanks
/// ignored). So `CI=true`, `CI=1` and `DRCC_REQUIRE_VERILATOR=yes` require it;
/// `CI=false`, `CI=0`, `CI=` and an unset variable do not.
pub fn required() -> bool {
    REQUIRE_VARS.iter().any(|k| {
        is_on(
            std::env::var_os(k)
                .as_deref()
                .map(|v| v.to_string_lossy())
                .as_deref(),
        )
    })
}

/// The rule of [`required`] for one variable's value (`None`: unset).
pub fn is_on(value: Option<&str>) -> bool {
    match value {
        None => false,
        Some(v) => {
            let v = v.trim().to_ascii_lowercase();
            !matches!(v.as_str(), "" | "0" | "false" | "no" | "off")
        }
    }
}
