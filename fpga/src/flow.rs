//! One top on one target, start to finish: the scan wrapper from the block's
//! ports, yosys on the top alone and in its wrapper (in parallel), then for
//! iCE40 nextpnr and icepack; the outcome as a [`SynthReport`].

use std::path::{Path, PathBuf};
use std::time::Duration;

use drcc_hdl::tops::Top;

use crate::report::{Measured, NoFit, Pnr, Reference, SynthReport, WrapperSummary};
use crate::scan::{scan_wrapper, Wrapper};
use crate::target::{Target, RECOMMENDED_CLOCK_MHZ};
use crate::tools::{ToolEnv, NEXTPNR_ICE40};
use crate::{breakdown, icepack, nextpnr, write_file, yosys, Error};

/// Where the flow reads and writes, and the tools it found.
pub struct Flow<'a> {
    /// The workspace: `rtl-out/<top>.v` and the constraints files are read
    /// relative to it.
    pub workspace: PathBuf,
    /// Each run goes to `<build_root>/<top>-<target>/`.
    pub build_root: PathBuf,
    /// Versions and supported families, from [`ToolEnv::probe`].
    pub env: ToolEnv,
    /// Told what runs next (the CLI prints it on stderr).
    pub progress: &'a dyn Fn(&str),
    /// Also synthesise each top with its blocks kept apart, for the area block
    /// by block ([`crate::breakdown`]), on the targets whose name is listed.
    pub breakdown_on: &'a [&'a str],
    /// How long nextpnr may run on one top before the top is reported as not
    /// routed ([`nextpnr::DEFAULT_LIMIT`] unless asked otherwise).
    pub pnr_limit: Duration,
}

fn abs(p: &Path) -> Result<PathBuf, Error> {
    std::fs::canonicalize(p).map_err(|e| Error(format!("cannot find {}: {e}", p.display())))
}

impl Flow<'_> {
    /// The report of `t` with no numbers yet (all a family that this yosys
    /// cannot synthesise gets).
    fn blank(&self, top: &Top, t: &'static Target) -> SynthReport {
        SynthReport {
            top: top.name.to_string(),
            target: t,
            family: t.family.to_string(),
            yosys: self.env.yosys_version.clone(),
            synth: t.synth.to_string(),
            board: t.board.to_string(),
            device: t.device.to_string(),
            board_clock_mhz: t.clock_mhz,
            constraints: t.constraints.to_string(),
            recommended_clock_mhz: RECOMMENDED_CLOCK_MHZ,
            unsupported: self.env.unsupported.get(t.name).cloned(),
            note: self.env.notes.get(t.name).cloned(),
            measured: None,
        }
    }

    /// `rtl-out/<top>.v`, checked to be the Verilog of the block whose ports
    /// the wrapper is built from.
    fn rtl(&self, top: &Top) -> Result<PathBuf, Error> {
        let rtl = self
            .workspace
            .join("rtl-out")
            .join(format!("{}.v", top.name));
        let text = std::fs::read_to_string(&rtl).map_err(|e| {
            Error(format!(
                "cannot read {}: {e}; run `drcc generate` first",
                rtl.display()
            ))
        })?;
        if text != top.verilog() {
            return Err(Error(format!(
                "{} is not the Verilog of the drcc-hdl block (stale?); run `drcc generate` first",
                rtl.display()
            )));
        }
        abs(&rtl)
    }

    /// Synthesises `top` for `t` (and for iCE40 places, routes and packs it).
    pub fn run(&self, top: &Top, t: &'static Target) -> Result<SynthReport, Error> {
        let mut report = self.blank(top, t);
        if report.unsupported.is_some() {
            return Ok(report);
        }
        let rtl = self.rtl(top)?;
        let wrapper = scan_wrapper(top.name, &top.ports())
            .map_err(|m| Error(format!("{}: {m}", rtl.display())))?;
        let dir = self.build_root.join(format!("{}-{}", top.name, t.name));
        drcc_tools::atomic::create_dir(&dir).map_err(Error)?;
        let dir = abs(&dir)?;
        let wrap_file = format!("{}.v", wrapper.module);
        write_file(&dir.join(&wrap_file), &wrapper.verilog)?;
        for f in ["json", "asc", "bin"] {
            let _ = std::fs::remove_file(dir.join(format!("{}.{f}", wrapper.module)));
        }

        (self.progress)(&format!(
            "{} on {}: yosys `{}` (the top alone and in its scan wrapper) in {}",
            top.name,
            t.name,
            t.synth,
            dir.display()
        ));
        let top_script = yosys::top_script(t, &rtl, top.name);
        let wrap_script = yosys::wrapper_script(t, &rtl, &wrap_file, &wrapper.module);
        // The two netlists are independent: one yosys per core.
        let (top_area, wrapper_area) = std::thread::scope(|s| {
            let a = s.spawn(|| yosys::run(&dir, top.name, &top_script, t.arch));
            let b = s.spawn(|| yosys::run(&dir, &wrapper.module, &wrap_script, t.arch));
            let failed = |_| Err(Error("internal error: yosys thread".to_string()));
            (
                a.join().unwrap_or_else(failed),
                b.join().unwrap_or_else(failed),
            )
        });
        let (top_area, wrapper_area) = (top_area?, wrapper_area?);
        let breakdown = if self.breakdown_on.contains(&t.name) {
            (self.progress)(&format!(
                "{} on {}: yosys with each block of the top kept apart (area by block)",
                top.name, t.name
            ));
            Some(breakdown::run(&dir, t, top.name, &top.verilog())?)
        } else {
            None
        };

        let (pnr, no_fit) = match t.pnr {
            Some(device) => match self.place_and_route(top, t, device, &dir, &wrapper)? {
                Ok(p) => (Some(p), None),
                Err(nf) => {
                    let verdict = match nf.unrouted_after_s {
                        Some(_) => "does not route on",
                        None => "does not fit",
                    };
                    (self.progress)(&format!(
                        "{} on {}: {verdict} the {}: {}",
                        top.name,
                        t.name,
                        t.device,
                        nf.describe()
                    ));
                    (None, Some(nf))
                }
            },
            None => (None, None),
        };
        report.measured = Some(Measured {
            reference: Reference::of(t, &top_area),
            wrapper_overhead: wrapper_area.minus(&top_area),
            top_area,
            wrapper_area,
            wrapper: WrapperSummary {
                module: wrapper.module.clone(),
                scan_in_bits: wrapper.n_in,
                scan_out_bits: wrapper.n_out,
                can_pins: wrapper.can.len(),
            },
            pnr,
            no_fit,
            breakdown,
            build_dir: dir,
        });
        Ok(report)
    }

    /// nextpnr-ice40 on the wrapper netlist with the board's pins, then icepack;
    /// `Err(NoFit)` inside when the design does not fit the part (a result, not a
    /// failure of the flow: `--all` goes on with the next top).
    fn place_and_route(
        &self,
        top: &Top,
        t: &Target,
        device: &[&str],
        dir: &Path,
        wrapper: &Wrapper,
    ) -> Result<Result<Pnr, NoFit>, Error> {
        let pcf = abs(&self.workspace.join(t.constraints))?;
        (self.progress)(&format!(
            "{} on {}: nextpnr-ice40 {} with {}",
            top.name,
            t.name,
            device.join(" "),
            t.constraints
        ));
        let log = match nextpnr::run(dir, device, &wrapper.module, &pcf, self.pnr_limit)? {
            Ok(log) => log,
            Err(nf) => return Ok(Err(nf)),
        };
        let bitstream = icepack::run(dir, &wrapper.module)?;
        Ok(Ok(Pnr {
            tool: NEXTPNR_ICE40.cmd.to_string(),
            version: self.env.nextpnr_version.clone().unwrap_or_default(),
            fmax_mhz: log.fmax_mhz,
            constraint_mhz: log.constraint_mhz,
            clock: log.clock,
            fmax_over_recommended: log.fmax_mhz / RECOMMENDED_CLOCK_MHZ,
            utilisation: log.utilisation,
            critical_path: log.critical_path,
            bitstream,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flow_in(workspace: &Path) -> Flow<'static> {
        Flow {
            workspace: workspace.to_path_buf(),
            build_root: workspace.join("build"),
            env: ToolEnv::default(),
            progress: &|_| {},
            breakdown_on: &[],
            pnr_limit: nextpnr::DEFAULT_LIMIT,
        }
    }

    /// The wrapper is built from the block's ports, so the Verilog yosys reads
    /// must be that block's: a stale `rtl-out/` file is refused.
    #[test]
    fn stale_rtl_is_refused() {
        let top = drcc_hdl::tops::top("can_channel").unwrap();
        let ws = std::env::temp_dir().join(format!("drcc-fpga-stale-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&ws);
        let flow = flow_in(&ws);
        let missing = flow.rtl(top).unwrap_err().0;
        assert!(missing.contains("run `drcc generate` first"), "{missing}");
        let file = ws.join("rtl-out").join("can_channel.v");
        write_file(&file, &top.verilog()).unwrap();
        assert_eq!(flow.rtl(top).unwrap(), abs(&file).unwrap());
        write_file(
            &file,
            &top.verilog()
                .replace("input wire  rx;", "input wire  rx_old;"),
        )
        .unwrap();
        let stale = flow.rtl(top).unwrap_err().0;
        assert!(
            stale.contains("is not the Verilog of the drcc-hdl block"),
            "{stale}"
        );
        let _ = std::fs::remove_dir_all(&ws);
    }

    /// A family this yosys cannot synthesise gets a report with no numbers,
    /// and nothing is run.
    #[test]
    fn unsupported_family_is_reported_not_run() {
        let top = drcc_hdl::tops::top("can_channel").unwrap();
        let mut flow = flow_in(Path::new("/nonexistent"));
        flow.env.unsupported.insert(
            "xc3s",
            "yosys 0.9: `synth_xilinx` does not support `-family xc3s`".into(),
        );
        let r = flow.run(top, Target::by_name("xc3s").unwrap()).unwrap();
        assert!(r.measured.is_none());
        assert_eq!(r.board, "Digilent Spartan-3 Starter Board");
        assert!(r.unsupported.unwrap().contains("-family xc3s"));
    }
}
