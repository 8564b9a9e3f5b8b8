// SPDX-License-Identifier: Apache-2.0
// dual_bus.v: two DRCC nodes on a dual CAN bus, for the cocotb bench
// (test_dual_bus.py). Each line is the wired-AND of the nodes' transmit pins
// (1 = recessive), as two transceivers on one cable make it. `cut_a` cuts line A
// between the nodes: each node's channel A then hears only itself (no
// acknowledgement, no frames from the other node), a fault the redundancy must
// hide. Copy it as the start of your own bench: node N's Wishbone is nN_*.
// dual_bus_apb.v and dual_bus_axi.v are the same bench on the APB and
// AXI4-Lite tops.
`timescale 1ns/1ps
module dual_bus (
    input  wire        clk,
    input  wire        rst,
    // node 0, Wishbone B4 classic (word addresses)
    input  wire        n0_cyc,
    input  wire        n0_stb,
    input  wire        n0_we,
    input  wire [5:0]  n0_adr,
    input  wire [31:0] n0_datwr,
    input  wire [3:0]  n0_sel,
    output wire [31:0] n0_datrd,
    output wire        n0_ack,
    output wire        n0_err,
    output wire        n0_irq,
    // node 1
    input  wire        n1_cyc,
    input  wire        n1_stb,
    input  wire        n1_we,
    input  wire [5:0]  n1_adr,
    input  wire [31:0] n1_datwr,
    input  wire [3:0]  n1_sel,
    output wire [31:0] n1_datrd,
    output wire        n1_ack,
    output wire        n1_err,
    output wire        n1_irq,
    // faults
    input  wire        cut_a,
    // the lines, to watch
    output wire        line_a,
    output wire        line_b
);
    wire n0_a_tx, n0_b_tx, n1_a_tx, n1_b_tx;
    assign line_a = n0_a_tx & n1_a_tx;
    assign line_b = n0_b_tx & n1_b_tx;
    wire n0_a_rx = cut_a ? n0_a_tx : line_a;
    wire n1_a_rx = cut_a ? n1_a_tx : line_a;

    drcc n0 (
        .clk(clk), .rst(rst),
        .wb_cyc_i(n0_cyc), .wb_stb_i(n0_stb), .wb_we_i(n0_we), .wb_adr_i(n0_adr),
        .wb_dat_i(n0_datwr), .wb_sel_i(n0_sel), .wb_dat_o(n0_datrd), .wb_ack_o(n0_ack),
        .wb_err_o(n0_err), .irq(n0_irq),
        .chan_a_tx(n0_a_tx), .chan_a_rx(n0_a_rx), .chan_b_tx(n0_b_tx), .chan_b_rx(line_b)
    );
    drcc n1 (
        .clk(clk), .rst(rst),
        .wb_cyc_i(n1_cyc), .wb_stb_i(n1_stb), .wb_we_i(n1_we), .wb_adr_i(n1_adr),
        .wb_dat_i(n1_datwr), .wb_sel_i(n1_sel), .wb_dat_o(n1_datrd), .wb_ack_o(n1_ack),
        .wb_err_o(n1_err), .irq(n1_irq),
        .chan_a_tx(n1_a_tx), .chan_a_rx(n1_a_rx), .chan_b_tx(n1_b_tx), .chan_b_rx(line_b)
    );
endmodule
