#!/usr/bin/env python3
"""The build outputs a ctest selection needs: the default build (`all`) less the executables that
only unselected tests run.

    scripts/suite_targets.py BUILD_DIR [CTEST_ARGS...]      e.g. build-asan -LE not_sanitized

Reads BUILD_DIR/build.ninja (what `all` builds, through its per-folder `all` targets) and every
CTestTestfile.cmake (each test's command, arguments and properties), asks ctest which tests
CTEST_ARGS select (-L/-LE/-R/-E as for ctest), and prints, one a line, every output of `all` except
those that some test names (as its command, an argument or in a property such as ENVIRONMENT) and
no selected test names. Such an output is a test executable whose tests are all left out, e.g. a
GoogleTest program whose only entry carries the label not_sanitized. Anything no test names (the
programs, which the script tests find in their --bin folder; libraries; the add-on's zip) stays.
It reads the tree as configured: run it after cmake, before the build (ctest lists a test whose
executable is not built yet, so the names come from CTestTestfile.cmake, not from ctest's JSON).
`cmake --build BUILD_DIR --target $(scripts/suite_targets.py BUILD_DIR ...)` then builds just that.
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from build_times import read_edges  # noqa: E402


def default_outputs(edges):
    """The outputs `all` builds: its inputs, with each folder's own `all` expanded."""
    out, stack, seen = [], ["all"], set()
    while stack:
        node = stack.pop()
        for dep in edges.get(node, []):
            if dep in seen:
                continue
            seen.add(dep)
            if dep.endswith("/all"):
                stack.append(dep)
            else:
                out.append(dep)
    return out


def named_paths(build_dir):
    """{test name: set of paths inside BUILD_DIR that its add_test and properties name}."""
    root = os.path.realpath(build_dir)
    path_re = re.compile(re.escape(root) + r"/[^\s\";:=]+")
    name_re = re.compile(r"^(?:add_test|set_tests_properties)\(\[=\[(.*?)\]=\]")
    names = {}
    for dirpath, _, files in os.walk(root):
        if "CTestTestfile.cmake" not in files:
            continue
        with open(os.path.join(dirpath, "CTestTestfile.cmake")) as f:
            for line in f:
                m = name_re.match(line)
                if not m:
                    continue
                paths = {os.path.relpath(p, root) for p in path_re.findall(line)}
                names.setdefault(m.group(1), set()).update(paths)
    return names


def selected_tests(build_dir, ctest_args):
    text = subprocess.run(["ctest", "--test-dir", build_dir, "--show-only=json-v1", *ctest_args],
                          check=True, capture_output=True, text=True).stdout
    return {t["name"] for t in json.loads(text)["tests"]}


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__.split("\n\n")[1])
    build_dir, ctest_args = sys.argv[1], sys.argv[2:]
    outputs = default_outputs(read_edges(build_dir))
    names = named_paths(build_dir)
    selected = selected_tests(build_dir, ctest_args)
    missing = selected - names.keys()
    if missing:
        sys.exit(f"suite_targets: no add_test line for {sorted(missing)[:5]}")
    named_any = set().union(*names.values()) if names else set()
    named_selected = set().union(*(names[t] for t in selected)) if selected else set()
    unused = named_any - named_selected
    for out in outputs:
        if out not in unused:
            print(out)
    for out in sorted(o for o in outputs if o in unused):
        print(f"suite_targets: left out {out} (only unselected tests run it)", file=sys.stderr)


if __name__ == "__main__":
    main()
