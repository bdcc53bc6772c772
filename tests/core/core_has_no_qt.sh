#!/usr/bin/env bash
# The layering rule: chaplygin_core compiles with no Qt include path and links no Qt library.
# core_has_no_qt.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
src=$2
db=$build/compile_commands.json
[ -f "$db" ] || { echo "no $db"; exit 1; }
core_commands=$(grep -E '"command".*core/CMakeFiles/chaplygin_core' "$db")
[ -n "$core_commands" ] || { echo "no chaplygin_core entries in $db"; exit 1; }
if echo "$core_commands" | grep -qiE 'qt6|qtcore|qcustomplot'; then
  echo "chaplygin_core is compiled with Qt on its include path"; exit 1
fi
if grep -rlE '#include[[:space:]]*<(Q[A-Za-z]|qcustomplot)' "$src/core"; then
  echo "core/ includes a Qt header"; exit 1
fi
echo "ok: core has no Qt"
