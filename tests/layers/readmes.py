#!/usr/bin/env python3
"""Every source file of core/, app/, lpy/ and python/ is named by the README of its folder or of
the nearest folder above it that has one (issue 49: "each folder's README names every file"): its
file name, its path from that folder, or `stem.{hpp,cpp}` appears in the README's text.

Usage: readmes.py SOURCE_DIR (prints each file no README names and exits 1, or exits 0)"""
import pathlib, sys
root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
missing = []
checked = 0
for top in ["core", "app", "lpy", "python"]:
    for p in sorted((root / top).rglob("*")):
        if not p.is_file() or p.suffix not in (".cpp", ".hpp", ".h", ".c", ".py") or "tests" in p.relative_to(root).parts:
            continue
        checked += 1
        d = p.parent
        while not (d / "README.md").exists() and d != root / top:
            d = d.parent
        readme = d / "README.md"
        if not readme.exists():
            missing.append(f"{p.relative_to(root)}: no README in its folder or above it up to {top}/")
            continue
        text = readme.read_text()
        rel = p.relative_to(d).as_posix()
        stem_forms = {p.name, rel, p.stem + ".{hpp,cpp}", p.stem + ".{h,c}"}
        if not any(f in text for f in stem_forms):
            missing.append(f"{p.relative_to(root)}: not named by {readme.relative_to(root)}")
if checked == 0:
    missing.append(f"{root}: no source file under core/, app/, lpy/ or python/ (not Sprout's tree?)")
print("\n".join(missing) if missing else f"each of {checked} files is named by its folder's README")
sys.exit(1 if missing else 0)
