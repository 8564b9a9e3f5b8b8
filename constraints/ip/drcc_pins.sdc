# SPDX-License-Identifier: Apache-2.0
# SDC constraints (Quartus TimeQuest, Libero SmartTime, Radiant) for a DRCC
# instance's CAN pins in your own top. Rename can_a_* / can_b_* to your ports.

# The CAN pins are asynchronous to the core clock: rx is synchronized by two
# flip-flops inside the core (marked for synchronizer identification in the
# RTL), tx changes once per CAN bit (>= 1 us) from a register.
set_false_path -from [get_ports {can_a_rx can_b_rx}]
set_false_path -to   [get_ports {can_a_tx can_b_tx}]
