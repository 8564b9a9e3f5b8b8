//! verilator-sys: placeholder
