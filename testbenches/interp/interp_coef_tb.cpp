// Coefficient-unit testbench program: streams the sample points of one raster line (and random
// sample sets) through the five coefficient units (case 1 / case 2 x shift-and-add / exact
// division by 3, quadratic), one interval per clock, checks each against its golden model, and
// writes the relative error that the shift-and-add /3 causes in A and C (CSV).
// Options common to every bench: common/common_options.h.
//
//   interp_coef_tb                      VCD traces/interp_coef.vcd, view traces/interp_coef.gtkw
//   interp_coef_tb --csv out/interp_div3.csv --extra-sets 2000 --no-vcd
//   interp_coef_tb --random 1000000 --seed 7   random sample sets only, against the golden models
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>

#include "testbenches/common/bench_runner.h"
#include "testbenches/options/bench_options.h"
#include "testbenches/interp/interp_coef_bench.h"
#include "testbenches/interp/interp_line.h"

using namespace shading;
using namespace shading::tb;

int sc_main(int argc, char* argv[]) {
    interp_coef_options o;
    if (auto rc = parse_interp_coef(argc, argv, o)) return *rc;
    bench_runner run("interp_coef", o.bench);
    if (auto rc = run.start(argc, argv)) return *rc;
    const std::string& csv_path = o.csv_path;
    const unsigned width = o.width, m = o.m, n_extra = o.n_extra;

    if (run.random()) {
        coef_bench bench("tb", random_coef_inputs(run.random_count(), run.seed()));
        bench.checker.keep_samples(false);
        bench.checker.inject_mismatch(run.inject(), run.inject_count());
        run.simulate(bench, sc_core::sc_max_time());
        for (std::size_t u = 0; u < 5; ++u)
            std::cout << "  " << variant_name(all_variants[u]) << ": mismatches " << bench.checker.mismatches(u) << '\n';
        run.report_random("random", bench.checker.checked(), bench.checker.mismatches(), "sample sets");
        return run.finish(bench.checker.checked(), bench.checker.mismatches());
    }

    const auto line = make_line(width, m);
    std::vector<coef_inputs> sets;
    for (const auto& iv : line.intervals) sets.push_back({iv.c1, iv.c2, iv.q});
    std::mt19937 rng(2024);
    std::uniform_int_distribution<uint64_t> u(0, interp::sample_fmt.mask());
    for (unsigned i = 0; i < n_extra; ++i)
        sets.push_back({{u(rng), u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}});

    coef_bench bench("tb", sets);
    bench.checker.inject_mismatch(run.inject(), run.inject_count());
    run.simulate(bench);

    // Relative error of A and C against the real-valued formulas of the same sample codes.
    const double lsb = interp::coef_fmt.lsb();
    auto r8 = [](uint64_t c) { return static_cast<double>(c) / 256.0; };
    std::array<double, 5> max_err{};
    std::ofstream csv;
    if (!csv_path.empty()) {
        csv.open(csv_path);
        csv << "interval,first_pixel,case,coef,real,shift_add,exact_div,rel_err_shift_add,rel_err_exact_div\n";
    }
    const auto& samples = bench.checker.samples();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const auto& s = samples[i];
        for (int cs = 0; cs < 2; ++cs) {
            const auto& in = cs == 0 ? s.in.c1 : s.in.c2;
            const auto set = cs == 0 ? interp::sample_set::case1 : interp::sample_set::case2;
            const auto r = ref::cubic_coefs({r8(in[0]), r8(in[1]), r8(in[2]), r8(in[3])}, set);
            const auto& sa = s.out[2 * cs];
            const auto& ex = s.out[2 * cs + 1];
            for (auto [name, real, vsa, vex] : {std::tuple{"A", r.a, sa.a * lsb, ex.a * lsb},
                                                std::tuple{"C", r.c, sa.c * lsb, ex.c * lsb}}) {
                if (std::abs(real) < 1.0) continue;  // relative error of a near-zero coefficient: not meaningful
                const double esa = (vsa - real) / real, eex = (vex - real) / real;
                max_err[2 * cs] = std::max(max_err[2 * cs], std::abs(esa));
                max_err[2 * cs + 1] = std::max(max_err[2 * cs + 1], std::abs(eex));
                if (csv.is_open() && i < line.intervals.size())
                    csv << i << ',' << line.intervals[i].first_pixel << ',' << cs + 1 << ',' << name << ',' << real
                        << ',' << vsa << ',' << vex << ',' << esa << ',' << eex << '\n';
            }
        }
        const auto rq = ref::quad_coefs({r8(s.in.q[0]), r8(s.in.q[1]), r8(s.in.q[2])});
        max_err[4] = std::max({max_err[4], std::abs(s.out[4].a * lsb - rq.b), std::abs(s.out[4].b * lsb - rq.c),
                               std::abs(s.out[4].c * lsb - rq.d)});
    }

    const double cpp = 1.0 / static_cast<double>(line.n());  // one interval's coefficients per clock
    std::cout << "interp_coef: " << samples.size() << " sample sets (" << line.intervals.size()
              << " line intervals + " << n_extra << " random), one set per clock\n";
    for (std::size_t u = 0; u < 5; ++u) {
        const std::string name = variant_name(all_variants[u]);
        const std::string note = u < 4 ? "max |rel err| of A and C vs real "
                                         "(the interpolation paper: /3 shift-add <= 0.79%)"
                                       : "max |abs err| of a,b,c vs real (exact: shifts and adds)";
        std::cout << "  " << name << ": mismatches " << bench.checker.mismatches(u) << ", " << note << " = "
                  << max_err[u] << '\n';
        run.summary({run.bench(), name, samples.size(), bench.checker.mismatches(u),
                     u < 4 ? fmt_percent(max_err[u], 4) : fmt_levels(max_err[u]), fmt_number(cpp), note});
    }
    return run.finish(samples.size(), bench.checker.mismatches());
}
