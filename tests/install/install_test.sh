#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, as a user or a package would: the program and
# every file that makes it desktop software, each checked by the tool that reads it.
#   tests/install/install_test.sh BUILD_DIR
set -euo pipefail
build="$1"
root="$(mktemp -d)"
trap 'rm -rf "$root"' EXIT
prefix="$root/usr"
cmake --install "$build" --prefix "$prefix" >/dev/null
fail() { echo "FAIL: $*" >&2; exit 1; }
for f in bin/sprout share/applications/sprout.desktop share/mime/packages/sprout.xml \
         share/icons/hicolor/scalable/apps/sprout.svg share/icons/hicolor/48x48/apps/sprout.png \
         share/icons/hicolor/256x256/apps/sprout.png share/man/man1/sprout.1.gz \
         share/bash-completion/completions/sprout share/doc/sprout/copyright; do
  [ -s "$prefix/$f" ] || fail "$f is not installed"
done

# The desktop entry: valid, opens a file with the viewer, names every type the MIME file defines.
desktop="$prefix/share/applications/sprout.desktop"
if command -v desktop-file-validate >/dev/null; then
  out="$(desktop-file-validate "$desktop" 2>&1)" || fail "desktop-file-validate: $out"
  [ -z "$out" ] || fail "desktop-file-validate: $out"
fi
grep -qx 'Exec=sprout %f' "$desktop" || fail "the desktop entry does not open a file with sprout"
types="$(grep -o 'mime-type type="[^"]*"' "$prefix/share/mime/packages/sprout.xml" | cut -d'"' -f2 | sort)"
listed="$(grep '^MimeType=' "$desktop" | cut -d= -f2 | tr ';' '\n' | grep -v '^$' | sort)"
[ "$types" = "$listed" ] || fail "the desktop entry's MimeType ($listed) is not the MIME file's types ($types)"
[ "$(echo "$types" | wc -l)" -ge 7 ] || fail "expected 7 MIME types"

# The MIME database built from it: the globs and cpfg's magic.
if command -v update-mime-database >/dev/null; then
  cp /usr/share/mime/packages/freedesktop.org.xml "$prefix/share/mime/packages/" 2>/dev/null || true
  update-mime-database "$prefix/share/mime" >/dev/null 2>&1 || fail "update-mime-database refused sprout.xml"
  for g in 'text/x-lsystem:\*\.lsys' 'text/x-lpy:\*\.lpy' 'text/x-cpfg-lsystem:\*\.l' 'text/x-fractint-lsystem:\*\.l' \
           'text/x-lparser:\*\.ls' 'text/x-ifs:\*\.ifs' 'text/x-sprout-forest:\*\.forest'; do
    grep -q "$g" "$prefix/share/mime/globs2" || fail "no glob $g in the MIME database"
  done
  grep -aq 'Lsystem:' "$prefix/share/mime/magic" || fail "cpfg's magic is not in the MIME database"
fi

# The icon is Sprout's own drawing: a picture with transparent corners and a plant in it.
python3 - "$prefix/share/icons/hicolor/48x48/apps/sprout.png" <<'PY' || fail "the 48x48 icon"
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n'
w, h = struct.unpack('>II', data[16:24])
assert (w, h) == (48, 48), (w, h)
idat, pos = b'', 8
while pos < len(data):
    n, = struct.unpack('>I', data[pos:pos + 4]); kind = data[pos + 4:pos + 8]
    if kind == b'IDAT': idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
raw, stride, rows, prev = zlib.decompress(idat), w * 4, [], bytearray(w * 4)
for y in range(h):  # PNG's row filters undone (RGBA, 8 bits)
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a, b, c = line[i - 4] if i >= 4 else 0, prev[i], prev[i - 4] if i >= 4 else 0
        p = a + b - c
        pr = a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c
        line[i] = (line[i] + [0, a, b, (a + b) // 2, pr][f]) & 255
    rows.append(line); prev = line
alpha = [rows[y][x * 4 + 3] for y in range(h) for x in range(w)]
opaque = sum(1 for a in alpha if a > 128)
assert alpha[0] == 0 and alpha[-1] == 0 and alpha[w - 1] == 0, "the corners are transparent"
assert 100 < opaque < w * h * 0.8, opaque
PY

# The manual page renders without warnings.
if command -v man >/dev/null; then
  warnings="$(man --warnings -l "$prefix/share/man/man1/sprout.1.gz" 2>&1 >/dev/null)"
  [ -z "$warnings" ] || fail "man: $warnings"
fi

# Bash completion: subcommands, options and preset names.
complete_line() {
  PATH="$prefix/bin:$PATH" bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _sprout; echo "${COMPREPLY[*]}"' _ \
    "$prefix/share/bash-completion/completions/sprout" "$@"
}
[ "$(complete_line sprout ren)" = "render" ] || fail "completion of a subcommand: '$(complete_line sprout ren)'"
[[ " $(complete_line sprout render x.lsys --no-) " == *" --no-ground "* ]] || fail "completion of render's options"
[[ " $(complete_line sprout expand fractal_pl) " == *" fractal_plant "* ]] || fail "completion of a preset name"

# The installed program runs from its prefix.
"$prefix/bin/sprout" --version | grep -q '^sprout ' || fail "--version"
"$prefix/bin/sprout" render koch -o "$root/koch.png" --size 160x120 >/dev/null 2>&1 || fail "render"
[ -s "$root/koch.png" ] || fail "no picture rendered"
# The C++ library: a ten-line project of someone else's builds against the installed tree
# (find_package(Sprout), Sprout::core) and derives a plant.
here="$(cd "$(dirname "$0")" && pwd)"
cmake -S "$here/consumer" -B "$root/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >"$root/consumer.log" 2>&1 \
  || { cat "$root/consumer.log"; fail "find_package(Sprout)"; }
cmake --build "$root/consumer" >>"$root/consumer.log" 2>&1 || { cat "$root/consumer.log"; fail "the consumer project does not build"; }
got="$("$root/consumer/consumer")"
want="$(printf 'F[+F]F[-F]F[+F[+F]F[-F]F]F[+F]F[-F]F[-F[+F]F[-F]F]F[+F]F[-F]F\n25 segments')"
[ "$got" = "$want" ] || fail "the consumer derived '$got'"
[ -s "$prefix/lib/cmake/Sprout/SproutConfig.cmake" ] || fail "no CMake package"
# The Python module, installed into the prefix's Python path.
pydir="$(ls -d "$prefix"/lib/python3*/dist-packages 2>/dev/null | head -1)"
if [ -n "$pydir" ]; then
  got="$(cd "$root" && PYTHONPATH="$pydir" /usr/bin/python3 -c 'import sprout; print(sprout.__file__.startswith("'"$pydir"'"), str(sprout.open("koch").derive(1)))')"
  [ "$got" = "True -(90)F-F++F-F++F-F++F-F++F-F++F-F" ] || fail "the installed Python module: '$got'"
fi
echo "install: ok ($prefix)"
