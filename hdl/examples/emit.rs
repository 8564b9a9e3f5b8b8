//! Prints the Verilog of one top (default can_channel):
//! `cargo run -p drcc-hdl --example emit -- [top] [--unreadable]`.
//! `--unreadable` prints the same logic before the readable step (a module per
//! flip-flop, channels A and B apart), to compare the two texts' area and Fmax.
fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let unreadable = args.iter().any(|a| a == "--unreadable");
    let name = args
        .iter()
        .find(|a| !a.starts_with("--"))
        .cloned()
        .unwrap_or_else(|| "can_channel".into());
    match drcc_hdl::tops::top(&name) {
        Some(t) if unreadable => print!("{}", t.unreadable_verilog()),
        Some(t) => print!("{}", t.verilog()),
        None => {
            eprintln!("unknown top `{name}`; known: {:?}", drcc_hdl::tops::names());
            std::process::exit(2);
        }
    }
}
