# Digilent Arty A7-35T (XC7A35TICSG324-1L): pins of the DRCC scan wrapper
# `<top>_scan` that `drcc synth --target xc7 --build-dir DIR` generates (see
# README.md here). Pin locations from Digilent's Arty-A7-35-Master.xdc.

# 100 MHz oscillator: 10 ns period
set_property -dict { PACKAGE_PIN E3 IOSTANDARD LVCMOS33 } [get_ports { clk }]
create_clock -add -name sys_clk_pin -period 10.000 -waveform {0 5} [get_ports { clk }]

# Reset, active high: push button BTN0
set_property -dict { PACKAGE_PIN D9 IOSTANDARD LVCMOS33 } [get_ports { rst }]

# CAN channel 0 (channel A) and 1 (channel B) on Pmod JA, to 3.3 V CAN
# transceivers. A top with one channel has no can1_* ports: Vivado warns and
# skips those two lines.
set_property -dict { PACKAGE_PIN G13 IOSTANDARD LVCMOS33 } [get_ports { can0_tx }]   ;# JA1
set_property -dict { PACKAGE_PIN B11 IOSTANDARD LVCMOS33 } [get_ports { can0_rx }]   ;# JA2
set_property -dict { PACKAGE_PIN A11 IOSTANDARD LVCMOS33 } [get_ports { can1_tx }]   ;# JA3
set_property -dict { PACKAGE_PIN D12 IOSTANDARD LVCMOS33 } [get_ports { can1_rx }]   ;# JA4

# Scan chain (host ports of the top) on Pmod JB
set_property -dict { PACKAGE_PIN E15 IOSTANDARD LVCMOS33 } [get_ports { scan_clk }]  ;# JB1
set_property -dict { PACKAGE_PIN E16 IOSTANDARD LVCMOS33 } [get_ports { scan_en }]   ;# JB2
set_property -dict { PACKAGE_PIN D15 IOSTANDARD LVCMOS33 } [get_ports { scan_in }]   ;# JB3
set_property -dict { PACKAGE_PIN C15 IOSTANDARD LVCMOS33 } [get_ports { scan_out }]  ;# JB4

# The scan and CAN pins are asynchronous to clk (the wrapper and the channel
# synchronise them); do not time them against it.
set_false_path -from [get_ports { rst scan_clk scan_en scan_in can*_rx }]
set_false_path -to [get_ports { scan_out can*_tx }]
