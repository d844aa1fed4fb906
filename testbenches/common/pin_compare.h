// The block level and the fast level of one unit side by side on one stimulus: pairs of their
// signals compared at every rising edge of the clock (a pair with a `when` pin only at the edges
// where that pin reads 1, e.g. data under valid), the first differences printed with their time.
// The fast-model tests of the interpolation units (forward differences, raster-line unit, Horner
// unit) share it.
#pragma once

#include <cstdio>
#include <functional>
#include <sstream>
#include <systemc>
#include <vector>

namespace shading::tb {

class pin_compare : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> clk{"clk"};

    SC_HAS_PROCESS(pin_compare);
    explicit pin_compare(const sc_core::sc_module_name& name) : sc_module(name) {
        SC_METHOD(on_edge);
        sensitive << clk.pos();
        dont_initialize();
    }

    // blk and fst must read the same at every rising edge (or, given `when`, wherever it reads 1).
    template <class T>
    void pair(const char* name, const sc_core::sc_signal_in_if<T>& blk, const sc_core::sc_signal_in_if<T>& fst,
              const sc_core::sc_signal_in_if<bool>* when = nullptr) {
        pairs_.push_back([name, &blk, &fst, when](std::ostream& os) {
            if ((when != nullptr && !when->read()) || blk.read() == fst.read()) return true;
            os << ' ' << name << ' ' << blk.read() << '/' << fst.read();
            return false;
        });
    }
    // The edges where `pin` reads 1 are counted (e.g. the block level's valid or done).
    void count(const sc_core::sc_signal_in_if<bool>& pin) { counted_pin_ = &pin; }

    std::size_t differences() const { return differences_; }  // edges where a pair differed
    std::size_t edges() const { return edges_; }
    std::size_t counted() const { return counted_; }

private:
    void on_edge() {
        ++edges_;
        if (counted_pin_ != nullptr && counted_pin_->read()) ++counted_;
        std::ostringstream os;
        bool same = true;
        for (const auto& p : pairs_) same = p(os) && same;
        if (!same && differences_++ < 5)
            std::printf("outputs differ at %s (block/fast):%s\n", sc_core::sc_time_stamp().to_string().c_str(),
                        os.str().c_str());
    }

    std::vector<std::function<bool(std::ostream&)>> pairs_;
    const sc_core::sc_signal_in_if<bool>* counted_pin_ = nullptr;
    std::size_t differences_ = 0, edges_ = 0, counted_ = 0;
};

}  // namespace shading::tb
