// One helper traces every signal below a module by its hierarchical name(), so the VCD's scopes
// follow the design's hierarchy (dots become scopes) and waveform names match the code.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <systemc>
#include <utility>

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

// A VCD file (path without the ".vcd" SystemC appends) with a 1 ps time unit, closed on
// destruction. Must be created before sc_start, after the design is built.
class vcd_file {
public:
    explicit vcd_file(const std::string& path_without_ext)
        : tf_(sc_core::sc_create_vcd_trace_file(path_without_ext.c_str())) {
        tf_->set_time_unit(1, sc_core::SC_PS);
    }
    ~vcd_file() { sc_core::sc_close_vcd_trace_file(tf_); }
    vcd_file(const vcd_file&) = delete;
    vcd_file& operator=(const vcd_file&) = delete;

    sc_core::sc_trace_file* get() const { return tf_; }
    void trace(sc_core::sc_object& root) { trace_all(tf_, &root); }

private:
    sc_core::sc_trace_file* tf_;
};

// Tracing on demand: when SHADING_TRACE names a directory, returns a VCD there called `name`.
// The directory is created if missing (README: SHADING_TRACE=/tmp/vcd); if that fails, SystemC's
// own error for the unopenable file says which path.
inline std::unique_ptr<vcd_file> vcd_from_env(const std::string& name) {
    const char* dir = std::getenv("SHADING_TRACE");
    if (dir == nullptr || *dir == '\0') return nullptr;
    std::error_code ignored;
    std::filesystem::create_directories(dir, ignored);
    return std::make_unique<vcd_file>(std::string(dir) + "/" + name);
}

}  // namespace shading
