#!/usr/bin/env bash
# install_test.sh BUILD_DIR: installs the build into a DESTDIR with prefix /usr, checks the
# layout, and runs the installed program headless on an installed scene.
set -euo pipefail
build=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dest=$work/root
if ! DESTDIR=$dest cmake --install "$build" --prefix /usr >"$work/install.log" 2>&1; then
  cat "$work/install.log"
  exit 1
fi
usr=$dest/usr
fail() { echo "FAIL: $*"; exit 1; }
[ -x "$usr/bin/chaplygin-lab" ] || fail "no bin/chaplygin-lab"
for f in share/applications/io.github.chaplyginlab.ChaplyginLab.desktop \
         share/metainfo/io.github.chaplyginlab.ChaplyginLab.metainfo.xml \
         share/icons/hicolor/scalable/apps/chaplygin-lab.svg \
         share/man/man1/chaplygin-lab.1.gz \
         share/doc/chaplygin-lab/copyright share/doc/chaplygin-lab/changelog.gz \
         share/mime/packages/io.github.chaplyginlab.ChaplyginLab.xml \
         share/doc/chaplygin-lab/README.md share/doc/chaplygin-lab/user-guide.md \
         share/chaplygin-lab/scenes/presets/circle.json share/chaplygin-lab/scenes/gallery/cusp.json; do
  [ -s "$usr/$f" ] || fail "no $f"
done
# the pt_BR catalogue is a Qt .qm file (its magic number), where the program looks for it first
qm=$usr/share/chaplygin-lab/translations/chaplygin-lab_pt_BR.qm
[ -s "$qm" ] || fail "no share/chaplygin-lab/translations/chaplygin-lab_pt_BR.qm"
[ "$(od -An -tx1 -N16 "$qm" | tr -d ' \n')" = 3cb86418caef9c95cd211cbf60a1bddd ] || fail "$qm is not a .qm file"
# each hicolor PNG is a PNG of its size (IHDR width and height, big-endian, at byte 16)
for size in 16 22 24 32 48 64 128 256 512; do
  png=$usr/share/icons/hicolor/${size}x${size}/apps/chaplygin-lab.png
  [ -s "$png" ] || fail "no ${size}x${size} icon"
  read -r w0 w1 w2 w3 h0 h1 h2 h3 < <(od -An -tu1 -j16 -N8 "$png")
  [ $(((w0 << 24) + (w1 << 16) + (w2 << 8) + w3)) -eq "$size" ] &&
    [ $(((h0 << 24) + (h1 << 16) + (h2 << 8) + h3)) -eq "$size" ] || fail "$png is not ${size}x${size}"
done
# the man page: every option of --help, and the installed (absolute) paths
man=$(gzip -dc "$usr/share/man/man1/chaplygin-lab.1.gz")
for option in preset screenshot presentation panel language at size headless version animation link; do
  grep -q -- "\\\\-\\\\-$option" <<<"$man" || fail "the man page lacks --$option"
done
grep -q '^\.I /usr/share/chaplygin\\-lab/scenes' <<<"$man" || fail "the man page's FILES are not /usr/share/..."
grep -q '/usr/share/doc/chaplygin\\-lab' <<<"$man" || fail "the man page does not point to /usr/share/doc"
# the desktop entry opens the scene type that the MIME package defines
mime=$(sed -n 's/^MimeType=\([^;]*\);.*/\1/p' "$usr/share/applications/io.github.chaplyginlab.ChaplyginLab.desktop")
[ -n "$mime" ] || fail "the desktop entry declares no MimeType"
grep -q "<mime-type type=\"$mime\">" "$usr/share/mime/packages/io.github.chaplyginlab.ChaplyginLab.xml" \
  || fail "the MIME package does not define $mime"
# the desktop entry names the installed program and icon; the metainfo launches that entry
desktop=$usr/share/applications/io.github.chaplyginlab.ChaplyginLab.desktop
exe=$(sed -n 's/^Exec=\([^ ]*\).*/\1/p' "$desktop")
[ -x "$usr/bin/$exe" ] || fail "Exec=$exe is not installed in bin/"
icon=$(sed -n 's/^Icon=//p' "$desktop")
[ -s "$usr/share/icons/hicolor/scalable/apps/$icon.svg" ] || fail "Icon=$icon is not installed"
grep -q "<launchable type=\"desktop-id\">$(basename "$desktop")</launchable>" \
  "$usr/share/metainfo/io.github.chaplyginlab.ChaplyginLab.metainfo.xml" || fail "the metainfo does not launch $(basename "$desktop")"

cd "$work"
export QT_QPA_PLATFORM=offscreen
"$usr/bin/chaplygin-lab" --headless --preset circle --csv out.csv
[ "$(head -c 2 out.csv)" = "t," ] || fail "out.csv has no header starting with t: $(head -1 out.csv)"
rows=$(($(wc -l <out.csv) - 1))
[ "$rows" -eq 501 ] || fail "out.csv has $rows rows, expected 501"
# one lap of the circle R = 2 with b = 1, v_T = 1 takes 2 pi sqrt(b^2 + R^2)/v_T (paper (89)-(96))
tail -1 out.csv | awk -F, '{ d = $1 - 2 * 3.14159265358979 * sqrt(5); if (d < -1e-9 || d > 1e-9) { print "FAIL: t_end " $1; exit 1 } }'
# an installed gallery scene: refused, naming the place
set +e
"$usr/bin/chaplygin-lab" --headless --scene "$usr/share/chaplygin-lab/scenes/gallery/corner-constant-speed.json" --csv corner.csv 2>err.txt
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "the constant-speed corner scene exited $rc, expected 2"
grep -q "corner at (" err.txt || fail "the corner refusal does not name the place: $(cat err.txt)"
[ ! -e corner.csv ] || fail "a refused scene wrote corner.csv"
# --help and --version with no display at all
for flag in --help --version; do
  env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$usr/bin/chaplygin-lab" $flag >flag.txt 2>&1 \
    || fail "the installed program's $flag exited $?: $(cat flag.txt)"
done
grep -qx "chaplygin-lab [0-9.]*" flag.txt || fail "--version printed: $(cat flag.txt)"
# the window in Portuguese differs from the English one (the installed catalogue is found)
"$usr/bin/chaplygin-lab" --screenshot en.png --preset circle --size 800x600 --language en
"$usr/bin/chaplygin-lab" --screenshot pt.png --preset circle --size 800x600 --language pt_BR
[ -s en.png ] && [ -s pt.png ] || fail "no screenshots"
! cmp -s en.png pt.png || fail "the pt_BR screenshot is the English one"
# the Python module (CHAPLYGIN_PYTHON): in lib/python3/dist-packages, and it imports and solves
# from there with Debian's python3 (docs/python.md)
if [ "$(sed -n 's/^CHAPLYGIN_PYTHON:BOOL=//p' "$build/CMakeCache.txt")" = ON ]; then
  site=$usr/lib/python3/dist-packages
  ls "$site"/chaplygin_lab.cpython-*.so >/dev/null 2>&1 || fail "no lib/python3/dist-packages/chaplygin_lab"
  x=$(cd "$work" && PYTHONPATH=$site /usr/bin/python3 -c \
    "import chaplygin_lab as cl; s = cl.Scene.preset('catenary').solve(); print(s.sample([0, 1, 2])['x'])" 2>&1) \
    || fail "the installed Python module: $x"
  echo "installed module: x = $x"
fi
echo "installed layout and headless run OK"
