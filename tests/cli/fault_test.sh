#!/usr/bin/env bash
# Fault injection for output files (docs/robustness.md, Writing files): fault_test.sh EXE CASE.
# full_disk_*: a 64 KiB tmpfs in a private mount namespace, filled up; readonly_*: a directory
# the writer may not change, as an unprivileged user (root ignores permissions).
# Exit 77 (skipped) where the machine does not allow the namespace or the user switch.
set -u
source "$(dirname "$0")/cli_case.sh" "$@"
chmod 755 "$work"
# skipped, with the reason in the test's output
skip() { echo "SKIP ($case_name): $*"; exit 77; }

full_disk() {
  # $1: extra CLI arguments that write into $dir
  command -v unshare >/dev/null || skip "no unshare command"
  unshare -m true 2>/dev/null || skip "no private mount namespace here (unshare -m is not permitted)"
  cat > "$work/inner.sh" <<INNER
set -u
dir=$work/disk
mkdir -p "\$dir"
mount -t tmpfs -o size=64k tmpfs "\$dir" 2>/dev/null || exit 77
echo precious > "\$dir/out.csv"
mkdir -p "\$dir/plots"
echo precious > "\$dir/plots/psi.png"
# fill the disk, leaving a few KiB: enough to start writing, not to finish
dd if=/dev/zero of="\$dir/fill" bs=1k count=52 status=none 2>/dev/null
"$exe" --headless --preset sinusoid --samples 20000 $1 >"$work/stdout" 2>"$work/stderr"
echo \$? > "$work/status"
cat "\$dir/out.csv" > "$work/after.csv"
cat "\$dir/plots/psi.png" > "$work/after.png"
ls -a "\$dir" "\$dir/plots" > "$work/listing"
umount "\$dir"
INNER
  unshare -m bash "$work/inner.sh"
  case $? in
  0) ;;
  77) skip "cannot mount a tmpfs in the private namespace" ;;
  *) fail "namespace setup" ;;
  esac
  [ -f "$work/status" ] || skip "the run inside the namespace did not happen"
  [ "$(cat "$work/status")" -eq 2 ] || fail "exit $(cat "$work/status"), expected 2: $(cat "$work/stderr")"
  grep -q "No space left on device" "$work/stderr" || fail "message: $(cat "$work/stderr")"
  [ "$(cat "$work/after.csv")" = precious ] || fail "the old CSV was replaced"
  [ "$(cat "$work/after.png")" = precious ] || fail "the old plot was replaced"
  grep -q "tmp-" "$work/listing" && fail "a temporary file was left behind: $(cat "$work/listing")"
  return 0
}

readonly_dir() {
  # $1: the option that writes into the read-only directory
  command -v runuser >/dev/null || skip "no runuser command"
  id nobody >/dev/null 2>&1 || skip "no user nobody"
  [ "$(id -u)" -eq 0 ] || skip "needs root to switch to nobody (root itself ignores permissions)"
  mkdir "$work/ro"
  echo precious > "$work/ro/out.csv"
  chmod 555 "$work/ro"
  runuser -u nobody -- true 2>/dev/null || skip "cannot switch to the user nobody"
  # a checkout in a private home (/root) is out of nobody's reach
  runuser -u nobody -- "$exe" --headless --help >/dev/null 2>&1 ||
    skip "the user nobody cannot run $exe (is the checkout in a private directory?)"
  runuser -u nobody -- "$exe" --headless --preset line $1 >"$work/stdout" 2>"$work/stderr"
  status=$?
  [ "$status" -eq 2 ] || fail "exit $status, expected 2: $(cat "$work/stderr")"
  grep -q "Permission denied" "$work/stderr" || fail "message: $(cat "$work/stderr")"
  [ "$(cat "$work/ro/out.csv")" = precious ] || fail "the old file was changed"
  [ "$(ls "$work/ro")" = out.csv ] || fail "something was left behind: $(ls "$work/ro")"
}

case "$case_name" in
full_disk_csv) full_disk "--csv \$dir/out.csv" ;;
full_disk_plots) full_disk "--plots \$dir/plots --format png,pdf,svg" ;;
readonly_csv) readonly_dir "--csv $work/ro/out.csv" ;;
readonly_summary) readonly_dir "--summary $work/ro/out.json" ;;
*) fail "unknown case" ;;
esac
echo "ok ($case_name)"
