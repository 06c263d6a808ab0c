#!/usr/bin/python3
"""cpfg reads the files Sprout's editors write (issue 52): every VLab object of the manuals
(../shared/corpus/vlab-manuals) is run by the real cpfg twice, as it is and with each of its
.func, .fset, .con, .cset, .s, .mat and .map files read and written again by Sprout's writers
(funcedit's, the gallery's, cuspy's, bezieredit's, medit's and palette's formats:
sprout._vlab_rewrite); cpfg derives the same string from both, and reads every rewritten file
(it refuses a surface whose links are broken, a function of too few points ...).

    vlab_files_roundtrip.py CPFG_BIN --build BUILD

Not part of the README's test command or CI: ctest runs it under the label `reference` when
SPROUT_CPFG_REFERENCE names the reference cpfg's bin folder.
"""
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import cpfg_compare  # noqa: E402

WRITTEN = (".func", ".fset", ".con", ".cset", ".s", ".mat", ".map")


def main():
    args = sys.argv[1:]
    if not args or not os.path.exists(os.path.join(args[0], "cpfg")):
        print("no reference cpfg (SPROUT_CPFG_REFERENCE): skipped")
        return 77
    bin_dir = args[0]
    build = args[args.index("--build") + 1] if "--build" in args else os.path.join(cpfg_compare.ROOT, "build")
    sys.path.insert(0, os.path.join(os.path.abspath(build), "python"))
    import sprout

    corpus = os.path.join(cpfg_compare.SHARED, "corpus", "vlab-manuals")
    failures, compared, files = [], 0, 0
    for folder in cpfg_compare.objects(corpus):
        name = os.path.relpath(folder, corpus)
        scratch = tempfile.mkdtemp(prefix="sprout-vlab-rt-")
        try:
            copy = os.path.join(scratch, os.path.basename(folder))
            shutil.copytree(folder, copy)
            rewritten = 0
            for f in sorted(os.listdir(copy)):
                path = os.path.join(copy, f)
                if os.path.splitext(f)[1] not in WRITTEN or not os.path.isfile(path):
                    continue
                data = sprout._sprout._vlab_rewrite(path)
                if data is None:
                    failures.append("%s: Sprout cannot read %s" % (name, f))
                    continue
                with open(path, "wb") as out:
                    out.write(data)
                rewritten += 1
            if rewritten == 0:
                continue
            theirs, why, _ = cpfg_compare.run_cpfg(bin_dir, folder)
            if theirs is None:
                print("%-40s cpfg refuses the object as it is (%s)" % (name, why))
                continue
            again, why, _ = cpfg_compare.run_cpfg(bin_dir, copy)
            files += rewritten
            if again is None:
                failures.append("%s: cpfg refuses it with Sprout's files: %s" % (name, why))
                continue
            diff = cpfg_compare.first_difference(again, theirs)
            compared += 1
            if diff is not None:
                failures.append("%s: cpfg derives another string with Sprout's files: %s" % (name, diff))
            else:
                print("%-40s same string with %d files written by Sprout" % (name, rewritten))
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
    for line in failures:
        print("FAIL " + line)
    print("%d objects run by cpfg with %d files written by Sprout: %d give the same string; %d failures"
          % (compared, files, compared - sum(1 for f in failures if "another string" in f), len(failures)))
    return 1 if failures or compared == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
