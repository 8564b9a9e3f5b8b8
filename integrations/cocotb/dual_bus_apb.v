// SPDX-License-Identifier: Apache-2.0
// dual_bus_apb.v: dual_bus.v on the APB top (rtl-out/drcc_apb.v): two DRCC
// nodes on a dual CAN bus, each line the wired-AND of the nodes' transmit pins
// (1 = recessive); `cut_a` cuts line A between the nodes. Node N's APB4 slave is
// nN_p*, named so that cocotbext-apb's ApbBus.from_prefix(dut, "nN") finds it.
`timescale 1ns/1ps
module dual_bus_apb (
    input  wire        clk,
    input  wire        rst,
    // node 0, APB4 (byte addresses)
    input  wire        n0_psel,
    input  wire        n0_penable,
    input  wire        n0_pwrite,
    input  wire [7:0]  n0_paddr,
    input  wire [31:0] n0_pwdata,
    input  wire [3:0]  n0_pstrb,
    output wire [31:0] n0_prdata,
    output wire        n0_pready,
    output wire        n0_pslverr,
    output wire        n0_irq,
    // node 1
    input  wire        n1_psel,
    input  wire        n1_penable,
    input  wire        n1_pwrite,
    input  wire [7:0]  n1_paddr,
    input  wire [31:0] n1_pwdata,
    input  wire [3:0]  n1_pstrb,
    output wire [31:0] n1_prdata,
    output wire        n1_pready,
    output wire        n1_pslverr,
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

    drcc_apb n0 (
        .clk(clk), .rst(rst),
        .s_apb_psel(n0_psel), .s_apb_penable(n0_penable), .s_apb_pwrite(n0_pwrite),
        .s_apb_paddr(n0_paddr), .s_apb_pwdata(n0_pwdata), .s_apb_pstrb(n0_pstrb),
        .s_apb_prdata(n0_prdata), .s_apb_pready(n0_pready), .s_apb_pslverr(n0_pslverr),
        .irq(n0_irq),
        .chan_a_tx(n0_a_tx), .chan_a_rx(n0_a_rx), .chan_b_tx(n0_b_tx), .chan_b_rx(line_b)
    );
    drcc_apb n1 (
        .clk(clk), .rst(rst),
        .s_apb_psel(n1_psel), .s_apb_penable(n1_penable), .s_apb_pwrite(n1_pwrite),
        .s_apb_paddr(n1_paddr), .s_apb_pwdata(n1_pwdata), .s_apb_pstrb(n1_pstrb),
        .s_apb_prdata(n1_prdata), .s_apb_pready(n1_pready), .s_apb_pslverr(n1_pslverr),
        .irq(n1_irq),
        .chan_a_tx(n1_a_tx), .chan_a_rx(n1_a_rx), .chan_b_tx(n1_b_tx), .chan_b_rx(line_b)
    );
endmodule
