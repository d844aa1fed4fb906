// Simulation speed of every model in one run, on Google Benchmark: results per second
// of each golden model, of each signal-level device (block delays on and off, tracing on and off),
// of the interpolation paper's units, of the whole shading pipeline on the head and of the TLM-2.0 wrappers in
// both timing modes, each with its ratio to its golden model (counter vs_golden = rate / golden's
// rate) and its mismatches against that golden model (a mismatch fails the run).
//
// SystemC elaborates once per process, so each SystemC case runs alone in a child process: the
// parent registers a proxy per case that re-executes this program (posix_spawn of /proc/self/exe
// with --perf-child and --benchmark_filter=^case$), reads the child's JSON and reports the child's
// items and timed seconds as its own (manual time). The child builds only that case's design,
// runs sc_start(SC_ZERO_TIME) (elaboration and initialisation, untimed), then one sc_start(batch)
// per benchmark iteration. A traced case writes its VCD into a temporary folder, removed at exit.
//
//   perf_models [--quick] [--benchmark_filter=...] [--benchmark_min_time=S] [--benchmark_out=F ...]
// --quick: tiny runs (min time 0.01 s, a 48-pixel head) for ctest; exit status 1 on any mismatch,
// unexpected SystemC report or failed child.
//
// Adding a row: one add_sc(...) line in register_cases() with a function that builds its harness
// (perf_harness.h; the specular devices' rows are in perf_specular.cpp), or add_golden(...) for a
// plain C++ model.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <systemc>
#include <vector>

#include "testbenches/common/child_processes.h"
#include "testbenches/common/report_log.h"
#include "core/trace.h"
#include "golden/interp_golden.h"
#include "arith/specular_arith.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"
#include "testbenches/interp/interp_coef_bench.h"
#include "testbenches/interp/interp_fd_bench.h"
#include "testbenches/interp/interp_horner_bench.h"
#include "testbenches/interp/interp_line_bench.h"
#include "perf_cases.h"
#include "perf_floor.h"
#include "perf_harness.h"
#include "perf_specular.h"
#include "golden_pipeline/pipeline.h"
#include "testbenches/pipeline/pipeline_sim.h"
#include "scene/world.h"
#include "tlm/line_tlm.h"
#include "testbenches/tlm/tlm_initiator.h"

// The fast pin-level abstractions of the interpolation paper's units and of the pipeline (modules/interp/*_fast.h,
// modules/pipeline/shading_pipeline_fast.h), when the tree has them.
#if __has_include("interp/horner_unit_fast.h") && __has_include("pipeline/shading_pipeline_fast.h")
#define SHADING_PERF_INTERP_FAST 1
#endif

namespace {

using namespace shading;
using perf::add_sc;
using perf::harness;
using perf::module;
using perf::sc_case;
using perf::sc_cases;
using perf::tlm_harness;

bool g_quick = false;
bool g_failed = false;
std::string g_min_time;  // --benchmark_min_time as given (forwarded to the children)

// Every rate is per CPU second of the process (as Google Benchmark's own): the machine may be shared.
double cpu_now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// ---------------------------------------------------------------- golden models (plain C++)

struct golden_case {
    std::string name, unit;
    std::function<std::size_t()> batch;  // evaluates a batch, returns the results it made
};
std::vector<golden_case>& goldens() {
    static std::vector<golden_case> g;
    return g;
}

constexpr std::array<uint64_t, 3> ksi{255, 140, 40};

// Random intervals for the interpolation goldens (fixed seed; the same generators as the benches).
const std::vector<tb::line_interval>& some_intervals() {
    static const std::vector<tb::line_interval> v = [] {
        std::vector<tb::line_interval> r;
        for (std::size_t i = 0; i < 256; ++i) {
            tb::split_rng g(7, i);
            tb::line_interval iv;
            iv.c1 = tb::random_samples<4>(g);
            iv.c2 = tb::random_samples<4>(g);
            iv.q = tb::random_samples<3>(g);
            r.push_back(iv);
        }
        return r;
    }();
    return v;
}

// The head, planned as the pipeline rows run it (forward differences, m = 4, head zones).
struct head_plan {
    scene::world w;
    scene::rasterised r;
    pipeline::frame_constants k;
    scene::device_config dev;
    pipeline::plan_config c;
    pipeline::plan p;
};
std::unique_ptr<head_plan> make_head(pipeline::evaluator e) {
    const unsigned size = g_quick ? 48 : 256;
    auto h = std::make_unique<head_plan>();
    h->w = scene::builtin_scene("head", SHADING_SOURCE_DIR, size, size);
    h->r = scene::rasterise(h->w);
    h->k = pipeline::frame_constants_of(h->w);
    h->c.eval = e;
    h->c.m = 4;
    h->c.degree = pipeline::degree_policy::zones;
    h->p = pipeline::make_plan(h->r, h->k, h->dev, h->c);
    return h;
}

void add_golden(const std::string& name, const std::string& unit, std::function<std::size_t()> batch) {
    goldens().push_back({name, unit, std::move(batch)});
}

void register_goldens() {
    add_golden("golden/ua60553", "evaluations", [] {
        static uint64_t code = 0;
        for (int i = 0; i < 1024; ++i) {
            code = (code + 7919) % (spec::cos_one + 1);
            benchmark::DoNotOptimize(golden_ua60553(120, code, ksi, overflow_mode::saturate).out);
        }
        return std::size_t{1024};
    });
    add_golden("golden/ua22802", "evaluations", [] {
        static uint64_t code = 0;
        for (int i = 0; i < 1024; ++i) {
            code = (code + 7919) % (spec::cos_one + 1);
            benchmark::DoNotOptimize(golden_ua22802(120, code, ksi, overflow_mode::saturate).out);
        }
        return std::size_t{1024};
    });
    add_golden("golden/ua60553_tuned", "evaluations", [] {
        static uint64_t code = 0;
        for (int i = 0; i < 1024; ++i) {
            code = (code + 7919) % (spec::cos_one + 1);
            benchmark::DoNotOptimize(golden_ua60553_tuned(120, code, ksi, overflow_mode::saturate).out);
        }
        return std::size_t{1024};
    });
    // The clocked devices' golden models (ours): the squared-quadratic law, and the square-and-multiply
    // walk over n's bits (n = 120 = 0b1111000: 6 squares and 3 multiplications).
    add_golden("golden/squared", "evaluations", [] {
        static uint64_t code = 0;
        for (int i = 0; i < 1024; ++i) {
            code = (code + 7919) % (spec::cos_one + 1);
            benchmark::DoNotOptimize(golden_squared(120, code, ksi, overflow_mode::saturate).out);
        }
        return std::size_t{1024};
    });
    add_golden("golden/sqmul", "evaluations", [] {
        static uint64_t code = 0;
        for (int i = 0; i < 1024; ++i) {
            code = (code + 7919) % (spec::cos_one + 1);
            benchmark::DoNotOptimize(golden_sqmul(120, code, ksi, overflow_mode::saturate).out);
        }
        return std::size_t{1024};
    });
    add_golden("golden/interp_coef", "sample sets", [] {
        for (const auto& iv : some_intervals())
            benchmark::DoNotOptimize(interp::golden_cubic_coefs(iv.c1, interp::sample_set::case1,
                                                                interp::div3_mode::shift_add));
        return some_intervals().size();
    });
    add_golden("golden/interp_horner", "evaluations", [] {
        std::size_t n = 0;
        for (const auto& iv : some_intervals()) {
            const auto k = interp::golden_cubic_coefs(iv.c1, interp::sample_set::case1, interp::div3_mode::shift_add);
            for (uint64_t t = 0; t <= interp::t_one; t += 16, ++n) benchmark::DoNotOptimize(interp::golden_horner(k, t, false));
        }
        return n;
    });
    add_golden("golden/interp_fd", "pixels", [] {
        std::size_t n = 0;
        for (const auto& iv : some_intervals()) {
            const auto k = interp::golden_cubic_coefs(iv.c1, interp::sample_set::case1, interp::div3_mode::shift_add);
            n += interp::golden_fd(k, 5, 32).size();
        }
        return n;
    });
    add_golden("golden/interp_line", "pixels", [] {
        static const std::vector<interp::interval_samples> ivs = [] {
            std::vector<interp::interval_samples> v;
            for (const auto& iv : some_intervals()) v.push_back({iv.c1, 32});
            return v;
        }();
        return interp::golden_interp_line(ivs, 5, interp::sample_set::case1, interp::div3_mode::shift_add).size();
    });
    add_golden("golden/pipeline_head", "pixels", [] {
        static const auto h = make_head(pipeline::evaluator::fd);
        const auto f = pipeline::golden_frame(h->p, h->k, h->dev, h->c);
        benchmark::DoNotOptimize(f.px.data());
        return static_cast<std::size_t>(h->p.pixels);
    });
}

// The golden model's own rate for the ratios, timed here (about 0.2 s of CPU, 0.01 s with --quick).
double golden_rate(const std::string& name) {
    static std::map<std::string, double> cache;
    if (auto it = cache.find(name); it != cache.end()) return it->second;
    for (const auto& g : goldens()) {
        if (g.name != name) continue;
        const double want = g_quick ? 0.01 : 0.2;
        std::size_t items = g.batch();  // warm-up
        items = 0;
        const double t0 = cpu_now();
        double s = 0;
        while (s < want) {
            items += g.batch();
            s = cpu_now() - t0;
        }
        return cache[name] = static_cast<double>(items) / s;
    }
    return 0.0;
}

// ---------------------------------------------------------------- SystemC cases


// Wraps one of the project's bench modules (stimulus, DUT, monitor, golden checker) as a harness.
template <class Bench>
class bench_harness : public harness {
public:
    template <typename... Args>
    explicit bench_harness(Args&&... args) : b_("tb", std::forward<Args>(args)...) {
        b_.checker.keep_samples(false);
    }
    sc_core::sc_object& root() override { return b_; }
    uint64_t items() const override { return b_.checker.checked(); }
    uint64_t mismatches() const override { return b_.checker.mismatches(); }
    sc_core::sc_time batch() const override { return period() * 1000.0; }
    sc_core::sc_time period() const override { return tb::interp_period(); }
    Bench& bench() { return b_; }

private:
    Bench b_;
};



struct line_tlm_top : tlm_harness {
    using wrapper_t = line_tlm<5, interp::sample_set::case1, interp::div3_mode::shift_add>;
    wrapper_t w;
    line_tlm_top(const sc_core::sc_module_name& n, tlm_timing t)
        : tlm_harness(n, &line_tlm_top::script,
                      t == tlm_timing::loosely_timed ? perf::lt_quantum() : sc_core::sc_time(20 * 8400, sc_core::SC_NS),
                      sc_core::sc_time(20, sc_core::SC_NS)),
          w("w", t) {
        init.socket.bind(w.socket);
    }
    // The script's buffers are members, not locals of the thread that never returns (its stack is
    // never unwound, so LeakSanitizer would report what only that stack points to).
    std::vector<interp::interval_samples> ivs_;
    std::vector<unsigned char> bytes_;
    std::vector<uint64_t> golden_;
    std::vector<uint32_t> px_;

    static void script(tlm_harness& self) {
        namespace m = shading::line_tlm_map;
        auto& i = self.init;
        auto& top = static_cast<line_tlm_top&>(self);
        auto& ivs = top.ivs_;
        for (const auto& iv : some_intervals()) ivs.push_back({iv.c1, 32});
        auto& bytes = top.bytes_;
        bytes.assign(16 * ivs.size(), 0);
        for (std::size_t j = 0; j < ivs.size(); ++j) {
            for (unsigned s = 0; s < 4; ++s) {
                const auto v = static_cast<uint16_t>(ivs[j].i[s]);
                std::memcpy(&bytes[16 * j + 2 * s], &v, 2);
            }
            const uint32_t len = ivs[j].len;
            std::memcpy(&bytes[16 * j + m::IV_LEN], &len, 4);
        }
        auto& golden = top.golden_;
        golden = interp::golden_interp_line(ivs, 5, interp::sample_set::case1, interp::div3_mode::shift_add);
        auto& px = top.px_;
        px.assign(golden.size(), 0);
        tlm_utils::tlm_quantumkeeper::set_global_quantum(perf::lt_quantum());
        tlm_utils::tlm_quantumkeeper qk;
        qk.reset();
        for (;;) {
            perf::lt_access(i, qk, tlm::TLM_WRITE_COMMAND, m::INTERVAL_BLOCK, bytes.data(),
                            static_cast<unsigned>(bytes.size()));
            perf::lt_access(i, qk, tlm::TLM_READ_COMMAND, m::PIXEL_BLOCK, reinterpret_cast<unsigned char*>(px.data()),
                            static_cast<unsigned>(4 * px.size()));
            for (std::size_t p = 0; p < px.size(); ++p) self.mismatches_ += px[p] != golden[p];
            self.items_ += px.size();
        }
    }
};






void add_pipeline(const std::string& name, pipeline::evaluator e, bool fast = false) {
    sc_case c{name, "golden/pipeline_head", "pixels", nullptr, false, nullptr};
    c.once = [e, fast](double& items, double& seconds, double& mismatches) {
        const auto h = make_head(e);
        pipeline::sim_options o;
#ifdef SHADING_PERF_INTERP_FAST
        if (fast) o.level = abstraction::fast;
#else
        (void)fast;
#endif
        const auto r = pipeline::simulate_frame(h->p, h->k, h->dev, h->c, o);
        items = static_cast<double>(h->p.pixels);
        seconds = r.seconds;
        mismatches = static_cast<double>(r.mismatches);
    };
    sc_cases().push_back(std::move(c));
}

void register_cases() {
    perf::register_floor_cases();
    perf::register_specular_cases();

    // The interpolation paper's units in the project's own benches (stimulus, DUT, monitor, golden checker).
    const std::size_t big = 50'000'000;  // more than any run streams; generated on demand
    add_sc("sc/interp_coef", "golden/interp_coef", "sample sets", [=] {
        return std::unique_ptr<harness>(new bench_harness<tb::coef_bench>(tb::random_coef_inputs(big, 1)));
    });
    for (bool traced : {false, true})
        add_sc(std::string("sc/interp_horner") + (traced ? "/traced" : ""), "golden/interp_horner", "evaluations",
               [=] {
                   return std::unique_ptr<harness>(
                       new bench_harness<tb::horner_bench>(tb::random_horner_requests(big, 1)));
               },
               traced);
    add_sc("sc/interp_fd", "golden/interp_fd", "pixels", [=] {
        return std::unique_ptr<harness>(new bench_harness<tb::fd_bench<5>>(tb::random_fd_intervals<5>(big, 1)));
    });
#ifdef SHADING_PERF_INTERP_FAST
    // The fast pin-level abstractions of the units (modules/interp/*_fast.h) in the same benches.
    for (bool traced : {false, true})
        add_sc(std::string("sc/interp_horner_fast") + (traced ? "/traced" : ""), "golden/interp_horner", "evaluations",
               [=] {
                   return std::unique_ptr<harness>(
                       new bench_harness<tb::horner_bench_fast>(tb::random_horner_requests(big, 1)));
               },
               traced);
    add_sc("sc/interp_fd_fast", "golden/interp_fd", "pixels", [=] {
        return std::unique_ptr<harness>(
            new bench_harness<tb::fd_bench<5, fd_eval_fast<5>>>(tb::random_fd_intervals<5>(big, 1)));
    });
    add_sc("sc/interp_line_fast", "golden/interp_line", "pixels", [=] {
        constexpr auto set = interp::sample_set::case1;
        constexpr auto div = interp::div3_mode::shift_add;
        using B = tb::line_bench<5, set, div, interp_line_unit_fast<5, set, div>>;
        return std::unique_ptr<harness>(new bench_harness<B>(tb::random_line_intervals<5>(big, 1)));
    });
#endif
    for (bool traced : {false, true})
        add_sc(std::string("sc/interp_line") + (traced ? "/traced" : ""), "golden/interp_line", "pixels",
               [=] {
                   using B = tb::line_bench<5, interp::sample_set::case1, interp::div3_mode::shift_add>;
                   return std::unique_ptr<harness>(new bench_harness<B>(tb::random_line_intervals<5>(big, 1)));
               },
               traced);

    add_pipeline("sc/pipeline_head/fd", pipeline::evaluator::fd);
    add_pipeline("sc/pipeline_head/horner", pipeline::evaluator::horner);
#ifdef SHADING_PERF_INTERP_FAST
    add_pipeline("sc/pipeline_head/fd_fast", pipeline::evaluator::fd, true);
    add_pipeline("sc/pipeline_head/horner_fast", pipeline::evaluator::horner, true);
#endif

    for (auto t : {tlm_timing::loosely_timed, tlm_timing::pin_accurate}) {
        const std::string mode_name = t == tlm_timing::loosely_timed ? "lt" : "pin";
        perf::add_specular_tlm("tlm/specular_tlm/" + mode_name, t == tlm_timing::pin_accurate);
        add_sc("tlm/line_tlm/" + mode_name, "golden/interp_line", "pixels", module<line_tlm_top>(t));
    }
}

// ---------------------------------------------------------------- child: one case, one elaboration

std::unique_ptr<harness> g_harness;
const sc_case* g_case = nullptr;
std::unique_ptr<vcd_file> g_vcd;
std::filesystem::path g_vcd_dir;

void child_batches(benchmark::State& st, const sc_case& c) {
    if (!g_harness) {
        g_case = &c;
        g_harness = c.make();
        if (c.traced) {
            std::string tmpl = (std::filesystem::temp_directory_path() / "perf_models_vcd.XXXXXX").string();
            if (mkdtemp(tmpl.data()) == nullptr) {
                st.SkipWithError("cannot create a temporary folder for the VCD");
                return;
            }
            g_vcd_dir = tmpl;
            g_vcd = std::make_unique<vcd_file>((g_vcd_dir / "trace").string());
            g_vcd->trace(g_harness->root());
        }
        sc_core::sc_start(sc_core::SC_ZERO_TIME);  // elaboration and initialisation, untimed
    }
    const uint64_t i0 = g_harness->items();
    const sc_core::sc_time t0 = sc_core::sc_time_stamp();
    const sc_core::sc_time batch = g_harness->batch();
    for (auto _ : st) sc_core::sc_start(batch);
    st.SetItemsProcessed(static_cast<int64_t>(g_harness->items() - i0));
    st.counters["mismatches"] = static_cast<double>(g_harness->mismatches());
    st.counters["clocks"] = (sc_core::sc_time_stamp() - t0) / g_harness->period();
}

// The frame's simulation seconds as CPU time: its wall seconds times the call's CPU / wall ratio
// (the call also elaborates, so its own CPU time would include that).
void child_once(benchmark::State& st, const sc_case& c) {
    double items = 0, seconds = 0, mismatches = 0;
    for (auto _ : st) {
        const double c0 = cpu_now();
        const auto w0 = std::chrono::steady_clock::now();
        c.once(items, seconds, mismatches);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
        const double cpu = cpu_now() - c0;
        st.SetIterationTime(wall > 0 && cpu < wall ? seconds * cpu / wall : seconds);
    }
    st.SetItemsProcessed(static_cast<int64_t>(items));
    st.counters["mismatches"] = mismatches;
}

// ---------------------------------------------------------------- parent: a proxy per case

struct child_result {
    bool ok = false;
    std::string error;
    double items = 0, seconds = 0, mismatches = 0, clocks = 0;
};

double unit_seconds(const std::string& u) {
    return u == "ns" ? 1e-9 : u == "us" ? 1e-6 : u == "ms" ? 1e-3 : 1.0;
}

child_result run_child(const sc_case& c) {
    child_result r;
    char out_tmpl[] = "/tmp/perf_models_child.XXXXXX";
    const int fd = mkstemp(out_tmpl);
    if (fd < 0) {
        r.error = "mkstemp failed";
        return r;
    }
    close(fd);
    const std::string out = out_tmpl;
    std::vector<std::string> args{"/proc/self/exe", "--perf-child", // Google Benchmark appends /iterations:1 and /manual_time to the registered name.
                                  "--benchmark_filter=^" + c.name + "(/iterations:1)?(/manual_time)?$",
                                  "--benchmark_format=json", "--benchmark_out=" + out,
                                  "--benchmark_out_format=json"};
    if (g_quick) args.push_back("--quick");
    if (!g_min_time.empty()) args.push_back("--benchmark_min_time=" + g_min_time);
    // Its standard output (the benchmark's console table) is discarded: the JSON file is read.
    const auto spec = [&](std::size_t) { return tb::child_spec{"/proc/self/exe", args, "/dev/null"}; };
    const int status = tb::run_children(1, 1, spec)[0];
    if (status < 0) {
        r.error = "cannot run the child process";
    } else {
        try {
            std::ifstream f(out);
            const auto j = nlohmann::json::parse(f);
            const auto& b = j.at("benchmarks").at(0);
            if (b.contains("error_occurred") && b["error_occurred"].get<bool>()) {
                r.error = b.value("error_message", std::string("child reported an error"));
            } else {
                // CPU seconds (the machine may be shared): Google Benchmark's rate is per CPU
                // second, except for a manual-time case (child_once), whose time is CPU time already.
                r.seconds = b.at("iterations").get<double>() * b.at(c.once ? "real_time" : "cpu_time").get<double>() *
                            unit_seconds(b.at("time_unit").get<std::string>());
                r.items = b.at("items_per_second").get<double>() * r.seconds;
                r.mismatches = b.value("mismatches", 0.0);
                r.clocks = b.value("clocks", 0.0);
                r.ok = true;
            }
        } catch (const std::exception& ex) {
            r.error = std::string("no result from the child: ") + ex.what();
        }
        if (r.ok && status != 0) {
            r.ok = false;
            r.error = "child exited with status " + std::to_string(status) +
                      " (unexpected SystemC report?)";
        }
    }
    std::filesystem::remove(out);
    return r;
}

void proxy(benchmark::State& st, const sc_case& c) {
    const child_result r = run_child(c);
    for (auto _ : st) st.SetIterationTime(r.ok ? r.seconds : 1e-9);
    if (!r.ok) {
        g_failed = true;
        st.SkipWithError(r.error.c_str());
        return;
    }
    st.SetItemsProcessed(static_cast<int64_t>(r.items));
    st.counters["mismatches"] = r.mismatches;
    if (r.mismatches > 0 && c.strict) g_failed = true;
    if (r.clocks > 0) st.counters["clocks_per_second"] = benchmark::Counter(r.clocks, benchmark::Counter::kIsRate);
    const double golden = golden_rate(c.golden);
    if (golden > 0 && r.seconds > 0) st.counters["vs_golden"] = r.items / r.seconds / golden;
    st.SetLabel(c.unit + "; golden " + c.golden);
}

void golden_bench(benchmark::State& st, const golden_case& g) {
    std::size_t items = g.batch();  // untimed warm-up: builds a batch's static inputs (the head's plan)
    items = 0;
    for (auto _ : st) items += g.batch();
    st.SetItemsProcessed(static_cast<int64_t>(items));
    st.SetLabel(g.unit);
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    // Our own flags first (Google Benchmark rejects flags it does not know).
    bool child = false;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--perf-child") child = true;
        else if (a == "--quick") g_quick = true;
        else {
            if (a.rfind("--benchmark_min_time=", 0) == 0) g_min_time = a.substr(std::strlen("--benchmark_min_time="));
            args.push_back(argv[i]);
        }
    }
    static std::string quick_min = "--benchmark_min_time=0.01";
    if (g_quick && g_min_time.empty()) {
        g_min_time = "0.01";
        args.push_back(quick_min.data());
    }
    int n = static_cast<int>(args.size());
    args.push_back(nullptr);

    register_goldens();
    register_cases();
    if (child) {
        tb::report_log::install();
        for (const auto& c : sc_cases()) {
            if (c.once)
                benchmark::RegisterBenchmark(c.name.c_str(), child_once, c)->UseManualTime()->Iterations(1);
            else
                benchmark::RegisterBenchmark(c.name.c_str(), child_batches, c);
        }
    } else {
        for (const auto& g : goldens()) benchmark::RegisterBenchmark(g.name.c_str(), golden_bench, g);
        for (const auto& c : sc_cases())
            benchmark::RegisterBenchmark(c.name.c_str(), proxy, c)->UseManualTime()->Iterations(1);
    }
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (child) {
        const bool bad = g_harness && g_harness->mismatches() > 0 && g_case->strict;
        g_vcd.reset();
        g_harness.reset();  // before the statics it uses (Verilator's context) go
        if (!g_vcd_dir.empty()) std::filesystem::remove_all(g_vcd_dir);
        const unsigned unexpected = tb::report_log::get().unexpected();
        if (unexpected > 0) std::fprintf(stderr, "perf_models: %u unexpected SystemC reports\n", unexpected);
        return bad || unexpected > 0 ? 1 : 0;
    }
    return g_failed ? 1 : 0;
}
