#!/usr/bin/env bash
# validate.sh TOOL ARGS...: runs a metadata validator, or skips (exit 77) where it is not installed.
tool=$1
if ! command -v "$tool" >/dev/null 2>&1; then
  echo "SKIP: $tool is not installed (desktop-file-utils / appstream)"
  exit 77
fi
exec "$@"
