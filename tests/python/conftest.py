"""Shared fixtures of the Python module's tests (docs/python.md).

The module comes from PYTHONPATH (build/python; with python/ for proxyvis_tools.reports, the
keys a comparison leaves out), the programs to compare with from PROXYVIS_BIN
(default build/bin), the bundled meshes from PROXYVIS_DATA (default data/). ctest sets all three;
by hand, from the checkout:  PYTHONPATH=build/python:python python3 -m pytest -q tests/python
"""
import json
import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.environ.get("PROXYVIS_BIN", os.path.join(ROOT, "build", "bin"))
DATA = os.environ.get("PROXYVIS_DATA", os.path.join(ROOT, "data"))



def data(name):
    return os.path.join(DATA, name)


def run(program, *args):
    """Runs build/bin/PROGRAM with ARGS; returns its completed process (exit code checked)."""
    p = subprocess.run([os.path.join(BIN, program), *map(str, args)], capture_output=True,
                       text=True, timeout=600)
    assert p.returncode == 0, f"{program} {args}: exit {p.returncode}\n{p.stderr}"
    return p


def run_json(program, *args, tmp_path):
    """Runs PROGRAM with ARGS and --json; returns the report it wrote."""
    out = tmp_path / f"{program}.json"
    run(program, *args, "--json", out, "-q")
    return json.loads(out.read_text())


@pytest.fixture(scope="session")
def bunny():
    """data/bunny.off (6,966 triangles, closed) as load_mesh reads it."""
    import proxyvis
    return proxyvis.load_mesh(data("bunny.off"))
