// A lean VCD writer for the values trace_all traces (bool and sc_uint<1..64>): it writes the file
// SystemC 2.3.4's own writer (vcd_trace_file) writes - the same scopes from dotted names, $var lines,
// identifiers, $dumpvars block, value lines and time stamps, so the saved views in traces/ keep
// working - at a fraction of its cost: one pass over a flat table per time step, values
// formatted into one buffer flushed with fwrite, no virtual call, string or stream per value.
// Other value types are reported (shading/trace), not traced: SHADING_TRACE_WRITER=systemc (trace.h)
// selects SystemC's writer for them.
// Both SystemC versions the project builds with (docs/systemc-versions.md): 2.3.x calls a trace
// file's cycle() from the kernel's list (sc_simcontext::add_trace_file); 3.0 removed that list and
// drives its own writers from a stage callback before every time step, which this writer then uses too.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <systemc>
#include <utility>
#include <vector>

#include "core/report_ids.h"

#if defined(SC_VERSION_MAJOR) && SC_VERSION_MAJOR >= 3
#define SHADING_VCD_STAGE_CALLBACK 1
#else
#define SHADING_VCD_STAGE_CALLBACK 0
#endif

namespace shading {

class vcd_writer : public sc_core::sc_trace_file
#if SHADING_VCD_STAGE_CALLBACK
    , private sc_core::sc_stage_callback_if
#endif
{
public:
    // Opens <path_without_ext>.vcd now (an unopenable path is reported at once, shading/trace) and
    // registers with the kernel, which calls cycle() after every delta cycle and time step.
    explicit vcd_writer(const std::string& path_without_ext) : filename_(path_without_ext + ".vcd") {
        fp_ = std::fopen(filename_.c_str(), "w");
        if (fp_ == nullptr) {
            SC_REPORT_ERROR(msg::trace, ("cannot open " + filename_ + " for writing").c_str());
            return;  // reached only if errors do not throw: every call below is then a no-op
        }
        grow(1 << 20);
        attach();
    }

    // Writes the last time stamp (as SystemC's writer does) and closes the file. A file closed before
    // the first time step has nothing in it: it is removed, with SystemC's warning in our words.
    ~vcd_writer() override {
        if (fp_ == nullptr) return;
        detach();
        if (!initialized_ || unusable_) {
            std::fclose(fp_);
            std::remove(filename_.c_str());
            if (!unusable_)
                SC_REPORT_WARNING(msg::trace, (filename_ + ": closed before any time step was traced, not written").c_str());
            return;
        }
        uint64_t high = 0, low = 0;
        timestamp(high, low);
        if (high > start_high_ || (high == start_high_ && low > start_low_)) {
            ensure(kStampBytes);
            used_ = static_cast<std::size_t>(put_stamp(buf_.get() + used_, high, low) - buf_.get());
        }
        flush();
        std::fclose(fp_);
    }
    vcd_writer(const vcd_writer&) = delete;
    vcd_writer& operator=(const vcd_writer&) = delete;

    const std::string& filename() const { return filename_; }

    // --- the types trace_all traces.
    void trace(const bool& object, const std::string& name) override {
        if (add_check(name)) add(name, nullptr, &object, 1);
    }
    void trace(const sc_dt::sc_uint_base& object, const std::string& name) override {
        if (add_check(name)) add(name, &object, nullptr, object.length());
    }

    // --- every other type: a defined error, not a silently missing waveform.
#define SHADING_VCD_UNSUPPORTED_A(tp) \
    void trace(const tp&, const std::string& name) override { unsupported(#tp, name); }
#define SHADING_VCD_UNSUPPORTED_B(tp) \
    void trace(const tp&, const std::string& name, int) override { unsupported(#tp, name); }
    SHADING_VCD_UNSUPPORTED_A(sc_core::sc_event)
    SHADING_VCD_UNSUPPORTED_A(sc_core::sc_time)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_bit)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_logic)
    SHADING_VCD_UNSUPPORTED_B(unsigned char)
    SHADING_VCD_UNSUPPORTED_B(unsigned short)
    SHADING_VCD_UNSUPPORTED_B(unsigned int)
    SHADING_VCD_UNSUPPORTED_B(unsigned long)
    SHADING_VCD_UNSUPPORTED_B(char)
    SHADING_VCD_UNSUPPORTED_B(short)
    SHADING_VCD_UNSUPPORTED_B(int)
    SHADING_VCD_UNSUPPORTED_B(long)
    SHADING_VCD_UNSUPPORTED_B(sc_dt::int64)
    SHADING_VCD_UNSUPPORTED_B(sc_dt::uint64)
    SHADING_VCD_UNSUPPORTED_A(float)
    SHADING_VCD_UNSUPPORTED_A(double)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_int_base)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_signed)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_unsigned)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_fxval)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_fxval_fast)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_fxnum)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_fxnum_fast)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_bv_base)
    SHADING_VCD_UNSUPPORTED_A(sc_dt::sc_lv_base)
#undef SHADING_VCD_UNSUPPORTED_A
#undef SHADING_VCD_UNSUPPORTED_B
    void trace(const unsigned int&, const std::string& name, const char**) override { unsupported("enum", name); }

    // As SystemC's: written where it is called, before the header if tracing has not begun.
    void write_comment(const std::string& comment) override {
        append("$comment\n");
        append(comment);
        append("\n$end\n\n");
    }

    void set_time_unit(double v, sc_core::sc_time_unit tu) override {
        if (initialized_) {
            SC_REPORT_ERROR(msg::trace, (filename_ + ": the time unit cannot change once tracing has begun").c_str());
            return;
        }
        if (unit_fs(tu) == 0) {
            SC_REPORT_ERROR(msg::trace, (filename_ + ": VCD time units finer than 1 fs are not supported").c_str());
            return;  // the unit stays as it was
        }
        trace_unit_fs_ = static_cast<uint64_t>(v * static_cast<double>(unit_fs(tu)));
        unit_set_ = true;
    }

    // Delta cycles would show as pseudo time steps; no view of this project uses them.
    void delta_cycles(bool flag) override {
        if (flag) SC_REPORT_ERROR(msg::trace, (filename_ + ": delta-cycle tracing is not supported; "
                                               "SHADING_TRACE_WRITER=systemc has it").c_str());
    }

protected:
    // Called by the kernel after every delta cycle (ignored, as SystemC's writer does by default) and
    // before every time step: the first writes the header and the values at the start, each later one
    // the values changed since, under the current time.
    void cycle(bool delta_cycle) override {
        if (delta_cycle || fp_ == nullptr || unusable_) return;
        if (!initialized_) {
            initialize();
            return;
        }
        uint64_t high = 0, low = 0;
        timestamp(high, low);
        if (low != 0 && !low_units_) resolution_warning();
        ensure(step_bytes_);
        char* const begin = buf_.get() + used_;
        char* out = begin;
        bool stamped = false;
        for (entry& e : entries_) {
            const uint64_t v = e.uint != nullptr ? e.uint->value() : static_cast<uint64_t>(*e.boolean);
            if (v == e.last) continue;
            if (!stamped) {
                out = put_stamp(out, high, low);
                stamped = true;
            }
            e.last = v;
            out = put_value(out, e, v);
        }
        if (stamped) *out++ = '\n';
        used_ += static_cast<std::size_t>(out - begin);
    }

private:
#if SHADING_VCD_STAGE_CALLBACK
    // SystemC 3.0: called before every time step, as its own writers are (sc_trace_file_base).
    void stage_callback(const sc_core::sc_stage&) override { cycle(false); }
    void attach() { sc_core::sc_register_stage_callback(*this, sc_core::SC_PRE_TIMESTEP); }
    void detach() { sc_core::sc_unregister_stage_callback(*this, sc_core::SC_PRE_TIMESTEP); }
#else
    void attach() { sc_core::sc_get_curr_simcontext()->add_trace_file(this); }
    void detach() { sc_core::sc_get_curr_simcontext()->remove_trace_file(this); }
#endif

    struct entry {
        const sc_dt::sc_uint_base* uint;  // exactly one of uint, boolean is set
        const bool* boolean;
        uint64_t last;  // the value last written
        int width;
        char id[5];
    };

    static constexpr std::size_t kStampBytes = 48;  // '#', two 20-digit numbers, '\n'

    void add(const std::string& name, const sc_dt::sc_uint_base* u, const bool* b, int width) {
        entry e{u, b, 0, width, {}};
        // SystemC's identifiers: five letters, the trace's index in base 26 ("aaaaa", "aaaab", ...).
        int index = static_cast<int>(entries_.size());
        for (int i = 4; i >= 0; --i, index /= 26) e.id[i] = static_cast<char>('a' + index % 26);
        entries_.push_back(e);
        names_.push_back(name);
    }

    bool add_check(const std::string& name) {
        if (!initialized_) return true;
        SC_REPORT_ERROR(msg::trace, (filename_ + ": cannot trace '" + name + "' once tracing has begun").c_str());
        return false;
    }

    void unsupported(const char* type, const std::string& name) {
        SC_REPORT_ERROR(msg::trace, ("'" + name + "' (" + type + ") is not traced: the project's VCD writer traces "
                                     "bool and sc_uint only; SHADING_TRACE_WRITER=systemc traces every type")
                                        .c_str());
    }

    void resolution_warning() {
        std::ostringstream ss;
        ss << filename_ << ": the kernel time " << sc_core::sc_time_stamp()
           << " is not a whole number of VCD time units; set a finer unit with set_time_unit";
        SC_REPORT_WARNING(msg::trace, ss.str().c_str());
    }

    static uint64_t unit_fs(sc_core::sc_time_unit tu) {
        switch (tu) {
            case sc_core::SC_FS: return 1;
            case sc_core::SC_PS: return 1000;
            case sc_core::SC_NS: return 1000000;
            case sc_core::SC_US: return 1000000000;
            case sc_core::SC_MS: return 1000000000000;
            case sc_core::SC_SEC: return 1000000000000000;
            default: return 0;  // SystemC 3.0's as, zs and ys: finer than this writer counts
        }
    }

    static std::string unit_name(uint64_t fs) {
        static const char* const names[] = {"fs", "ps", "ns", "us", "ms", "sec"};
        uint64_t scale = 1;
        for (const char* n : names) {
            for (uint64_t m : {1, 10, 100})
                if (fs == scale * m) return std::to_string(m) + " " + n;
            scale *= 1000;
        }
        SC_REPORT_ERROR(msg::trace, ("VCD time unit not a power of ten: " + std::to_string(fs) + " fs").c_str());
        return "";
    }

    // The current time in trace units, split as SystemC's writer does: with a trace unit finer than
    // the kernel's resolution, `low` is the fraction (always 0 here) printed with low_digits_ digits.
    void timestamp(uint64_t& high, uint64_t& low) const {
        const uint64_t now = sc_core::sc_time_stamp().value();
        if (low_units_) {
            high = now;
            low = 0;
        } else {
            high = now / unit_divisor_;
            low = now % unit_divisor_;
        }
    }

    void initialize() {
        initialized_ = true;
        kernel_unit_fs_ = static_cast<uint64_t>(std::llround(sc_core::sc_get_time_resolution().to_seconds() * 1e15));
        if (kernel_unit_fs_ == 0) {  // SystemC 3.0 allows a resolution below 1 fs
            SC_REPORT_ERROR(msg::trace, (filename_ + ": the kernel's time resolution is finer than 1 fs; not traced, "
                                                     "SHADING_TRACE_WRITER=systemc may be used").c_str());
            unusable_ = true;  // nothing is written; the file is removed when the writer closes
            return;
        }
        if (!unit_set_) trace_unit_fs_ = kernel_unit_fs_;
        low_units_ = kernel_unit_fs_ > trace_unit_fs_;
        if (low_units_) {
            for (uint64_t r = kernel_unit_fs_ / trace_unit_fs_; r >= 10; r /= 10) ++low_digits_;
        } else {
            unit_divisor_ = trace_unit_fs_ / kernel_unit_fs_;
        }

        char date[200];
        const std::time_t now = std::time(nullptr);
        std::strftime(date, sizeof date, "%b %d, %Y       %H:%M:%S", std::localtime(&now));
        append("$date\n     " + std::string(date) + "\n$end\n\n");
        append("$version\n " + std::string(sc_core::sc_version()) + "\n$end\n\n");
        append("$timescale\n     " + unit_name(trace_unit_fs_) + "\n$end\n\n");
        print_scopes();
        append("$enddefinitions  $end\n\n");

        timestamp(start_high_, start_low_);
        std::ostringstream ss;
        ss << "All initial values are dumped below at time " << sc_core::sc_time_stamp().to_seconds() << " sec = ";
        if (low_units_) {
            ss << start_high_ << std::string(static_cast<std::size_t>(low_digits_), '0');
        } else {
            ss << start_high_;
        }
        ss << " timescale units.";
        write_comment(ss.str());

        // The most one time step can write: its stamp and every value line.
        step_bytes_ = kStampBytes + 1;
        for (const entry& e : entries_) step_bytes_ += static_cast<std::size_t>(e.width) + 9;
        append("$dumpvars\n");
        ensure(step_bytes_);
        char* out = buf_.get() + used_;
        for (entry& e : entries_) {
            e.last = e.uint != nullptr ? e.uint->value() : static_cast<uint64_t>(*e.boolean);
            out = put_value(out, e, e.last);
        }
        used_ = static_cast<std::size_t>(out - buf_.get());
        append("$end\n\n");
        names_.clear();
        names_.shrink_to_fit();
    }

    // SystemC's scope tree: the name's dotted parts are nested "$scope module" blocks under
    // "SystemC"; in each, its own signals in trace order, then its sub-scopes by name.
    struct scope {
        std::vector<std::pair<std::string, std::size_t>> traces;
        std::map<std::string, std::unique_ptr<scope>> scopes;
    };

    void print_scopes() {
        scope top;
        bool filtered = false;
        for (std::size_t i = 0; i < names_.size(); ++i) {
            std::string name = names_[i];
            for (char& ch : name) {
                if (ch == '[' || ch == ']') {
                    ch = ch == '[' ? '(' : ')';
                    filtered = true;
                }
            }
            // Split as SystemC does (std::getline on '.'), so odd names end up where they did.
            std::stringstream ss(name);
            std::string token, next;
            std::getline(ss, token, '.');
            scope* at = &top;
            while (std::getline(ss, next, '.')) {
                auto& sub = at->scopes[token];
                if (!sub) sub = std::make_unique<scope>();
                at = sub.get();
                token = next;
            }
            at->traces.emplace_back(token, i);
        }
        if (filtered)
            SC_REPORT_WARNING(msg::trace, (filename_ + ": traced names with [] are written with ()").c_str());
        print_scope(top, "SystemC");
    }

    void print_scope(const scope& s, const std::string& name) {
        append("$scope module " + name + " $end\n");
        for (const auto& [local, i] : s.traces) {
            // printf's "% 3d" of the width, as SystemC writes it: "  1", " 16".
            const entry& e = entries_[i];
            std::string width = " " + std::to_string(e.width);
            if (width.size() < 3) width.insert(0, 3 - width.size(), ' ');
            std::string line = "$var wire  " + width + "  " + std::string(e.id, 5) + "  " + local;
            line += e.width == 1 ? "       $end\n" : " [" + std::to_string(e.width - 1) + ":0]  $end\n";
            append(line);
        }
        for (const auto& [sub_name, sub] : s.scopes) print_scope(*sub, sub_name);
        append("$upscope $end\n");
    }

    // "#<time>\n"
    char* put_stamp(char* out, uint64_t high, uint64_t low) const {
        *out++ = '#';
        out = put_decimal(out, high);
        if (low_units_) {
            char digits[24];
            char* end = put_decimal(digits, low);
            for (auto n = end - digits; n < low_digits_; ++n) *out++ = '0';
            out = std::copy(digits, end, out);
        }
        *out++ = '\n';
        return out;
    }

    static char* put_decimal(char* out, uint64_t v) {
        char tmp[20];
        int n = 0;
        do {
            tmp[n++] = static_cast<char>('0' + v % 10);
            v /= 10;
        } while (v != 0);
        while (n > 0) *out++ = tmp[--n];
        return out;
    }

    // "<bit><id>\n" for one bit; "b<bits without leading zeros> <id>\n" for a vector (SystemC
    // strips leading zeros but keeps one for a zero value).
    static char* put_value(char* out, const entry& e, uint64_t v) {
        if (e.width == 1) {
            *out++ = static_cast<char>('0' + (v & 1));
        } else {
            *out++ = 'b';
            if (v == 0) {
                *out++ = '0';
            } else {
                const int bits = 64 - __builtin_clzll(v);
                for (int b = bits - 1; b >= 0; --b) *out++ = static_cast<char>('0' + ((v >> b) & 1));
            }
            *out++ = ' ';
        }
        std::memcpy(out, e.id, 5);
        out += 5;
        *out++ = '\n';
        return out;
    }

    // Room for `n` more bytes in the buffer, flushing it if needed.
    void ensure(std::size_t n) {
        if (used_ + n <= cap_) return;
        flush();
        if (n > cap_) grow(n);
    }

    // A buffer of n bytes, left uninitialised: a short trace touches a few of its pages, and the
    // zeroing a std::vector does cost each writer a MiB of stores (most of a short run's time).
    void grow(std::size_t n) {
        buf_.reset(new char[n]);
        cap_ = n;
    }

    void append(const std::string& s) {
        if (fp_ == nullptr) return;
        ensure(s.size());
        std::memcpy(buf_.get() + used_, s.data(), s.size());
        used_ += s.size();
    }

    void flush() {
        if (used_ != 0) std::fwrite(buf_.get(), 1, used_, fp_);
        used_ = 0;
    }

    std::string filename_;
    std::FILE* fp_ = nullptr;
    std::unique_ptr<char[]> buf_;
    std::size_t cap_ = 0, used_ = 0;
    std::size_t step_bytes_ = 0;
    std::vector<entry> entries_;
    std::vector<std::string> names_;  // until the header is written
    bool initialized_ = false;
    bool unusable_ = false;  // the kernel's resolution cannot be written (below 1 fs)
    bool unit_set_ = false;
    bool low_units_ = false;
    int low_digits_ = 0;
    uint64_t trace_unit_fs_ = 0, kernel_unit_fs_ = 0, unit_divisor_ = 1;
    uint64_t start_high_ = 0, start_low_ = 0;
};

}  // namespace shading

#undef SHADING_VCD_STAGE_CALLBACK
