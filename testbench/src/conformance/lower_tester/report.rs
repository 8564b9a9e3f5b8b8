//! The failure report of a script run: the bits around the first mismatch as a
//! table (drive, bus, IUT `tx`, expectation, probes).

use super::*;

pub(super) fn val(b: bool) -> &'static str {
    if b {
        "R"
    } else {
        "D"
    }
}

/// Bits `i-12 ..= i+6` of a run as a table.
pub(super) fn table(script: &Script, recs: &[BitRecord], i: usize) -> String {
    let mut s = String::from(
        "  bit  label                      LT   bus  tx   exp  field           TEC  REC st  events\n",
    );
    let lo = i.saturating_sub(12);
    for (k, r) in recs.iter().enumerate().skip(lo).take(19) {
        let exp = script.bits[k].expect.map(val).unwrap_or("-");
        let mut ev = String::new();
        if r.rx_valid {
            ev.push_str("rx_valid ");
        }
        if r.tx_done {
            ev.push_str("tx_done ");
        }
        if r.arb_lost {
            ev.push_str("arb_lost ");
        }
        if let Some(w) = r.waited {
            let _ = write!(ev, "waited {w} clk ");
        }
        let _ = writeln!(
            s,
            "{} {:4} {:26} {:4} {:4} {:4} {:4} {:15} {:4} {:3} {:2}  {}",
            if k == i { ">" } else { " " },
            k,
            r.label,
            r.drive.symbol(),
            val(r.bus),
            val(r.tx),
            exp,
            field::name(r.probes.field),
            r.probes.tec,
            r.probes.rec,
            r.probes.err_state,
            ev
        );
    }
    s
}
