//! Prints the Verilog of one top (default can_channel): `cargo run -p drcc-hdl --example emit`.
fn main() {
    let name = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "can_channel".into());
    match drcc_hdl::tops::emit(&name) {
        Some(v) => print!("{v}"),
        None => eprintln!("unknown top `{name}`; known: {:?}", drcc_hdl::tops::names()),
    }
}
