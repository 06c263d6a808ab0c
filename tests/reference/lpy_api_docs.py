"""The docs page "L-Py's API in Sprout" (docs/formats/lpy-api.md), made from the two dir()s:
the reference L-Py's, kept in tests/data/lpy-api-reference.json, and Sprout's. lpy_api.py docs
writes it (--write) or checks that the page is what they give (--check), so it cannot drift."""


def _mark(present, ui, name):
    if name in ui:
        return "UI only: " + ui[name]
    return "yes" if present else "**missing**"


def page(ref_inv, mine_inv, ui):
    mine_names = set(mine_inv["names"])
    members_of = mine_inv.get("members_of", {})
    ref_classes = ref_inv["classes"]
    names = ref_inv["names"]
    have = sum(1 for n in names if n in mine_names)
    total_m = sum(len(ms) for ms in ref_classes.values())
    have_m = sum(1 for c, ms in ref_classes.items() for m in ms if m in set(members_of.get(c, [])))
    out = [
        "# L-Py's API in Sprout",
        "",
        "Every public name of the real L-Py's `openalea.lpy` (3.15.4, its `dir()`) and every public",
        "member of its public classes, beside Sprout's. The page is generated from the two `dir()`s by",
        "`tests/reference/lpy_api.py docs` and checked by the test `Docs.LpyApiPageIsWhatTheTwoDirsGive`,",
        "so it says what the build has. Behaviour is checked against the real L-Py by the differential",
        "cases of `tests/reference/lpy_api_cases/` (`python3 tests/reference/lpy_api.py compare",
        "REF_PYTHON --build build`, ctest label `reference`).",
        "",
        "| | in L-Py | in Sprout |",
        "|---|---|---|",
        "| public names | %d | %d (%.0f%%) |" % (len(names), have, 100.0 * have / max(1, len(names))),
        "| members of public classes | %d | %d (%.0f%%) |" % (total_m, have_m, 100.0 * have_m / max(1, total_m)),
        "",
        "## Names of `openalea.lpy`",
        "",
        "| name | in Sprout |",
        "|---|---|",
    ]
    for n in names:
        out.append("| `%s` | %s |" % (n, _mark(n in mine_names, ui, n)))
    for cls in sorted(ref_classes):
        ms = ref_classes[cls]
        if not ms:
            continue
        mine = set(members_of.get(cls, []))
        out += ["", "## `%s`" % cls, "", "| member | in Sprout |", "|---|---|"]
        for m in ms:
            out.append("| `%s` | %s |" % (m, _mark(m in mine, ui, cls + "." + m)))
    extra = sorted(n for n in mine_names if n not in set(names))
    if extra:
        out += ["", "## Sprout's own", "", "Names Sprout's `openalea.lpy` has that L-Py's does not: "
                + ", ".join("`%s`" % n for n in extra) + "."]
    return "\n".join(out) + "\n"
