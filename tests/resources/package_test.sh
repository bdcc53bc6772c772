#!/usr/bin/env bash
# package_test.sh BUILD_DIR: cpack -G DEB into a temporary directory; the package's Depends names
# the Qt 6, GSL, muparser and GiNaC runtime libraries (dpkg-shlibdeps) and it holds the program,
# the desktop entry, the metainfo, the icons and the man page. Skips without dpkg-shlibdeps.
set -euo pipefail
build=$1
for tool in dpkg-shlibdeps dpkg-deb; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool is not installed (dpkg-dev)"
    exit 77
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
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
    *) echo "FAIL: Depends lacks $lib"; exit 1 ;;
  esac
done
contents=$(dpkg-deb -c "$deb")
for f in ./usr/bin/chaplygin-lab ./usr/share/applications/io.github.chaplyginlab.ChaplyginLab.desktop \
         ./usr/share/metainfo/io.github.chaplyginlab.ChaplyginLab.metainfo.xml \
         ./usr/share/icons/hicolor/48x48/apps/chaplygin-lab.png ./usr/share/man/man1/chaplygin-lab.1; do
  grep -q " $f\$" <<<"$contents" || { echo "FAIL: the package lacks $f"; exit 1; }
done
echo "package OK: $(basename "$deb")"
