//! The scan wrapper: a generated `<top>_scan` Verilog module that puts a top on
//! a real package. The clock, `rst` and the CAN pins go to package pins; every
//! other input of the top is driven from a scan chain and every other output is
//! captured into it, so that a top with hundreds of host ports fits a 48-pin
//! package and nothing is optimised away.
//!
//! The ports come from the rust-hdl block ([`drcc_hdl::tops::Top::ports`]), not
//! from the Verilog. A top's CAN pins are found from its port names: every input
//! whose name has an `rx` word (`rx`, `rx_a`, `chan_b_rx`) and an output of the
//! same width whose name has `tx` in its place. [`CAN_PIN_OVERRIDES`] lists them
//! by hand for a top whose names do not follow that rule; a top added to
//! `drcc_hdl::tops::TOPS` is picked up with no change here.

use std::fmt::Write as _;

use drcc_hdl::tops::{Direction, Port};

/// CAN pin pairs `(rx, tx)` of tops whose port names do not follow the
/// `rx` / `tx` word rule; one line per top. Tops not listed are detected.
pub const CAN_PIN_OVERRIDES: &[(&str, &[(&str, &str)])] = &[];

/// One CAN pin pair of the top: the receive input and the transmit output
/// (a bit of them if they are vectors).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CanPin {
    /// Top port feeding the receiver (`rx` or `rx[bit]`).
    pub rx: String,
    /// Top port driven by the transmitter.
    pub tx: String,
}

/// The generated scan wrapper of a top.
#[derive(Debug, Clone)]
pub struct Wrapper {
    /// Module name: `<top>_scan`.
    pub module: String,
    /// Verilog text.
    pub verilog: String,
    /// Bits of the input chain (top inputs other than the clock, rst and CAN rx).
    pub n_in: usize,
    /// Bits of the output chain (top outputs other than CAN tx).
    pub n_out: usize,
    /// CAN pin pairs: wrapper pin `can<k>_rx` / `can<k>_tx` -> top port (bit).
    pub can: Vec<CanPin>,
}

/// The `rx`/`tx` pairs of a top, as `(rx port, tx port)` names.
pub fn can_port_pairs(top: &str, ports: &[Port]) -> Result<Vec<(String, String)>, String> {
    let has =
        |name: &str, dir: Direction| ports.iter().any(|p| p.name == name && p.direction == dir);
    if let Some((_, pairs)) = CAN_PIN_OVERRIDES.iter().find(|(n, _)| *n == top) {
        for (rx, tx) in *pairs {
            for (name, dir, what) in [
                (rx, Direction::Input, "input"),
                (tx, Direction::Output, "output"),
            ] {
                if !has(name, dir) {
                    return Err(format!(
                        "CAN_PIN_OVERRIDES names `{name}` for {top}, but the top has no such {what} port"
                    ));
                }
            }
        }
        return Ok(pairs
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect());
    }
    let mut pairs = Vec::new();
    for p in ports.iter().filter(|p| p.direction == Direction::Input) {
        let words: Vec<&str> = p.name.split('_').collect();
        for (i, w) in words.iter().enumerate() {
            if *w != "rx" {
                continue;
            }
            let mut tx_words = words.clone();
            tx_words[i] = "tx";
            let tx_name = tx_words.join("_");
            if let Some(tx) = ports.iter().find(|q| {
                q.name == tx_name && q.direction == Direction::Output && q.width == p.width
            }) {
                pairs.push((p.name.clone(), tx.name.clone()));
                break;
            }
        }
    }
    Ok(pairs)
}

/// rust-hdl declares a port of more than one bit as `[width-1:0]`, a single bit
/// without a range.
fn is_vector(port: &Port) -> bool {
    port.width > 1
}

/// Bit `bit` of a port, as a Verilog expression.
fn slice(port: &Port, bit: usize) -> String {
    if is_vector(port) {
        format!("{}[{bit}]", port.name)
    } else {
        port.name.clone()
    }
}

/// `reg <= {reg[n-2:0], input}` for an n-bit shift register.
fn shift_expr(reg: &str, n: usize, input: &str) -> String {
    if n == 1 {
        input.to_string()
    } else {
        format!("{{{reg}[{}:0], {input}}}", n - 2)
    }
}

/// `reg[hi:lo]`, or `reg[hi]` for one bit.
fn range(reg: &str, hi: usize, lo: usize) -> String {
    if hi == lo {
        format!("{reg}[{hi}]")
    } else {
        format!("{reg}[{hi}:{lo}]")
    }
}

/// Is this the top's reset input (by name: rust-hdl has no reset kind)?
fn is_reset(p: &Port) -> bool {
    p.name == "rst" && p.direction == Direction::Input && p.width == 1
}

/// Generates `<top>_scan`: see the module documentation.
pub fn scan_wrapper(top: &str, ports: &[Port]) -> Result<Wrapper, String> {
    if !ports
        .iter()
        .any(|p| p.is_clock && p.direction == Direction::Input && p.width == 1)
    {
        return Err(format!("{top}: no clock input"));
    }
    let pairs = can_port_pairs(top, ports)?;
    let find = |n: &str| ports.iter().find(|p| p.name == n).expect("pair from ports");

    // CAN pins, bit by bit.
    let mut can = Vec::new();
    for (rx, tx) in &pairs {
        let (rx, tx) = (find(rx), find(tx));
        for b in 0..rx.width {
            can.push(CanPin {
                rx: slice(rx, b),
                tx: slice(tx, b),
            });
        }
    }
    let is_can = |p: &Port| pairs.iter().any(|(r, t)| p.name == *r || p.name == *t);
    let chain_in =
        |p: &&Port| p.direction == Direction::Input && !p.is_clock && !is_reset(p) && !is_can(p);
    let chain_out = |p: &&Port| p.direction == Direction::Output && !is_can(p);
    let n_in: usize = ports.iter().filter(chain_in).map(|p| p.width).sum();
    let n_out: usize = ports.iter().filter(chain_out).map(|p| p.width).sum();
    let module = format!("{top}_scan");

    let mut v = String::new();
    header(&mut v, top, &module, n_in, n_out, can.len());
    chains(&mut v, n_in, n_out);

    // The instance: clock and reset, CAN pins, then the chains in port order.
    let mut conns = Vec::new();
    let mut in_at = n_in;
    let mut out_at = n_out;
    for p in ports {
        let conn = if p.is_clock {
            "clk".to_string()
        } else if is_reset(p) {
            "rst_s[1]".to_string()
        } else if let Some(bits) = can_bits(&can, p) {
            bits
        } else if p.direction == Direction::Input {
            let hi = in_at - 1;
            in_at -= p.width;
            range("in_hold", hi, in_at)
        } else {
            let hi = out_at - 1;
            out_at -= p.width;
            range("outs", hi, out_at)
        };
        conns.push(format!("        .{}({conn})", p.name));
    }
    debug_assert_eq!((in_at, out_at), (0, 0));
    let _ = writeln!(v, "\n    {top} dut (\n{}\n    );", conns.join(",\n"));
    let _ = writeln!(v, "endmodule");
    Ok(Wrapper {
        module,
        verilog: v,
        n_in,
        n_out,
        can,
    })
}

/// The file comment, the module header and the package pins.
fn header(w: &mut String, top: &str, module: &str, n_in: usize, n_out: usize, n_can: usize) {
    let _ = writeln!(
        w,
        "// {module}.v: generated by `drcc synth` into its build directory (not part of rtl-out/).\n\
         //\n\
         // Scan wrapper of `{top}` for place and route on a real package: clk, rst and the\n\
         // CAN pins are package pins; the other {n_in} input bits of {top} are driven from a\n\
         // scan chain and its other {n_out} output bits are captured into it, so nothing is\n\
         // optimised away.\n\
         //\n\
         // The chain runs scan_in -> in_shift[{n_in}] -> out_shift[{n_out}] -> scan_out; each\n\
         // port takes its bits most significant first, ports in declaration order (the\n\
         // first bit shifted in ends in the first input port's MSB). While scan_en is high\n\
         // every rising edge of scan_clk shifts the chain by one bit; when scan_en falls\n\
         // the shifted inputs are applied to {top} (in_hold); while scan_en is low\n\
         // out_shift captures the outputs every clock. rst and the scan pins pass\n\
         // two-flip-flop synchronisers. in_hold is all zero after configuration.\n"
    );
    let mut pins: Vec<String> = ["clk", "rst", "scan_clk", "scan_en", "scan_in", "scan_out"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    for k in 0..n_can {
        pins.push(format!("can{k}_rx"));
        pins.push(format!("can{k}_tx"));
    }
    let _ = writeln!(w, "module {module}({});", pins.join(", "));
    for p in ["clk", "rst", "scan_clk", "scan_en", "scan_in"] {
        let _ = writeln!(w, "    input wire {p};");
    }
    let _ = writeln!(w, "    output wire scan_out;");
    for k in 0..n_can {
        let _ = writeln!(w, "    input wire can{k}_rx;");
        let _ = writeln!(w, "    output wire can{k}_tx;");
    }
}

/// The synchronisers, the input chain (`in_shift` -> `in_hold`) and the output
/// chain (`outs` -> `out_shift` -> `scan_out`).
fn chains(w: &mut String, n_in: usize, n_out: usize) {
    let _ = writeln!(
        w,
        "\n    reg [1:0] rst_s;\n    reg [2:0] sclk_s;\n    reg [1:0] sen_s;\n    reg [1:0] sin_s;\n    reg sen_q;\n    \
         always @(posedge clk) begin\n        rst_s <= {{rst_s[0], rst}};\n        \
         sclk_s <= {{sclk_s[1:0], scan_clk}};\n        sen_s <= {{sen_s[0], scan_en}};\n        \
         sin_s <= {{sin_s[0], scan_in}};\n        sen_q <= sen_s[1];\n    end\n    \
         wire shift = sen_s[1] & sclk_s[1] & ~sclk_s[2];\n    \
         wire update = sen_q & ~sen_s[1];"
    );
    if n_in > 0 {
        let _ = writeln!(
            w,
            "\n    reg [{m}:0] in_shift;\n    reg [{m}:0] in_hold;\n    \
             always @(posedge clk) begin\n        \
             if (shift) in_shift <= {e};\n        if (update) in_hold <= in_shift;\n    end",
            m = n_in - 1,
            e = shift_expr("in_shift", n_in, "sin_s[1]")
        );
    }
    let chain_tail = if n_in > 0 {
        format!("in_shift[{}]", n_in - 1)
    } else {
        "sin_s[1]".to_string()
    };
    if n_out > 0 {
        let _ = writeln!(
            w,
            "\n    wire [{m}:0] outs;\n    reg [{m}:0] out_shift;\n    \
             always @(posedge clk) begin\n        \
             if (shift) out_shift <= {e};\n        else if (!sen_s[1]) out_shift <= outs;\n    end\n    \
             assign scan_out = out_shift[{m}];",
            m = n_out - 1,
            e = shift_expr("out_shift", n_out, &chain_tail)
        );
    } else {
        let _ = writeln!(w, "\n    assign scan_out = {chain_tail};");
    }
}

/// The wrapper pins connected to a CAN port of the top (MSB first), if it is one.
fn can_bits(can: &[CanPin], p: &Port) -> Option<String> {
    let input = p.direction == Direction::Input;
    let side = if input { "rx" } else { "tx" };
    let pin = |c: &CanPin| -> String {
        if input {
            c.rx.clone()
        } else {
            c.tx.clone()
        }
    };
    let pins: Vec<String> = can
        .iter()
        .enumerate()
        .filter(|(_, c)| {
            let s = pin(c);
            s == p.name || s.starts_with(&format!("{}[", p.name))
        })
        .map(|(k, _)| format!("can{k}_{side}"))
        .collect();
    if pins.is_empty() {
        return None;
    }
    if pins.len() == 1 && !is_vector(p) {
        return Some(pins[0].clone());
    }
    let msb_first: Vec<String> = pins.into_iter().rev().collect();
    Some(format!("{{{}}}", msb_first.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn port(name: &str, direction: Direction, width: usize) -> Port {
        Port {
            name: name.to_string(),
            direction,
            width,
            is_clock: name == "clk",
            doc: String::new(),
        }
    }

    /// A toy top: host ports, a classical `rx`/`tx` pair, a second pair named
    /// by channel, and an `rx_*` output that is not a CAN pin.
    fn toy() -> Vec<Port> {
        use Direction::{Input as I, Output as O};
        vec![
            port("clk", I, 1),
            port("rst", I, 1),
            port("cfg", I, 6),
            port("rx", I, 1),
            port("tx", O, 1),
            port("rx_valid", O, 1),
            port("rx_data", O, 8),
            port("tx_data", I, 8),
            port("chan_b_rx", I, 1),
            port("chan_b_tx", O, 1),
        ]
    }

    #[test]
    fn finds_can_pins_by_their_rx_tx_words() {
        assert_eq!(
            can_port_pairs("toy", &toy()).unwrap(),
            [
                ("rx".to_string(), "tx".to_string()),
                ("chan_b_rx".to_string(), "chan_b_tx".to_string())
            ]
        );
        // A pair must have the same width on both sides.
        let mut odd = toy();
        odd[4].width = 2;
        assert_eq!(can_port_pairs("toy", &odd).unwrap().len(), 1);
    }

    #[test]
    fn wrapper_chains_every_other_port() {
        let w = scan_wrapper("toy", &toy()).unwrap();
        assert_eq!((w.n_in, w.n_out, w.can.len()), (6 + 8, 1 + 8, 2));
        let v = &w.verilog;
        assert!(v.contains("module toy_scan(clk, rst, scan_clk, scan_en, scan_in, scan_out, can0_rx, can0_tx, can1_rx, can1_tx);"), "{v}");
        assert!(v.contains(".cfg(in_hold[13:8])"), "{v}");
        assert!(v.contains(".tx_data(in_hold[7:0])"), "{v}");
        assert!(v.contains(".rx_valid(outs[8])"), "{v}");
        assert!(v.contains(".rx_data(outs[7:0])"), "{v}");
        assert!(v.contains(".rx(can0_rx)"), "{v}");
        assert!(v.contains(".chan_b_tx(can1_tx)"), "{v}");
        assert!(v.contains(".rst(rst_s[1])"), "{v}");
        assert!(v.contains(".clk(clk)"), "{v}");
        assert!(
            v.contains("reg [13:0] in_shift;") && v.contains("reg [8:0] out_shift;"),
            "{v}"
        );
    }

    #[test]
    fn vector_can_ports_take_one_pin_per_bit() {
        use Direction::{Input as I, Output as O};
        let ports = vec![port("clk", I, 1), port("rx", I, 3), port("tx", O, 3)];
        let w = scan_wrapper("star", &ports).unwrap();
        assert_eq!((w.n_in, w.n_out), (0, 0));
        assert_eq!(
            w.can[2],
            CanPin {
                rx: "rx[2]".into(),
                tx: "tx[2]".into()
            }
        );
        let v = &w.verilog;
        assert!(v.contains(".rx({can2_rx, can1_rx, can0_rx})"), "{v}");
        assert!(v.contains(".tx({can2_tx, can1_tx, can0_tx})"), "{v}");
        // No chain: scan_in passes straight to scan_out.
        assert!(v.contains("assign scan_out = sin_s[1];"), "{v}");
    }

    #[test]
    fn a_top_needs_a_clock() {
        let ports = vec![port("rx", Direction::Input, 1)];
        assert!(scan_wrapper("toy", &ports)
            .unwrap_err()
            .contains("no clock"));
    }

    /// The real tops: CAN pins where the contracts put them, every other port
    /// on the chain. can_channel is one ISO 11898-1 channel (one rx/tx pair);
    /// the DRCC has two redundant channels.
    #[test]
    fn real_tops_put_their_can_pins_on_package_pins() {
        for (name, pairs) in [("can_channel", 1), ("drcc", 2)] {
            let top = drcc_hdl::tops::top(name).unwrap();
            let ports = top.ports();
            let w = scan_wrapper(name, &ports).unwrap();
            assert_eq!(w.can.len(), pairs, "{name}: {:?}", w.can);
            let width = |d: Direction| -> usize {
                ports
                    .iter()
                    .filter(|p| p.direction == d)
                    .map(|p| p.width)
                    .sum()
            };
            // clk and rst are pins, not chain bits.
            assert_eq!(w.n_in + pairs + 2, width(Direction::Input), "{name}");
            assert_eq!(w.n_out + pairs, width(Direction::Output), "{name}");
        }
    }
}
