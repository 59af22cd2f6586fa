"""docs/python.md's examples run as a notebook would: every ```python block of the page, in
order, in one namespace, from a folder holding the page's `data/` (the bundled meshes) and `out/`.
The claims its comments make are then checked on what the blocks left behind."""
import contextlib
import io
import os
import re

from conftest import DATA, ROOT


def blocks():
    text = open(os.path.join(ROOT, "docs", "python.md"), encoding="utf-8").read()
    return re.findall(r"^```python\n(.*?)^```$", text, flags=re.S | re.M)


def test_the_page_has_examples():
    assert len(blocks()) >= 3


def test_examples_run_in_order_and_say_true(tmp_path, monkeypatch):
    os.symlink(DATA, tmp_path / "data")
    (tmp_path / "out").mkdir()
    monkeypatch.chdir(tmp_path)
    namespace, printed = {}, io.StringIO()
    with contextlib.redirect_stdout(printed):
        for code in blocks():
            exec(compile(code, "docs/python.md", "exec"), namespace)
    # Block 1: a proved outside proxy of the bunny at 2 %.
    assert namespace["report"]["class"] == "outside"
    assert 0 < len(namespace["Fp"]) <= 0.02 * 6966 + 1
    # Block 2: the check finds no HM' ray and exact containment; the proxy file is written.
    assert namespace["r"]["counts"]["HM"] == 0
    assert namespace["r"]["exact"] == "contains"
    assert (tmp_path / "out" / "bunny.outside.ply").stat().st_size > 0
    # Block 3: the open teapot is refused with exit code 2 and the message the comment quotes.
    assert namespace["info"]["boundary_edges"] == 160
    assert printed.getvalue().startswith("2 V, F: 160 boundary edges; an inside proxy needs")
