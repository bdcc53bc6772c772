#!/bin/bash
# The pt_BR catalogue is complete for the sources as they are: lupdate (into a copy) finds every
# tr() string of ui/ and app/, at least 150 are translated and at most 5 % are unfinished.
# usage: translations_test.sh LUPDATE GENERATOR_SCRIPT PROJECT_CMAKE TS_FILE LUPDATE_OPTION...
# (the options of the update_translations target: -no-obsolete, -locations none, the aliases)
set -eu
lupdate=$1 generator=$2 project_in=$3 ts=$4
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -DIN_FILE="$project_in" -DOUT_FILE="$work/project.json" -P "$generator"
cp "$ts" "$work/check.ts"
"$lupdate" -project "$work/project.json" "$@" -ts "$work/check.ts" \
  >"$work/lupdate.log" 2>&1 || { cat "$work/lupdate.log"; exit 1; }
total=$(grep -c '<message' "$work/check.ts")
unfinished=$(grep -c 'type="unfinished"' "$work/check.ts" || true)
finished=$((total - unfinished))
echo "pt_BR: $total messages, $finished finished, $unfinished unfinished"
if [ "$finished" -lt 150 ]; then
  echo "fewer than 150 finished translations"; exit 1
fi
if [ $((unfinished * 20)) -gt "$total" ]; then
  echo "more than 5 % unfinished: run the update_translations target and translate these:"
  grep -B2 'type="unfinished"' "$work/check.ts" | grep '<source>' | head -40
  exit 1
fi
