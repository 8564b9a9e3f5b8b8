// drcc_shim_common.h: helpers shared by the C ABI shims of every Verilated top:
// the per-instance wrapper (own VerilatedContext, model, optional VCD trace), the
// port mask helper and the layout fingerprint that Rust checks against its
// #[repr(C)] mirrors. C++ only; included by <top>_shim.cpp.

#ifndef DRCC_SHIM_COMMON_H
#define DRCC_SHIM_COMMON_H

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <new>

#include "verilated.h"
#include "verilated_vcd_c.h"

namespace drcc {

/// All-ones mask of `width` bits in type T (width 1..=64).
template <typename T, unsigned width>
constexpr T mask() {
    static_assert(width >= 1 && width <= 64, "port width must be 1..64");
    static_assert(width <= sizeof(T) * 8, "port table: C type too narrow for the port width");
    return width >= 64 ? static_cast<T>(~0ULL) : static_cast<T>((1ULL << (width % 64)) - 1ULL);
}

/// FNV-1a, 64 bit. The same fold is implemented in verilator-sys/src/lib.rs.
struct LayoutHash {
    uint64_t h = 0xcbf29ce484222325ULL;
    void byte(uint8_t b) {
        h ^= b;
        h *= 0x100000001b3ULL;
    }
    void u64(uint64_t v) {
        for (int i = 0; i < 8; ++i) byte(static_cast<uint8_t>(v >> (8 * i)));
    }
    /// One field: its name, a 0 byte, then offset, size and bit width as u64 LE.
    void field(const char* name, uint64_t offset, uint64_t size, uint64_t width) {
        for (const char* p = name; *p; ++p) byte(static_cast<uint8_t>(*p));
        byte(0);
        u64(offset);
        u64(size);
        u64(width);
    }
    /// End of one struct: a '|' byte and the struct size.
    void end(uint64_t size) {
        byte('|');
        u64(size);
    }
};

/// One simulated instance of top `V`: its own context (so that several instances
/// can live in one process and be stepped alternately), the model, the trace.
template <typename V>
struct Instance {
    VerilatedContext ctx;
    V top;
    VerilatedVcdC* tfp = nullptr;
    /// Number of completed step() calls; step n dumps at times 2n and 2n+1.
    uint64_t cycle = 0;
    /// Always make two evals per clock (see clockEdge).
    bool exact = false;

    Instance() : ctx{}, top{&ctx, "TOP"} {
        // Tracing may be switched on at any time later: it must be allowed before
        // the first eval. Done per context, not via the static
        // Verilated::traceEverOn(), which acts on the thread's current context.
        ctx.traceEverOn(true);
        // The VerilatedContext constructor made this context the thread's (and the
        // process's) "current" one. Forget it, so that no global pointer dangles
        // once this instance is freed (possibly on another thread). The model keeps
        // its own explicit context pointer and never needs the global one.
        Verilated::threadContextp(nullptr);
        // Run Verilator's one-time initialisation (initial blocks, settle) now,
        // with clk low: it also initialises the "previous clk" trigger state, which
        // must not happen inside the first step (the single-eval edge relies on it).
        top.clk = 0;
        top.eval();
    }
    ~Instance() {
        traceClose();
        top.final();
    }
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    int traceOpen(const char* path) {
        traceClose();
        VerilatedVcdC* t = new (std::nothrow) VerilatedVcdC;
        if (!t) return -ENOMEM;
        // trace() must precede open(); a fresh VerilatedVcdC per file keeps that true.
        top.trace(t, 99);
        errno = 0;
        t->open(path);
        if (!t->isOpen()) {
            const int e = errno ? errno : EIO;
            delete t;
            return -e;
        }
        tfp = t;
        return 0;
    }
    void traceDump(uint64_t time) {
        if (tfp) tfp->dump(time);
    }
    void traceClose() {
        if (!tfp) return;
        tfp->close();
        delete tfp;
        tfp = nullptr;
    }

    /// Evaluates clk=0 then clk=1 (inputs already applied), dumping each phase.
    ///
    /// Fast path (no trace open, `exact` false, and `armEdge` returns true): one
    /// eval only. `armEdge` clears Verilator's "previous clk" trigger state, so
    /// the eval with clk=1 sees a rising edge; Verilator evaluates the
    /// input-combinational region before the edge-triggered one, so the result is
    /// the same as the two evals (the clk=0 eval only settles logic that the clk=1
    /// eval settles again). That halves the work per clock for rust-hdl style RTL,
    /// where most logic is combinational from the inputs.
    template <typename ArmEdge>
    inline void clockEdge(ArmEdge armEdge) {
        if (VL_LIKELY(tfp == nullptr && !exact) && armEdge(top)) {
            top.clk = 1;
            top.eval();
            ++cycle;
            return;
        }
        top.clk = 0;
        top.eval();
        if (VL_UNLIKELY(tfp != nullptr)) tfp->dump(2 * cycle);
        top.clk = 1;
        top.eval();
        if (VL_UNLIKELY(tfp != nullptr)) tfp->dump(2 * cycle + 1);
        ++cycle;
    }
};

/// Allocates an instance; nullptr on failure (no C++ exception crosses the C ABI).
template <typename V>
Instance<V>* newInstance() {
    try {
        return new Instance<V>();
    } catch (...) {
        return nullptr;
    }
}

}  // namespace drcc

#endif  // DRCC_SHIM_COMMON_H
