#!/usr/bin/env bash
# mime_test.sh MIME_XML DESKTOP_FILE SCENE: the scene file type in a scratch XDG data folder.
# update-mime-database accepts the package; GLib's content sniffing (gio) names the type for a
# scene saved as *.chaplygin.json and for one saved as plain *.json (by its "format" member), and
# not for other JSON; the desktop entry declares that type.
set -euo pipefail
xml=$1 desktop=$2 scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
type=$(sed -n 's/.*<mime-type type="\([^"]*\)".*/\1/p' "$xml")
[ -n "$type" ] || fail "no mime-type in $xml"
grep -q "^MimeType=.*$type;" "$desktop" || fail "the desktop entry does not declare $type"
mkdir -p "$work/mime/packages"
cp /usr/share/mime/packages/freedesktop.org.xml "$xml" "$work/mime/packages/"
XDG_DATA_HOME=$work XDG_DATA_DIRS=$work update-mime-database "$work/mime" 2>"$work/update.log" || { cat "$work/update.log"; fail "update-mime-database"; }
[ ! -s "$work/update.log" ] || { cat "$work/update.log"; fail "update-mime-database warned"; }
cp "$scene" "$work/lesson.chaplygin.json"
cp "$scene" "$work/lesson.json"
echo '{"format": "something else", "version": 1}' >"$work/other.json"
content_type() {
  XDG_DATA_HOME=$work XDG_DATA_DIRS=$work gio info -a standard::content-type "$1" |
    sed -n 's/.*standard::content-type: //p'
}
for f in lesson.chaplygin.json lesson.json; do
  got=$(content_type "$work/$f")
  [ "$got" = "$type" ] || fail "$f is '$got', expected $type"
done
got=$(content_type "$work/other.json")
[ "$got" = application/json ] || fail "other JSON is '$got', expected application/json"
echo "scene type $type OK"
