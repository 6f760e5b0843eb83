#!/usr/bin/env bash
# The README's test command: set up everything (tools/bootstrap.sh), run every test
# through ctest (C++ on 1/2/4 MPI ranks, pytest files), and end with the summary
# line "N passed, N failed" counted over the individual test cases.
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$top/tools/bootstrap.sh" || { echo "0 passed, 1 failed"; exit 1; }

cd "${CLUSTERDYN_BUILD_DIR:-$top/build}" || exit 1
rm -rf test-results
ctest --output-on-failure --timeout 1800 -j "$(nproc)" "$@"
ctest_rc=$?
/usr/bin/python3 "$top/tools/test_summary.py" test-results "$ctest_rc" Testing/Temporary/LastTestsFailed.log
