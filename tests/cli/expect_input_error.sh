#!/usr/bin/env bash
# Run ltn on bad input and check what a user must get: exit status 2, one
# line on stderr, the error, that contains EXPECTED (the parameter's name),
# and no output directory.
#
# usage: expect_input_error.sh LTN OUTPUT_DIR EXPECTED -- ARGS...
set -u
ltn=$1 output_dir=$2 expected=$3
shift 4
rm -rf "$output_dir"
stderr=$("$ltn" "$@" --output-dir "$output_dir" 2>&1 >/dev/null)
status=$?
echo "exit status: $status"
echo "stderr: $stderr"
[ "$status" -eq 2 ] || { echo "FAIL: expected exit status 2"; exit 1; }
grep -qF -- "$expected" <<<"$stderr" ||
  { echo "FAIL: the error does not mention: $expected"; exit 1; }
[ "$(wc -l <<<"$stderr")" -eq 1 ] && [[ $stderr == "ltn: error: "* ]] ||
  { echo "FAIL: stderr is not the error's line alone"; exit 1; }
[ ! -e "$output_dir" ] ||
  { echo "FAIL: output was written to $output_dir"; exit 1; }
echo PASS
