#!/usr/bin/env bash
# package_test.sh BUILD_DIR: cpack -G DEB into a temporary directory; the package's Depends names
# the Qt 6, GSL, muparser and GiNaC runtime libraries (dpkg-shlibdeps), it recommends ffmpeg, holds
# the program, the desktop entry, the metainfo, the MIME type, the icons, the compressed man page,
# the copyright and changelog and the pt_BR catalogue; lintian reports no error and no warning; the
# package unpacked into a scratch root runs: --help, --version, headless, a pt_BR screenshot. With
# the Python module (CHAPLYGIN_PYTHON), the package depends on python3 and python3-numpy, holds the
# module in Debian's system Python path and the unpacked module imports and solves.
set -euo pipefail
build=$1
for tool in dpkg-shlibdeps dpkg-deb lintian; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "FAIL: $tool is not installed (dpkg-dev, lintian: scripts/setup installs them)"
    exit 1
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
if ! cpack -G DEB -B "$work" --config "$build/CPackConfig.cmake" >"$work/cpack.log" 2>&1; then
  cat "$work/cpack.log"
  exit 1
fi
deb=$(find "$work" -maxdepth 1 -name 'chaplygin-lab_*.deb')
[ -n "$deb" ] || { echo "FAIL: no .deb"; cat "$work/cpack.log"; exit 1; }
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libqt6core6 libqt6widgets6 libgsl libmuparser libginac; do
  case "$depends" in
    *"$lib"*) ;;
    *) fail "Depends lacks $lib" ;;
  esac
done
python_module=$(sed -n 's/^CHAPLYGIN_PYTHON:BOOL=//p' "$build/CMakeCache.txt")
if [ "$python_module" = ON ]; then
  for dep in "python3 (>= 3." "python3 (<< 3." python3-numpy; do
    case "$depends" in
      *"$dep"*) ;;
      *) fail "Depends lacks $dep" ;;
    esac
  done
fi
[ "$(dpkg-deb -f "$deb" Recommends)" = "ffmpeg, qt6-translations-l10n" ] || fail "Recommends: $(dpkg-deb -f "$deb" Recommends)"
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/chaplygin-lab ./usr/share/applications/io.github.chaplyginlab.ChaplyginLab.desktop \
         ./usr/share/metainfo/io.github.chaplyginlab.ChaplyginLab.metainfo.xml \
         ./usr/share/mime/packages/io.github.chaplyginlab.ChaplyginLab.xml \
         ./usr/share/icons/hicolor/48x48/apps/chaplygin-lab.png ./usr/share/man/man1/chaplygin-lab.1.gz \
         ./usr/share/doc/chaplygin-lab/copyright ./usr/share/doc/chaplygin-lab/changelog.gz \
         ./usr/share/chaplygin-lab/translations/chaplygin-lab_pt_BR.qm; do
  grep -q " $f\$" <<<"$contents" || fail "the package lacks $f"
done
if [ "$python_module" = ON ]; then
  grep -qE " \./usr/lib/python3/dist-packages/chaplygin_lab\.cpython-[0-9]+-[a-z0-9_]+-linux-gnu\.so\$" \
    <<<"$contents" || fail "the package lacks the Python module in /usr/lib/python3/dist-packages"
  grep -q " ./usr/share/doc/chaplygin-lab/python.md\$" <<<"$contents" || fail "the package lacks python.md"
fi
# lintian at its default level: no error, no warning (root may run it with --allow-root). The
# package is made from the Release build, which carries Debian's hardening flags; a sanitizer
# build's package is only reported on, since its instrumentation replaces them
lintian_flags=()
[ "$(id -u)" -ne 0 ] || lintian_flags=(--allow-root)
lintian "${lintian_flags[@]}" "$deb" >"$work/lintian.txt" 2>&1 || true
cat "$work/lintian.txt"
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
if grep -qE '^[EW]: ' "$work/lintian.txt"; then
  if [ "$build_type" = Release ]; then
    fail "lintian reports errors or warnings"
  fi
  echo "lintian's findings above are not checked in a $build_type build"
fi
# the package's own files, unpacked into a scratch root, run
root=$work/root
dpkg-deb -x "$deb" "$root"
exe=$root/usr/bin/chaplygin-lab
cd "$work"
for flag in --help --version; do
  env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$exe" $flag >flag.txt 2>&1 \
    || fail "the packaged program's $flag exited $?: $(cat flag.txt)"
done
QT_QPA_PLATFORM=offscreen "$exe" --headless --preset catenary --samples 11 --csv cat.csv
[ "$(wc -l <cat.csv)" -eq 12 ] || fail "the packaged program's CSV: $(wc -l <cat.csv) lines"
"$exe" --screenshot en.png --preset catenary --size 800x600 --language en
"$exe" --screenshot pt.png --preset catenary --size 800x600 --language pt_BR
! cmp -s en.png pt.png || fail "the packaged program's pt_BR screenshot is the English one"
if [ "$python_module" = ON ]; then
  # the done-when line of the module, from the unpacked package with Debian's python3
  x=$(PYTHONPATH=$root/usr/lib/python3/dist-packages /usr/bin/python3 -c \
    "import chaplygin_lab as cl; s = cl.Scene.preset('catenary').solve(); print(s.sample([0, 1, 2])['x'])" 2>&1) \
    || fail "the packaged Python module: $x"
  python_file=$(PYTHONPATH=$root/usr/lib/python3/dist-packages /usr/bin/python3 -c \
    "import chaplygin_lab; print(chaplygin_lab.__file__)")
  case "$python_file" in
    "$root"/usr/lib/python3/dist-packages/*) ;;
    *) fail "imported $python_file, not the packaged module" ;;
  esac
  echo "packaged module: x = $x"
fi
echo "package OK: $(basename "$deb")"
