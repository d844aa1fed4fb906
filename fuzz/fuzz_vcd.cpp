// Fuzz target: the project's VCD writer (modules/core/vcd_writer.h) with any traced names, widths,
// time unit and values. Per input: up to 16 traces (bool, or sc_uint of 1..64 bits) under names
// taken from the input, a time unit from 1 fs to 100 s, then up to 16 time steps, each assigning
// some values and advancing the simulation. Every input must leave a memory-clean run with only
// the writer's documented shading/trace warnings. When every name is a plain identifier path
// (dotted parts of printable characters without spaces or brackets), the file must also read back:
// one $var per trace with its width and a unique identifier, balanced scopes, time stamps never
// falling, and each trace's last value in the file equal to its last value in the simulation.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <systemc>
#include <unistd.h>
#include <vector>

#include "core/vcd_writer.h"
#include "fuzz_check.h"

namespace {

void report_handler(const sc_core::sc_report& r, const sc_core::sc_actions&) {
    if (r.get_severity() == sc_core::SC_INFO) return;
    if (r.get_severity() == sc_core::SC_WARNING && std::string(r.get_msg_type()) == shading::msg::trace) return;
    FUZZ_CHECK(false, "unexpected report %s: %s", r.get_msg_type(), r.get_msg());
}

bool plain_name(const std::string& n) {
    if (n.empty() || n.front() == '.' || n.back() == '.') return false;
    for (std::size_t i = 0; i < n.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(n[i]);
        if (c <= ' ' || c >= 127 || c == '[' || c == ']' || c == '(' || c == ')' || c == '$') return false;
        if (c == '.' && n[i + 1] == '.') return false;
    }
    return true;
}

struct traced {
    std::string name;
    int width;
    bool is_bool;
    bool b = false;
    std::unique_ptr<sc_dt::sc_uint_base> u;
    uint64_t value() const { return is_bool ? b : u->value(); }
};

// Reads the file back (plain names only): identifier -> last value; checks the structure.
void read_back(const std::string& file, const std::vector<traced>& t) {
    std::ifstream in(file);
    FUZZ_CHECK(in.good(), "%s was not written", file.c_str());
    std::string line;
    std::map<std::string, int> width_of;
    std::map<std::string, uint64_t> last;
    int depth = 0;
    bool defs = true;
    long long prev_time = -1;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (defs) {
            if (line.rfind("$scope", 0) == 0) ++depth;
            if (line.rfind("$upscope", 0) == 0) --depth;
            FUZZ_CHECK(depth >= 0, "unbalanced $upscope");
            if (line.rfind("$var", 0) == 0) {
                std::istringstream ss(line);
                std::string var, wire, id, name;
                int w = 0;
                ss >> var >> wire >> w >> id >> name;
                FUZZ_CHECK(width_of.count(id) == 0, "identifier %s twice", id.c_str());
                width_of[id] = w;
            }
            if (line.rfind("$enddefinitions", 0) == 0) {
                defs = false;
                FUZZ_CHECK(depth == 0, "scopes not closed: %d open", depth);
                FUZZ_CHECK(width_of.size() == t.size(), "%zu $var lines for %zu traces", width_of.size(), t.size());
            }
            continue;
        }
        if (line[0] == '#') {
            const long long now = std::stoll(line.substr(1));
            // Equal stamps only when the unit is coarser than a step (the documented resolution warning).
            FUZZ_CHECK(now >= prev_time, "time stamp %lld after %lld", now, prev_time);
            prev_time = now;
        } else if (line[0] == 'b') {
            const auto sp = line.find(' ');
            FUZZ_CHECK(sp != std::string::npos, "vector value line without identifier: %s", line.c_str());
            const std::string bits = line.substr(1, sp - 1), id = line.substr(sp + 1);
            FUZZ_CHECK(width_of.count(id) == 1, "value for unknown identifier %s", id.c_str());
            FUZZ_CHECK(bits.size() <= static_cast<std::size_t>(width_of[id]), "%zu bits for a %d-bit trace",
                       bits.size(), width_of[id]);
            uint64_t v = 0;
            for (char c : bits) v = (v << 1) | static_cast<uint64_t>(c == '1');
            last[id] = v;
        } else if (line[0] == '0' || line[0] == '1') {
            const std::string id = line.substr(1);
            FUZZ_CHECK(width_of.count(id) == 1 && width_of[id] == 1, "scalar value for %s", id.c_str());
            last[id] = static_cast<uint64_t>(line[0] == '1');
        }
    }
    FUZZ_CHECK(!defs, "no $enddefinitions");
    // Identifiers in trace order: SystemC's five letters, the index in base 26.
    for (std::size_t i = 0; i < t.size(); ++i) {
        std::string id(5, 'a');
        for (std::size_t k = 0, x = i; k < 5; ++k, x /= 26) id[4 - k] = static_cast<char>('a' + x % 26);
        FUZZ_CHECK(width_of.count(id) == 1 && width_of[id] == t[i].width, "trace %zu: identifier %s, width %d", i,
                   id.c_str(), t[i].width);
        FUZZ_CHECK(last.count(id) == 1 && last[id] == t[i].value(), "trace %zu (%s): last value in the file %llu, "
                   "simulated %llu", i, t[i].name.c_str(), static_cast<unsigned long long>(last[id]),
                   static_cast<unsigned long long>(t[i].value()));
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string base = [] {
        sc_core::sc_report_handler::set_handler(&report_handler);
        return "/tmp/shading_fuzz_vcd_" + std::to_string(getpid());
    }();
    shading::fuzz::input in(data, size);
    static const sc_core::sc_time_unit units[] = {sc_core::SC_FS, sc_core::SC_PS, sc_core::SC_NS,
                                                  sc_core::SC_US, sc_core::SC_MS, sc_core::SC_SEC};
    const uint8_t unit = in.u8();
    std::vector<traced> t(1 + in.u8() % 16);
    bool plain = true;
    for (auto& x : t) {
        x.name = in.str(24);
        const uint8_t w = in.u8();
        x.is_bool = (w & 0x80) != 0;
        x.width = x.is_bool ? 1 : 1 + w % 64;
        if (!x.is_bool) x.u = std::make_unique<sc_dt::sc_uint_base>(x.width);
        plain = plain && plain_name(x.name);
    }
    const std::size_t steps = 1 + in.u8() % 16;
    {
        shading::vcd_writer w(base);
        if (unit & 0x80) {
            static const double scale[] = {1.0, 10.0, 100.0};
            w.set_time_unit(scale[(unit >> 3) % 3], units[unit % 6]);
        }
        for (auto& x : t) {
            if (x.is_bool) w.trace(x.b, x.name);
            else w.trace(*x.u, x.name);
        }
        for (std::size_t s = 0; s < steps; ++s) {
            const uint8_t mask = in.u8();
            for (std::size_t i = 0; i < t.size(); ++i) {
                if (!((mask >> (i % 8)) & 1)) continue;
                const uint64_t v = in.u64();
                if (t[i].is_bool) t[i].b = v & 1;
                else *t[i].u = v;  // sc_uint_base keeps its width's low bits
            }
            // Whole nanoseconds, so the default 1 ps unit needs no fraction; a coarser unit than the
            // step is the writer's documented resolution warning.
            sc_core::sc_start(sc_core::sc_time(1 + in.u8(), sc_core::SC_NS));
        }
    }
    if (plain) read_back(base + ".vcd", t);
    std::remove((base + ".vcd").c_str());
    return 0;
}

// libsystemc's own main() calls sc_main; this program has its own main (libFuzzer's or the replay
// driver's) and never reaches it, but the library still needs the symbol.
int sc_main(int, char**) { return 2; }
