#!/usr/bin/env python3
"""The documentation, tested like code: what README.md and docs/**/*.md show must work.

  check_docs.py examples SPROUT ROOT   every grammar block marked `<!-- example -->` derives (an
                                       IFS or a forest, which is no one string, renders)
  check_docs.py commands SPROUT ROOT   every `sprout ...` line of a block marked `<!-- runnable -->`
                                       exits 0 (in a fresh folder), and a marked ```python block
                                       runs whole against build/python; `<!-- runnable output -->`
                                       also compares what each command prints with the lines
                                       written under it
  check_docs.py options SPROUT ROOT    every option the program's usage lines name is on the
                                       command-line page (which is also the manual page)

The marker sits on the line just before a fenced block; the fence's info string names the kind
of grammar (docs/contributing.md says how to write one).
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

EXTENSIONS = {"lsys": ".lsys", "cpfg": ".l", "lpy": ".lpy", "lparser": ".ls", "explorer": ".ls", "ifs": ".ifs", "forest": ".forest",
              "fractint": ".l"}
TIMEOUT = 120


def pages(root):
    yield root / "README.md"
    yield from sorted((root / "docs").rglob("*.md"))


def marked_blocks(path, marker):
    """(line of the fence, info string, block lines, the marker's words) for each marked block."""
    lines = path.read_text(encoding="utf-8").splitlines()
    for i, line in enumerate(lines):
        m = re.fullmatch(r"\s*<!--\s*(%s)\b([^>]*)-->\s*" % marker, line)
        if not m:
            continue
        fence = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if not fence.startswith("```"):
            raise SystemExit("%s:%d: '%s' is not followed by a fenced block" % (path, i + 1, marker))
        body = []
        j = i + 2
        while j < len(lines) and not lines[j].strip().startswith("```"):
            body.append(lines[j])
            j += 1
        yield i + 2, fence[3:].strip().split(" ")[0], body, m.group(2).split()


def run(cmd, cwd, env, stdin_text=None, shell=False):
    return subprocess.run(cmd, cwd=cwd, env=env, shell=shell, capture_output=True, text=True,
                          timeout=TIMEOUT, input=stdin_text, executable="/bin/bash" if shell else None)


def check_examples(sprout, root):
    failures, count = [], 0
    for page in pages(root):
        for line, kind, body, _ in marked_blocks(page, "example"):
            where = "%s:%d" % (page.relative_to(root), line)
            if kind not in EXTENSIONS:
                failures.append("%s: example of unknown kind '%s' (one of %s)" % (where, kind, ", ".join(EXTENSIONS)))
                continue
            count += 1
            with tempfile.TemporaryDirectory() as tmp:
                grammar = pathlib.Path(tmp) / ("example" + EXTENSIONS[kind])
                grammar.write_text("\n".join(body) + "\n", encoding="utf-8")
                # A scene (an IFS, a forest) is no one string: it is drawn instead, small.
                cmd = [sprout, "expand", str(grammar)]
                if kind in ("ifs", "forest"):
                    cmd = [sprout, "render", str(grammar), "-o", "example.png", "--size", "64x48"]
                r = run(cmd, tmp, dict(os.environ))
                if r.returncode != 0:
                    failures.append("%s: the %s example does not derive (exit %d):\n%s" % (where, kind, r.returncode, r.stderr.strip()))
    return count, failures


def commands_of(body):
    """(command, the output lines written under it) for each command of a block."""
    prompted = any(l.startswith("$ ") for l in body)
    out = []
    for l in body:
        if prompted and l.startswith("$ "):
            out.append((l[2:], []))
        elif not prompted and l.startswith("sprout "):
            out.append((l, []))
        elif prompted and out:
            out[-1][1].append(l)
    return [(c, o) for c, o in out if re.search(r"(^|\|\s*)sprout\b", c)]


def check_commands(sprout, root):
    failures, count = [], 0
    with tempfile.TemporaryDirectory() as bindir:
        # `sprout` on PATH is the program under test, so lines run as a reader would type them.
        os.symlink(sprout, os.path.join(bindir, "sprout"))
        env = dict(os.environ, PATH=bindir + os.pathsep + os.environ.get("PATH", ""))
        for page in pages(root):
            for line, kind, body, words in marked_blocks(page, "runnable"):
                where = "%s:%d" % (page.relative_to(root), line)
                if kind == "python":
                    count += 1
                    failures += check_python(sprout, where, body)
                    continue
                with tempfile.TemporaryDirectory() as tmp:
                    for cmd, expected in commands_of(body):
                        count += 1
                        r = run("set -o pipefail; " + cmd, tmp, env, shell=True)
                        if r.returncode != 0:
                            failures.append("%s: `%s` exits %d:\n%s" % (where, cmd, r.returncode, r.stderr.strip()))
                        elif "output" in words and r.stdout.splitlines() != expected:
                            failures.append("%s: `%s` prints\n%s\nbut the page says\n%s" % (where, cmd, r.stdout.rstrip(), "\n".join(expected)))
    return count, failures


def check_python(sprout, where, body):
    """A Python block runs whole against the module built beside the program (build/python)."""
    module = os.path.join(os.path.dirname(sprout), "python")
    if not os.path.isdir(os.path.join(module, "sprout")):
        return ["%s: a Python example, but no `sprout` module was built in %s" % (where, module)]
    with tempfile.TemporaryDirectory() as tmp:
        script = os.path.join(tmp, "example.py")
        with open(script, "w", encoding="utf-8") as f:
            f.write("\n".join(body) + "\n")
        env = dict(os.environ, PYTHONPATH=module)
        r = run(["/usr/bin/python3", script], tmp, env)
        if r.returncode != 0:
            return ["%s: the Python example exits %d:\n%s" % (where, r.returncode, r.stderr.strip())]
    return []


def check_options(sprout, root):
    page = (root / "docs" / "command-line.md").read_text(encoding="utf-8")
    usage = ""
    for args in ([], ["expand"], ["render"], ["export"]):
        r = run([sprout] + (args or ["--help"]), root, dict(os.environ))
        usage += r.stdout + r.stderr
    options = sorted(set(re.findall(r"(?<![\w-])--[a-z][a-z-]+", usage)))
    if len(options) < 20:
        return len(options), ["read only %d options from the usage lines:\n%s" % (len(options), usage)]
    missing = [o for o in options if "`%s" % o not in page]
    return len(options), ["docs/command-line.md does not describe %s" % o for o in missing]


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("examples", "commands", "options"):
        sys.exit(__doc__)
    mode, sprout, root = sys.argv[1], os.path.abspath(sys.argv[2]), pathlib.Path(sys.argv[3]).resolve()
    count, failures = {"examples": check_examples, "commands": check_commands, "options": check_options}[mode](sprout, root)
    for f in failures:
        print(f, file=sys.stderr)
    print("%s: %d checked, %d failed" % (mode, count, len(failures)))
    if count == 0:
        print("nothing was checked: the pages hold no marked block", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
