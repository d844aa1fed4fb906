// SystemC report handling shared by the testbench programs and the GoogleTest suites.
// Every warning, error or fatal is logged with its message id. In tests, a report that the test
// did not announce with expect() becomes a test failure; announced ones are counted so the test
// can check they really fired.
#pragma once

#include <map>
#include <set>
#include <string>
#include <systemc>
#include <vector>

namespace shading::tb {

class report_log {
public:
    static report_log& get() {
        static report_log log;
        return log;
    }

    // Route SystemC reports here. `fail` is called for a report not announced with expect().
    static void install(void (*fail)(const sc_core::sc_report&) = nullptr) {
        get().fail_ = fail;
        sc_core::sc_report_handler::set_handler(&handler);
    }

    void expect(const std::string& id) { expected_.insert(id); }
    unsigned count(const std::string& id) const {
        auto it = counts_.find(id);
        return it == counts_.end() ? 0u : it->second;
    }
    // The texts of the first 64 reports of an id, for tests that check what a report says.
    std::vector<std::string> messages(const std::string& id) const {
        auto it = messages_.find(id);
        return it == messages_.end() ? std::vector<std::string>{} : it->second;
    }
    unsigned unexpected() const { return unexpected_; }
    void set_verbose(bool v) { verbose_ = v; }

private:
    static void handler(const sc_core::sc_report& r, const sc_core::sc_actions& actions) {
        auto& self = get();
        if (r.get_severity() == sc_core::SC_INFO) {
            if (self.verbose_) sc_core::sc_report_handler::default_handler(r, sc_core::SC_DISPLAY);
            return;  // kernel chatter ("stopped by user", "timescale unit set") is not a finding
        }
        const std::string id = r.get_msg_type();
        ++self.counts_[id];
        auto& texts = self.messages_[id];
        if (texts.size() < 64) texts.push_back(r.get_msg());
        const bool announced = self.expected_.count(id) > 0;
        if (!announced) ++self.unexpected_;
        if (!announced || self.verbose_)
            sc_core::sc_report_handler::default_handler(r, sc_core::SC_DISPLAY);
        if (!announced && self.fail_) self.fail_(r);
        // Bad input must never crash the model: errors are logged, not thrown. Fatal stays fatal.
        if (r.get_severity() == sc_core::SC_FATAL)
            sc_core::sc_report_handler::default_handler(r, actions);
    }

    std::set<std::string> expected_;
    std::map<std::string, unsigned> counts_;
    std::map<std::string, std::vector<std::string>> messages_;
    unsigned unexpected_ = 0;
    bool verbose_ = false;
    void (*fail_)(const sc_core::sc_report&) = nullptr;
};

}  // namespace shading::tb
