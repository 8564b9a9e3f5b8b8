// can_channel_shim.cpp: the C ABI around the Verilated `can_channel` top (Vcan_channel). Every
// function is declared in can_channel_ports.h and mirrored in verilator-sys/src/lib.rs;
// the port table lives in can_channel_ports.h, the code in verilated_top_shim.inc.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "Vcan_channel.h"
#include "can_channel_ports.h"
#include "drcc_shim_common.h"

// build.rs defines DRCC_CAN_CHANNEL_CLK_PREV when it finds the model's "previous clk" member.
#ifdef DRCC_CAN_CHANNEL_CLK_PREV
#include "Vcan_channel___024root.h"
#define DRCC_SHIM_CLK_PREV DRCC_CAN_CHANNEL_CLK_PREV
#endif

#define DRCC_SHIM_MODEL Vcan_channel
#define DRCC_SHIM_NAME "can_channel"
#define DRCC_SHIM_IN CanChannelIn
#define DRCC_SHIM_OUT CanChannelOut
#define DRCC_SHIM_INPUTS DRCC_CAN_CHANNEL_INPUTS
#define DRCC_SHIM_OUTPUTS DRCC_CAN_CHANNEL_OUTPUTS
#define DRCC_SHIM_FN(f) drcc_can_channel_##f

#include "verilated_top_shim.inc"
