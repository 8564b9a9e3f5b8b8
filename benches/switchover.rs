//! Switchover benchmark (`cargo bench --bench switchover`, same as
//! `drcc bench --switchover`): the DRCC paper's Fig. 8 experiment (channel A
//! without acknowledgement) at 125 kbit/s, 500 kbit/s and 1 Mbit/s for each switch
//! policy, printing the time from the first failed attempt to the message on
//! channel B beside the paper's ~25 ms. No assertions on time.

fn main() {
    match drcc_testbench::paper::switchover_table(drcc_testbench::EngineKind::Model) {
        Ok(t) => print!("{t}"),
        Err(e) => {
            eprintln!("switchover bench: {e}");
            std::process::exit(2);
        }
    }
}
