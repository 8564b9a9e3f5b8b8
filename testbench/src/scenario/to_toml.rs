//! Writing a [`Scenario`] back as TOML (frames with `at_cycle`), for saving
//! generated scenarios.

use super::*;

impl Scenario {
    /// The scenario as TOML (frames with `at_cycle`), loadable with
    /// [`Scenario::parse`]; used to save generated scenarios for `drcc sim`.
    pub fn to_toml(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let q = |x: &str| toml::Value::String(x.to_string()).to_string();
        let _ = writeln!(s, "name = {}", q(&self.name));
        let _ = writeln!(s, "description = {}", q(&self.description));
        let _ = writeln!(s, "clock_hz = {}", self.clock_hz);
        let nodes: Vec<String> = self.nodes.iter().map(|n| q(n)).collect();
        let _ = writeln!(s, "nodes = [{}]", nodes.join(", "));
        let _ = writeln!(s, "max_cycles = {}", self.max_cycles);
        let _ = writeln!(s, "reset_cycles = {}", self.reset_cycles);
        // The configuration: as scenario keys when every node shares it, else per node.
        let same = self.configs.windows(2).all(|w| w[0] == w[1]);
        let default = ControllerConfig::default();
        let write_config = |s: &mut String, c: &ControllerConfig| {
            if c.mode != default.mode {
                let _ = writeln!(s, "mode = {}", q(mode_name(c.mode)));
            }
            if c.ewl != default.ewl {
                let _ = writeln!(s, "ewl = {}", c.ewl);
            }
            if c.single_shot != default.single_shot {
                let _ = writeln!(s, "single_shot = {}", c.single_shot);
            }
        };
        if same {
            if let Some(c) = self.configs.first() {
                write_config(&mut s, c);
            }
        }
        let t = &self.timing;
        let _ = writeln!(
            s,
            "\n[timing]\nbrp = {}\ntseg1 = {}\ntseg2 = {}\nsjw = {}\ntriple_sampling = {}",
            t.brp, t.tseg1, t.tseg2, t.sjw, t.triple_sampling
        );
        if !same {
            for (name, c) in self.nodes.iter().zip(&self.configs) {
                if *c != default {
                    let _ = writeln!(s, "\n[[node_config]]\nnode = {}", q(name));
                    write_config(&mut s, c);
                }
            }
        }
        for (i, f) in self.frames.iter().enumerate() {
            let fr = &f.frame;
            let _ = writeln!(s, "\n[[frame]] # {i}");
            let _ = writeln!(s, "node = {}", q(&self.nodes[f.node]));
            let _ = writeln!(s, "at_cycle = {}", f.at_cycle);
            let _ = writeln!(s, "id = 0x{:X}", fr.id);
            let _ = writeln!(s, "extended = {}", fr.ide);
            let _ = writeln!(s, "remote = {}", fr.rtr);
            let _ = writeln!(s, "dlc = {}", fr.dlc);
            if !fr.rtr {
                let d: Vec<String> = fr.data[..fr.data_len()]
                    .iter()
                    .map(|b| format!("0x{b:02X}"))
                    .collect();
                let _ = writeln!(s, "data = [{}]", d.join(", "));
            }
            if f.single_shot {
                let _ = writeln!(s, "single_shot = true");
            }
        }
        if let Expectations::Explicit(list) = &self.expect {
            for e in list {
                let _ = writeln!(s, "\n[[expect]]\nnode = {}", q(&self.nodes[e.node]));
                if let Some(r) = &e.receives {
                    let _ = writeln!(s, "receives = {r:?}");
                }
                if let Some(r) = &e.sends {
                    let _ = writeln!(s, "sends = {r:?}");
                }
                if let Some(r) = &e.fails {
                    let _ = writeln!(s, "fails = {r:?}");
                }
            }
        }
        for a in &self.aborts {
            let _ = writeln!(
                s,
                "\n[[abort]]\nnode = {}\nat_cycle = {}",
                q(&self.nodes[a.node]),
                a.at_cycle
            );
        }
        for f in &self.faults {
            let _ = writeln!(s, "\n[[fault]]\nkind = {}", q(f.kind.name()));
            match f.target {
                FaultTarget::Bus => {
                    let _ = writeln!(s, "target = \"bus\"");
                }
                FaultTarget::Tx(n) | FaultTarget::Rx(n) => {
                    let side = if matches!(f.target, FaultTarget::Tx(_)) {
                        "tx"
                    } else {
                        "rx"
                    };
                    let _ = writeln!(s, "target = \"{side}\"\nnode = {}", q(&self.nodes[n]));
                }
            }
            let _ = writeln!(s, "at_cycle = {}\ncycles = {}", f.start, f.cycles);
        }
        s
    }
}
