#!/usr/bin/env bash
# tools/mesh_upload.py's unit tests (tests/tools/test_mesh_upload.py): frame bytes against hand-made
# vectors, the response parser, the window state machine and every injected fault against a fake
# receiver, and main() over a real pseudo-terminal through pyserial. pyserial is Debian's
# python3-serial, so the system interpreter runs them (not PYTHON, which may be the venv's); a
# skipped test is a failure here, since the pty test is skipped only without pyserial.
source "$(dirname "$0")/../lib.sh"
py=/usr/bin/python3
need_file "$py"
work=$(fresh_dir upload-host-tool-unit)
status=0
"$py" tests/tools/test_mesh_upload.py -v >"$work/out" 2>&1 || status=$?
tail -n 5 "$work/out"
expect_status 0 "the unit tests"
expect_no_line 'skipped' "$work/out"
ran=$(sed -n 's/^Ran \([0-9]*\) tests.*/\1/p' "$work/out")
[ "${ran:-0}" -ge 25 ] || fail "only ${ran:-0} tests ran"
pass "upload-host-tool-unit: $ran unit tests of mesh_upload.py passed"
