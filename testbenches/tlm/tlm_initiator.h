// A small TLM-2.0 initiator for the wrapper tests and the benchmark: a simple_initiator_socket and
// one SC_THREAD that runs a script (a function given the initiator), then stops the simulation
// (no script: no thread, the socket is driven from another initiator's script).
// Its helpers issue single-word and block accesses with b_transport and keep the annotated delay
// of the last access, so a test can compare it with the simulated time that passed.
#pragma once

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <systemc>
#include <vector>

namespace shading::tb {

class tlm_initiator : public sc_core::sc_module {
public:
    tlm_utils::simple_initiator_socket<tlm_initiator> socket{"socket"};
    using script = std::function<void(tlm_initiator&)>;

    SC_HAS_PROCESS(tlm_initiator);
    tlm_initiator(const sc_core::sc_module_name& name, script s) : sc_module(name), script_(std::move(s)) {
        if (script_) SC_THREAD(run);  // without a script: a socket another initiator's thread drives
    }

    bool finished() const { return finished_; }

    // The last access: its annotated delay (b_transport's delay after the call, starting from
    // `delay_in`) and the simulated time the call took.
    sc_core::sc_time delay_in = sc_core::SC_ZERO_TIME;
    sc_core::sc_time last_delay, last_elapsed;

    tlm::tlm_response_status access(tlm::tlm_command cmd, uint64_t addr, unsigned char* data, unsigned len,
                                    unsigned char* byte_enables = nullptr, unsigned streaming_width = 0) {
        tlm::tlm_generic_payload p;
        p.set_command(cmd);
        p.set_address(addr);
        p.set_data_ptr(data);
        p.set_data_length(len);
        p.set_streaming_width(streaming_width ? streaming_width : len);
        p.set_byte_enable_ptr(byte_enables);
        p.set_byte_enable_length(byte_enables ? len : 0);
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        sc_core::sc_time d = delay_in;
        const sc_core::sc_time t0 = sc_core::sc_time_stamp();
        socket->b_transport(p, d);
        last_delay = d;
        last_elapsed = sc_core::sc_time_stamp() - t0;
        return p.get_response_status();
    }
    tlm::tlm_response_status write32(uint64_t addr, uint32_t v) {
        unsigned char b[4];
        std::memcpy(b, &v, 4);
        return access(tlm::TLM_WRITE_COMMAND, addr, b, 4);
    }
    tlm::tlm_response_status read32(uint64_t addr, uint32_t& v) {
        unsigned char b[4] = {};
        const auto s = access(tlm::TLM_READ_COMMAND, addr, b, 4);
        std::memcpy(&v, b, 4);
        return s;
    }
    uint32_t read32(uint64_t addr) {
        uint32_t v = 0xDEADBEEF;
        read32(addr, v);
        return v;
    }
    // Debug transport: bytes transferred.
    unsigned debug(tlm::tlm_command cmd, uint64_t addr, unsigned char* data, unsigned len) {
        tlm::tlm_generic_payload p;
        p.set_command(cmd);
        p.set_address(addr);
        p.set_data_ptr(data);
        p.set_data_length(len);
        return socket->transport_dbg(p);
    }
    std::vector<unsigned char> debug_read(uint64_t addr, unsigned len) {
        std::vector<unsigned char> v(len);
        v.resize(debug(tlm::TLM_READ_COMMAND, addr, v.data(), len));
        return v;
    }

private:
    void run() {
        script_(*this);
        finished_ = true;
        sc_core::sc_stop();
    }
    script script_;
    bool finished_ = false;
};

}  // namespace shading::tb
