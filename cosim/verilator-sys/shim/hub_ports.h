// hub_ports.h: the port table of the Verilated `hub` top (N = 4 node ports,
// M = 2 interlinks) and the plain-C ABI built from it (structs HubIn / HubOut and
// the drcc_hub_* functions implemented in hub_shim.cpp).
//
// THIS TABLE IS THE ONE PLACE TO EDIT WHEN THE RTL PORTS CHANGE, together with its
// mirror `HubIn` / `HubOut` in ../src/lib.rs (same order, same types)
// and the conversion in cosim/src/engine/hub_verilator.rs.
//  - build.rs parses the X(...) lines below and compares them with the ports
//    Verilator reports in Vhub.h (direction and bit width): a mismatch stops
//    the build with a message naming the port.
//  - The layout (name, offset, size, width of every field) is hashed on both sides;
//    Hub::new() in Rust refuses to run if the hashes differ.
// Format: X(c_type, port_name, bit_width), one port per line, in struct order.
// `clk` is driven by the shim, not listed here. Single-bit ports are uint8_t
// holding 0 or 1.

#ifndef DRCC_HUB_PORTS_H
#define DRCC_HUB_PORTS_H

#include <stdint.h>

// clang-format off
#define DRCC_HUB_INPUTS(X) \
    X(uint8_t,  rst,                            1)   \
    X(uint8_t,  wb_cyc_i,                       1)   \
    X(uint8_t,  wb_stb_i,                       1)   \
    X(uint8_t,  wb_we_i,                        1)   \
    X(uint8_t,  wb_adr_i,                       6)   \
    X(uint32_t, wb_dat_i,                       32)   \
    X(uint8_t,  uplink,                         4)   \
    X(uint8_t,  sublink_in,                     2)

#define DRCC_HUB_OUTPUTS(X) \
    X(uint32_t, wb_dat_o,                       32)   \
    X(uint8_t,  wb_ack_o,                       1)   \
    X(uint8_t,  irq,                            1)   \
    X(uint8_t,  downlink,                       4)   \
    X(uint8_t,  sublink_out,                    2)   \
    X(uint8_t,  coupled,                        1)   \
    X(uint8_t,  sample_point,                   1)   \
    X(uint8_t,  trk_state,                      2)   \
    X(uint8_t,  ack_window,                     1)   \
    X(uint8_t,  decoupled,                      1)   \
    X(uint8_t,  port_enabled,                   6)
// clang-format on

#define DRCC_PORT_FIELD(type, name, width) type name;

/// Every input of `hub` except `clk`, sampled at the rising edge made by step().
typedef struct HubIn {
    DRCC_HUB_INPUTS(DRCC_PORT_FIELD)
} HubIn;

/// Every output of `hub`, as it is right after the rising edge.
typedef struct HubOut {
    DRCC_HUB_OUTPUTS(DRCC_PORT_FIELD)
} HubOut;

#undef DRCC_PORT_FIELD

#ifdef __cplusplus
extern "C" {
#endif

/// Layout fingerprint of HubIn/HubOut (see drcc_shim_common.h).
uint64_t drcc_hub_abi(void);
/// New instance with its own VerilatedContext; NULL on allocation failure.
void* drcc_hub_new(void);
/// Frees an instance (closes its trace first). NULL is ignored.
void drcc_hub_free(void* handle);
/// Applies *in, makes one rising edge of clk (evaluating clk=0 then clk=1, or a
/// single equivalent eval, see drcc_hub_fast_edge), copies the outputs to *out.
void drcc_hub_step(void* handle, const HubIn* in, HubOut* out);
/// 1 if step() can make one eval per clock instead of two (see drcc_shim_common.h).
int drcc_hub_fast_edge(void);
/// exact != 0: always two evals per clock (clk=0, clk=1), as with a trace open.
/// Results are identical either way; this exists to check exactly that.
void drcc_hub_set_exact(void* handle, int exact);
/// Opens a VCD file; 0 on success, -errno on failure. Closes an open one first.
int drcc_hub_trace_open(void* handle, const char* path);
/// Dumps the current values at `time` (units: half clock periods) if a trace is open.
void drcc_hub_trace_dump(void* handle, uint64_t time);
/// Flushes and closes the trace, if open.
void drcc_hub_trace_close(void* handle);

#ifdef __cplusplus
}
#endif

#endif  // DRCC_HUB_PORTS_H
