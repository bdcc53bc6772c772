#!/usr/bin/env bash
# Command-line cases of --sweep and --animation: sweep_animation_test.sh EXE CASE.
set -u
source "$(dirname "$0")/cli_case.sh" "$@"
# frames of a video, counted by decoding it
frames() { ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
codec() { ffprobe -v error -select_streams v:0 -show_entries stream=codec_name -of csv=p=0 "$1"; }

case "$case_name" in
sweep_bad_range)
  # b < |a| = 0.5 at the first value; nothing on stdout
  run 2 --preset sinusoid --sweep b=0.4:2.4:8 --csv -
  expect_err "sweep b: b = 0.4 (value 1 of 8) is invalid"
  expect_err "must be >= |a| = 0.5"
  [ ! -s "$work/out" ] || fail "wrote output: $(head -2 "$work/out")"
  # the first bad value in the middle of the range: a = 1.5 > b = 1
  run 2 --preset circle --sweep a=0:2:5 --csv "$work/s.csv"
  expect_err "a = 1.5 (value 4 of 5) is invalid"
  [ ! -e "$work/s.csv" ] || fail "wrote the CSV"
  run 2 --preset circle --sweep R=1:2:3
  expect_err "sweep R: unknown parameter for the sleigh"
  run 2 --preset circle --sweep b=1:2
  expect_err "expects NAME=FROM:TO:COUNT"
  run 2 --preset circle --sweep b=1:2:2.5
  expect_err "COUNT"
  run 2 --preset circle --sweep vs=1:2:3
  expect_err "in energy mode sweep vT, not vs"
  run 2 --preset circle --sweep vT=0:2:3
  expect_err "vT = 0 (value 1 of 3) is invalid"
  run 2 --preset circle --sweep b=1:2:3 --summary -
  expect_err "^chaplygin-lab: --summary: does not apply to --sweep"
  ;;
sweep_columns_and_plots)
  run 0 --preset catenary --sweep vT=0.5:2:4 --csv "$work/s.csv" --plots "$work/plots" --format png,svg
  head -1 "$work/s.csv" | grep -qx 'vT,duration,max_abs_lambda,max_abs_control_couple,max_abs_force_lateral,max_abs_control_power,final_separation' \
    || fail "header: $(head -1 "$work/s.csv")"
  [ "$(wc -l < "$work/s.csv")" -eq 5 ] || fail "rows"
  # duration scales as 1/v_T and lambda as v_T (energy mode: time law (112), lambda = m(b Psidot - a phidot))
  csv_awk "$work/s.csv" 'NR==2 {t=$duration; l=$max_abs_lambda} NR==5 {r=t/$duration; q=$max_abs_lambda/l; if (r < 4-1e-9 || r > 4+1e-9 || q < 4-1e-9 || q > 4+1e-9) exit 1}' \
    || fail "scaling with vT: $(cat "$work/s.csv")"
  # the disk's and the carriage's own parameters
  run 0 --preset circle --system disk --sweep R=0.2:0.6:3 --csv "$work/d.csv"
  [ "$(wc -l < "$work/d.csv")" -eq 4 ] && head -1 "$work/d.csv" | grep -q '^R,duration,' || fail "disk sweep: $(cat "$work/d.csv")"
  run 0 --preset line --system carriage --sweep M=0.5:2:4 --csv "$work/c.csv"
  [ "$(wc -l < "$work/c.csv")" -eq 5 ] || fail "carriage sweep: $(cat "$work/c.csv")"
  run 2 --preset line --system disk --sweep R=-1:1:3
  expect_err "R = -1 (value 1 of 3) is invalid"
  for q in duration max_abs_lambda max_abs_control_couple max_abs_force_lateral max_abs_control_power final_separation; do
    head -c 8 "$work/plots/sweep_$q.png" | od -An -c | grep -q 'P   N   G' || fail "sweep_$q.png"
    grep -q '<svg' "$work/plots/sweep_$q.svg" || fail "sweep_$q.svg"
  done
  ;;
animation_gif)
  run 0 --preset circle --animation "$work/circle.gif" --fps 4 --size 320x240
  [ "$(codec "$work/circle.gif")" = gif ] || fail "not a GIF: $(codec "$work/circle.gif")"
  n=$(frames "$work/circle.gif")
  # t_end = 2 pi sqrt(5) = 14.05 s at 4 fps: frames at 0, 0.25, ..., 14 and 14.05
  [ "$n" -ge 20 ] && [ "$n" -eq 58 ] || fail "GIF frames: $n"
  w=$(ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$work/circle.gif")
  [ "$w" = "320,240" ] || fail "size $w"
  ls -a "$work" | grep -q '^\.circle' && fail "temporary file left: $(ls -a "$work")"
  ;;
animation_mp4)
  run 0 --preset circle --animation "$work/circle.mp4" --fps 10 --size 322x242
  [ "$(codec "$work/circle.mp4")" = h264 ] || fail "not H.264: $(codec "$work/circle.mp4")"
  n=$(frames "$work/circle.mp4")
  [ "$n" -eq 142 ] || fail "MP4 frames: $n"
  ;;
animation_png_frames)
  run 0 --preset line --animation "$work/frames/" --fps 2 --size 200x150
  n=$(ls "$work/frames" | grep -c '^frame_[0-9]\{5\}\.png$')
  # the line takes 4 sqrt(5) = 8.94 s: frames at 0, 0.5, ..., 8.5 and 8.94
  [ "$n" -eq 19 ] || fail "frames: $n ($(ls "$work/frames" | head))"
  head -c 8 "$work/frames/frame_00018.png" | od -An -c | grep -q 'P   N   G' || fail "PNG"
  # a folder name without extension also means frames; stale frames of a longer run go
  touch "$work/frames/frame_00042.png"
  run 0 --preset line --animation "$work/frames" --fps 2 --size 200x150
  [ -e "$work/frames/frame_00042.png" ] && fail "stale frame kept"
  [ "$(ls "$work/frames" | wc -l)" -eq 19 ] || fail "frames after rerun"
  run 2 --preset line --animation "$work/clip.avi"
  expect_err "unknown format '.avi'"
  run 2 --preset line --animation "$work/x/" --size 10x10
  expect_err "--size"
  run 2 --preset line --animation "$work/x/" --csv -
  expect_err "writes the animation alone"
  run 2 --preset line --fps 10 --csv -
  expect_err "--fps: applies only to --animation"
  # --body draws the bodies as asked (the line's sleigh to scale by default, here as markers)
  run 0 --preset line --animation "$work/markers/" --fps 2 --size 200x150 --body marker
  [ "$(ls "$work/markers" | wc -l)" -eq 19 ] || fail "marker frames"
  cmp -s "$work/frames/frame_00004.png" "$work/markers/frame_00004.png" && fail "--body marker drew the same frame"
  run 0 --preset line --animation "$work/auto/" --fps 2 --size 200x150 --body auto
  cmp -s "$work/frames/frame_00004.png" "$work/auto/frame_00004.png" || fail "--body auto is not the default"
  run 2 --preset line --animation "$work/x/" --body tiny
  expect_err "--body: expected auto, scale, outline or marker, got 'tiny'"
  run 2 --preset line --body marker --csv -
  expect_err "--body: applies only to --animation"
  ;;
animation_without_ffmpeg)
  # PATH without ffmpeg: GIF and MP4 are refused with a clear message, PNG frames still work
  PATH=/nonexistent run 2 --preset circle --animation "$work/circle.gif" --fps 2 --size 200x150
  expect_err "needs the ffmpeg program, which is not on PATH"
  left=$(ls -A "$work" | grep -vx 'out\|err')
  [ -z "$left" ] || fail "left files: $left"
  PATH=/nonexistent run 2 --preset circle --animation "$work/circle.mp4"
  expect_err "ffmpeg"
  PATH=/nonexistent run 0 --preset line --animation "$work/f/" --fps 1 --size 200x150
  [ "$(ls "$work/f" | wc -l)" -eq 10 ] || fail "PNG frames without ffmpeg: $(ls "$work/f")"
  ;;
*)
  fail "unknown case"
  ;;
esac
echo "ok ($case_name)"
