"""load_mesh and save_mesh: the loader's and mesh-info's reading and report, round trips in the
formats the programs write, atomic writes with their sidecar, errors with the programs' codes."""
import os

import numpy as np
import pytest

import proxyvis
from conftest import data, run_json


def triangles(V, F):
    """The triangles as sorted corner coordinates in float32, each from its smallest corner (the
    same oriented triangles in any vertex or face order give the same list)."""
    corners = V.astype(np.float32)[F].tolist()
    return sorted(min(t[i:] + t[:i] for i in range(3)) for t in corners)


def test_load_mesh_matches_mesh_info(bunny, tmp_path):
    V, F, report = bunny
    assert V.dtype == np.float64 and V.shape == (3485, 3) and V.flags.c_contiguous
    assert F.dtype == np.int32 and F.shape == (6966, 3)
    assert report["faces"] == 6966 and report["closed"] and report["manifold"]
    # The same dict as mesh-info --json's entry for the file.
    assert report == run_json("mesh-info", data("bunny.off"), tmp_path=tmp_path)[0]


def test_load_mesh_text_file_gives_its_decimals():
    # bunny.off's decimals as float64; rounded to float32 they are the vertices the programs use.
    V, _, _ = proxyvis.load_mesh(data("bunny.off"))
    first = [float(x) for x in open(data("bunny.off")).read().split("\n")[2].split()]
    assert V[0].tolist() == first
    assert not np.array_equal(V, V.astype(np.float32).astype(np.float64))


@pytest.mark.parametrize("ext", ["ply", "obj", "off", "drc", "glb"])
def test_save_mesh_round_trip(bunny, tmp_path, ext):
    V, F, _ = bunny
    path = tmp_path / f"bunny.{ext}"
    proxyvis.save_mesh(str(path), V, F)
    assert (tmp_path / f"bunny.{ext}.sha256").exists()  # the sidecar loading verifies
    V2, F2, report = proxyvis.load_mesh(str(path))
    # Written as float32: read back, each coordinate is the float32 of the one given. Draco
    # stores the same triangles in another order.
    if ext == "drc":
        assert triangles(V2, F2) == triangles(V, F)
    else:
        np.testing.assert_array_equal(F2, F)
        np.testing.assert_array_equal(V2.astype(np.float32), V.astype(np.float32))
    assert report["faces"] == 6966 and report["closed"]
    assert sorted(os.listdir(tmp_path)) == [f"bunny.{ext}", f"bunny.{ext}.sha256"]


def test_save_mesh_ascii_ply_and_lists(tmp_path):
    path = tmp_path / "tet.ply"
    V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    proxyvis.save_mesh(str(path), V, F, ascii=True)
    assert path.read_bytes().startswith(b"ply\nformat ascii")
    V2, F2, report = proxyvis.load_mesh(str(path))
    assert V2.tolist() == V and F2.tolist() == F and report["closed"]


def test_save_mesh_errors(bunny, tmp_path):
    V, F, _ = bunny
    with pytest.raises(proxyvis.Error) as e:
        proxyvis.save_mesh(str(tmp_path / "bunny.stl"), V, F)
    assert e.value.exit_code == 2 and "unknown mesh file extension '.stl'" in e.value.message
    with pytest.raises(proxyvis.Error) as e:
        proxyvis.save_mesh(str(tmp_path / "missing" / "bunny.ply"), V, F)
    assert e.value.exit_code == 3
    assert os.listdir(tmp_path) == []  # nothing partial left


def test_load_mesh_errors(tmp_path):
    with pytest.raises(proxyvis.Error) as e:
        proxyvis.load_mesh(str(tmp_path / "none.obj"))
    assert e.value.exit_code == 2 and "none.obj" in e.value.message
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    with pytest.raises(proxyvis.Error) as e:
        proxyvis.load_mesh(str(bad))
    assert e.value.exit_code == 2 and str(e.value) == e.value.message


def test_error_type():
    e = proxyvis.Error("x: broken", 3)
    assert isinstance(e, Exception) and e.message == "x: broken" and e.exit_code == 3
    import pickle
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.message, e2.exit_code) == ("x: broken", 3)
