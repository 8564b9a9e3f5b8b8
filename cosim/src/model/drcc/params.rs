//! Generation parameters of the DRCC (drcc_contract.md §1.1): the sizes fixed
//! when the Verilog is generated. The model takes them at construction; the
//! default is the configuration every proof of the repository ran on.

/// The sizes of one DRCC configuration (contract §1.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DrccParams {
    /// DMR mailboxes `M` (DMR contract §2).
    pub mailboxes: usize,
    /// RX FIFO entries (§7).
    pub rx_fifo_depth: u8,
    /// Entries of each TX queue (§6).
    pub tx_queue_depth: u8,
    /// Duplicate-removal history entries `H` (§7).
    pub history: u8,
    /// The CiA 701 DMR function: without it `CTRL.dmr` cannot be set (§1.1).
    pub dmr: bool,
    /// The replicated-star node: without it `CTRL.star` cannot be set (§1.1).
    pub star: bool,
}

impl DrccParams {
    /// `drcc`: M = 16, RX FIFO 32, TX queues 8, history 32.
    pub const DEFAULT: DrccParams = DrccParams {
        mailboxes: 16,
        rx_fifo_depth: 32,
        tx_queue_depth: 8,
        history: 32,
        dmr: true,
        star: true,
    };

    /// `drcc_small`: no DMR, no star node, M = 0, RX FIFO 8, TX queues 4,
    /// history 16.
    pub const SMALL: DrccParams = DrccParams {
        mailboxes: 0,
        rx_fifo_depth: 8,
        tx_queue_depth: 4,
        history: 16,
        dmr: false,
        star: false,
    };

    /// The default sizes with `m` mailboxes (`drcc_m0`: 0).
    pub fn with_mailboxes(m: usize) -> Self {
        DrccParams {
            mailboxes: m,
            ..Self::DEFAULT
        }
    }
}

impl Default for DrccParams {
    fn default() -> Self {
        Self::DEFAULT
    }
}
