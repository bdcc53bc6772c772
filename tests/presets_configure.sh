#!/usr/bin/env bash
# Every configure preset that switches a part of the project off still configures: a test or
# target that names a switched-off target breaks only that preset's configure (CMakePresets.json).
# presets_configure.sh SOURCE_DIR WORK_DIR
set -u
src=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
status=0
for preset in $(python3 -c '
import json, sys
presets = json.load(open(sys.argv[1] + "/CMakePresets.json"))["configurePresets"]
for p in presets:
    cache = p.get("cacheVariables", {})
    if any(v == "OFF" for k, v in cache.items() if k.startswith("CHAPLYGIN_")):
        print(p["name"])
' "$src"); do
  if cmake -S "$src" -B "$work/$preset" --preset "$preset" >"$work/$preset.log" 2>&1; then
    echo "ok: preset $preset configures"
  else
    echo "preset $preset does not configure:"
    grep -A6 'CMake Error' "$work/$preset.log"
    status=1
  fi
done
rm -rf "$work"
exit $status
