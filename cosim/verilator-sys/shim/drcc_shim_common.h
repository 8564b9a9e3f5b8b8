// drcc_shim_common.h: helpers shared by the C ABI shims of every Verilated top:
// the per-instance wrapper (own VerilatedContext, model, optional VCD trace), the
// fast evaluation of one clock edge (evalStep), the port mask helper and the
// layout fingerprint that Rust checks against its #[repr(C)] mirrors. C++ only;
// included by <top>_shim.cpp.

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
    /// evaluation only, `evalEdge(top, inputsChanged)`. `armEdge` clears
    /// Verilator's "previous clk" trigger state, so the evaluation with clk=1 sees
    /// a rising edge; Verilator evaluates the input-combinational region before
    /// the edge-triggered one, so the result is the same as the two evals (the
    /// clk=0 eval only settles logic that the clk=1 eval settles again). That
    /// halves the work per clock for rust-hdl style RTL, where most logic is
    /// combinational from the inputs. `evalEdge` is `top.eval()` or `evalStep`,
    /// which also skips the input-combinational region when `inputsChanged` is
    /// false.
    template <typename ArmEdge, typename EvalEdge>
    inline void clockEdge(bool inputsChanged, ArmEdge armEdge, EvalEdge evalEdge) {
        if (VL_LIKELY(tfp == nullptr && !exact) && armEdge(top)) {
            top.clk = 1;
            evalEdge(top, inputsChanged);
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

/// One evaluation of a Verilated model, as `V<top>::eval()` makes it
/// (`V<top>::eval_step()` around `V<top>___024root___eval()`), copied line for line
/// from what Verilator 5.006 generates, with one change: the input-combinational
/// ("ico") loop runs only if `inputsChanged`.
///
/// Why that is exact: Verilator 5.006 runs the ico region on the first iteration of
/// every eval, whether or not an input changed. Each eval ends settled (the
/// act/nba loop runs until no trigger fires, and the combinational logic that
/// depends on registers is re-evaluated in the nba region), so with the same
/// inputs the ico region recomputes the values it already holds. Skipping it
/// removes half of the combinational work of most clocks: a CAN input changes at
/// most once per bit, the host's Wishbone inputs stay put while it polls.
///
/// build.rs enables this (DRCC_<TOP>_EVAL_STEP) only when the model's two
/// functions match build/eval_5006.txt, the normalised text they were copied
/// from; any other Verilator steps through `eval()`. The region functions are
/// the model's own (external linkage), passed as template arguments.
template <typename Root, typename Syms, void (*TriggersIco)(Root*), void (*Ico)(Root*),
          void (*TriggersAct)(Root*), void (*Act)(Root*), void (*Nba)(Root*)>
inline void evalStep(Root* vlSelf, bool inputsChanged) {
    Syms* const vlSymsp = vlSelf->vlSymsp;
#if VM_TRACE
    vlSymsp->__Vm_activity = true;
#endif
    // The constructor's first eval() ran the initial blocks (__Vm_didInit): the
    // caller only gets here after it.
    Verilated::mtaskId(0);
    if (inputsChanged) {
        vlSelf->__VicoIterCount = 0U;
        bool icoContinue = true;
        while (icoContinue) {
            icoContinue = false;
            TriggersIco(vlSelf);
            if (vlSelf->__VicoTriggered.any()) {
                icoContinue = true;
                if (VL_UNLIKELY(0x64U < vlSelf->__VicoIterCount)) {
                    VL_FATAL_MT(__FILE__, __LINE__, "",
                                "Input combinational region did not converge.");
                }
                vlSelf->__VicoIterCount = 1U + vlSelf->__VicoIterCount;
                Ico(vlSelf);
            }
        }
    }
    decltype(vlSelf->__VactTriggered) preTriggered;
    uint32_t nbaIterCount = 0U;
    bool nbaContinue = true;
    while (nbaContinue) {
        nbaContinue = false;
        vlSelf->__VnbaTriggered.clear();
        vlSelf->__VactIterCount = 0U;
        vlSelf->__VactContinue = 1U;
        while (vlSelf->__VactContinue) {
            vlSelf->__VactContinue = 0U;
            TriggersAct(vlSelf);
            if (vlSelf->__VactTriggered.any()) {
                vlSelf->__VactContinue = 1U;
                if (VL_UNLIKELY(0x64U < vlSelf->__VactIterCount)) {
                    VL_FATAL_MT(__FILE__, __LINE__, "", "Active region did not converge.");
                }
                vlSelf->__VactIterCount = 1U + vlSelf->__VactIterCount;
                preTriggered.andNot(vlSelf->__VactTriggered, vlSelf->__VnbaTriggered);
                vlSelf->__VnbaTriggered.set(vlSelf->__VactTriggered);
                Act(vlSelf);
            }
        }
        if (vlSelf->__VnbaTriggered.any()) {
            nbaContinue = true;
            if (VL_UNLIKELY(0x64U < nbaIterCount)) {
                VL_FATAL_MT(__FILE__, __LINE__, "", "NBA region did not converge.");
            }
            nbaIterCount = 1U + nbaIterCount;
            Nba(vlSelf);
        }
    }
    Verilated::endOfThreadMTask(vlSymsp->__Vm_evalMsgQp);
    Verilated::endOfEval(vlSymsp->__Vm_evalMsgQp);
}

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
