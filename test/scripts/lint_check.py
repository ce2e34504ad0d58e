#!/usr/bin/env python3
"""Suite-wide lint checks, run as tests (results in JUnit XML for catkin_test_results).

  ros-free      core code (each package's include/ and src/, and benchmark/) must not include
                ROS (`ros/`, `rl_msgs/`, `cv_bridge/`, ...). ROS adapters live in folders named
                `ros/` (include/<pkg>/ros/, src/ros/) and nodes in src/nodes/; tests are exempt.
  clang-format  every C++ file is clean under the committed .clang-format.
  package-deps  the packages are composed, not stacked: each suite package names (in
                package.xml, in CMakeLists.txt outside comments, in a C++ #include) only the
                suite packages it may depend on (SUITE_DEPENDENCIES); rl_env knows no robot,
                rl_agent no environment, and only rl_experiment composes them.

Usage: lint_check.py {ros-free|clang-format|package-deps} ROOT XUNIT_FILE
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


# The suite packages each package may name; the others (launch files, suite tests,
# metapackage) may name any. A generic package never depends on a specific one.
SUITE_DEPENDENCIES = {
    "rl_msgs": set(),
    "naoqi_bridge_msgs": set(),
    "rl_common": set(),
    "rl_env": {"rl_common", "rl_msgs"},
    "rl_agent": {"rl_common", "rl_msgs"},
    "nao_interface": {"rl_common", "rl_env", "rl_msgs", "naoqi_bridge_msgs"},
    "rl_experiment": {"rl_common", "rl_env", "rl_agent", "nao_interface", "rl_msgs"},
    "rl_python": {"rl_common", "rl_env", "rl_agent"},
}
DEPEND_TAG = re.compile(r"<(?:\w+_)?depend>\s*([\w-]+)\s*</")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](\w+)/')


def package_name(pkg: Path) -> str:
    m = re.search(r"<name>\s*([\w-]+)\s*</name>", (pkg / "package.xml").read_text())
    return m.group(1) if m else pkg.name


def check_package_deps(root: Path):
    pkgs = {package_name(p): p for p in packages(root)}
    cases = []
    for name, allowed in sorted(SUITE_DEPENDENCIES.items()):
        pkg = pkgs.get(name)
        if pkg is None:
            cases.append((f"package_deps.{name}", [f"package {name} not found under {root}"]))
            continue
        forbidden = (set(SUITE_DEPENDENCIES) | set(pkgs)) - allowed - {name}
        problems = []
        for n, line in enumerate((pkg / "package.xml").read_text().splitlines(), 1):
            for dep in DEPEND_TAG.findall(line):
                if dep in forbidden:
                    problems.append(f"{name}/package.xml:{n}: depends on {dep}")
        for n, line in enumerate((pkg / "CMakeLists.txt").read_text().splitlines(), 1):
            code = line.split("#", 1)[0]
            for word in re.findall(r"[\w-]+", code):
                if word in forbidden:
                    problems.append(f"{name}/CMakeLists.txt:{n}: names {word}: {line.strip()}")
        for f in sorted(cpp_files(pkg)):
            for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if m and m.group(1) in forbidden:
                    problems.append(f"{f.relative_to(root)}:{n}: {line.strip()}")
        if problems:
            problems.insert(0, f"{name} may name only {', '.join(sorted(allowed)) or 'no suite package'}")
        cases.append((f"package_deps.{name}", problems))
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
    checks = {"ros-free": check_ros_free, "clang-format": check_clang_format,
              "package-deps": check_package_deps}
    if len(sys.argv) != 4 or sys.argv[1] not in checks:
        print(__doc__)
        return 2
    check, root, xunit = sys.argv[1], Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    cases = checks[check](root)
    failures = write_xunit(xunit, f"lint_{check.replace('-', '_')}", cases)
    for name, problems in cases:
        for p in problems:
            print(p)
    print(f"{check}: {len(cases) - failures} clean, {failures} with problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
