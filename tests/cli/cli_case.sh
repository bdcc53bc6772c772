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

# the number of the column NAME in the header of the CSV FILE (nothing when it has none)
col() { head -1 "$1" | tr , '\n' | grep -nx -- "$2" | cut -d: -f1; }
# csv_awk FILE PROGRAM [AWK OPTIONS...]: awk -F, PROGRAM over the CSV, in which $NAME is the column
# that the header calls NAME (each name is an awk variable holding its column's number, so a program
# must not assign to one); a $NAME that the header lacks fails the case
csv_awk() {
  local file=$1 program=$2 name n=0 vars=()
  shift 2
  for name in $(grep -o '\$[A-Za-z_][A-Za-z0-9_]*' <<<"$program" | cut -c2- | sort -u); do
    [ -n "$(col "$file" "$name")" ] || fail "$file has no column $name: $(head -1 "$file")"
  done
  for name in $(head -1 "$file" | tr , ' '); do vars+=(-v "$name=$((n += 1))"); done
  awk -F, "${vars[@]}" "$@" "$program" "$file"
}
