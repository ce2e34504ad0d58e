#!/usr/bin/env python3
"""Suite-wide lint checks, run as tests (results in JUnit XML for catkin_test_results).

  ros-free      core code (each package's include/ and src/, and benchmark/) must not include
                ROS (`ros/`, `rl_msgs/`, `cv_bridge/`, ...). ROS adapters live in folders named
                `ros/` (include/<pkg>/ros/, src/ros/) and nodes in src/nodes/; tests are exempt.
  clang-format  every C++ file is clean under the committed .clang-format.

Usage: lint_check.py {ros-free|clang-format} ROOT XUNIT_FILE
"""
import os
import re
import subprocess
import sys
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

CPP_SUFFIXES = {".cpp", ".cc", ".h", ".hpp"}
SKIP_DIRS = {".git", "build", "devel", "install", "log"}
ROS_INCLUDE = re.compile(
    r'^\s*#\s*include\s*[<"](ros/|rl_msgs/|cv_bridge/|sensor_msgs/|std_msgs/|std_srvs/|'
    r'naoqi_bridge_msgs/|image_transport/|rosbag/|tf2?_?\w*/)')
ADAPTER_DIRS = {"ros", "nodes", "test"}


def cpp_files(root: Path):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS and not d.startswith(".build")]
        for f in filenames:
            if Path(f).suffix in CPP_SUFFIXES:
                yield Path(dirpath) / f


def packages(root: Path):
    return sorted(p.parent for p in root.glob("*/package.xml"))


def is_core(path: Path, pkg: Path) -> bool:
    rel = path.relative_to(pkg).parts
    if not rel or rel[0] not in ("include", "src", "benchmark"):
        return False
    return not any(part in ADAPTER_DIRS for part in rel[:-1])


def check_ros_free(root: Path):
    cases = []
    for pkg in packages(root):
        problems = []
        for f in sorted(cpp_files(pkg)):
            if not is_core(f, pkg):
                continue
            for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
                if ROS_INCLUDE.match(line):
                    problems.append(f"{f.relative_to(root)}:{n}: {line.strip()}")
        cases.append((f"ros_free.{pkg.name}", problems))
    return cases


def check_clang_format(root: Path):
    cases = []
    for f in sorted(cpp_files(root)):
        res = subprocess.run(["clang-format", "--dry-run", "-Werror", str(f)],
                             capture_output=True, text=True)
        problems = [] if res.returncode == 0 else [
            f"{f.relative_to(root)} is not clang-format clean "
            f"(fix: clang-format -i {f.relative_to(root)})"] + res.stderr.splitlines()[:6]
        cases.append((f"clang_format.{str(f.relative_to(root)).replace('/', '.')}", problems))
    return cases


def write_xunit(path: Path, suite: str, cases):
    failures = sum(1 for _, p in cases if p)
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w") as out:
        out.write('<?xml version="1.0" encoding="UTF-8"?>\n')
        out.write(f'<testsuite name={quoteattr(suite)} tests="{len(cases)}" '
                  f'failures="{failures}" errors="0">\n')
        for name, problems in cases:
            out.write(f'  <testcase classname={quoteattr(suite)} name={quoteattr(name)}>')
            if problems:
                out.write(f'<failure message={quoteattr(problems[0])}>'
                          f'{escape(chr(10).join(problems))}</failure>')
            out.write('</testcase>\n')
        out.write('</testsuite>\n')
    return failures


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("ros-free", "clang-format"):
        print(__doc__)
        return 2
    check, root, xunit = sys.argv[1], Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    cases = check_ros_free(root) if check == "ros-free" else check_clang_format(root)
    failures = write_xunit(xunit, f"lint_{check.replace('-', '_')}", cases)
    for name, problems in cases:
        for p in problems:
            print(p)
    print(f"{check}: {len(cases) - failures} clean, {failures} with problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
