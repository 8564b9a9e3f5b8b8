// drcc_ports.h: the port table of the Verilated `drcc` top and the
// plain-C ABI built from it (structs DrccIn / DrccOut and the
// drcc_drcc_* functions implemented in drcc_shim.cpp).
//
// THIS TABLE IS THE ONE PLACE TO EDIT WHEN THE RTL PORTS CHANGE, together with its
// mirror `DrccIn` / `DrccOut` in ../src/lib.rs (same order, same types)
// and the conversion in cosim/src/engine/drcc_verilator.rs.
//  - build.rs parses the X(...) lines below and compares them with the ports
//    Verilator reports in Vdrcc.h (direction and bit width): a mismatch stops
//    the build with a message naming the port.
//  - The layout (name, offset, size, width of every field) is hashed on both sides;
//    CanChannel::new() in Rust refuses to run if the hashes differ.
// Format: X(c_type, port_name, bit_width), one port per line, in struct order.
// c_type must be wide enough for the port (uint8_t <= 8 bits, uint16_t <= 16,
// uint32_t <= 32, uint64_t <= 64). `clk` is driven by the shim, not listed here.
// Single-bit ports are uint8_t holding 0 or 1.

#ifndef DRCC_DRCC_PORTS_H
#define DRCC_DRCC_PORTS_H

#include <stdint.h>

// clang-format off
#define DRCC_DRCC_INPUTS(X) \
    X(uint8_t,  rst,                            1)   \
    X(uint8_t,  wb_cyc_i,                       1)   \
    X(uint8_t,  wb_stb_i,                       1)   \
    X(uint8_t,  wb_we_i,                        1)   \
    X(uint8_t,  wb_adr_i,                       6)   \
    X(uint32_t, wb_dat_i,                       32)   \
    X(uint8_t,  chan_a_rx,                      1)   \
    X(uint8_t,  chan_b_rx,                      1)

#define DRCC_DRCC_OUTPUTS(X) \
    X(uint32_t, wb_dat_o,                       32)   \
    X(uint8_t,  wb_ack_o,                       1)   \
    X(uint8_t,  irq,                            1)   \
    X(uint8_t,  chan_a_tx,                      1)   \
    X(uint8_t,  chan_b_tx,                      1)   \
    X(uint8_t,  state,                          4)   \
    X(uint8_t,  tx_channel,                     1)   \
    X(uint8_t,  transmission_ack,               1)   \
    X(uint8_t,  chan_a_transmission_req,        1)   \
    X(uint8_t,  chan_b_transmission_req,        1)   \
    X(uint8_t,  tx_success,                     1)   \
    X(uint8_t,  tx_ok_channel,                  2)   \
    X(uint8_t,  tx_failure,                     1)   \
    X(uint8_t,  tx_failure_channel,             2)   \
    X(uint8_t,  tx_going_on,                    1)   \
    X(uint16_t, chan_a_bsp_tx_err_cnt,          9)   \
    X(uint8_t,  chan_a_bsp_node_error_passive,  1)   \
    X(uint16_t, chan_b_bsp_tx_err_cnt,          9)   \
    X(uint8_t,  chan_b_bsp_node_error_passive,  1)   \
    X(uint8_t,  aux_a_state,                    2)   \
    X(uint8_t,  aux_b_state,                    2)   \
    X(uint8_t,  chan_a_sample_point,            1)   \
    X(uint8_t,  chan_b_sample_point,            1)   \
    X(uint8_t,  chan_a_field,                   5)   \
    X(uint8_t,  chan_b_field,                   5)   \
    X(uint8_t,  chan_a_rec,                     8)   \
    X(uint8_t,  chan_b_rec,                     8)   \
    X(uint8_t,  chan_a_err_state,               2)   \
    X(uint8_t,  chan_b_err_state,               2)
// clang-format on

#define DRCC_PORT_FIELD(type, name, width) type name;

/// Every input of `drcc` except `clk`, sampled at the rising edge made by step().
typedef struct DrccIn {
    DRCC_DRCC_INPUTS(DRCC_PORT_FIELD)
} DrccIn;

/// Every output of `drcc`, as it is right after the rising edge.
typedef struct DrccOut {
    DRCC_DRCC_OUTPUTS(DRCC_PORT_FIELD)
} DrccOut;

#undef DRCC_PORT_FIELD

#ifdef __cplusplus
extern "C" {
#endif

/// Layout fingerprint of DrccIn/DrccOut (see drcc_shim_common.h).
uint64_t drcc_drcc_abi(void);
/// New instance with its own VerilatedContext; NULL on allocation failure.
void* drcc_drcc_new(void);
/// Frees an instance (closes its trace first). NULL is ignored.
void drcc_drcc_free(void* handle);
/// Applies *in, makes one rising edge of clk (evaluating clk=0 then clk=1, or a
/// single equivalent eval, see drcc_drcc_fast_edge), copies the outputs to *out.
void drcc_drcc_step(void* handle, const DrccIn* in, DrccOut* out);
/// 1 if step() can make one eval per clock instead of two (see drcc_shim_common.h).
int drcc_drcc_fast_edge(void);
/// exact != 0: always two evals per clock (clk=0, clk=1), as with a trace open.
/// Results are identical either way; this exists to check exactly that.
void drcc_drcc_set_exact(void* handle, int exact);
/// Opens a VCD file; 0 on success, -errno on failure. Closes an open one first.
int drcc_drcc_trace_open(void* handle, const char* path);
/// Dumps the current values at `time` (units: half clock periods) if a trace is open.
void drcc_drcc_trace_dump(void* handle, uint64_t time);
/// Flushes and closes the trace, if open.
void drcc_drcc_trace_close(void* handle);

#ifdef __cplusplus
}
#endif

#endif  // DRCC_DRCC_PORTS_H
