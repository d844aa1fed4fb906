// The wrappers' error tables (test_specular_tlm, test_line_tlm): each bad access must give its TLM
// response in no time (neither waited nor annotated), set its bit in STATUS's bus-error log, and
// leave the state visible through debug transport as it was; a failed read returns no data.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include "tlm_initiator.h"

namespace shading::tb {

struct bad_access {
    const char* what;
    tlm::tlm_command cmd;
    uint64_t addr;
    unsigned len;
    bool be;      // with byte enables (FF FF 00 00)
    unsigned sw;  // streaming width (0: len)
    tlm::tlm_response_status want;
    uint32_t bit;                   // the error log's bit
    unsigned char* data = nullptr;  // a write's bytes; nullptr: 64 bytes of 0xA5 (every read)
};

// error_log(i): STATUS's error bits; clear_log(i): clears them (a response); snapshot(i): the state.
template <class ErrorLog, class ClearLog, class Snapshot>
void expect_bad_accesses(tlm_initiator& i, const std::vector<bad_access>& cases, ErrorLog error_log,
                         ClearLog clear_log, Snapshot snapshot) {
    const auto s0 = snapshot(i);
    unsigned char buf[64] = {};
    unsigned char be[4] = {0xFF, 0xFF, 0, 0};
    for (const bad_access& c : cases) {
        unsigned char* data = c.data != nullptr ? c.data : buf;
        std::fill(std::begin(buf), std::end(buf), 0xA5);
        const auto s = i.access(c.cmd, c.addr, data, c.len, c.be ? be : nullptr, c.sw);
        EXPECT_EQ(s, c.want) << c.what;
        EXPECT_EQ(i.last_elapsed, sc_core::SC_ZERO_TIME) << c.what;
        EXPECT_EQ(i.last_delay, sc_core::SC_ZERO_TIME) << c.what;
        EXPECT_EQ(error_log(i), c.bit) << c.what << ": the bus-error log";
        ASSERT_EQ(clear_log(i), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(snapshot(i), s0) << c.what << ": state changed";
        if (c.cmd == tlm::TLM_READ_COMMAND) {
            EXPECT_EQ(data[0], 0xA5) << c.what << ": a failed read returned data";
        }
    }
}

}  // namespace shading::tb
