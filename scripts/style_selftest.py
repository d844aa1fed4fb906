#!/usr/bin/env python3
"""The style checks (function_lengths.py, include_cycles.py) run on small trees written here, whose
answers are known by construction: each check must fail on the tree that breaks its rule, naming
the right file, line and function or includes, and pass on the same tree without the fault. So a
check can fail, and fails for the right reason.

Usage: scripts/style_selftest.py function_lengths|include_cycles WORK_DIR
Exit 0 when every case behaves, 1 otherwise (each wrong case printed). Standard library only.
"""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def run(script, *args):
    p = subprocess.run([sys.executable, os.path.join(HERE, script)] + list(args), capture_output=True, text=True)
    return p.returncode, p.stdout


def body(lines, first="int x = 0;"):
    """`lines` lines of a body (the braces not counted): plain statements after `first`."""
    return "\n".join([first] + ["x += %d;" % k for k in range(1, lines)]) + "\n"


def function_file(n_long):
    """A source whose functions have known lengths; the last one is n_long lines long. Braces hide
    in comments, strings, a raw string and character literals, a lambda and a local class sit inside
    a body, a member function in a class, a digit separator, and a macro invocation without ';'."""
    parts = []
    parts.append("#include <string>\n#define OPEN {\n")  # line 1, 2: a brace in a directive
    parts.append("namespace a { namespace {\n")  # line 3
    # line 4: a 3-line function with braces in a string, a comment, a character literal
    parts.append('int f() {  // }}}\n    return std::string("}}{").size() + \'}\' + 1\'000;\n}\n')
    # line 7: a class whose member function is 4 lines; the class itself is not a function
    parts.append("struct s {\n    int m{3};\n    int g() const {\n        auto l = [] { return 1; };\n"
                 "        return l();\n    }\n};\n")
    # line 14: a macro invocation without ';' before a 2-line function
    parts.append("MAKE_THING(s)\nint h() {\n    return 2; }\n")
    # line 17: a raw string holding braces and a fake end, inside a 4-line function
    parts.append('const char* r() {\n    return R"x(})" }\n{)x";\n}\n')
    # line 21: the long function, its first line the template line; a local class and a lambda inside
    parts.append("template <class T>\nT long_one(T t) {\n    struct local { int v; };\n"
                 "    auto twice = [&](int v) {\n        return 2 * v;\n    };\n")
    parts.append(body(n_long - 8, "int x = twice(local{1}.v);"))
    parts.append("    return t;\n}\n")
    parts.append("}  // namespace\n}  // namespace a\n")
    return "".join(parts)


def check_function_lengths(work):
    problems = []
    root = os.path.join(work, "lengths")
    shutil.rmtree(root, ignore_errors=True)
    # src/ at limit 10: long_one at 11 lines is over; studies/ at limit 20: the same 11 lines pass;
    # a TEST body and an operator in src/ over the limit too.
    write(root, "src/x/one.cpp", function_file(11))
    write(root, "studies/one.cpp", function_file(11))
    write(root, "src/x/t.cpp", "TEST(Suite, Name) {\n" + body(10) + "}\n"
          "bool operator==(const a& l, const a& r) {\n" + body(2) + "}\n")
    rc, out = run("function_lengths.py", "--root", root, "--rule", "src=10", "--rule", "studies=20")
    want = ["src/x/one.cpp:21: long_one is 11 lines (limit 10)",
            "src/x/t.cpp:1: TEST(Suite, Name) is 12 lines (limit 10)"]
    if rc != 1 or out.split("\n")[:-1] != want:
        problems.append("function_lengths on long functions: exit %d, printed\n%s\nwanted exit 1 and\n%s"
                        % (rc, out, "\n".join(want)))
    # The scan itself: every function found with its length.
    rc, out = run("function_lengths.py", "--root", root, "--rule", "src/x/one.cpp=100", "--list")
    want = ["src/x/one.cpp:4: f 3", "src/x/one.cpp:9: g 4", "src/x/one.cpp:15: h 2", "src/x/one.cpp:17: r 4",
            "src/x/one.cpp:21: long_one 11"]
    if rc != 0 or out.split("\n")[:-1] != want:
        problems.append("function_lengths --list: exit %d, printed\n%s\nwanted exit 0 and\n%s"
                        % (rc, out, "\n".join(want)))
    # At the limit exactly: passes.
    write(root, "src/x/one.cpp", function_file(10))
    write(root, "src/x/t.cpp", "TEST(Suite, Name) {\n" + body(8) + "}\n")
    rc, out = run("function_lengths.py", "--root", root, "--rule", "src=10", "--rule", "studies=20")
    if rc != 0:
        problems.append("function_lengths at the limit: exit %d, printed\n%s" % (rc, out))
    # Unbalanced braces: cannot scan, exit 2.
    write(root, "src/x/bad.cpp", "namespace a {\nint f() {\n")
    rc, out = run("function_lengths.py", "--root", root, "--rule", "src=10")
    if rc != 2:
        problems.append("function_lengths on unbalanced braces: exit %d, wanted 2" % rc)
    return problems


def cycle_tree(root):
    """An acyclic tree whose includes use every way a name is resolved: beside the file, then the
    roots src/floor, src, modules and the project root; one include only in a comment."""
    shutil.rmtree(root, ignore_errors=True)
    write(root, "src/floor/formats/f.h", "#pragma once\n#include <cstdint>\n")
    write(root, "src/floor/arith/a.h", '#pragma once\n#include "formats/f.h"\n')
    write(root, "src/golden/g.h", '#pragma once\n#include "arith/a.h"\n// #include "m/unit.h"\n')
    write(root, "modules/m/beside.h", '#pragma once\n#include "formats/f.h"\n')
    write(root, "modules/m/unit.h", '#pragma once\n#include "beside.h"\n#include "arith/a.h"\n')
    write(root, "testbenches/t/tb.cpp", '#include "m/unit.h"\n#include "golden/g.h"\n#include "gen.h"\n')
    write(root, "studies/s/s.cpp", '#include "testbenches/t/helper.h"\n')
    write(root, "testbenches/t/helper.h", '#pragma once\n#include "m/unit.h"\n')


def check_include_cycles(work):
    problems = []
    root = os.path.join(work, "cycles")

    def case(name, rel, line, expect_rc, words, absent=()):
        cycle_tree(root)
        write(root, "src/golden/g2.h", "#pragma once\n")
        if rel:
            with open(os.path.join(root, rel), "a", encoding="utf-8") as f:
                f.write(line + "\n")
        rc, out = run("include_cycles.py", "--root", root)
        missing = [w for w in words if w not in out] + ["no " + w for w in absent if w in out]
        if rc != expect_rc or missing:
            problems.append("include_cycles, %s: exit %d (wanted %d), printed\n%s\nmissing: %s"
                            % (name, rc, expect_rc, out, missing))

    case("acyclic tree", None, None, 0, [])
    # Two files through the roots: the floor's header names a module's, which names it back.
    case("file cycle", "src/floor/formats/f.h", '#include "m/beside.h"', 1,
         ["file cycle: modules/m/beside.h -> src/floor/formats/f.h -> modules/m/beside.h"])
    # No file cycle, but the floor's arith includes a golden header (g2.h, which includes nothing),
    # while golden/g.h includes arith: src/floor and src/golden depend on each other.
    case("folder cycle", "src/floor/arith/a.h", '#include "golden/g2.h"', 1,
         ["folder cycle: src/floor -> src/golden -> src/floor",
          "src/floor/arith/a.h:3 includes src/golden/g2.h", "src/golden/g.h:2 includes src/floor/arith/a.h"],
         absent=["file cycle"])
    # A top folder cycle: a module including a testbench header, which includes the module.
    case("top folder cycle", "modules/m/beside.h", '#include "testbenches/t/helper.h"', 1,
         ["folder cycle: modules -> testbenches -> modules"])
    return problems


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("function_lengths", "include_cycles"):
        print(__doc__, file=sys.stderr)
        return 2
    work = sys.argv[2]
    os.makedirs(work, exist_ok=True)
    problems = check_function_lengths(work) if sys.argv[1] == "function_lengths" else check_include_cycles(work)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
