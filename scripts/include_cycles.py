#!/usr/bin/env python3
"""Cycles in the include graph of the sources: between files, and between folders at every level of
the tree, so that each dependency goes one way (a lower folder never includes from a folder that
includes it).

Usage: scripts/include_cycles.py [--root DIR] [--folder-levels]

Reads every .h/.hpp/.cpp file under src/, modules/, testbenches/, fuzz/ and studies/ of DIR (the
project root by default). A quoted include is resolved as the compiler does here: beside the
including file, then in the include roots src/floor, src, modules and the project root; an include
found in none of them (a generated header) and an angle include are not followed. Then:
  - files: a file that reaches itself through its includes is a cycle;
  - folders: at each depth (src, then src/floor, then src/floor/formats, ...) each file belongs to
    the folder of that depth that holds it, and folder A depends on folder B when a file of A
    includes a file of B; a folder that reaches itself that way is a cycle (a folder's files may
    include each other freely).
Each cycle is printed with the includes that close it ("a.h -> b.h -> a.h", then for a folder cycle
one include per step). The check sees includes only: two .cpp files that call each other's
functions through a declaration, without including each other, are not a cycle to it.
--folder-levels prints the folder graph's edges at each depth first.
Exit 0 without a cycle, 1 with one. Standard library only.
"""
import argparse
import os
import re
import sys

TREES = ("src", "modules", "testbenches", "fuzz", "studies")
INCLUDE_ROOTS = ("src/floor", "src", "modules", ".")
EXTENSIONS = (".h", ".hpp", ".cpp")
QUOTED = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def without_comments(text):
    """The text with /* */ and // comments removed, so a commented-out include is not followed."""
    return re.sub(r"/\*.*?\*/|//[^\n]*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)


def source_files(root):
    out = []
    for tree in TREES:
        for d, subdirs, files in os.walk(os.path.join(root, tree)):
            subdirs.sort()
            out += [os.path.relpath(os.path.join(d, f), root) for f in sorted(files) if f.endswith(EXTENSIONS)]
    return out


def resolve(root, rel, name):
    """The file (relative to root) a quoted include of `name` in file `rel` names, or None."""
    for base in (os.path.dirname(rel),) + INCLUDE_ROOTS:
        cand = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(root, cand)):
            return cand
    return None


def include_graph(root):
    """{file: [(included file, line number)]} over the source trees."""
    files = source_files(root)
    graph = {}
    for rel in files:
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = without_comments(f.read())
        edges = []
        for m in QUOTED.finditer(text):
            target = resolve(root, rel, m.group(1))
            if target is not None:
                edges.append((target, text.count("\n", 0, m.start(1)) + 1))
        graph[rel] = edges
    return graph


def strongly_connected(nodes, succ):
    """Tarjan's strongly connected components with more than one node, or with a self-loop."""
    index, low, on_stack, stack, comps = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        # Iterative, so a deep include chain does not reach Python's recursion limit.
        work = [(v, iter(sorted(succ.get(v, ()))))]
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        while work:
            node, it = work[-1]
            advanced = False
            for w in it:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(succ.get(w, ())))))
                    advanced = True
                    break
                if w in on_stack:
                    low[node] = min(low[node], index[w])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    comp.append(w)
                    if w == node:
                        break
                if len(comp) > 1 or node in succ.get(node, ()):
                    comps.append(sorted(comp))

    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return comps


def one_cycle(comp, succ):
    """A shortest cycle through the component's first node, as a list of nodes (first repeated last)."""
    start = comp[0]
    members = set(comp)
    prev = {start: None}
    frontier = [start]
    while frontier:
        nxt = []
        for v in frontier:
            for w in sorted(succ.get(v, ())):
                if w == start:
                    path = [v]
                    while prev[path[-1]] is not None:
                        path.append(prev[path[-1]])
                    return list(reversed(path)) + [start]
                if w in members and w not in prev:
                    prev[w] = v
                    nxt.append(w)
        frontier = nxt
    return comp + [start]


def folder_at(rel, depth):
    """The folder of `depth` components that holds file rel, or None when the file is shallower."""
    parts = rel.split("/")[:-1]
    return "/".join(parts[:depth]) if len(parts) >= depth else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--folder-levels", action="store_true")
    args = ap.parse_args()
    graph = include_graph(args.root)
    problems = []

    succ = {f: {t for t, _ in edges} for f, edges in graph.items()}
    for comp in strongly_connected(graph, succ):
        problems.append("file cycle: " + " -> ".join(one_cycle(comp, succ)))

    max_depth = max((len(f.split("/")) - 1 for f in graph), default=0)
    for depth in range(1, max_depth + 1):
        fsucc, why = {}, {}
        for f, edges in graph.items():
            a = folder_at(f, depth)
            for t, line in edges:
                b = folder_at(t, depth)
                if a is None or b is None or a == b:
                    continue
                fsucc.setdefault(a, set()).add(b)
                why.setdefault((a, b), "%s:%d includes %s" % (f, line, t))
        if args.folder_levels:
            for (a, b), w in sorted(why.items()):
                print("depth %d: %s -> %s (%s)" % (depth, a, b, w))
        for comp in strongly_connected(fsucc, fsucc):
            cyc = one_cycle(comp, fsucc)
            steps = ["    %s" % why[(cyc[k], cyc[k + 1])] for k in range(len(cyc) - 1)]
            problems.append("folder cycle: " + " -> ".join(cyc) + "\n" + "\n".join(steps))

    for p in problems:
        print(p)
    if problems:
        print("%d include cycle(s): move the shared piece down to a folder both can include" % len(problems),
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
