// One helper traces every signal below a module by its hierarchical name(), so the VCD's scopes
// follow the design's hierarchy (dots become scopes) and waveform names match the code.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <systemc>
#include <utility>

#include "core/report_ids.h"
#include "core/vcd_writer.h"

namespace shading {

namespace detail {
template <typename T>
bool try_trace(sc_core::sc_trace_file* tf, sc_core::sc_object* obj) {
    if (auto* sig = dynamic_cast<sc_core::sc_signal_in_if<T>*>(obj)) {
        sc_core::sc_trace(tf, *sig, obj->name());
        return true;
    }
    return false;
}

template <std::size_t... W>
bool try_trace_uint(sc_core::sc_trace_file* tf, sc_core::sc_object* obj, std::index_sequence<W...>) {
    return (try_trace<sc_dt::sc_uint<W + 1>>(tf, obj) || ...);
}
}  // namespace detail

// Traces every bool and sc_uint<1..64> signal in the subtree rooted at `root` (ports are not
// traced: they show the same nets as the signals they are bound to).
inline void trace_all(sc_core::sc_trace_file* tf, sc_core::sc_object* root) {
    if (!detail::try_trace<bool>(tf, root))
        detail::try_trace_uint(tf, root, std::make_index_sequence<64>{});
    for (auto* child : root->get_child_objects()) trace_all(tf, child);
}

// Which writer a vcd_file uses. lean: the project's (core/vcd_writer.h, the same file at a fraction of
// the cost); systemc: SystemC's own (every type, delta cycles), the escape hatch; both: the project's
// at <path>.vcd and SystemC's at <path>_systemc.vcd, side by side, to compare them.
enum class vcd_writer_kind { lean, systemc, both };

// SHADING_TRACE_WRITER=systemc or both; unset or empty: lean. Anything else is reported
// (shading/trace) and the lean writer used.
inline vcd_writer_kind vcd_writer_from_env() {
    const char* w = std::getenv("SHADING_TRACE_WRITER");
    if (w == nullptr || *w == '\0' || std::string(w) == "lean") return vcd_writer_kind::lean;
    if (std::string(w) == "systemc") return vcd_writer_kind::systemc;
    if (std::string(w) == "both") return vcd_writer_kind::both;
    SC_REPORT_ERROR(msg::trace, ("SHADING_TRACE_WRITER=" + std::string(w) + ": expected systemc, both or lean").c_str());
    return vcd_writer_kind::lean;
}

// A VCD file (path without the ".vcd" the writers append) with a 1 ps time unit, closed on
// destruction. Must be created before sc_start, after the design is built.
class vcd_file {
public:
    explicit vcd_file(const std::string& path_without_ext, vcd_writer_kind kind = vcd_writer_from_env()) {
        if (kind != vcd_writer_kind::systemc) {
            lean_ = std::make_unique<vcd_writer>(path_without_ext);
            lean_->set_time_unit(1, sc_core::SC_PS);
        }
        if (kind != vcd_writer_kind::lean) {
            const std::string path = kind == vcd_writer_kind::both ? path_without_ext + "_systemc" : path_without_ext;
            systemc_ = sc_core::sc_create_vcd_trace_file(path.c_str());
            systemc_->set_time_unit(1, sc_core::SC_PS);
        }
    }
    ~vcd_file() {
        if (systemc_ != nullptr) sc_core::sc_close_vcd_trace_file(systemc_);
    }
    vcd_file(const vcd_file&) = delete;
    vcd_file& operator=(const vcd_file&) = delete;

    // The project's writer if it is in use, else SystemC's.
    sc_core::sc_trace_file* get() const { return lean_ ? static_cast<sc_core::sc_trace_file*>(lean_.get()) : systemc_; }
    void trace(sc_core::sc_object& root) {
        if (lean_) trace_all(lean_.get(), &root);
        if (systemc_ != nullptr) trace_all(systemc_, &root);
    }

private:
    std::unique_ptr<vcd_writer> lean_;
    sc_core::sc_trace_file* systemc_ = nullptr;
};

// Tracing on demand: when SHADING_TRACE names a directory, returns a VCD there called `name`.
// The directory is created if missing (README: SHADING_TRACE=/tmp/vcd); if that fails, the writer's
// error for the unopenable file (shading/trace) says which path.
inline std::unique_ptr<vcd_file> vcd_from_env(const std::string& name) {
    const char* dir = std::getenv("SHADING_TRACE");
    if (dir == nullptr || *dir == '\0') return nullptr;
    std::error_code ignored;
    std::filesystem::create_directories(dir, ignored);
    return std::make_unique<vcd_file>(std::string(dir) + "/" + name);
}

}  // namespace shading
