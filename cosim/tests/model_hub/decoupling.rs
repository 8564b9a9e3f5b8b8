//! Decoupling (hub contract §7): sticky until recouple, forced decoupling, and
//! what entering reset mode clears.

use super::*;

#[test]
fn decoupling_after_decouple_bits_is_sticky_until_recouple() {
    let cfg = [(RESTORE_CFG, 10 | 30 << 16)];
    let mut b = Bench::running(2, 1, &cfg, true);
    // The only sublink stuck dominant: isolated at its 28th sample (sd_run_sub 28).
    b.pins = 0b011;
    let k = b.now();
    for _ in 0..70 * CPB {
        b.step();
    }
    let iso = k + 8 + 27 * CPB;
    // §6.1: in the guard registers one clock after the SAMPLE edge
    assert!(!enabled(&b.log[iso + 1], 2));
    // no_twin counts from the next sample (the isolation edge still had it
    // enabled before the edge): decoupled at the 30th sample after it.
    let dec = iso + 30 * CPB;
    assert!(!b.log[dec - 1].probes.decoupled);
    assert!(b.log[dec].probes.decoupled);
    // Released and quiet for far longer than restore_bits: frozen while decoupled.
    b.pins = 0b111;
    b.idle_bits(100);
    assert!(b.log[b.now() - 1].probes.decoupled);
    assert_eq!(b.read(STATUS) & 0b10, 0b10);
    assert_eq!(b.read(STATUS) >> 16, 0b011);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION | INT_DECOUPLED);
    // recouple: at the write edge, decoupled cleared and the sublink enabled with
    // its kind and counts kept.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: CTRL,
        wb_dat_w: ACK_INTERDEP | RECOUPLE,
        ..b.pin_inputs()
    });
    assert!(!o.probes.decoupled && enabled(&o, 2));
    b.step();
    assert_eq!(b.port_reg(2), 1 | 1 << 1 | 1 << 16);
    assert_eq!(b.read(CTRL), ACK_INTERDEP, "commands read 0");
}

#[test]
fn forced_decoupling_makes_the_hub_a_star_of_its_own() {
    let mut b = Bench::running(2, 1, &[], true);
    b.write(CTRL, ACK_INTERDEP | FORCE_DECOUPLE);
    assert!(b.log[b.now() - 2].probes.decoupled, "at the write edge");
    assert_eq!(b.read(INT_STATUS), INT_DECOUPLED);
    // The twin (sublink, still enabled) no longer reaches the hub's view.
    b.pins = 0b011;
    let s = b.step();
    b.step();
    b.step();
    assert!(b.log[s + 2].probes.coupled);
    assert_eq!(b.log[s + 2].downlink, 0b11);
    assert_eq!(b.read(STATUS) >> 16, 0b111);
    // Own nodes still do, and go to the twin.
    b.pins = 0b010;
    let s = b.step();
    b.step();
    b.step();
    assert!(!b.log[s + 2].probes.coupled);
    assert_eq!((b.log[s + 2].downlink, b.log[s + 2].sublink_out), (0, 0));
    // recouple: the twin counts again.
    b.pins = 0b111;
    b.idle_bits(2);
    b.write(CTRL, ACK_INTERDEP | RECOUPLE);
    b.pins = 0b011;
    let s = b.step();
    b.step();
    b.step();
    assert!(!b.log[s + 2].probes.coupled);
    // Commands in reset mode do nothing.
    b.pins = 0b111;
    b.idle_bits(2);
    b.write(CTRL, ACK_INTERDEP | RESET_MODE);
    b.write(CTRL, ACK_INTERDEP | RESET_MODE | FORCE_DECOUPLE);
    assert!(
        !b.log[b.now() - 2].probes.decoupled,
        "not at the write edge"
    );
    assert_eq!(b.read(STATUS) & 0b10, 0);
}

#[test]
fn entering_reset_mode_clears_the_guards_but_keeps_int_status() {
    let mut b = Bench::running(2, 1, &[], true);
    b.drive(&[0b110; 20]);
    b.idle_bits(2);
    assert_eq!(b.port_reg(0) & 1, 0);
    b.write(CTRL, ACK_INTERDEP | RESET_MODE);
    // §6.1: the hold reaches the guard registers one edge after the decision
    // state (held from the write's next edge on)
    b.step();
    assert_eq!(b.port_reg(0), 1);
    assert_eq!(b.read(STATUS), 1 | 0b111 << 16);
    assert_eq!(b.read(STATS), 0);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
}
