#!/usr/bin/env python3
"""Every C++ function longer than its folder's limit, with file:line, so a function stays short
enough to read at once.

Usage: scripts/function_lengths.py [--root DIR] --rule PATH=LIMIT [--rule PATH=LIMIT ...] [--list]

Each rule gives a limit in lines to every .h/.hpp/.cpp file under PATH (a folder or one file,
relative to DIR, the project root by default); the longest matching PATH wins, and a file that no
rule covers is not read. A function's length counts from the first line of its declaration (its
template<> line included) to its closing brace. Functions are found by matching braces outside
comments, strings, character literals and preprocessor lines, at namespace and class scope: a
member function defined in its class counts on its own, and a lambda or a local class inside a body
counts toward the function around it. A lambda at namespace scope counts as a function. TEST(...)
bodies are functions; SC_MODULE(...) is a class.

--list prints every function found with its length (for checking the scan itself).
Exit 0 if every function is within its limit, 1 if one is over it (each printed as
"file:line: name is N lines (limit L)"), 2 on bad usage or a file whose braces do not match.
Standard library only.
"""
import argparse
import os
import re
import sys

EXTENSIONS = (".h", ".hpp", ".cpp")
IDENT = re.compile(r"[A-Za-z_]\w*")
# Words that may follow a function's parameter list before its body.
QUALIFIERS = {"const", "volatile", "noexcept", "override", "final", "mutable", "constexpr", "try", "&", "&&",
              "throw", "__attribute__"}
MACRO = re.compile(r"[A-Z][A-Z0-9_]*")
ACCESS = re.compile(r"^\s*(public|private|protected)\s*$")
TYPE_HEAD = re.compile(r"^(?:typedef\s+|static\s+|inline\s+|constexpr\s+)*(class|struct|union|enum)\b")


class ScanError(Exception):
    pass


def strip_code(text):
    """The text with comments, string and character literals and preprocessor lines replaced by
    spaces; newlines are kept, so an offset's line is the same as in the original."""
    out = list(text)
    n = len(text)
    i = 0
    line_start = True  # only blanks since the last newline

    def blank(a, b):
        for k in range(a, b):
            if out[k] != "\n":
                out[k] = " "

    while i < n:
        c = text[i]
        if c == "\n":
            line_start = True
            i += 1
            continue
        if line_start and c == "#":
            j = i
            while j < n and text[j] != "\n":
                if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n":
                    j += 2
                    continue
                if text.startswith("/*", j):  # a block comment that starts on the directive's line
                    end = text.find("*/", j + 2)
                    j = n if end < 0 else end + 2
                    continue
                j += 1
            blank(i, j)
            i = j
            continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            blank(i, j)
            i = j
            continue
        if text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            blank(i, j)
            i = j
            continue
        if c == '"':
            # A raw string R"delim( ... )delim", with or without an encoding prefix.
            m = re.search(r"(?:u8|u|U|L)?R$", text[max(0, i - 3):i])
            if m and (i - len(m.group(0)) == 0 or not (text[i - len(m.group(0)) - 1].isalnum()
                                                       or text[i - len(m.group(0)) - 1] == "_")):
                paren = text.find("(", i)
                delim = text[i + 1:paren]
                end = text.find(")" + delim + '"', paren)
                if paren < 0 or end < 0:
                    raise ScanError("unterminated raw string at offset %d" % i)
                j = end + len(delim) + 2
                blank(i, j)
                i = j
                continue
            j = i + 1
            while j < n and text[j] != '"':
                if text[j] == "\\":
                    j += 1
                elif text[j] == "\n":
                    raise ScanError("unterminated string at offset %d" % i)
                j += 1
            blank(i, j + 1)
            i = j + 1
            continue
        if c == "'":
            # A digit separator (1'000'000) when the token before it is a number.
            k = i - 1
            while k >= 0 and (text[k].isalnum() or text[k] in "_.'"):
                k -= 1
            if k + 1 < i and text[k + 1].isdigit():
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != "'":
                if text[j] == "\\":
                    j += 1
                elif text[j] == "\n":
                    raise ScanError("unterminated character literal at offset %d" % i)
                j += 1
            blank(i, j + 1)
            i = j + 1
            continue
        i += 1
    return "".join(out)


def match(code, i, open_c, close_c):
    """The offset of the bracket that closes the one at i (brackets of the one kind only)."""
    depth = 0
    for j in range(i, len(code)):
        if code[j] == open_c:
            depth += 1
        elif code[j] == close_c:
            depth -= 1
            if depth == 0:
                return j
    raise ScanError("the %s at offset %d is never closed" % (open_c, i))


def tokens(head):
    """The head's tokens: identifiers, numbers, punctuation, and ( ), [ ], { } groups as one token
    each (the text of the group)."""
    out = []
    i = 0
    n = len(head)
    while i < n:
        c = head[i]
        if c.isspace():
            i += 1
        elif c in "([{":
            close = {"(": ")", "[": "]", "{": "}"}[c]
            j = match(head, i, c, close)
            out.append(head[i:j + 1])
            i = j + 1
        elif c.isalnum() or c == "_":
            m = re.compile(r"\w+").match(head, i)
            out.append(m.group(0))
            i = m.end()
        elif head.startswith("&&", i) or head.startswith("->", i) or head.startswith("::", i):
            out.append(head[i:i + 2])
            i += 2
        else:
            out.append(c)
            i += 1
    return out


def function_suffix(rest):
    """Whether the tokens after a parameter list are what may stand between it and a body:
    qualifiers, then a trailing return type or a constructor's initialiser list."""
    k = 0
    while k < len(rest):
        t = rest[k]
        if t in QUALIFIERS:
            k += 1
            if k < len(rest) and rest[k].startswith("(") and t in ("noexcept", "throw", "__attribute__"):
                k += 1
        elif t.startswith("[["):  # an attribute, [[...]], one token
            k += 1
        else:
            break
    if k == len(rest):
        return "body"
    if rest[k] == "->" and "=" not in rest[k:] and ";" not in rest[k:]:
        return "body"
    if rest[k] == ":":
        return "init"
    return None


def head_tokens(head):
    """The tokens of a declaration's head without its template<...> prefix, an operator's symbol
    joined to the word operator ("operator==", "operator()")."""
    toks = tokens(head)
    while toks and toks[0] == "template":
        depth = 0
        for k in range(1, len(toks)):
            depth += (toks[k] == "<") - (toks[k] == ">")
            if depth == 0:
                toks = toks[k + 1:]
                break
        else:
            toks = []
    out = []
    k = 0
    while k < len(toks):
        t = toks[k]
        if t == "operator":
            k += 1
            if k < len(toks) and toks[k] in ("()", "[]"):
                t += toks[k]
                k += 1
            while k < len(toks) and not toks[k].startswith("(") and not IDENT.fullmatch(toks[k]):
                t += toks[k]
                k += 1
            while k < len(toks) and IDENT.fullmatch(toks[k]) and t == "operator":  # operator bool
                t += " " + toks[k]
                k += 1
        else:
            k += 1
        out.append(t)
    return out


def classify(head):
    """What a { at namespace or class scope opens, from the text before it: 'scope' (a namespace,
    extern "C", a class), 'function', 'init' (a brace of a constructor's initialiser list, the head
    goes on after it) or 'data' (an initialiser, the head goes on after it)."""
    h_toks = head_tokens(head)
    words = " ".join(h_toks)
    if re.match(r"^(inline\s+)?namespace\b", words) or words in ("extern", ""):
        return "scope"
    if h_toks and h_toks[0] == "SC_MODULE":
        return "scope"
    if TYPE_HEAD.match(words) and not re.match(r"^(class|struct|union|enum)\s+[\w:]+\s+[\w:]+\s*\(", words):
        return "scope"
    # A lambda: [captures] (params) qualifiers, or [captures] alone, after an '='.
    if "=" in h_toks:
        after = h_toks[len(h_toks) - h_toks[::-1].index("="):]
        lam = [k for k, t in enumerate(after) if t.startswith("[") and not t.startswith("[[")]
        if lam:
            rest = after[lam[0] + 1:]
            if rest and rest[0].startswith("("):
                rest = rest[1:]
            if function_suffix(rest) == "body":
                return "function"
        return "data"
    for k, t in enumerate(h_toks):
        if t.startswith("(") and k > 0:
            kind = function_suffix(h_toks[k + 1:])
            if kind == "body":
                return "function"
            if kind == "init":
                last = h_toks[-1]
                if IDENT.fullmatch(last) or last == ">":
                    return "init"
                return "function"
    return "data"


def function_name(head):
    """A readable name: the qualified name before the parameter list, or MACRO(args) for a
    macro-defined function such as TEST(Suite, Name)."""
    toks = head_tokens(re.sub(r"\s+", " ", head.strip()))
    if "=" in toks:  # a lambda: the variable it initialises
        k = toks.index("=")
        return (toks[k - 1] if k > 0 else "") + " (lambda)"
    for k, t in enumerate(toks):
        if not (t.startswith("(") and k > 0):
            continue
        prev = toks[k - 1]
        if prev.startswith("operator"):
            name = [prev]
        elif IDENT.fullmatch(prev):
            if prev.isupper() and len(prev) > 1:  # TEST(Suite, Name), SC_CTOR(name)
                return prev + t
            name = [prev]
        else:
            continue
        j = k - 2
        if j >= 0 and toks[j] == "~":
            name[:0] = ["~"]
            j -= 1
        while j >= 1 and toks[j] == "::" and IDENT.fullmatch(toks[j - 1]):
            name[:0] = [toks[j - 1], "::"]
            j -= 2
        return "".join(name)
    return " ".join(toks)[:60]


def standalone_macro(code, close):
    """Whether the MACRO(...) that closes at `close` stands alone: the next code is on a later line
    and is not the body, an initialiser list or a qualifier of what the macro began."""
    m = re.compile(r"\s*(\S)").match(code, close + 1)
    if not m or "\n" not in code[close + 1:m.start(1)]:
        return False
    if m.group(1) in "{:;=":
        return False
    word = IDENT.match(code, m.start(1))
    return not (word and word.group(0) in QUALIFIERS)


def functions(text):
    """(first line, last line, name) of every function in a C++ source text."""
    code = strip_code(text)
    line_at = []
    line = 1
    for c in code:
        line_at.append(line)
        if c == "\n":
            line += 1
    found = []
    depth = 0  # open namespaces and classes
    head_start = None
    i = 0
    n = len(code)
    while i < n:
        c = code[i]
        if c.isspace():
            i += 1
            continue
        if head_start is None:
            head_start = i
        if c == ";":
            head_start = None
        elif c == ":" and not code.startswith("::", i) and code[i - 1] != ":" \
                and ACCESS.match(code[head_start:i]):
            head_start = None
        elif c == "}":
            depth -= 1
            if depth < 0:
                raise ScanError("a } at line %d closes nothing" % line_at[i])
            head_start = None
        elif c == "(":
            close = match(code, i, "(", ")")
            if MACRO.fullmatch(code[head_start:i].strip()) and standalone_macro(code, close):
                head_start = None  # a macro invocation that is a declaration of its own, no ';'
            i = close
        elif c == "{":
            head = code[head_start:i]
            kind = classify(head)
            if kind == "scope":
                depth += 1
                head_start = None
            elif kind == "function":
                j = match(code, i, "{", "}")
                found.append((line_at[head_start], line_at[j], function_name(head)))
                head_start = None
                i = j
            else:  # init or data: skip the braces, the declaration goes on
                i = match(code, i, "{", "}")
        i += 1
    if depth != 0:
        raise ScanError("%d namespace or class braces are never closed" % depth)
    return found


def limit_for(rel, rules):
    """The limit of the longest rule path that contains rel, or None."""
    best = None
    for path, limit in rules:
        p = path.rstrip("/")
        if p in ("", ".") or rel == p or rel.startswith(p + "/"):
            if best is None or len(p) > len(best[0]):
                best = (p, limit)
    return None if best is None else best[1]


def source_files(root, rules):
    seen = set()
    for path, _ in rules:
        top = os.path.join(root, path)
        if os.path.isfile(top):
            seen.add(os.path.relpath(top, root))
            continue
        for d, subdirs, files in os.walk(top):
            subdirs.sort()
            for f in files:
                if f.endswith(EXTENSIONS):
                    seen.add(os.path.relpath(os.path.join(d, f), root))
    return sorted(seen)


def parse_rule(s):
    m = re.fullmatch(r"(.*)=(\d+)", s)
    if not m:
        raise argparse.ArgumentTypeError("a rule is PATH=LIMIT, not %r" % s)
    return (os.path.normpath(m.group(1)) if m.group(1) else ".", int(m.group(2)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--rule", action="append", type=parse_rule, required=True)
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    over = []
    broken = 0
    for rel in source_files(args.root, args.rule):
        limit = limit_for(rel, args.rule)
        if limit is None:
            continue
        with open(os.path.join(args.root, rel), encoding="utf-8") as f:
            text = f.read()
        try:
            found = functions(text)
        except ScanError as e:
            print("%s: cannot scan: %s" % (rel, e), file=sys.stderr)
            broken += 1
            continue
        for first, last, name in found:
            length = last - first + 1
            if args.list:
                print("%s:%d: %s %d" % (rel, first, name, length))
            if length > limit:
                over.append("%s:%d: %s is %d lines (limit %d)" % (rel, first, name, length, limit))
    for o in over:
        print(o)
    if broken:
        return 2
    if over:
        print("%d function(s) over the limit: split them into named steps" % len(over), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
