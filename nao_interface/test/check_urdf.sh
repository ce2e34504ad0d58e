#!/bin/sh
# Runs urdfdom's check_urdf on a URDF and writes the verdict as a JUnit file for
# catkin_test_results. Usage: check_urdf.sh URDF XUNIT_FILE
urdf=$1
out=$2
mkdir -p "$(dirname "$out")"
if log=$(check_urdf "$urdf" 2>&1); then
  printf '<?xml version="1.0"?>\n<testsuite name="check_urdf" tests="1" failures="0" errors="0"><testcase classname="check_urdf" name="nao_upper_body"/></testsuite>\n' >"$out"
else
  msg=$(printf '%s' "$log" | tr -d '<>&"' | head -c 2000)
  printf '<?xml version="1.0"?>\n<testsuite name="check_urdf" tests="1" failures="1" errors="0"><testcase classname="check_urdf" name="nao_upper_body"><failure message="check_urdf failed">%s</failure></testcase></testsuite>\n' "$msg" >"$out"
fi
