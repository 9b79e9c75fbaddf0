"""Write tests/durations.txt from a pytest JUnit XML report: the tests that took at least
MIN_SECONDS (setup, call and teardown together), longest first. conftest.py hands out the
modules with the longest totals first, so that with several workers the long ones do not end
up running alone at the end of the suite.

    make test ARGS="--junitxml=/tmp/junit.xml"
    /usr/bin/python3 tests/tools/record_durations.py /tmp/junit.xml > tests/durations.txt
"""

import sys
import xml.etree.ElementTree as ET

# Below this a test hardly changes its module's total (a module of many short tests, such as
# a table of bad arguments, still adds up).
MIN_SECONDS = 0.5


def durations(junit_path):
    """{nodeid: seconds} from a JUnit report (classname a.b.c + name -> a/b/c.py::name)."""
    found = {}
    for case in ET.parse(junit_path).getroot().iter("testcase"):
        module = case.get("classname", "").replace(".", "/") + ".py"
        nodeid = f"{module}::{case.get('name')}"
        found[nodeid] = found.get(nodeid, 0.0) + float(case.get("time") or 0.0)
    return found


def main(argv):
    if len(argv) != 2:
        sys.exit("usage: record_durations.py JUNIT.xml > tests/durations.txt")
    rows = sorted(durations(argv[1]).items(), key=lambda row: -row[1])
    print("# seconds nodeid (tests/tools/record_durations.py; longest first)")
    for nodeid, seconds in rows:
        if seconds >= MIN_SECONDS:
            print(f"{seconds:.1f} {nodeid}")


if __name__ == "__main__":
    main(sys.argv)
