#!/usr/bin/env bash
# The real window under Xvfb (docs/robustness.md, The real window):
#   real_window_test.sh APP TESTS CASE
# qtest: the QtTest checks that need a real X server (TESTS, with QT_QPA_PLATFORM=xcb);
# session: APP started as a new user would (no settings) and driven with xdotool: the Animation
# menu, Space, a step, F11 and Esc, F1, a resize; checked on screenshots of the screen.
# bad_file_dialog: APP FILE with a bad scene and no terminal shows the message in a dialog.
# zoom_extremes: APP on the longest gallery scene, playing, zoomed with the wheel to the closest
# and the farthest view the program allows and back: every burst of wheel steps is painted within
# seconds (no stall), the program lives on and its peak resident memory stays under 1 GB.
# Exit 77 (skipped, with the reason) where Xvfb, xdotool, xwininfo or ImageMagick are missing.
set -u
app=$1
tests=$2
case_name=$3
skip() { echo "SKIP ($case_name): $*"; exit 77; }
fail() { echo "FAIL ($case_name): $*" >&2; exit 1; }
for tool in Xvfb xdotool xwininfo import compare; do
  command -v "$tool" >/dev/null || skip "no $tool (apt-get install xvfb xdotool x11-utils imagemagick)"
done
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  wait 2>/dev/null
  if [ -n "${KEEP_SHOTS:-}" ]; then cp "$work"/*.png "$KEEP_SHOTS"/ 2>/dev/null; fi
  rm -rf "$work"
}
trap cleanup EXIT

# a display of its own: Xvfb picks a free number and writes it once it accepts clients
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || skip "Xvfb did not start: $(head -c 300 "$work/xvfb.log")"
export DISPLAY=":$(head -1 "$work/display")"
export QT_QPA_PLATFORM=xcb
# a new user: no settings
export HOME=$work/home XDG_CONFIG_HOME=$work/home/.config XDG_RUNTIME_DIR=$work/run
mkdir -p "$HOME" "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
# the first start's "What am I looking at?" window is dismissed, so that it takes no keys or clicks
mkdir -p "$XDG_CONFIG_HOME/ChaplyginLab"
printf '[help]\nintroductionDismissed=true\n' >"$XDG_CONFIG_HOME/ChaplyginLab/Chaplygin Lab.conf"

shot() { import -window root "$work/$1.png" || fail "no screenshot $1"; }
# pixels that differ between two screenshots inside WxH+X+Y
differ() {
  compare -metric AE -extract "$3" "$work/$1.png" "$work/$2.png" null: 2>&1 | sed 's/[^0-9.e+].*//'
}
more_than() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }
# polls (up to 20 s, for slow sanitizer builds): shot NAME until more than N pixels inside WxH+X+Y
# differ from shot REF
changed() {
  for _ in $(seq 40); do
    shot "$1"
    more_than "$(differ "$2" "$1" "$3")" "$4" && return 0
    sleep 0.5
  done
  return 1
}

case "$case_name" in
qtest)
  "$tests" -o "$work/qtest.txt",txt
  status=$?
  cat "$work/qtest.txt"
  [ "$status" -eq 0 ] || fail "the QtTest checks failed on the real X server"
  ;;
session)
  "$app" >"$work/app.log" 2>&1 &
  pids+=($!)
  window=$(timeout 30 xdotool search --sync --onlyvisible --name '— Chaplygin Lab$' | head -1)
  [ -n "$window" ] || fail "no window: $(head -c 500 "$work/app.log")"
  geometry=$(xwininfo -id "$window" | awk '/Width:/ { w = $2 } /Height:/ { h = $2 } END { print w "x" h }')
  [ "$geometry" = "1280x800" ] || fail "a first start on a 1280x800 screen is $geometry"
  sleep 1
  canvas=600x300+400+60
  left=330x380+5+40
  # Animation > Preset 3 (catenary): the canvas changes
  shot start
  xdotool mousemove --sync 156 8 click 1
  sleep 0.5
  shot menu
  # Play, the steps, Loop, start, end, the seconds, Play new scenes, Preset 1, 2, 3
  xdotool key --delay 50 Down Down Down Down Down Down Down Down Down Down Down Down Return
  changed catenary start "$canvas" 1000 || fail "Preset 3 did not change the canvas"
  # Space plays (the canvas moves), Space pauses (it stays), a step moves it again
  xdotool mousemove --sync 700 250 click 1 key space
  sleep 1
  shot playing1
  changed playing2 playing1 "$canvas" 100 || fail "Space did not play"
  xdotool key space
  # paused once two shots half a second apart agree
  paused=
  shot paused2
  for _ in $(seq 20); do
    sleep 0.5
    mv "$work/paused2.png" "$work/paused1.png"
    shot paused2
    [ "$(differ paused1 paused2 "$canvas")" = 0 ] && paused=1 && break
  done
  [ -n "$paused" ] || fail "the second Space did not pause"
  xdotool key period
  changed stepped paused2 "$canvas" 10 || fail "the step did not move the bodies"
  # F11: the docks on the left give way to the canvas; Esc brings them back as they were
  xdotool key F11
  changed presenting stepped "$left" 20000 || fail "F11 left the left docks in place"
  xdotool key Escape
  back=
  for _ in $(seq 40); do
    sleep 0.5
    shot back
    [ "$(differ stepped back "$left")" = 0 ] && back=1 && break
  done
  [ -n "$back" ] || fail "Esc did not bring the Path dock back as it was"
  # F1: the help window
  xdotool key F1
  timeout 10 xdotool search --sync --onlyvisible --name '^Chaplygin Lab help$' >/dev/null \
    || fail "F1 opened no help window"
  # narrowed to 1024x768 while it runs: the window follows and the program lives on
  xdotool windowsize --sync "$window" 1024 768
  sleep 1
  geometry=$(xwininfo -id "$window" | awk '/Width:/ { w = $2 } /Height:/ { h = $2 } END { print w "x" h }')
  [ "$geometry" = "1024x768" ] || fail "resized to $geometry"
  kill -0 "${pids[1]}" || fail "the program ended: $(head -c 500 "$work/app.log")"
  if grep -E "QWidget|QLayout|QPainter|Segmentation|terminate" "$work/app.log"; then
    fail "warnings on stderr"
  fi
  ;;
bad_file_dialog)
  # a bad scene opened as from a file manager (no terminal on stderr): a dialog says what is
  # wrong, and the window is there behind it with the default scene
  printf '{"format": "chaplygin-lab-scene", "version": 1, "path": 3}' >"$work/bad.json"
  "$app" "$work/bad.json" </dev/null >"$work/app.log" 2>&1 &
  pids+=($!)
  dialog=$(timeout 30 xdotool search --sync --onlyvisible --name '^Cannot open the scene$' | head -1)
  [ -n "$dialog" ] || fail "no dialog: $(head -c 500 "$work/app.log")"
  timeout 10 xdotool search --sync --onlyvisible --name '— Chaplygin Lab$' >/dev/null \
    || fail "no main window behind the dialog"
  grep -q "bad.json" "$work/app.log" || fail "stderr does not name the file: $(cat "$work/app.log")"
  xdotool windowactivate --sync "$dialog" key Return 2>/dev/null || xdotool key Return
  for _ in $(seq 20); do
    xdotool search --onlyvisible --name '^Cannot open the scene$' >/dev/null || break
    sleep 0.5
  done
  xdotool search --onlyvisible --name '^Cannot open the scene$' >/dev/null && fail "Return did not close the dialog"
  kill -0 "${pids[1]}" || fail "the program ended: $(head -c 500 "$work/app.log")"
  ;;
zoom_extremes)
  scene=$(dirname "$0")/../../resources/scenes/gallery/long-horizon.json
  [ -f "$scene" ] || fail "no gallery scene $scene"
  "$app" "$scene" >"$work/app.log" 2>&1 &
  pids+=($!)
  window=$(timeout 30 xdotool search --sync --onlyvisible --name '— Chaplygin Lab$' | head -1)
  [ -n "$window" ] || fail "no window: $(head -c 500 "$work/app.log")"
  sleep 1
  # the time read-out at the canvas's top: it changes with every frame while the scene plays
  readout=300x24+370+20
  # Space plays; then bursts of ten wheel steps (1.2 times each) about the body's start on the
  # circle: 50 in (past the closest zoom, 1e5 px/m), 120 out (past the farthest, 1e-3 px/m), 70
  # in again
  xdotool mousemove --sync 845 212 click 1 key space
  sleep 1
  shot before
  peak_kb() { awk '/VmHWM/ { print $2 }' "/proc/${pids[1]}/status"; }
  # the program's own CPU time [s] (user and system), which the machine's other work does not
  # inflate as it does the wall time
  cpu_s() { awk -v hz="$(getconf CLK_TCK)" '{ print ($14 + $15) / hz }' "/proc/${pids[1]}/stat"; }
  bursts=0
  slowest=0
  for direction in 4 4 4 4 4 5 5 5 5 5 5 5 5 5 5 5 5 4 4 4 4 4 4 4; do
    before_cpu=$(cpu_s)
    xdotool click --repeat 10 --delay 5 "$direction"
    shot "burst$bursts"
    # the program answers: the read-out changes once it has drawn a frame after the burst
    for _ in $(seq 240); do
      shot "after$bursts"
      more_than "$(differ "burst$bursts" "after$bursts" "$readout")" 0 && break
      sleep 0.25
    done
    more_than "$(differ "burst$bursts" "after$bursts" "$readout")" 0 ||
      fail "burst $bursts: the canvas stopped"
    used=$(awk -v a="$before_cpu" -v b="$(cpu_s)" 'BEGIN { print b - a }')
    more_than "$used" "$slowest" && slowest=$used
    echo "burst $bursts (button $direction): $used s of CPU"
    kill -0 "${pids[1]}" || fail "the program ended at burst $bursts: $(head -c 500 "$work/app.log")"
    bursts=$((bursts + 1))
  done
  peak=$(peak_kb)
  echo "zoomed in and out in $bursts bursts while playing: at most $slowest s of CPU a burst, peak resident memory $((peak / 1024)) MB"
  # ten wheel steps, each drawing the layers anew, and the frames played meanwhile
  more_than "$slowest" 5 && fail "a burst of ten wheel steps took $slowest s of CPU"
  [ "$peak" -lt 1048576 ] || fail "peak resident memory $((peak / 1024)) MB, over 1 GB"
  if grep -E "QWidget|QLayout|QPainter|Segmentation|terminate|non-finite" "$work/app.log"; then
    fail "warnings on stderr"
  fi
  ;;
lecture_keys)
  # a lecture given as the window's argument: its first scene; Page Down and Page Up step through
  # it, also in presentation mode (F11), and the window's title says where the lecture is
  lecture=$(dirname "$0")/../../docs/images/scenes/lecture-sleigh.json
  [ -f "$lecture" ] || fail "no lecture $lecture"
  "$app" "$lecture" >"$work/app.log" 2>&1 &
  pids+=($!)
  window=$(timeout 30 xdotool search --sync --onlyvisible --name '^Lecture, scene 1 of 4 — ' | head -1)
  [ -n "$window" ] || fail "no window on the lecture's first scene: $(head -c 500 "$work/app.log")"
  sleep 1
  at() { timeout 10 xdotool search --sync --name "^Lecture, scene $1 of 4 — " >/dev/null; }
  xdotool mousemove --sync 700 250 click 1 key Next
  at 2 || fail "Page Down did not show the lecture's second scene"
  xdotool key F11
  sleep 1
  xdotool key Next
  at 3 || fail "Page Down in presentation mode did not show the third scene"
  xdotool key Next Next
  at 1 || fail "Page Down after the last scene did not go round to the first"
  xdotool key Prior
  at 4 || fail "Page Up did not show the last scene"
  kill -0 "${pids[1]}" || fail "the program ended: $(head -c 500 "$work/app.log")"
  if grep -E "QWidget|QLayout|QPainter|Segmentation|terminate" "$work/app.log"; then
    fail "warnings on stderr"
  fi
  ;;
*)
  fail "unknown case"
  ;;
esac
