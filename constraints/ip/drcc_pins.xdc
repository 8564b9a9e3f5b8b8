# SPDX-License-Identifier: Apache-2.0
# Vivado constraints for a DRCC instance's CAN pins in your own top.
# Rename can_a_* / can_b_* to your top's ports; add PACKAGE_PIN and IOSTANDARD
# as your board needs (3.3 V transceivers: LVCMOS33).

# The CAN pins are asynchronous to the core clock: rx is synchronized by two
# flip-flops inside the core, tx changes once per CAN bit (>= 1 us) from a
# register. Do not time them against the core clock.
set_false_path -from [get_ports {can_a_rx can_b_rx}]
set_false_path -to   [get_ports {can_a_tx can_b_tx}]

# The receive synchronizers (two flip-flops per rx pin, `meta` then `sync`).
# The RTL carries ASYNC_REG already; this repeats it for flows that drop
# attributes, and keeps each pair close together.
set_property ASYNC_REG TRUE [get_cells -hier -filter {NAME =~ *rx_sync/meta_reg || NAME =~ *rx_sync/sync_reg}]

# A missing transceiver reads recessive.
set_property PULLUP TRUE [get_ports {can_a_rx can_b_rx}]
