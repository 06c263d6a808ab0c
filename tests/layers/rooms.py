#!/usr/bin/env python3
"""The house's rooms (issue 49): no C++ or Python source of core/, app/, lpy/, python/ over 600
lines, no function over 150 lines, and a file over 400 lines opens with an index of its sections
(as Dear ImGui's imgui.cpp does: "Index of this file:" then "[SECTION] Title" lines) whose
titles are the [SECTION] markers of its body, in order.

A C++ function is counted from the line of its opening brace to the line of its closing brace
(lambdas and local classes inside it count toward it; namespaces, classes and structs are not
functions, their member functions are); a Python function from its `def` to its last line (ast).

Usage: rooms.py SOURCE_DIR   (prints each room too big and exits 1, or exits 0)
       rooms.py --self-test  (the check finds rooms too big in a scratch tree, and only those)"""
import ast
import pathlib
import re
import sys
import tempfile

MAX_FILE, MAX_FUNCTION, INDEXED_FROM = 600, 150, 400
FOLDERS = ["core", "app", "lpy", "python"]
SUFFIXES = (".cpp", ".hpp", ".h", ".c", ".py")


def blank_strings_and_comments(text):
    """The C++ text with comments, strings and character literals blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i)
            j = end + len(m.group(1)) + 2
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):  # 50'000 is a digit separator
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j += 1
        else:
            out.append(c)
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def cpp_functions(text):
    """(first line, last line) of each function body at namespace or class scope."""
    s = blank_strings_and_comments(text)
    stack, found, line, last = [], [], 1, 0
    for idx, ch in enumerate(s):
        if ch == "\n":
            line += 1
        elif ch == "{":
            head = s[last:idx]
            scope = re.search(r"\b(namespace|class|struct|union|enum)\b[^()]*$", head) or re.search(r"extern\s*$", head)
            if all(kind == "scope" for kind, _ in stack):
                stack.append(("scope" if scope else "function", line))
            else:
                stack.append(("inner", line))
            last = idx + 1
        elif ch == "}":
            if stack:
                kind, start = stack.pop()
                if kind == "function":
                    found.append((start, line))
            last = idx + 1
        elif ch == ";":
            last = idx + 1
    return found


def index_problems(rel, text, comment):
    lines = text.split("\n")
    marker = re.compile(r"^\s*" + re.escape(comment) + r" \[SECTION\] (.+?)\s*$")
    listed = re.compile(r"^\s*" + re.escape(comment) + r"\s+\[SECTION\] (.+?)\s*$")
    try:
        start = next(k for k, l in enumerate(lines[:60]) if "Index of this file:" in l)
    except StopIteration:
        return [f"{rel}: {len(lines) - 1} lines and no index of its sections at its top (\"Index of this file:\")"]
    index = []
    k = start + 1
    while k < len(lines) and listed.match(lines[k]):
        index.append(listed.match(lines[k]).group(1))
        k += 1
    body = [m.group(1) for m in map(marker.match, lines[k:]) if m]
    if not index:
        return [f"{rel}: its index lists no [SECTION]"]
    if index != body:
        return [f"{rel}: its index ({', '.join(index)}) is not its sections ({', '.join(body)})"]
    return []


def rooms(root):
    bad = []
    read = 0
    for folder in FOLDERS:
        for p in sorted((root / folder).rglob("*")):
            if p.suffix not in SUFFIXES or not p.is_file():
                continue
            text = p.read_text(encoding="utf-8")
            read += 1
            n = text.count("\n")
            rel = p.relative_to(root)
            if n > MAX_FILE:
                bad.append(f"{rel}: {n} lines (over {MAX_FILE})")
            if n > INDEXED_FROM:
                bad += index_problems(rel, text, "#" if p.suffix == ".py" else "//")
            if p.suffix == ".py":
                for node in ast.walk(ast.parse(text)):
                    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        length = node.end_lineno - node.lineno + 1
                        if length > MAX_FUNCTION:
                            bad.append(f"{rel}:{node.lineno}: function {node.name} of {length} lines (over {MAX_FUNCTION})")
            else:
                for start, end in cpp_functions(text):
                    if end - start + 1 > MAX_FUNCTION:
                        bad.append(f"{rel}:{start}: a function of {end - start + 1} lines (over {MAX_FUNCTION})")
    if read == 0:
        bad.append(f"{root}: no source file under {', '.join(FOLDERS)} (not Sprout's tree?)")
    return bad


def self_test():
    """A scratch tree with one room too big of each kind, and rooms that are not."""
    def body(n):
        return "".join(f"    x += {k};\n" for k in range(n))
    files = {
        # a function of 151 lines (its braces' lines included): too long
        "core/long.cpp": "namespace a {\nint f(int x) {\n" + body(149) + "}\n}  // namespace a\n",
        # a class of 300 lines whose functions are short, and a lambda inside one: fine
        "core/class.hpp": "struct S {\n" + "".join(f"    int f{k}(int x) {{\n{body(3)}        return x; }}\n" for k in range(40))
                          + "};\nint g() {\n    auto l = [] { return \"}\"; };\n    return l()[0];\n}\n",
        "app/long.py": "def f():\n" + "".join(f"    x = {k}\n" for k in range(150)) + "\n",
        "lpy/big.cpp": "// a file of 601 lines\n" + "int v;\n" * 600,
        "lpy/unindexed.hpp": "// over 400 lines, no index\n" + "int w;\n" * 401,
        "python/mismatch.cpp": "// Index of this file:\n//   [SECTION] One\n//   [SECTION] Two\n" + "int u;\n" * 400
                               + "// [SECTION] One\n// [SECTION] Three\n",
        "python/indexed.py": "# Index of this file:\n#   [SECTION] One\n" + "u = 1\n" * 400 + "# [SECTION] One\n",
    }
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for name, text in files.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)
        found = rooms(root)
    expected = [
        "core/long.cpp:2: a function of 151 lines (over 150)",
        "app/long.py:1: function f of 151 lines (over 150)",
        "lpy/big.cpp: 601 lines (over 600)",
        "lpy/big.cpp: 601 lines and no index of its sections at its top (\"Index of this file:\")",
        "lpy/unindexed.hpp: 402 lines and no index of its sections at its top (\"Index of this file:\")",
        "python/mismatch.cpp: its index (One, Two) is not its sections (One, Three)",
    ]
    if sorted(found) != sorted(expected):
        print("the rooms check found:\n  " + "\n  ".join(found) + "\nnot:\n  " + "\n  ".join(expected))
        return 1
    print(f"the rooms check finds each of {len(expected)} rooms too big, and nothing else")
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    problems = rooms(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "."))
    print("\n".join(problems) if problems else "every room is small enough")
    sys.exit(1 if problems else 0)
