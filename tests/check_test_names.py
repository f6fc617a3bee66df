#!/usr/bin/env python3
"""Fails when a Catch TEST_CASE name (its string literals joined) holds a ';'.

catch_discover_tests hands each name to ctest as a list item, and CMake splits lists at ';': such a
test becomes two names that match no test, and ctest fails them ("No tests ran") far from the cause.
Usage: check_test_names.py TESTS_DIR
"""
import pathlib
import re
import sys

CASE = re.compile(r'TEST_CASE\(((?:\s*"(?:[^"\\]|\\.)*")+)')
LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')

bad = []
for path in sorted(pathlib.Path(sys.argv[1]).rglob("*.cpp")):
    text = path.read_text(encoding="utf-8")
    for match in CASE.finditer(text):
        name = "".join(LITERAL.findall(match.group(1)))
        if ";" in name:
            line = text.count("\n", 0, match.start()) + 1
            bad.append(f"{path}:{line}:1: test name holds a ';', which ctest splits: {name}")
print("\n".join(bad) if bad else "no test name holds a ';'")
sys.exit(1 if bad else 0)
