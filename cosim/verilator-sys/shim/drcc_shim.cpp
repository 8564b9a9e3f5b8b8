// drcc_shim.cpp: the C ABI around the Verilated `drcc` top
// (Vdrcc). Every function here is declared in drcc_ports.h and
// mirrored in verilator-sys/src/lib.rs. The port table itself lives in
// drcc_ports.h; nothing in this file names an individual port except clk.
//
// Clocking and trace time: step() applies the inputs, evaluates with clk=0, then
// with clk=1 (one rising edge), and copies the outputs. With a trace open, step
// number n (counted from 0 since the instance was created) dumps the clk=0 phase at
// VCD time 2n and the clk=1 phase at 2n+1: one VCD time unit is half a clock period,
// whatever $timescale the file header states.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "Vdrcc.h"
#include "drcc_ports.h"
#include "drcc_shim_common.h"

// build.rs defines DRCC_DRCC_CLK_PREV as the name of the model's internal
// "clk at the previous eval" member when it finds exactly one (Verilator 5.006:
// __Vtrigrprev__TOP__clk); without it every step makes two evals.
#ifdef DRCC_DRCC_CLK_PREV
#include "Vdrcc___024root.h"
#endif

namespace {

using Inst = drcc::Instance<Vdrcc>;

/// Prepares a single eval with clk=1 to see a rising edge; false if unsupported.
inline bool armEdge(Vdrcc& t) {
#ifdef DRCC_DRCC_CLK_PREV
    t.rootp->DRCC_DRCC_CLK_PREV = 0;
    return true;
#else
    (void)t;
    return false;
#endif
}

// Every listed port must exist on the model with a storage type no wider than the
// struct field (a port that changes from 8 to 9 bits fails here, not silently).
#define DRCC_CHECK_PORT(ctype, name, width)                        \
    static_assert(sizeof(Vdrcc::name) <= sizeof(ctype),     \
                  "drcc port " #name " no longer fits its port-table type");
DRCC_DRCC_INPUTS(DRCC_CHECK_PORT)
DRCC_DRCC_OUTPUTS(DRCC_CHECK_PORT)
#undef DRCC_CHECK_PORT

static_assert(std::is_standard_layout<DrccIn>::value, "DrccIn must be plain C");
static_assert(std::is_standard_layout<DrccOut>::value, "DrccOut must be plain C");

}  // namespace

extern "C" uint64_t drcc_drcc_abi(void) {
    drcc::LayoutHash h;
#define DRCC_HASH_IN(type, name, width) \
    h.field(#name, offsetof(DrccIn, name), sizeof(type), width);
#define DRCC_HASH_OUT(type, name, width) \
    h.field(#name, offsetof(DrccOut, name), sizeof(type), width);
    DRCC_DRCC_INPUTS(DRCC_HASH_IN)
    h.end(sizeof(DrccIn));
    DRCC_DRCC_OUTPUTS(DRCC_HASH_OUT)
    h.end(sizeof(DrccOut));
#undef DRCC_HASH_IN
#undef DRCC_HASH_OUT
    return h.h;
}

extern "C" void* drcc_drcc_new(void) { return drcc::newInstance<Vdrcc>(); }

extern "C" void drcc_drcc_free(void* handle) { delete static_cast<Inst*>(handle); }

extern "C" void drcc_drcc_step(void* handle, const DrccIn* in, DrccOut* out) {
    Inst* const s = static_cast<Inst*>(handle);
    Vdrcc& t = s->top;
    // Inputs are masked to their port width: Verilator assumes unused high bits are 0.
#define DRCC_SET_IN(type, name, width) t.name = in->name & drcc::mask<type, width>();
    DRCC_DRCC_INPUTS(DRCC_SET_IN)
#undef DRCC_SET_IN
    s->clockEdge(armEdge);
#define DRCC_GET_OUT(type, name, width) out->name = static_cast<type>(t.name);
    DRCC_DRCC_OUTPUTS(DRCC_GET_OUT)
#undef DRCC_GET_OUT
}

extern "C" int drcc_drcc_fast_edge(void) {
#ifdef DRCC_DRCC_CLK_PREV
    return 1;
#else
    return 0;
#endif
}

extern "C" void drcc_drcc_set_exact(void* handle, int exact) {
    static_cast<Inst*>(handle)->exact = exact != 0;
}

extern "C" int drcc_drcc_trace_open(void* handle, const char* path) {
    return static_cast<Inst*>(handle)->traceOpen(path);
}

extern "C" void drcc_drcc_trace_dump(void* handle, uint64_t time) {
    static_cast<Inst*>(handle)->traceDump(time);
}

extern "C" void drcc_drcc_trace_close(void* handle) {
    static_cast<Inst*>(handle)->traceClose();
}
