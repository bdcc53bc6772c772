#!/usr/bin/env bash
# package_test.sh BUILD_DIR: cpack -G DEB into a temporary directory; the package's Depends names
# the Qt 6, GSL, muparser and GiNaC runtime libraries (dpkg-shlibdeps), it recommends ffmpeg, holds
# the program, the desktop entry, the metainfo, the MIME type, the icons, the compressed man page,
# the copyright and changelog and the pt_BR catalogue; lintian reports no error and no warning; the
# package unpacked into a scratch root runs: --help, --version, headless, a pt_BR screenshot.
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
[ "$(dpkg-deb -f "$deb" Recommends)" = ffmpeg ] || fail "Recommends: $(dpkg-deb -f "$deb" Recommends)"
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/chaplygin-lab ./usr/share/applications/io.github.chaplyginlab.ChaplyginLab.desktop \
         ./usr/share/metainfo/io.github.chaplyginlab.ChaplyginLab.metainfo.xml \
         ./usr/share/mime/packages/io.github.chaplyginlab.ChaplyginLab.xml \
         ./usr/share/icons/hicolor/48x48/apps/chaplygin-lab.png ./usr/share/man/man1/chaplygin-lab.1.gz \
         ./usr/share/doc/chaplygin-lab/copyright ./usr/share/doc/chaplygin-lab/changelog.gz \
         ./usr/share/chaplygin-lab/translations/chaplygin-lab_pt_BR.qm; do
  grep -q " $f\$" <<<"$contents" || fail "the package lacks $f"
done
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
echo "package OK: $(basename "$deb")"
