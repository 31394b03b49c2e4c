#!/usr/bin/python3
"""Prints the ten slowest tests of a tools/test.sh run, so that growth is seen: the core's
GoogleTest cases from the ctest logs (Release and sanitizer builds) and the rostests from their
JUnit results.
  tools/slowest_tests.py <test_logs folder> <ROS test_results folder>"""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

CTEST_LINE = re.compile(r"Test\s+#\d+: (\S+) \.+\s+Passed\s+([0-9.]+) sec")


def core_tests(logs):
    """(seconds, label) of each core test in core.log; the sanitizer build's cases come second in
    the log and are labelled so."""
    found = []
    path = os.path.join(logs, "core.log")
    if not os.path.exists(path):
        return found
    build = "Release"
    with open(path, encoding="utf-8", errors="replace") as log:
        for line in log:
            if "AddressSanitizer" in line and line.startswith("=="):
                build = "ASan+UBSan"
            match = CTEST_LINE.search(line)
            if match:
                found.append((float(match.group(2)), "core %s: %s" % (build, match.group(1))))
    return found


def rostests(results):
    """(seconds, label) of each rostest's JUnit file."""
    found = []
    for path in glob.glob(os.path.join(results, "rostest-*.xml")):
        try:
            suite = ElementTree.parse(path).getroot()
            seconds = float(suite.get("time", "0"))
        except (ElementTree.ParseError, ValueError):
            continue
        name = os.path.basename(path)[len("rostest-"):-len(".xml")].replace("test_ros_", "")
        found.append((seconds, "rostest: %s" % name))
    return found


def main():
    logs, results = sys.argv[1], sys.argv[2]
    tests = sorted(core_tests(logs) + rostests(results), reverse=True)[:10]
    print("ten slowest tests:")
    for seconds, label in tests:
        print("  %8.1f s  %s" % (seconds, label))


if __name__ == "__main__":
    main()
