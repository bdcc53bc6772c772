# Sourced by the command-line test scripts (SCRIPT EXE CASE): the executable, the case name, a
# scratch directory removed on exit, and the checks the cases share.
exe=$1
case_name=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL ($case_name): $*" >&2; exit 1; }

# run EXPECTED_STATUS args...: runs the CLI, keeps stdout/stderr, checks the exit status
run() {
  local expected=$1; shift
  "$exe" --headless "$@" >"$work/out" 2>"$work/err"
  local status=$?
  [ "$status" -eq "$expected" ] || fail "exit $status, expected $expected for: $* ; stderr: $(cat "$work/err")"
}
expect_err() { grep -q -- "$1" "$work/err" || fail "stderr lacks '$1': $(cat "$work/err")"; }
