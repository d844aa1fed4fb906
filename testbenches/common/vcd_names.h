// Reads the signal names a VCD declares and the names a GTKWave save file lists, so tests can
// check that a hand-written .gtkw view shows only nets that exist (GTKWave silently drops the
// others). Names in GTKWave's form: scope path + name + "[msb:lsb]" for buses.
// Also reads what a view shows at first sight (dump file, opening window, marker, each trace's
// number format) so tests can check it without a display: view_problems().
#pragma once

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "formats/fixed_point.h"

namespace shading::tb {

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

// GTKWave 3.3.118's trace flags (analyzer.h: bit n = TR_*_B in enum TraceEntFlagBits). A save
// file writes them as "@<hex>", and they hold for every trace after it up to the next "@" line.
namespace gtkw_flag {
inline constexpr uint64_t hex = 1ull << 1, dec = 1ull << 2, bin = 1ull << 3, oct = 1ull << 4;
inline constexpr uint64_t is_signed = 1ull << 10, ascii = 1ull << 11, real = 1ull << 18;
inline constexpr uint64_t fpdecshift = 1ull << 30;  // value = code / 2^[fpshift_count]
}  // namespace gtkw_flag

struct gtkw_trace {
    std::string name;  // as listed: SystemC.<scopes>.<net>[msb:lsb]
    uint64_t flags = 0;
    int fpshift = 0;   // the "[fpshift_count] n" in force (also sticky; 0 until set)
};

struct gtkw_view {
    std::string dumpfile, savefile;  // [dumpfile] "..." / [savefile] "..."
    int64_t timestart = 0;           // left edge of the waves pane, in the VCD's time unit
    double zoom = 0;                 // "*<zoom> <marker> ..." line
    int64_t marker = -1;
    int width = 0, height = 0, signals_width = 0, sst_width = 0;
    std::vector<gtkw_trace> traces;
    std::vector<std::string> rows;   // every row of the signal pane in order: traces and group lines

    // Right edge of the opening window. GTKWave draws 2^-zoom time units per 200 pixels (calczoom:
    // pixelsperframe = 200); the waves pane gets the window width less the signal pane, the SST
    // pane (its width is kept even when collapsed) and ~50 px of borders and scroll bar.
    int64_t window_end() const {
        const double wave_px = width - signals_width - sst_width - 50;
        return timestart + static_cast<int64_t>(wave_px * std::pow(2.0, -zoom) / 200.0);
    }
    // Rows of the signal pane visible without scrolling: the pane starts ~150 px below the
    // window's top (title, tool bar, time ruler) and GTKWave's default font gives ~21 px a row
    // (read off screenshots of these views at 1600x900 under Xvfb: 36 rows; this counts 35).
    int visible_rows() const { return height <= 150 ? 0 : (height - 150) / 21; }
};

inline gtkw_view gtkw_read(const std::string& gtkw_path) {
    gtkw_view v;
    uint64_t flags = 0;
    int fpshift = 0;
    std::ifstream gtkw(gtkw_path);
    auto quoted = [](const std::string& line) {
        const auto a = line.find('"'), b = line.rfind('"');
        return a == std::string::npos || b == a ? std::string() : line.substr(a + 1, b - a - 1);
    };
    for (std::string line; std::getline(gtkw, line);) {
        std::istringstream in(line);
        std::string key;
        in >> key;
        if (line.rfind('@', 0) == 0) flags = std::stoull(line.substr(1), nullptr, 16);
        else if (key == "[fpshift_count]") in >> fpshift;
        else if (key == "[dumpfile]") v.dumpfile = quoted(line);
        else if (key == "[savefile]") v.savefile = quoted(line);
        else if (key == "[timestart]") in >> v.timestart;
        else if (key == "[size]") in >> v.width >> v.height;
        else if (key == "[signals_width]") in >> v.signals_width;
        else if (key == "[sst_width]") in >> v.sst_width;
        else if (line.rfind('*', 0) == 0) std::istringstream(line.substr(1)) >> v.zoom >> v.marker;
        else if (line.rfind("SystemC.", 0) == 0) v.traces.push_back({line, flags, fpshift});

        if (line.rfind("SystemC.", 0) == 0 || line.rfind('-', 0) == 0) v.rows.push_back(line);
    }
    return v;
}

// What a VCD holds per net (GTKWave's name form): its width and the times its value changes.
struct vcd_content {
    std::map<std::string, unsigned> width;
    std::map<std::string, std::vector<int64_t>> changes;
    int64_t end = 0;  // last time stamp
};

inline vcd_content vcd_read(const std::string& vcd_path) {
    vcd_content c;
    std::map<std::string, std::vector<std::string>> by_id;
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
            std::string kind, id, name, range;
            unsigned width = 0;
            vcd >> kind >> width >> id >> name >> range;
            std::string full;
            for (const auto& s : scope) full += s + ".";
            full += name + (range == "$end" ? "" : range);
            c.width[full] = width;
            by_id[id].push_back(full);
        } else if (tok == "$enddefinitions") {
            break;
        }
    }
    int64_t now = 0;
    for (std::string tok; vcd >> tok;) {
        std::string id;
        if (tok[0] == '#') {
            now = std::stoll(tok.substr(1));
            c.end = now;
            continue;
        } else if (tok[0] == 'b' || tok[0] == 'r') {
            vcd >> id;
        } else if (tok[0] == '0' || tok[0] == '1' || tok[0] == 'x' || tok[0] == 'z') {
            id = tok.substr(1);
        } else {
            continue;  // $dumpvars, $end, ...
        }
        for (const auto& name : by_id[id]) c.changes[name].push_back(now);
    }
    return c;
}

// The names a VCD declares (GTKWave's form), from the same reader.
inline std::set<std::string> vcd_declared(const std::string& vcd_path) {
    std::set<std::string> names;
    for (const auto& [name, width] : vcd_read(vcd_path).width) names.insert(name);
    return names;
}

// The number format a view must give each bus it shows: a name (scope path below "SystemC."
// without the [msb:lsb]) and its format from the tables in src/floor/formats.
using view_formats = std::map<std::string, qfmt>;

// Everything that would keep a user from reading a view at first sight, one line each (empty:
// none). `vcd_path` is a VCD of the bench the view is for, long enough to reach the marker.
// - the view names its dump file, relative, beside it ([dumpfile] "<stem>.vcd"), and [savefile]
//   so GTKWave finds the dump beside the save file when opened from another directory;
// - the marker lies inside the opening window, and no net the view shows changes at the marker
//   (on an edge the pane shows the value of one side while the README describes the other);
// - every bus shows a number, no hex/octal/binary/ASCII: decimal, signed exactly when its format
//   is signed, with GTKWave's fixed-point shift equal to its format's fraction bits, and its width
//   in the VCD is the format's; every bus has a format; single bits show as bits;
// - every net of `first_sight` (the outputs and valid strobes, named as in `formats`) lies in the
//   rows visible without scrolling.
inline std::vector<std::string> view_problems(const std::string& gtkw_path, const std::string& vcd_path,
                                              const std::string& dump_stem, const view_formats& formats,
                                              const std::vector<std::string>& first_sight = {}) {
    std::vector<std::string> p;
    const gtkw_view v = gtkw_read(gtkw_path);
    const vcd_content vcd = vcd_read(vcd_path);
    if (v.dumpfile != dump_stem + ".vcd")
        p.push_back("[dumpfile] is \"" + v.dumpfile + "\", not \"" + dump_stem + ".vcd\" (relative, beside the view)");
    if (v.savefile != dump_stem + ".gtkw")
        p.push_back("[savefile] is \"" + v.savefile + "\", not \"" + dump_stem + ".gtkw\"");
    if (v.width <= 0 || v.signals_width <= 0) p.push_back("no [size] or [signals_width]");
    const int64_t t0 = v.timestart, t1 = v.window_end();
    if (!(v.marker > t0 && v.marker < t1))
        p.push_back("marker " + std::to_string(v.marker) + " outside the opening window [" + std::to_string(t0) +
                    ", " + std::to_string(t1) + "]");
    if (vcd.end <= v.marker) p.push_back("the VCD ends before the marker: the edge check cannot run");
    if (v.traces.empty()) p.push_back("the view shows no trace");
    for (const auto& want : first_sight) {
        std::size_t row = 0;
        while (row < v.rows.size() && v.rows[row].substr(0, v.rows[row].find('[')) != "SystemC." + want) ++row;
        if (row == v.rows.size())
            p.push_back(want + " should be visible at first sight but is not in the view");
        else if (static_cast<int>(row) >= v.visible_rows())
            p.push_back(want + " is on row " + std::to_string(row + 1) + ", below the " +
                        std::to_string(v.visible_rows()) + " rows visible without scrolling");
    }
    for (const auto& t : v.traces) {
        const auto w = vcd.width.find(t.name);
        if (w == vcd.width.end()) {
            p.push_back(t.name + " is not in the VCD");
            continue;
        }
        const auto ch = vcd.changes.find(t.name);
        if (ch != vcd.changes.end())
            for (int64_t when : ch->second)
                if (when == v.marker && when > 0) p.push_back(t.name + " changes at the marker");
        using namespace gtkw_flag;
        if (w->second == 1) {
            if (!(t.flags & bin)) p.push_back(t.name + " (a bit) is not shown as a bit");
            continue;
        }
        if (t.flags & (hex | oct | bin | ascii | real) || !(t.flags & dec))
            p.push_back(t.name + " is not shown in decimal");
        const std::string key = t.name.substr(8, t.name.find('[') - 8);  // drop "SystemC." and the range
        const auto f = formats.find(key);
        if (f == formats.end()) {
            p.push_back(key + " has no format to check it against");
            continue;
        }
        if (f->second.width != w->second)
            p.push_back(key + " is " + std::to_string(w->second) + " bits in the VCD, its format " +
                        std::to_string(f->second.width));
        if (bool(t.flags & is_signed) != f->second.is_signed)
            p.push_back(key + (f->second.is_signed ? " is signed but shown unsigned" : " is unsigned but shown signed"));
        const int shift = (t.flags & fpdecshift) ? t.fpshift : 0;
        if (shift != f->second.frac)
            p.push_back(key + " shown with fixed-point shift " + std::to_string(shift) + ", its format has " +
                        std::to_string(f->second.frac) + " fraction bits");
    }
    return p;
}

inline std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += "\n  " + l;
    return s;
}

}  // namespace shading::tb
