// SPDX-License-Identifier: Apache-2.0
// dual_bus_axi.v: dual_bus.v on the AXI4-Lite top (rtl-out/drcc_axi.v): two
// DRCC nodes on a dual CAN bus, each line the wired-AND of the nodes' transmit
// pins (1 = recessive); `cut_a` cuts line A between the nodes. Node N's
// AXI4-Lite slave is nN_*, named so that cocotbext-axi's
// AxiLiteBus.from_prefix(dut, "nN") finds it.
`timescale 1ns/1ps
module dual_bus_axi (
    input  wire        clk,
    input  wire        rst,
    // node 0, AXI4-Lite (byte addresses)
    input  wire [7:0]  n0_awaddr,
    input  wire        n0_awvalid,
    output wire        n0_awready,
    input  wire [31:0] n0_wdata,
    input  wire [3:0]  n0_wstrb,
    input  wire        n0_wvalid,
    output wire        n0_wready,
    output wire [1:0]  n0_bresp,
    output wire        n0_bvalid,
    input  wire        n0_bready,
    input  wire [7:0]  n0_araddr,
    input  wire        n0_arvalid,
    output wire        n0_arready,
    output wire [31:0] n0_rdata,
    output wire [1:0]  n0_rresp,
    output wire        n0_rvalid,
    input  wire        n0_rready,
    output wire        n0_irq,
    // node 1
    input  wire [7:0]  n1_awaddr,
    input  wire        n1_awvalid,
    output wire        n1_awready,
    input  wire [31:0] n1_wdata,
    input  wire [3:0]  n1_wstrb,
    input  wire        n1_wvalid,
    output wire        n1_wready,
    output wire [1:0]  n1_bresp,
    output wire        n1_bvalid,
    input  wire        n1_bready,
    input  wire [7:0]  n1_araddr,
    input  wire        n1_arvalid,
    output wire        n1_arready,
    output wire [31:0] n1_rdata,
    output wire [1:0]  n1_rresp,
    output wire        n1_rvalid,
    input  wire        n1_rready,
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

    drcc_axi n0 (
        .clk(clk), .rst(rst),
        .s_axi_awaddr(n0_awaddr), .s_axi_awvalid(n0_awvalid), .s_axi_awready(n0_awready),
        .s_axi_wdata(n0_wdata), .s_axi_wstrb(n0_wstrb), .s_axi_wvalid(n0_wvalid),
        .s_axi_wready(n0_wready),
        .s_axi_bresp(n0_bresp), .s_axi_bvalid(n0_bvalid), .s_axi_bready(n0_bready),
        .s_axi_araddr(n0_araddr), .s_axi_arvalid(n0_arvalid), .s_axi_arready(n0_arready),
        .s_axi_rdata(n0_rdata), .s_axi_rresp(n0_rresp), .s_axi_rvalid(n0_rvalid),
        .s_axi_rready(n0_rready),
        .irq(n0_irq),
        .chan_a_tx(n0_a_tx), .chan_a_rx(n0_a_rx), .chan_b_tx(n0_b_tx), .chan_b_rx(line_b)
    );
    drcc_axi n1 (
        .clk(clk), .rst(rst),
        .s_axi_awaddr(n1_awaddr), .s_axi_awvalid(n1_awvalid), .s_axi_awready(n1_awready),
        .s_axi_wdata(n1_wdata), .s_axi_wstrb(n1_wstrb), .s_axi_wvalid(n1_wvalid),
        .s_axi_wready(n1_wready),
        .s_axi_bresp(n1_bresp), .s_axi_bvalid(n1_bvalid), .s_axi_bready(n1_bready),
        .s_axi_araddr(n1_araddr), .s_axi_arvalid(n1_arvalid), .s_axi_arready(n1_arready),
        .s_axi_rdata(n1_rdata), .s_axi_rresp(n1_rresp), .s_axi_rvalid(n1_rvalid),
        .s_axi_rready(n1_rready),
        .irq(n1_irq),
        .chan_a_tx(n1_a_tx), .chan_a_rx(n1_a_rx), .chan_b_tx(n1_b_tx), .chan_b_rx(line_b)
    );
endmodule
