// Writes a Wavefront OBJ of a procedural model no program has seen (test_obj.h: a folded blob, or a
// cluster of six at different depths), with a normal per vertex, so the race can be run at test time
// on a model it was not tuned on. Plain argv (three options): exit 0 after writing or --help,
// 1 if the file cannot be written, 2 for bad usage.
//   build/bin/make_test_obj --shape blob --segments 64 --out out/race_obj/blob.obj
#include <cstdio>
#include <cstdlib>
#include <string>

#include "testbenches/common/exit_status.h"
#include "testbenches/scene/test_obj.h"

namespace {

const char* usage =
    "make_test_obj: a Wavefront OBJ (v, vn, f a//a b//b c//c) of a procedural model\n"
    "Usage: make_test_obj [--shape blob|cluster] [--segments N] [--out PATH]\n"
    "  --shape     blob: one sphere displaced by products of sines (folds, many small triangles);\n"
    "              cluster: six such blobs of different sizes at different depths (default blob)\n"
    "  --segments  longitudes of each blob, even, 4..2048; half as many latitude bands (default 64)\n"
    "  --out       the file to write (default test.obj)\n";

int bad(const std::string& why) {
    std::fprintf(stderr, "make_test_obj: %s\n%s", why.c_str(), usage);
    return shading::tb::exit_usage;
}

}  // namespace

int main(int argc, char* argv[]) {
    namespace obj = shading::tb::test_obj;
    std::string shape = "blob", out = "test.obj";
    unsigned long segments = 64;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-h" || a == "--help") {
            std::fputs(usage, stdout);
            return shading::tb::exit_success;
        }
        if (a != "--shape" && a != "--segments" && a != "--out") return bad("unknown option '" + a + "'");
        if (i + 1 >= argc) return bad(a + " needs a value");
        const std::string v = argv[++i];
        if (a == "--shape") {
            shape = v;
        } else if (a == "--out") {
            out = v;
        } else {
            char* end = nullptr;
            segments = std::strtoul(v.c_str(), &end, 10);
            if (v.empty() || v[0] == '-' || *end != '\0' || segments < 4 || segments > 2048 || segments % 2)
                return bad("--segments '" + v + "' is not an even number in 4..2048");
        }
    }
    bool known = false;
    for (const auto& n : obj::shape_names()) known = known || n == shape;
    if (!known) return bad("unknown --shape '" + shape + "' (blob, cluster)");
    if (out.empty()) return bad("--out needs a path");

    const shading::scene::mesh m = obj::make_shape(shape, static_cast<unsigned>(segments));
    const std::string comment = "make_test_obj --shape " + shape + " --segments " + std::to_string(segments);
    if (!obj::write_obj(m, out, comment)) {
        std::fprintf(stderr, "make_test_obj: cannot write %s\n", out.c_str());
        return shading::tb::exit_failure;
    }
    std::printf("Wrote %s: %s, %zu vertices, %zu triangles.\n", out.c_str(), shape.c_str(), m.positions.size(),
                m.triangles.size());
    return shading::tb::exit_success;
}
