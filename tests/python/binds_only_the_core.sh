#!/usr/bin/env bash
# The Python module's layer (docs/architecture.md): chaplygin_lab compiles with no Qt include path,
# includes only the core's folders, and its shared object needs no Qt library.
# binds_only_the_core.sh BUILD_DIR SOURCE_DIR MODULE_FILE
set -u
build=$1
src=$2
module=$3
db=$build/compile_commands.json
commands=$(grep -E '"command".*python/CMakeFiles/chaplygin_lab' "$db")
[ -n "$commands" ] || { echo "no chaplygin_lab entries in $db"; exit 1; }
if echo "$commands" | grep -qiE 'qt6|qtcore|qcustomplot'; then
  echo "chaplygin_lab is compiled with Qt on its include path"; exit 1
fi
core_folders=$(cd "$src/core" && ls -d */ | tr -d / | paste -sd '|')
bad=$(grep -hoE '#include[[:space:]]*"[^"]+"' "$src"/app/python/*.cpp "$src"/app/python/*.h |
  grep -vE "\"(($core_folders)/[a-z_]+\\.h|bindings\\.h)\"")
[ -z "$bad" ] || { echo "app/python/ includes what is not the core: $bad"; exit 1; }
if grep -lE '#include[[:space:]]*<(Q[A-Za-z]|qcustomplot)' "$src"/app/python/*; then
  echo "app/python/ includes a Qt header"; exit 1
fi
needed=$(readelf -d "$module" | grep NEEDED)
if echo "$needed" | grep -qiE 'qt|qcustomplot'; then
  echo "the module needs Qt: $needed"; exit 1
fi
echo "ok: the Python module binds only the core"
