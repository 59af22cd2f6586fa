"""proxy() against proxy-gen on the same mesh and options: the same proxy (faces and vertices) and
the same report but for timings and file names; the same result at any thread count."""
import numpy as np
import pytest

import proxyvis
from conftest import data, run_json
from proxyvis_tools.reports import TIMING_KEYS, without

# proxy-gen adds what concerns the files it read and wrote.
FILE_KEYS = TIMING_KEYS | {"path", "output", "output_sha256"}


def proxy_gen(tmp_path, *flags):
    """proxy-gen on data/bunny.off with FLAGS: the proxy written (binary PLY: its float32
    vertices exactly) as load_mesh reads it, and the JSON report."""
    out = tmp_path / "proxy.ply"
    report = run_json("proxy-gen", data("bunny.off"), "-o", out, *flags, tmp_path=tmp_path)
    Vp, Fp, _ = proxyvis.load_mesh(str(out))
    return Vp, Fp, report


@pytest.mark.parametrize("kind", ["outside", "inside", "general"])
def test_proxy_equals_proxy_gen(bunny, tmp_path, kind):
    V, F, _ = bunny
    Vp, Fp, report = proxyvis.proxy(V, F, kind=kind, ratio=0.02)
    Vg, Fg, expected = proxy_gen(tmp_path, "--kind", kind, "--ratio", "0.02")
    assert report["class"] == expected["class"] == kind
    assert report["faces"] == expected["faces"] == len(Fp)
    np.testing.assert_array_equal(Fp, Fg)
    np.testing.assert_array_equal(Vp, Vg)
    assert Vp.dtype == np.float64 and Fp.dtype == np.int32
    # Every number equal (class, checks with the double reading, volume ratio, Hausdorff, budget).
    assert without(report, FILE_KEYS) == without(expected, FILE_KEYS)
    stages = set(expected["seconds"]) - {"load"}
    assert set(report["seconds"]) == stages and report["input"]["path"] == "V, F"
    if kind != "general":
        assert report["checks"]["containment_double"] == expected["checks"]["containment_double"]


def test_proxy_options_mirror_proxy_gen(bunny, tmp_path):
    V, F, _ = bunny
    Vp, Fp, report = proxyvis.proxy(V, F, kind="outside", method="hull", max_faces=40, seed=3)
    Vg, Fg, expected = proxy_gen(tmp_path, "--method", "hull", "--max-faces", "40", "--seed", "3")
    np.testing.assert_array_equal(Vp, Vg)
    np.testing.assert_array_equal(Fp, Fg)
    assert without(report, FILE_KEYS) == without(expected, FILE_KEYS)
    assert report["parameters"]["max_seconds"] == 600 and report["parameters"]["budget"] == "hard"


def test_threads_give_the_same_proxy(bunny):
    V, F, _ = bunny
    one = proxyvis.proxy(V, F, kind="outside", ratio=0.02, threads=1)
    two = proxyvis.proxy(V, F, kind="outside", ratio=0.02, threads=2)
    np.testing.assert_array_equal(one[0], two[0])
    np.testing.assert_array_equal(one[1], two[1])
    assert without(one[2], TIMING_KEYS) == without(two[2], TIMING_KEYS)


def test_float32_reading_has_no_second_reading(bunny):
    # Vertices that are float32 numbers have one reading: no containment_double, as for a
    # binary file.
    V, F, _ = bunny
    _, _, report = proxyvis.proxy(V.astype(np.float32), F, kind="outside", method="hull")
    assert "containment_double" not in report["checks"] and report["class"] == "outside"


@pytest.mark.parametrize("kwargs, text", [
    (dict(kind="sideways"), "unknown --kind 'sideways'"),
    (dict(kind="outside", method="erode"), "unknown method 'erode' for --kind outside"),
    (dict(ratio=2.0), "--ratio must be in"),
    (dict(alpha=float("nan")), "--alpha must be in"),
    (dict(max_faces=-1), "--max-faces must be >= 0"),
    (dict(min_faces=2), "--min-faces must be >= 4"),
    (dict(budget="firm"), "unknown --budget 'firm'"),
    (dict(threads=-1), "--threads must be in [0, 4096]"),
])
def test_bad_settings(bunny, kwargs, text):
    V, F, _ = bunny
    with pytest.raises(proxyvis.Error) as e:
        proxyvis.proxy(V, F, **kwargs)
    assert e.value.exit_code == 2 and text in e.value.message


def test_inside_of_open_mesh_is_bad_input():
    # The teapot is open: an inside proxy needs fill_holes, as proxy-gen says (exit code 2).
    V, F, _ = proxyvis.load_mesh(data("teapot.obj"))
    with pytest.raises(proxyvis.Error) as e:
        proxyvis.proxy(V, F, kind="inside")
    assert e.value.exit_code == 2 and e.value.message.startswith("V, F: ")


def test_docstring_reads_like_help():
    doc = proxyvis.proxy.__doc__
    assert doc.startswith("proxy(V: object, F: object, kind: str = 'outside'")
    for text in ["convex-parts (a proved union of convex pieces", "max_faces", "Face budget",
                 "clearance_ulps", "Raises proxyvis.Error"]:
        assert text in " ".join(doc.split()), text
    assert "rays" in proxyvis.check.__doc__ and "Number of segments" in proxyvis.check.__doc__
