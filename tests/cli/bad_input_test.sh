#!/usr/bin/env bash
# Runs one line of bad_inputs.txt: bad_input_test.sh EXE NAME.
# Passes when the CLI exits 2, names the problem (EXPECTED on stderr) and writes no file.
set -u
exe=$1
name=$2
here=$(dirname "$0")
line=$(grep -E "^$name \|" "$here/bad_inputs.txt") || { echo "no case $name"; exit 1; }
expected=$(echo "$line" | awk -F' [|] ' '{print $2}')
args=$(echo "$line" | awk -F' [|] ' '{print $3}')
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=${args//OUTDIR/$work/plots}
printf '{"format": "chaplygin-lab-scene", "version": 1e400}' > "$work/overflow.json"
args=${args//SCENE_OVERFLOW/$work/overflow.json}
eval "set -- $args"
"$exe" --headless "$@" --csv "$work/out.csv" --summary "$work/out.json" >"$work/stdout" 2>"$work/stderr"
status=$?
[ "$status" -eq 2 ] || { echo "FAIL $name: exit $status, expected 2; stderr: $(head -c 400 "$work/stderr")"; exit 1; }
grep -qF -- "$expected" "$work/stderr" || { echo "FAIL $name: stderr lacks '$expected': $(head -c 400 "$work/stderr")"; exit 1; }
[ "$(wc -l < "$work/stderr")" -le 2 ] || { echo "FAIL $name: more than a short message"; exit 1; }
for f in out.csv out.json plots; do
  [ -e "$work/$f" ] && { echo "FAIL $name: $f was written despite the error"; exit 1; }
done
echo "ok $name: $(cat "$work/stderr")"
