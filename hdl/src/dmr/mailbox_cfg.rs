//! The DMR mailboxes' identifier and mask memory (DMR contract §2.1, §4.1):
//! `MB_ID` ({dir, ide, id}) and `MB_MASK` of every mailbox in block RAM, with a
//! registered read port. In reset mode the read address is the host's `MB_SEL`
//! (window reads, the §2.2 identifier checks); while the DRCC runs it belongs to
//! the DMR engine's scan. The memory is not cleared by `rst` (0 after FPGA
//! configuration, as every block RAM).
//!
//! Collisions: a host write and a read of the same address meet at the write
//! edge; that read data is reloaded at the next edge, before any later access is
//! taken (every Wishbone access takes two clocks), so it is never observed.

use crate::memory::bram::Bram;
use rust_hdl::prelude::*;

/// Identifier and mask memory of 16 mailboxes.
#[derive(LogicBlock, Default)]
pub struct MailboxCfg {
    /// System clock.
    pub clk: Signal<In, Clock>,
    // ---- read port ----
    /// Mailbox to read (loaded at every edge).
    pub read_address: Signal<In, Bits<4>>,
    /// `MB_ID` of the mailbox read at the previous edge: [30] dir, [29] ide, [28:0] id.
    pub id_word: Signal<Out, Bits<31>>,
    /// `MB_MASK` of the mailbox read at the previous edge.
    pub mask: Signal<Out, Bits<29>>,
    // ---- host writes ----
    /// Mailbox written.
    pub write_address: Signal<In, Bits<4>>,
    /// Write `MB_ID` (`wdat[30:0]`) at this edge.
    pub we_id: Signal<In, Bit>,
    /// Write `MB_MASK` (`wdat[28:0]`) at this edge.
    pub we_mask: Signal<In, Bit>,
    /// The written word ([30:0] of the bus data).
    pub wdat: Signal<In, Bits<31>>,
    id_ram: Bram<Bits<31>, 4>,
    mask_ram: Bram<Bits<29>, 4>,
}

impl Logic for MailboxCfg {
    #[hdl_gen]
    fn update(&mut self) {
        self.id_ram.clk.next = self.clk.val();
        self.id_ram.read_address.next = self.read_address.val();
        self.id_ram.read_enable.next = true;
        self.id_ram.write_address.next = self.write_address.val();
        self.id_ram.write_data.next = self.wdat.val();
        self.id_ram.write_enable.next = self.we_id.val();
        self.mask_ram.clk.next = self.clk.val();
        self.mask_ram.read_address.next = self.read_address.val();
        self.mask_ram.read_enable.next = true;
        self.mask_ram.write_address.next = self.write_address.val();
        self.mask_ram.write_data.next = self.wdat.val().get_bits::<29>(0);
        self.mask_ram.write_enable.next = self.we_mask.val();
        self.id_word.next = self.id_ram.read_data.val();
        self.mask.next = self.mask_ram.read_data.val();
    }
}
