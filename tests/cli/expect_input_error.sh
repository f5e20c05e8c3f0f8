#!/usr/bin/env bash
# Run ltn on bad input and check what a user must get: exit status 2, the
# error on one line of stderr that contains EXPECTED (the parameter's name),
# no other text of ltn's or of the libraries it calls (muparser's diagnosis,
# deal.II's exception blocks), and no output directory. Lines of the MPI
# runtime (warnings some machines print) are not ltn's and may stand beside.
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
[ "$(grep -c '^ltn: ' <<<"$stderr")" -eq 1 ] &&
  grep -q '^ltn: error: ' <<<"$stderr" &&
  ! grep -qE '^(Message|Formula|Token|Position|Errc): |An error occurred|Stacktrace' <<<"$stderr" ||
  { echo "FAIL: stderr is not the error's line alone"; exit 1; }
[ ! -e "$output_dir" ] ||
  { echo "FAIL: output was written to $output_dir"; exit 1; }
echo PASS
