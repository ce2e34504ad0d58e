#!/usr/bin/env python3
"""Summarises the JUnit result files of `catkin run_tests`.

Prints each failing test case, then a closing line `N passed, N failed`, and exits non-zero
if anything failed or no result was found. A test binary that crashed before writing its file
shows up through catkin's "missing result" file, which counts as a failure.
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path


def main(results_dir: str) -> int:
    files = sorted(Path(results_dir).rglob("*.xml"))
    passed = failed = skipped = 0
    for f in files:
        try:
            root = ET.parse(f).getroot()
        except ET.ParseError as e:
            print(f"FAILED {f}: unreadable result file ({e})")
            failed += 1
            continue
        cases = root.iter("testcase")
        found = False
        for case in cases:
            found = True
            name = f"{case.get('classname', '')}.{case.get('name', '')}"
            if case.find("failure") is not None or case.find("error") is not None:
                failed += 1
                node = case.find("failure") if case.find("failure") is not None else case.find("error")
                msg = (node.get("message") or node.text or "").strip().splitlines()
                print(f"FAILED {f.parent.name}/{f.name}: {name}: {msg[0] if msg else ''}")
            elif case.find("skipped") is not None or case.get("status") == "notrun":
                skipped += 1
            else:
                passed += 1
        if not found and (int(root.get("failures", 0)) or int(root.get("errors", 0))):
            failed += 1
            print(f"FAILED {f}: suite reports errors without test cases")
    if not files:
        print(f"no test results under {results_dir}")
        failed += 1
    extra = f" ({skipped} skipped)" if skipped else ""
    print(f"{passed} passed, {failed} failed{extra}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "build/test_results"))
