#!/usr/bin/env python3
"""Sprout's manual page, made from the documentation's command-line page (docs/command-line.md).

One text for both, so the site and `man sprout` cannot say different things. The page keeps to
what this reads: `# Title`, then a `name - summary` line (the NAME section), `##` sections,
`###` subsections, paragraphs, `- item` lists (an item that starts with a code span and a colon
is an option: `- `--seed S`: what it does`), fenced code blocks and HTML comments (dropped).
Anything else (a table, an admonition) stops the build with the line it is on.

usage: md2man.py PAGE.md VERSION DATE > sprout.1
"""
import re
import sys


def escape(text):
    """roff's special characters in running text."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return text


def inline(text):
    """Markdown's inline marks as roff fonts; links keep their text."""
    out = []
    pos = 0
    pattern = re.compile(r"`([^`]+)`|\*\*([^*]+)\*\*|\*([^*]+)\*|\[([^\]]+)\]\([^)]+\)")
    for m in pattern.finditer(text):
        out.append(escape(text[pos:m.start()]))
        code, bold, italic, link = m.groups()
        if code is not None:
            out.append("\\fB" + escape(code) + "\\fR")
        elif bold is not None:
            out.append("\\fB" + escape(bold) + "\\fR")
        elif italic is not None:
            out.append("\\fI" + escape(italic) + "\\fR")
        else:
            out.append(inline(link))
        pos = m.end()
    out.append(escape(text[pos:]))
    return "".join(out)


def line_start(text):
    """A roff line may not start with a control character."""
    return "\\&" + text if text[:1] in (".", "'") else text


def convert(lines, version, date):
    out = ['.TH SPROUT 1 "%s" "Sprout %s" "User Commands"' % (date, version)]
    i = 0
    name_done = False
    paragraph = []

    def flush():
        if paragraph:
            out.append(".PP")
            out.append(line_start(inline(" ".join(paragraph))))
            paragraph.clear()

    def fail(message):
        sys.exit("%s:%d: %s" % (sys.argv[1], i + 1, message))

    while i < len(lines):
        line = lines[i].rstrip("\n")
        stripped = line.strip()
        if stripped.startswith("<!--"):
            flush()
            while "-->" not in lines[i]:
                i += 1
            i += 1
            continue
        if line.startswith("# "):
            flush()
            i += 1
            continue
        if not name_done and stripped:
            # The NAME line: "sprout - summary".
            name, _, summary = stripped.partition(" - ")
            if not summary:
                fail("expected the NAME line 'sprout - summary' after the title")
            out += [".SH NAME", "%s \\- %s" % (escape(name), escape(summary))]
            name_done = True
            i += 1
            continue
        if line.startswith("## ") or line.startswith("### "):
            flush()
            level, title = line.split(" ", 1)
            out.append((".SH " if level == "##" else ".SS ") + escape(title.upper() if level == "##" else title))
            i += 1
            continue
        if stripped.startswith("```"):
            flush()
            out += [".PP", ".nf", ".RS 2"]
            i += 1
            while i < len(lines) and not lines[i].strip().startswith("```"):
                out.append(line_start(escape(lines[i].rstrip("\n"))))
                i += 1
            out += [".RE", ".fi"]
            i += 1
            continue
        if line.startswith("- "):
            flush()
            item = [line[2:].strip()]
            i += 1
            while i < len(lines) and lines[i].startswith("  ") and lines[i].strip():
                item.append(lines[i].strip())
                i += 1
            text = " ".join(item)
            m = re.match(r"((?:`[^`]+`(?:, )?)+): (.*)", text)
            if m:
                out += [".TP", line_start(inline(m.group(1))), line_start(inline(m.group(2)))]
            else:
                out += [".IP \\(bu 2", line_start(inline(text))]
            continue
        if stripped.startswith("|") or stripped.startswith("!!!") or stripped.startswith("<"):
            fail("the manual page cannot hold this (a table, an admonition or HTML)")
        if not stripped:
            flush()
        else:
            paragraph.append(stripped)
        i += 1
    flush()
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: md2man.py PAGE.md VERSION DATE")
    with open(sys.argv[1], encoding="utf-8") as f:
        lines = f.readlines()
    sys.stdout.write(convert(lines, sys.argv[2], sys.argv[3]))


if __name__ == "__main__":
    main()
