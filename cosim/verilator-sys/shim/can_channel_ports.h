// can_channel_ports.h: the port table of the Verilated `can_channel` top and the
// plain-C ABI built from it (structs CanChannelIn / CanChannelOut and the
// drcc_can_channel_* functions implemented in can_channel_shim.cpp).
//
// THIS TABLE IS THE ONE PLACE TO EDIT WHEN THE RTL PORTS CHANGE, together with its
// mirror `CanChannelIn` / `CanChannelOut` in ../src/lib.rs (same order, same types)
// and the conversion in cosim/src/engine/verilator.rs.
//  - build.rs parses the X(...) lines below and compares them with the ports
//    Verilator reports in Vcan_channel.h (direction and bit width): a mismatch stops
//    the build with a message naming the port.
//  - The layout (name, offset, size, width of every field) is hashed on both sides;
//    CanChannel::new() in Rust refuses to run if the hashes differ.
// Format: X(c_type, port_name, bit_width), one port per line, in struct order.
// c_type must be wide enough for the port (uint8_t <= 8 bits, uint16_t <= 16,
// uint32_t <= 32, uint64_t <= 64). `clk` is driven by the shim, not listed here.
// Single-bit ports are uint8_t holding 0 or 1.

#ifndef DRCC_CAN_CHANNEL_PORTS_H
#define DRCC_CAN_CHANNEL_PORTS_H

#include <stdint.h>

// clang-format off
#define DRCC_CAN_CHANNEL_INPUTS(X) \
    X(uint8_t,  rst,             1)   \
    X(uint8_t,  cfg_brp,         6)   \
    X(uint8_t,  cfg_tseg1,       4)   \
    X(uint8_t,  cfg_tseg2,       3)   \
    X(uint8_t,  cfg_sjw,         2)   \
    X(uint8_t,  cfg_triple,      1)   \
    X(uint8_t,  cfg_mode,        2)   \
    X(uint8_t,  cfg_ewl,         8)   \
    X(uint8_t,  cfg_single_shot, 1)   \
    X(uint8_t,  rx,              1)   \
    X(uint8_t,  tx_req,          1)   \
    X(uint32_t, tx_id,           29)  \
    X(uint8_t,  tx_ide,          1)   \
    X(uint8_t,  tx_rtr,          1)   \
    X(uint8_t,  tx_dlc,          4)   \
    X(uint64_t, tx_data,         64)  \
    X(uint8_t,  tx_abort,        1)

#define DRCC_CAN_CHANNEL_OUTPUTS(X) \
    X(uint8_t,  tx,              1)   \
    X(uint8_t,  tx_pending,      1)   \
    X(uint8_t,  tx_done,         1)   \
    X(uint8_t,  arb_lost,        1)   \
    X(uint8_t,  tx_failed,       1)   \
    X(uint8_t,  rx_valid,        1)   \
    X(uint32_t, rx_id,           29)  \
    X(uint8_t,  rx_ide,          1)   \
    X(uint8_t,  rx_rtr,          1)   \
    X(uint8_t,  rx_dlc,          4)   \
    X(uint64_t, rx_data,         64)  \
    X(uint8_t,  sample_point,    1)   \
    X(uint8_t,  sampled_bit,     1)   \
    X(uint8_t,  field,           5)   \
    X(uint16_t, tec,             9)   \
    X(uint8_t,  rec,             8)   \
    X(uint8_t,  err_state,       2)   \
    X(uint8_t,  err_warning,     1)   \
    X(uint8_t,  err_valid,       1)   \
    X(uint8_t,  err_kind,        3)   \
    X(uint8_t,  err_field,       5)   \
    X(uint8_t,  err_tx,          1)   \
    X(uint8_t,  alc,             5)   \
    X(uint8_t,  cnt_bit,         8)   \
    X(uint8_t,  cnt_stuff,       8)   \
    X(uint8_t,  cnt_crc,         8)   \
    X(uint8_t,  cnt_form,        8)   \
    X(uint8_t,  cnt_ack,         8)
// clang-format on

#define DRCC_PORT_FIELD(type, name, width) type name;

/// Every input of `can_channel` except `clk`, sampled at the rising edge made by step().
typedef struct CanChannelIn {
    DRCC_CAN_CHANNEL_INPUTS(DRCC_PORT_FIELD)
} CanChannelIn;

/// Every output of `can_channel`, as it is right after the rising edge.
typedef struct CanChannelOut {
    DRCC_CAN_CHANNEL_OUTPUTS(DRCC_PORT_FIELD)
} CanChannelOut;

#undef DRCC_PORT_FIELD

#ifdef __cplusplus
extern "C" {
#endif

/// Layout fingerprint of CanChannelIn/CanChannelOut (see drcc_shim_common.h).
uint64_t drcc_can_channel_abi(void);
/// New instance with its own VerilatedContext; NULL on allocation failure.
void* drcc_can_channel_new(void);
/// Frees an instance (closes its trace first). NULL is ignored.
void drcc_can_channel_free(void* handle);
/// Applies *in, makes one rising edge of clk (evaluating clk=0 then clk=1, or a
/// single equivalent eval, see drcc_can_channel_fast_edge), copies the outputs to *out.
void drcc_can_channel_step(void* handle, const CanChannelIn* in, CanChannelOut* out);
/// 1 if step() can make one eval per clock instead of two (see drcc_shim_common.h).
int drcc_can_channel_fast_edge(void);
/// exact != 0: always two evals per clock (clk=0, clk=1), as with a trace open.
/// Results are identical either way; this exists to check exactly that.
void drcc_can_channel_set_exact(void* handle, int exact);
/// Opens a VCD file; 0 on success, -errno on failure. Closes an open one first.
int drcc_can_channel_trace_open(void* handle, const char* path);
/// Dumps the current values at `time` (units: half clock periods) if a trace is open.
void drcc_can_channel_trace_dump(void* handle, uint64_t time);
/// Flushes and closes the trace, if open.
void drcc_can_channel_trace_close(void* handle);

#ifdef __cplusplus
}
#endif

#endif  // DRCC_CAN_CHANNEL_PORTS_H
