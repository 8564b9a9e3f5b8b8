// hub_shim.cpp: the C ABI around the Verilated `hub` top (Vhub). Every
// function is declared in hub_ports.h and mirrored in verilator-sys/src/lib.rs;
// the port table lives in hub_ports.h, the code in verilated_top_shim.inc.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "Vhub.h"
#include "hub_ports.h"
#include "drcc_shim_common.h"

// build.rs defines DRCC_HUB_CLK_PREV when it finds the model's "previous clk" member.
#ifdef DRCC_HUB_CLK_PREV
#include "Vhub___024root.h"
#define DRCC_SHIM_CLK_PREV DRCC_HUB_CLK_PREV
#endif

#define DRCC_SHIM_MODEL Vhub
#define DRCC_SHIM_NAME "hub"
#define DRCC_SHIM_IN HubIn
#define DRCC_SHIM_OUT HubOut
#define DRCC_SHIM_INPUTS DRCC_HUB_INPUTS
#define DRCC_SHIM_OUTPUTS DRCC_HUB_OUTPUTS
#define DRCC_SHIM_FN(f) drcc_hub_##f

#include "verilated_top_shim.inc"
