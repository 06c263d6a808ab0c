#!/usr/bin/env bash
# The Debian package: `cpack -G DEB` in the build folder, lintian without errors, and the
# package unpacked into a temporary root (dpkg-deb -x) runs: --version, a render, and the
# desktop entry's Exec line on a grammar file.
#   tests/install/deb_test.sh BUILD_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
root="$(mktemp -d)"
trap 'rm -rf "$root"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# Packed from a copy of the build's install, so a test running beside this one never sees a
# half-written package in the build folder.
(cd "$build" && cpack -G DEB -B "$root/pack" >"$root/cpack.log" 2>&1) || { cat "$root/cpack.log"; fail "cpack"; }
deb="$(ls "$root"/pack/sprout_*.deb)"
dpkg-deb -I "$deb" > "$root/info"
grep -q '^ Depends:.*libpng16' "$root/info" || fail "Depends does not come from dpkg-shlibdeps: $(grep Depends "$root/info")"
grep -q '^ Depends:.*libosmesa6' "$root/info" || fail "Depends lacks libosmesa6 (dlopened)"
if command -v lintian >/dev/null; then
  lintian --fail-on error "$deb" > "$root/lintian" 2>&1 || { cat "$root/lintian"; fail "lintian reports errors"; }
fi
dpkg-deb -x "$deb" "$root/x"
bin="$root/x/usr/bin/sprout"
[ -x "$bin" ] || fail "no usr/bin/sprout in the package"
"$bin" --version | grep -q '^sprout ' || fail "--version"
"$bin" render fractal_plant -o "$root/plant.png" --size 200x150 >/dev/null 2>&1 || fail "render"
[ -s "$root/plant.png" ] || fail "no picture"
# The desktop entry's Exec line, as a file manager runs it on a double-clicked .lsys (no display
# here: the viewer says so and leaves a picture of the file's plant).
exec_line="$(grep '^Exec=' "$root/x/usr/share/applications/sprout.desktop" | cut -d= -f2-)"
printf 'n: 3\nangle: 90\naxiom: F-F-F-F\nF -> F-F+F+FF-F-F+F\n' > "$root/island.lsys"
cmd="${exec_line//%f/$root/island.lsys}"
cmd="$root/x/usr/bin/$cmd"  # the program of the Exec line, from the package
(cd "$root" && env -u DISPLAY -u WAYLAND_DISPLAY $cmd >/dev/null 2>"$root/exec.err") || { cat "$root/exec.err"; fail "the Exec line"; }
grep -q 'island.lsys' "$root/exec.err" || fail "the Exec line did not open the file: $(cat "$root/exec.err")"
[ -s "$root/sprout.png" ] || fail "the Exec line left no picture"
echo "deb: ok ($(basename "$deb"), $(stat -c %s "$deb") bytes)"
