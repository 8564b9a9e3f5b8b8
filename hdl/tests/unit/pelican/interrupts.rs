//! Tests of `drcc_hdl::pelican::interrupts` against the SJA1000 data sheet's IR
//! and IER (6.4.6: RI "set while the receive FIFO is not empty", the other bits
//! set by their events and "reset by a read access of the interrupt register";
//! EI "set on every change of either the error status or bus status") and
//! pelican_contract.md §9 (P-IR-1..6, P-IRQ-1, P-MOD-5, P-MOD-6).

use drcc_hdl::pelican::interrupts::Interrupts;
use rust_hdl::prelude::*;

// IR / IER bits (data sheet 6.4.6, 6.4.7)
const RI: u64 = 0x01;
const TI: u64 = 0x02;
const EI: u64 = 0x04;
const DOI: u64 = 0x08;
const EPI: u64 = 0x20;
const ALI: u64 = 0x40;
const BEI: u64 = 0x80;
const ALL: u64 = 0xFF;

const ACTIVE: u64 = 0;
const PASSIVE: u64 = 1;
const BUS_OFF: u64 = 2;

/// One rising edge; the one-edge inputs drop after it.
fn edge(uut: &mut Interrupts) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
    uut.ier_write.next = false;
    uut.ir_read.next = false;
    uut.rm_rise.next = false;
    uut.ti_evt.next = false;
    uut.doi_evt.next = false;
    uut.bei_evt.next = false;
    uut.ali_evt.next = false;
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
}

fn fresh(ier: u64) -> Interrupts {
    let mut uut = Interrupts::default();
    uut.connect_all();
    uut.wdata.next = 0u64.into();
    uut.rm.next = false;
    uut.rbs.next = false;
    uut.es.next = false;
    uut.bs.next = false;
    uut.err_state.next = ACTIVE.into();
    uut.xir_pending.next = false;
    uut.rst.next = true;
    edge(&mut uut);
    uut.rst.next = false;
    uut.ier_write.next = true;
    uut.wdata.next = ier.into();
    edge(&mut uut);
    uut
}

fn ir(uut: &Interrupts) -> u64 {
    uut.ir_q.val().to_u64()
}

/// A read of IR taken at an edge: returns the value read (before the edge).
fn read_ir(uut: &mut Interrupts) -> u64 {
    let v = ir(uut);
    uut.ir_read.next = true;
    edge(uut);
    v
}

#[test]
fn reset_clears_ir_ier_and_irq() {
    let mut uut = fresh(0);
    uut.rst.next = true;
    edge(&mut uut);
    assert_eq!(
        (ir(&uut), uut.ier_q.val().to_u64(), uut.irq.val()),
        (0, 0, false)
    );
}

#[test]
fn ri_is_a_level_of_rbs_and_rie() {
    let mut uut = fresh(RI);
    uut.rbs.next = true;
    edge(&mut uut);
    assert_eq!(ir(&uut), RI, "P-IR-2");
    assert!(uut.irq.val(), "P-IRQ-1: irq one clock after the bit");
    // a read does not clear it; the FIFO emptying does
    assert_eq!(read_ir(&mut uut), RI);
    assert_eq!(ir(&uut), RI);
    uut.rbs.next = false;
    edge(&mut uut);
    assert_eq!(ir(&uut), 0);
    edge(&mut uut);
    assert!(!uut.irq.val());
    // RIE 0: no RI
    let mut uut = fresh(0);
    uut.rbs.next = true;
    edge(&mut uut);
    assert_eq!(ir(&uut), 0);
}

#[test]
fn an_event_sets_its_bit_only_if_enabled_before_the_edge() {
    let mut uut = fresh(0);
    uut.ti_evt.next = true;
    uut.ier_write.next = true;
    uut.wdata.next = TI.into();
    edge(&mut uut);
    assert_eq!(
        ir(&uut),
        0,
        "P-IR-2: a later IER write raises no past event"
    );
    uut.ti_evt.next = true;
    edge(&mut uut);
    assert_eq!(ir(&uut), TI);
}

#[test]
fn a_read_clears_and_an_event_at_the_read_wins() {
    let mut uut = fresh(ALL);
    uut.ti_evt.next = true;
    uut.doi_evt.next = true;
    uut.bei_evt.next = true;
    uut.ali_evt.next = true;
    edge(&mut uut);
    assert_eq!(ir(&uut), TI | DOI | BEI | ALI);
    uut.ali_evt.next = true;
    assert_eq!(read_ir(&mut uut), TI | DOI | BEI | ALI);
    assert_eq!(ir(&uut), ALI, "P-IR-3: the event of the read edge stays");
    assert_eq!(read_ir(&mut uut), ALI);
    assert_eq!(ir(&uut), 0);
}

#[test]
fn no_event_in_reset_mode() {
    let mut uut = fresh(ALL);
    uut.rm.next = true;
    uut.ti_evt.next = true;
    uut.bei_evt.next = true;
    uut.es.next = true;
    uut.err_state.next = PASSIVE.into();
    edge(&mut uut);
    assert_eq!(ir(&uut), 0, "P-MOD-6");
    // the comparison registers followed: no event on leaving reset mode
    uut.rm.next = false;
    edge(&mut uut);
    assert_eq!(ir(&uut), 0);
}

#[test]
fn ei_marks_every_change_of_es_and_bs() {
    let mut uut = fresh(EI);
    uut.es.next = true;
    edge(&mut uut);
    assert_eq!(read_ir(&mut uut), EI, "ES 0 -> 1");
    edge(&mut uut);
    assert_eq!(ir(&uut), 0, "no change, no event");
    uut.bs.next = true;
    edge(&mut uut);
    assert_eq!(read_ir(&mut uut), EI, "BS 0 -> 1");
    uut.bs.next = false;
    uut.es.next = false;
    edge(&mut uut);
    assert_eq!(read_ir(&mut uut), EI, "both fall");
}

#[test]
fn entering_reset_mode_clears_all_but_ei_and_the_bus_off_sets_ei() {
    let mut uut = fresh(ALL);
    uut.ti_evt.next = true;
    uut.doi_evt.next = true;
    uut.ali_evt.next = true;
    uut.bei_evt.next = true;
    edge(&mut uut);
    // the bus-off edge: BS rises, the hold sets RM (P-BO-1, P-BO-2, P-MOD-5)
    uut.bs.next = true;
    uut.err_state.next = BUS_OFF.into();
    uut.rm_rise.next = true;
    uut.ti_evt.next = true;
    uut.clk.next = Clock::from(false);
    assert!(simulate(&mut uut, 100));
    assert!(uut.bs_rise.val(), "the rise the mode unit takes");
    edge(&mut uut);
    assert_eq!(
        ir(&uut),
        EI,
        "TI, DOI, ALI, BEI cleared; EI set by the bus-off"
    );
}

#[test]
fn epi_marks_passive_and_its_end_unless_es_falls_with_it() {
    let mut uut = fresh(EPI);
    uut.err_state.next = PASSIVE.into();
    uut.es.next = true;
    edge(&mut uut);
    assert_eq!(read_ir(&mut uut), EPI, "active -> passive");
    // passive -> active with the counters below the warning limit already
    uut.es.next = false;
    edge(&mut uut);
    uut.err_state.next = ACTIVE.into();
    edge(&mut uut);
    assert_eq!(read_ir(&mut uut), EPI, "passive -> active");
    // passive -> active with ES falling at the same edge (a switchover)
    uut.err_state.next = PASSIVE.into();
    uut.es.next = true;
    edge(&mut uut);
    read_ir(&mut uut);
    uut.err_state.next = ACTIVE.into();
    uut.es.next = false;
    edge(&mut uut);
    assert_eq!(ir(&uut), 0, "P-IR-6: EI alone reports it");
    // passive -> bus-off and bus-off -> active raise none
    uut.err_state.next = PASSIVE.into();
    edge(&mut uut);
    read_ir(&mut uut);
    uut.err_state.next = BUS_OFF.into();
    edge(&mut uut);
    assert_eq!(ir(&uut), 0);
    uut.err_state.next = ACTIVE.into();
    edge(&mut uut);
    assert_eq!(ir(&uut), 0);
}

#[test]
fn an_enabled_extension_interrupt_raises_irq() {
    let mut uut = fresh(0);
    uut.xir_pending.next = true;
    uut.clk.next = Clock::from(false);
    assert!(simulate(&mut uut, 100));
    assert!(!uut.irq.val(), "registered");
    edge(&mut uut);
    assert!(uut.irq.val(), "P-IRQ-1");
    assert_eq!(ir(&uut), 0);
}

#[test]
fn interrupts_synthesizes() {
    let mut uut = Interrupts::default();
    uut.connect_all();
    crate::synth_check::yosys_check("interrupts", &generate_verilog(&uut));
}
