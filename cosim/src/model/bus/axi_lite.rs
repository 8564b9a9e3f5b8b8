//! The AXI4-Lite front end (contract §3): a registered bridge that holds one write
//! address, one write data beat and one read address, runs one register-port access
//! at a time (writes and reads alternate when both are ready) and holds its response
//! until the master takes it.

use super::{strobe, word_index, PortIn, PortOut, OKAY, SLVERR};

/// The AXI4-Lite inputs in one clock (prefix `s_axi_`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AxiIn {
    /// Byte address (`awaddr[1:0]` are ignored).
    pub awaddr: u16,
    pub awvalid: bool,
    pub wdata: u32,
    /// `wstrb[3:0]`.
    pub wstrb: u8,
    pub wvalid: bool,
    pub bready: bool,
    /// Byte address (`araddr[1:0]` are ignored).
    pub araddr: u16,
    pub arvalid: bool,
    pub rready: bool,
}

/// The AXI4-Lite outputs in one clock.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AxiOut {
    pub awready: bool,
    pub wready: bool,
    /// `bresp[1:0]`: [`OKAY`] or [`SLVERR`].
    pub bresp: u8,
    pub bvalid: bool,
    pub arready: bool,
    pub rdata: u32,
    /// `rresp[1:0]`: [`OKAY`] or [`SLVERR`].
    pub rresp: u8,
    pub rvalid: bool,
}

/// The AXI4-Lite bridge (§3). Every field is a register of §3, 0 after `rst`.
#[derive(Clone, Copy, Debug, Default)]
pub struct AxiLiteBridge {
    aw_full: bool,
    aw_adr: u8,
    w_full: bool,
    w_dat: u32,
    w_strb: u8,
    ar_full: bool,
    ar_adr: u8,
    cyc: bool,
    we: bool,
    last_write: bool,
    bvalid: bool,
    bresp: u8,
    rvalid: bool,
    rdata: u32,
    rresp: u8,
}

impl AxiLiteBridge {
    /// The state after `rst` (all 0).
    pub fn reset(&mut self) {
        *self = AxiLiteBridge::default();
    }

    /// The register port's inputs in the clock before the next edge (from the state
    /// only): `wb_cyc_i = wb_stb_i = cyc`, `wb_we_i = we`,
    /// `wb_adr_i = we ? aw_adr : ar_adr`, `wb_dat_i = w_dat`, `wb_sel_i = w_strb`.
    pub fn port_in(&self) -> PortIn {
        PortIn {
            cyc: self.cyc,
            we: self.we,
            adr: if self.we { self.aw_adr } else { self.ar_adr },
            dat: self.w_dat,
            sel: self.w_strb,
        }
    }

    /// One rising edge without reset: `i` = the bus inputs in the clock before the
    /// edge, `port` = the register port's outputs in that clock (i.e. after the
    /// previous edge). Rules 1 to 4 of §3, every condition on the values before the
    /// edge (Interpretation 5).
    pub fn edge(&mut self, i: &AxiIn, port: &PortOut) {
        let s = *self; // before the edge
        let n = self; // after the edge
        let done = port.ack | port.err;

        // 1. Address and data channels (`*ready` = `!*_full` before the edge).
        if i.awvalid & !s.aw_full {
            n.aw_full = true;
            n.aw_adr = word_index(i.awaddr);
        }
        if i.wvalid & !s.w_full {
            n.w_full = true;
            n.w_dat = i.wdata;
            n.w_strb = strobe(i.wstrb);
        }
        if i.arvalid & !s.ar_full {
            n.ar_full = true;
            n.ar_adr = word_index(i.araddr);
        }

        // 2. Start an access (fair arbitration when both are ready).
        if !s.cyc {
            // a held response blocks only its own kind
            let write_ready = s.aw_full & s.w_full & !s.bvalid;
            let read_ready = s.ar_full & !s.rvalid;
            let start = match (write_ready, read_ready) {
                (true, true) => Some(!s.last_write),
                (true, false) => Some(true),
                (false, true) => Some(false),
                (false, false) => None,
            };
            if let Some(write) = start {
                n.cyc = true;
                n.we = write;
                n.last_write = write;
            }
        }

        // 3. End an access.
        if s.cyc & done {
            n.cyc = false;
            let resp = if port.err { SLVERR } else { OKAY };
            if s.we {
                n.aw_full = false;
                n.w_full = false;
                n.bvalid = true;
                n.bresp = resp;
            } else {
                n.ar_full = false;
                n.rvalid = true;
                n.rdata = port.dat;
                n.rresp = resp;
            }
        }

        // 4. Responses.
        if s.bvalid & i.bready {
            n.bvalid = false;
        }
        if s.rvalid & i.rready {
            n.rvalid = false;
        }
    }

    /// The bus outputs now (from the state).
    pub fn outputs(&self) -> AxiOut {
        AxiOut {
            awready: !self.aw_full,
            wready: !self.w_full,
            bresp: self.bresp,
            bvalid: self.bvalid,
            arready: !self.ar_full,
            rdata: self.rdata,
            rresp: self.rresp,
            rvalid: self.rvalid,
        }
    }
}

#[cfg(test)]
mod tests;
