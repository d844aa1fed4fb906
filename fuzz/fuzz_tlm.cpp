// Fuzz target: random payload sequences into every TLM-2.0 wrapper (modules/tlm), through an
// initiator socket, b_transport and transport_dbg alike. The input's first byte picks the wrapper;
// each later group of bytes is one access (command, address, length, streaming width, byte
// enables, incoming delay, data). Checked per access against tlm_oracle.h's reading of
// modules/tlm/README.md: the response status; an error response sets its STATUS log bit, draws one
// shading/tlm warning, charges no time and changes nothing else; a read returns the documented
// bytes (results from the devices' golden models); a debug access transfers the documented count
// with no side effect. At the end of each input the whole map is compared with the shadow.
//
// SystemC elaborates once per process: the wrappers and the initiator are built at the first input;
// each input then runs inside the simulation (one sc_start that the initiator's thread pauses).
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include <cstdint>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "fuzz_check.h"
#include "tlm_oracle.h"

using namespace shading;
using namespace shading::fuzz;
using sc_core::sc_time;
using sc_core::SC_NS;

namespace {

unsigned tlm_warnings = 0;
bool pin_mode_now = false;

// shading/tlm warnings are counted (each error response must draw one); shading/input is the
// pin-accurate device's documented range warning; every other report is a finding.
void report_handler(const sc_core::sc_report& r, const sc_core::sc_actions&) {
    if (r.get_severity() == sc_core::SC_INFO) return;
    const std::string id = r.get_msg_type();
    if (r.get_severity() == sc_core::SC_WARNING && id == msg::tlm) {
        ++tlm_warnings;
        return;
    }
    if (r.get_severity() == sc_core::SC_WARNING && id == msg::input && pin_mode_now) return;
    FUZZ_CHECK(false, "unexpected report %s: %s", id.c_str(), r.get_msg());
}

uint64_t xorshift(uint64_t& s) {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return s;
}

using socket_t = tlm_utils::simple_initiator_socket<sc_core::sc_module>;

// One wrapper under test with its shadow model.
struct target {
    virtual ~target() = default;
    virtual void run(input& in) = 0;  // called from the initiator's thread
};

template <class W, class Model>
struct target_impl : target {
    W wrapper;
    socket_t socket;
    Model model;
    bool pin;

    target_impl(const char* name, tlm_timing t)
        : wrapper(name, t), socket((std::string(name) + "_initiator").c_str()), pin(t == tlm_timing::pin_accurate) {
        socket.bind(wrapper.socket);
        model.pin = pin;
    }

    // Plain accesses, used to bring the wrapper to a known state at the start of an input.
    tlm::tlm_response_status put(uint64_t addr, unsigned char* d, unsigned len) {
        tlm::tlm_generic_payload p;
        p.set_command(tlm::TLM_WRITE_COMMAND);
        p.set_address(addr);
        p.set_data_ptr(d);
        p.set_data_length(len);
        p.set_streaming_width(len);
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        sc_time delay = sc_core::SC_ZERO_TIME;
        socket->b_transport(p, delay);
        return p.get_response_status();
    }
    tlm::tlm_response_status put32(uint64_t addr, uint32_t v) {
        unsigned char b[4];
        std::memcpy(b, &v, 4);
        return put(addr, b, 4);
    }
    unsigned dbg(tlm::tlm_command cmd, uint64_t addr, unsigned char* d, unsigned len) {
        tlm::tlm_generic_payload p;
        p.set_command(cmd);
        p.set_address(addr);
        p.set_data_ptr(d);
        p.set_data_length(len);
        p.set_streaming_width(len);
        return socket->transport_dbg(p);
    }
    std::vector<unsigned char> debug_image(int r) {
        const region& g = Model::map[r];
        std::vector<unsigned char> v(g.end - g.begin);
        const unsigned got = dbg(tlm::TLM_READ_COMMAND, g.begin, v.data(), static_cast<unsigned>(v.size()));
        FUZZ_CHECK(got == v.size(), "debug read of region %d: %u of %zu bytes", r, got, v.size());
        return v;
    }
    void compare(int r, const char* when) {
        const auto got = debug_image(r), want = model.image(r);
        for (std::size_t i = 0; i < got.size(); ++i)
            FUZZ_CHECK(got[i] == want[i], "%s: region %d byte 0x%zx is 0x%02x, documented 0x%02x", when, r, i, got[i],
                       want[i]);
    }

    void reset();

    // The documented status and, for an error, its STATUS log bit.
    tlm::tlm_response_status expected(const access& a, uint32_t& bit) const;

    void run(input& in) override {
        pin_mode_now = pin;
        reset();
        for (int r = 0; r < 3; ++r) compare(r, "after reset");
        constexpr uint64_t cap = (1u << 16) + 64;  // no valid access is longer (the largest window: 64 KiB)
        for (int ops = 0; ops < 32 && !in.empty(); ++ops) {
            const uint8_t sel = in.u8(), am = in.u8(), lm = in.u8();
            const bool debug = (sel & 7) == 7;
            static const tlm::tlm_command cmds[4] = {tlm::TLM_READ_COMMAND, tlm::TLM_WRITE_COMMAND,
                                                     tlm::TLM_IGNORE_COMMAND, tlm::TLM_WRITE_COMMAND};
            access a{};
            a.cmd = cmds[(sel >> 3) & 3];
            const region& g = Model::map[(am >> 3) % 3];
            if (am % 4 == 0) {
                a.addr = in.u64();
            } else {
                uint64_t off = in.u16() % (g.end - g.begin + 32);
                if (am & 4) off &= ~static_cast<uint64_t>(g.granule - 1);
                a.addr = g.begin + off;
            }
            switch (lm % 4) {
                case 0: a.len = g.granule; break;
                case 1: a.len = g.granule * (1u + in.u8()); break;
                case 2: a.len = in.u16(); break;
                default: a.len = in.u32(); break;
            }
            a.streaming_width = (lm & 0x10) ? in.u32() : a.len;
            a.byte_enables = (lm & 0xC0) == 0xC0;
            const sc_time delay_in(in.u8(), SC_NS);
            uint64_t seed = (static_cast<uint64_t>(in.u16()) << 16) | 0x9E37u;
            std::vector<unsigned char> buf(std::min(a.len, cap));
            // Random data where a write can be valid (the writable windows are at most 4 KiB).
            for (std::size_t i = 0; i < buf.size(); ++i)
                buf[i] = i < 4096 ? static_cast<unsigned char>(xorshift(seed)) : 0xA5;
            // Interval lengths inside 1..2^M for most line bursts (else nearly every one is refused).
            if (lm & 0x20) fix_lengths(buf);
            a.data = buf.data();
            std::vector<unsigned char> be(1 + sel % 8, 0xFF);

            if (debug) {
                const bool read = a.cmd == tlm::TLM_READ_COMMAND;
                const unsigned len32 = static_cast<unsigned>(std::min(a.len, cap));
                const int r = debug_region(a.addr, len32, Model::map);
                const unsigned want = read && r >= 0 ? len32 : 0;
                const std::vector<unsigned char> before = buf;
                const unsigned got = dbg(a.cmd, a.addr, buf.data(), len32);
                FUZZ_CHECK(got == want, "debug %s of %u bytes at 0x%llx: %u bytes, documented %u",
                           read ? "read" : "write", len32, static_cast<unsigned long long>(a.addr), got, want);
                if (want > 0) {
                    const auto img = model.image(r);
                    FUZZ_CHECK(std::memcmp(buf.data(), img.data() + (a.addr - Model::map[r].begin), want) == 0,
                               "debug read at 0x%llx: wrong bytes", static_cast<unsigned long long>(a.addr));
                } else {
                    FUZZ_CHECK(buf == before, "a debug access that transferred nothing wrote the buffer");
                }
                compare(0, "after a debug access");
                continue;
            }

            tlm::tlm_generic_payload p;
            p.set_command(a.cmd);
            p.set_address(a.addr);
            p.set_data_ptr(buf.data());
            p.set_data_length(static_cast<unsigned>(std::min<uint64_t>(a.len, 0xFFFFFFFFu)));
            a.len = p.get_data_length();
            p.set_streaming_width(static_cast<unsigned>(std::min<uint64_t>(a.streaming_width, 0xFFFFFFFFu)));
            a.streaming_width = p.get_streaming_width();
            p.set_byte_enable_ptr(a.byte_enables ? be.data() : nullptr);
            p.set_byte_enable_length(a.byte_enables ? static_cast<unsigned>(be.size()) : 0);
            p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
            uint32_t bit = 0;
            const auto want = expected(a, bit);
            const std::vector<unsigned char> before = buf;
            const unsigned warnings = tlm_warnings;
            sc_time delay = delay_in;
            socket->b_transport(p, delay);
            const auto got = p.get_response_status();
            FUZZ_CHECK(got == want, "%s of %llu bytes at 0x%llx (width %llu%s): %s, documented %s",
                       a.cmd == tlm::TLM_READ_COMMAND ? "read" : a.cmd == tlm::TLM_WRITE_COMMAND ? "write" : "ignore",
                       static_cast<unsigned long long>(a.len), static_cast<unsigned long long>(a.addr),
                       static_cast<unsigned long long>(a.streaming_width), a.byte_enables ? ", byte enables" : "",
                       p.get_response_string().c_str(), tlm::tlm_generic_payload().get_response_string().c_str());
            if (got != tlm::TLM_OK_RESPONSE) {
                FUZZ_CHECK(tlm_warnings == warnings + 1, "an error response drew %u warnings", tlm_warnings - warnings);
                FUZZ_CHECK(delay == delay_in, "an error response charged time");
                FUZZ_CHECK(buf == before, "an error response wrote the data buffer");
                model.errors |= bit;
            } else {
                FUZZ_CHECK(tlm_warnings == warnings, "an OK response drew a warning");
                if (a.cmd == tlm::TLM_WRITE_COMMAND) {
                    model.apply_write(a);
                } else if (a.cmd == tlm::TLM_READ_COMMAND) {
                    const int r = debug_region(a.addr, a.len, Model::map);
                    FUZZ_CHECK(r >= 0, "an OK read outside every region");
                    const auto img = model.image(r);
                    FUZZ_CHECK(std::memcmp(buf.data(), img.data() + (a.addr - Model::map[r].begin), a.len) == 0,
                               "read of %llu bytes at 0x%llx: not the documented bytes",
                               static_cast<unsigned long long>(a.len), static_cast<unsigned long long>(a.addr));
                } else {
                    FUZZ_CHECK(buf == before, "an ignored command wrote the data buffer");
                }
            }
            compare(0, "after an access");
        }
        for (int r = 0; r < 3; ++r) compare(r, "at the end of the input");
    }

    void fix_lengths(std::vector<unsigned char>& buf) const;
};

// --- specular_tlm<V>
template <class V>
using specular_target = target_impl<specular_tlm<V>, specular_model<V>>;

template <class W, class Model>
void target_impl<W, Model>::fix_lengths(std::vector<unsigned char>&) const {}

template <class W, class Model>
tlm::tlm_response_status target_impl<W, Model>::expected(const access& a, uint32_t& bit) const {
    const auto s = model.status(a);
    bit = error_bit(s);
    return s;
}

// N, KSI and OVF to 0, the log cleared, one pixel shaded then invalidated by a write of N: the
// state the model starts from (the windows keep their contents: the model adopts them).
template <class W, class Model>
void target_impl<W, Model>::reset() {
    FUZZ_CHECK(put32(0x024, 1u << 31) == tlm::TLM_OK_RESPONSE, "reset: CONTROL");
    for (uint64_t a : {0x000, 0x004, 0x008, 0x00C, 0x010, 0x000})
        FUZZ_CHECK(put32(a, 0) == tlm::TLM_OK_RESPONSE, "reset: register 0x%llx", static_cast<unsigned long long>(a));
    model.n = 0;
    model.ksi = {0, 0, 0};
    model.wrap = false;
    model.cos_reg = 0;
    model.rgb = model.golden(0);
    model.errors = 0;
    model.invalidate();
    const auto cos = debug_image(1), res = debug_image(2);
    std::memcpy(model.cos.data(), cos.data(), cos.size());
    for (std::size_t i = 0; i < 1024; ++i) std::memcpy(model.res[i].data(), res.data() + 16 * i, 16);
}

// --- line_tlm<M, SET, DIV>
template <unsigned M, interp::sample_set SET, interp::div3_mode DIV>
using line_target = target_impl<line_tlm<M, SET, DIV>, line_model<M, SET, DIV>>;

#define LINE_SPECIALISE(M, SET, DIV)                                                                        \
    template <>                                                                                             \
    void line_target<M, SET, DIV>::fix_lengths(std::vector<unsigned char>& buf) const {                     \
        for (std::size_t k = 8; k + 4 <= buf.size(); k += 16) {                                             \
            const uint32_t l = 1u + get32(buf.data() + k) % (1u << M);                                      \
            std::memcpy(buf.data() + k, &l, 4);                                                             \
        }                                                                                                   \
    }                                                                                                       \
    template <>                                                                                             \
    tlm::tlm_response_status line_target<M, SET, DIV>::expected(const access& a, uint32_t& bit) const {     \
        return model.status(a, bit);                                                                        \
    }                                                                                                       \
    template <>                                                                                             \
    void line_target<M, SET, DIV>::reset() {                                                                \
        FUZZ_CHECK(put32(0x004, 1u << 31) == tlm::TLM_OK_RESPONSE, "reset: CONTROL");                       \
        unsigned char iv[16] = {};                                                                          \
        iv[8] = 1;                                                                                          \
        FUZZ_CHECK(put(0x1000, iv, 16) == tlm::TLM_OK_RESPONSE, "reset: one interval");                     \
        model.errors = 0;                                                                                   \
        model.intervals = debug_image(1);                                                                   \
        const auto px = debug_image(2);                                                                     \
        std::memcpy(model.pixels.data(), px.data(), px.size());                                             \
        model.ready = true;                                                                                 \
        model.pixel_count = 1;                                                                              \
        model.pixels[0] = static_cast<uint32_t>(                                                            \
            interp::golden_interp_line({interp::interval_samples{{0, 0, 0, 0}, 1}}, M, SET, DIV).at(0));    \
    }
using interp::div3_mode;
using interp::sample_set;
LINE_SPECIALISE(5, sample_set::case1, div3_mode::shift_add)
LINE_SPECIALISE(3, sample_set::case2, div3_mode::exact)
#undef LINE_SPECIALISE

// Every wrapper, elaborated once; the thread runs the input it is handed, then pauses.
struct harness : sc_core::sc_module {
    std::vector<std::unique_ptr<target>> targets;
    target* pending = nullptr;
    input* in = nullptr;

    SC_HAS_PROCESS(harness);
    explicit harness(const sc_core::sc_module_name& name) : sc_module(name) {
        const auto lt = tlm_timing::loosely_timed, pa = tlm_timing::pin_accurate;
        targets.push_back(std::make_unique<specular_target<a_gen_linear>>("ua60553_lt", lt));
        targets.push_back(std::make_unique<specular_target<a_gen_rom>>("ua22802_lt", lt));
        targets.push_back(std::make_unique<specular_target<a_gen_tuned>>("tuned_lt", lt));
        targets.push_back(std::make_unique<specular_target<squared_device>>("squared_lt", lt));
        targets.push_back(std::make_unique<line_target<5, sample_set::case1, div3_mode::shift_add>>("line5_lt", lt));
        targets.push_back(std::make_unique<line_target<3, sample_set::case2, div3_mode::exact>>("line3_lt", lt));
        targets.push_back(std::make_unique<specular_target<a_gen_linear>>("ua60553_pa", pa));
        targets.push_back(std::make_unique<specular_target<a_gen_rom>>("ua22802_pa", pa));
        targets.push_back(std::make_unique<specular_target<a_gen_tuned>>("tuned_pa", pa));
        targets.push_back(std::make_unique<specular_target<squared_device>>("squared_pa", pa));
        targets.push_back(std::make_unique<line_target<5, sample_set::case1, div3_mode::shift_add>>("line5_pa", pa));
        // Appended, so the committed seeds keep their targets.
        targets.push_back(std::make_unique<specular_target<sqmul_device>>("sqmul_lt", lt));
        targets.push_back(std::make_unique<specular_target<sqmul_device>>("sqmul_pa", pa));
        SC_THREAD(serve);
    }
    void serve() {
        for (;;) {
            if (pending != nullptr) {
                pending->run(*in);
                pending = nullptr;
            }
            sc_core::sc_pause();
            wait(sc_core::SC_ZERO_TIME);
        }
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static harness* h = [] {
        sc_core::sc_report_handler::set_handler(&report_handler);
        return new harness("fuzz");
    }();
    input in(data, size);
    h->pending = h->targets[in.u8() % h->targets.size()].get();
    h->in = &in;
    sc_core::sc_start();
    FUZZ_CHECK(h->pending == nullptr, "the simulation paused before the input was served");
    return 0;
}

// libsystemc's own main() calls sc_main; this program has its own main (libFuzzer's or the replay
// driver's) and never reaches it, but the library still needs the symbol.
int sc_main(int, char**) { return 2; }
