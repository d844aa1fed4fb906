// Reads the signal names a VCD declares and the names a GTKWave save file lists, so tests can
// check that a hand-written .gtkw view shows only nets that exist (GTKWave silently drops the
// others). Names in GTKWave's form: scope path + name + "[msb:lsb]" for buses.
#pragma once

#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace shading::tb {

inline std::set<std::string> vcd_declared(const std::string& vcd_path) {
    std::set<std::string> names;
    std::vector<std::string> scope;
    std::ifstream vcd(vcd_path);
    for (std::string tok; vcd >> tok;) {
        if (tok == "$scope") {
            std::string kind, name;
            vcd >> kind >> name;
            scope.push_back(name);
        } else if (tok == "$upscope") {
            if (!scope.empty()) scope.pop_back();
        } else if (tok == "$var") {
            std::string kind, width, id, name, range;
            vcd >> kind >> width >> id >> name >> range;
            std::string full;
            for (const auto& s : scope) full += s + ".";
            names.insert(full + name + (range == "$end" ? "" : range));
        } else if (tok == "$enddefinitions") {
            break;
        }
    }
    return names;
}

// The traces a save file shows (its lines that start with the top scope "SystemC.").
inline std::vector<std::string> gtkw_listed(const std::string& gtkw_path) {
    std::vector<std::string> listed;
    std::ifstream gtkw(gtkw_path);
    for (std::string line; std::getline(gtkw, line);)
        if (line.rfind("SystemC.", 0) == 0) listed.push_back(line);
    return listed;
}

// Where the committed traces/*.gtkw live (the tests run in the build tree).
inline std::string source_path(const std::string& relative) {
    return std::string(SHADING_SOURCE_DIR) + "/" + relative;
}

}  // namespace shading::tb
