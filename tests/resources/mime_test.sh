#!/usr/bin/env bash
# mime_test.sh MIME_XML DESKTOP_FILE SCENE: the scene file type in a scratch XDG data folder.
# update-mime-database accepts the package; GLib's content sniffing (gio) names the type for a
# scene saved as *.chaplygin.json and for one saved as plain *.json (by its "format" member), and
# not for other JSON; the desktop entry declares that type, and opens chaplygin-lab: links.
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
# scene links: the entry handles the chaplygin-lab: scheme and takes a URL (%u); a link opened
# through GLib (as a browser or a chat does) reaches the program whole, and so does a file
grep -q '^MimeType=.*x-scheme-handler/chaplygin-lab;' "$desktop" \
  || fail "the desktop entry does not handle x-scheme-handler/chaplygin-lab"
grep -q '^Exec=chaplygin-lab %u$' "$desktop" || fail "the desktop entry's Exec does not take %u"
mkdir -p "$work/applications"
printf '#!/bin/sh\nprintf "%%s\\n" "$@" >"%s/received"\n' "$work" >"$work/record"
chmod +x "$work/record"
sed "s|^Exec=chaplygin-lab|Exec=$work/record|" "$desktop" >"$work/applications/$(basename "$desktop")"
update-desktop-database "$work/applications"
link='chaplygin-lab:eNpljsEOgjAQRO98RdOjAikHE-OvGA8LrKWxLU1LjITw725bwIO3fbOzO7MUjPHn6A1M_MZ4N4DTs1S20tBWoU'
for target in "$link" "$work/lesson.chaplygin.json"; do
  rm -f "$work/received"
  XDG_DATA_HOME=$work XDG_DATA_DIRS=$work XDG_CONFIG_HOME=$work/config timeout 20 gio open "$target" \
    || fail "gio open $target"
  for _ in $(seq 50); do [ -s "$work/received" ] && break; sleep 0.1; done
  [ "$(cat "$work/received" 2>/dev/null)" = "$target" ] \
    || fail "opening $target ran the entry with '$(cat "$work/received" 2>/dev/null)'"
done
echo "scene links open through the desktop entry"
