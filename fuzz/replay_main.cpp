// The fuzz targets' main() in the ordinary builds (gcc, and gcc under ASan/UBSan): runs each file
// named on the command line, or each file inside a directory named there, through
// LLVMFuzzerTestOneInput once, as OSS-Fuzz's standalone driver does. ctest replays the committed
// corpus this way in seconds; scripts/fuzz.sh links the same targets against libFuzzer instead
// (SHADING_FUZZ=ON), whose own main() then searches for new inputs.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {
bool run_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "replay: cannot read %s\n", p.string().c_str());
        return false;
    }
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // A heap copy of exactly the input's size, so ASan sees a read past its end (as libFuzzer's).
    std::vector<uint8_t> data(bytes.begin(), bytes.end());
    uint8_t* buf = data.empty() ? nullptr : new uint8_t[data.size()];
    std::copy(data.begin(), data.end(), buf);
    LLVMFuzzerTestOneInput(buf, data.size());
    delete[] buf;
    return true;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE_OR_DIR...\n", argv[0]);
        return 2;
    }
    std::size_t runs = 0;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path arg(argv[i]);
        std::vector<std::filesystem::path> files;
        std::error_code ec;
        if (std::filesystem::is_directory(arg, ec)) {
            for (const auto& e : std::filesystem::directory_iterator(arg))
                if (e.is_regular_file()) files.push_back(e.path());
            std::sort(files.begin(), files.end());
        } else {
            files.push_back(arg);
        }
        for (const auto& f : files) {
            if (!run_file(f)) return 2;
            ++runs;
        }
    }
    std::printf("replay: %zu inputs, no finding\n", runs);
    return 0;
}
