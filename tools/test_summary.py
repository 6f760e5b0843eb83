"""Summary of a ctest run from the JUnit XML files the tests write.

Prints "N passed, N failed" (and ", N skipped") over the individual test cases and
exits non-zero when anything failed, including a ctest entry that wrote no XML.
usage: test_summary.py RESULTS_DIR CTEST_RC LAST_TESTS_FAILED_LOG
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

results, ctest_rc, failed_log = sys.argv[1], int(sys.argv[2]), sys.argv[3]
passed = failed = skipped = 0
for path in sorted(glob.glob(os.path.join(results, "*.xml"))):
    for case in ET.parse(path).getroot().iter("testcase"):
        if case.find("failure") is not None or case.find("error") is not None:
            failed += 1
        elif case.find("skipped") is not None or case.get("result") == "skipped":
            skipped += 1
        else:
            passed += 1
# a ctest entry that failed without reporting a failed case (a crash, a timeout)
if ctest_rc != 0 and failed == 0:
    failed = max(1, sum(1 for _ in open(failed_log)) if os.path.exists(failed_log) else 1)
if passed + failed == 0:
    failed = 1    # no test ran: that is a failure too
print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
sys.exit(1 if failed else 0)
