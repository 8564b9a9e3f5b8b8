// drcc_shim.cpp: the C ABI around the Verilated `drcc` top (Vdrcc). Every
// function is declared in drcc_ports.h and mirrored in verilator-sys/src/lib.rs;
// the port table lives in drcc_ports.h, the code in verilated_top_shim.inc.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "Vdrcc.h"
#include "drcc_ports.h"
#include "drcc_shim_common.h"

// build.rs defines DRCC_DRCC_CLK_PREV when it finds the model's "previous clk" member.
#ifdef DRCC_DRCC_CLK_PREV
#include "Vdrcc___024root.h"
#define DRCC_SHIM_CLK_PREV DRCC_DRCC_CLK_PREV
#endif

#define DRCC_SHIM_MODEL Vdrcc
#define DRCC_SHIM_NAME "drcc"
#define DRCC_SHIM_IN DrccIn
#define DRCC_SHIM_OUT DrccOut
#define DRCC_SHIM_INPUTS DRCC_DRCC_INPUTS
#define DRCC_SHIM_OUTPUTS DRCC_DRCC_OUTPUTS
#define DRCC_SHIM_FN(f) drcc_drcc_##f

#include "verilated_top_shim.inc"
