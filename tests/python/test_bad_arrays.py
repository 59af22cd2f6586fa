"""Bad arrays raise proxyvis.Error with exit code 2 and a message naming the array, from every
function that takes arrays; arrays NumPy can convert are accepted (copied), C-contiguous float64
and int32 ones are read in place."""
import numpy as np
import pytest

import proxyvis

TET_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
TET_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)


def nan_vertex():
    v = TET_V.copy()
    v[2, 1] = np.nan
    return v


def inf_vertex():
    v = TET_V.copy()
    v[1, 0] = -np.inf
    return v


def face_index(value, dtype=np.int32):
    f = TET_F.astype(dtype)
    f[3, 2] = value
    return f


BAD = {
    "V 2 columns": (TET_V[:, :2], TET_F, "V: shape (4, 2) is not (n, 3)"),
    "V 1-D": (TET_V.ravel(), TET_F, "V: shape (12,) is not (n, 3)"),
    "V 3-D": (TET_V[None], TET_F, "V: shape (1, 4, 3) is not (n, 3)"),
    "F 4 columns": (TET_V, np.zeros((4, 4), np.int32), "F: shape (4, 4) is not (m, 3)"),
    "F float32": (TET_V, TET_F.astype(np.float32), "F: dtype float32 is not an integer type"),
    "F float64": (TET_V, TET_F.astype(np.float64), "F: dtype float64 is not an integer type"),
    "V strings": (TET_V.astype(str), TET_F, "V: dtype <U32 is not a real number type"),
    "V complex": (TET_V.astype(complex), TET_F, "is not a real number type"),
    "V bool": (TET_V.astype(bool), TET_F, "V: dtype bool is not a real number type"),
    "V None": (None, TET_F, "V: dtype object is not a real number type"),
    "V ragged": ([[0, 0], [1, 0, 0]], TET_F, "V: not an array"),
    "V NaN": (nan_vertex(), TET_F, "V: vertex 2 has a NaN or infinite coordinate"),
    "V inf": (inf_vertex(), TET_F, "V: vertex 1 has a NaN or infinite coordinate"),
    "V beyond float": (TET_V * 1e300, TET_F, "V: vertex 1 has a coordinate beyond float range"),
    "F index = n": (TET_V, face_index(4),
                    "F: vertex index out of range; triangle 3 references vertex 4 but V has 4"),
    "F index < 0": (TET_V, face_index(-1), "triangle 3 references vertex -1"),
    "F index int64 huge": (TET_V, face_index(2**40, np.int64), "references vertex 1099511627776"),
    "F uint64 huge": (TET_V, face_index(2**64 - 1, np.uint64), "triangle 3 references vertex -1"),
    "V empty": (np.zeros((0, 3)), TET_F, "V: empty array"),
    "F empty": (TET_V, np.zeros((0, 3), np.int32), "F: empty array"),
    "V shape (0,)": (np.zeros(0), TET_F, "V: shape (0,) is not (n, 3)"),
}


def call_proxy(V, F):
    proxyvis.proxy(V, F, kind="general")


def call_check_original(V, F):
    proxyvis.check(V, F, TET_V * 2, TET_F, rays=100)


def call_check_proxy(V, F):
    proxyvis.check(TET_V * 2, TET_F, V, F, rays=100)


def call_save(V, F, path="unused.ply"):
    proxyvis.save_mesh(path, V, F)


@pytest.mark.parametrize("case", BAD.keys())
@pytest.mark.parametrize("call", [call_proxy, call_check_original, call_check_proxy, call_save])
def test_bad_arrays_raise_error(case, call):
    V, F, text = BAD[case]
    if call is call_check_proxy:
        text = text.replace("V:", "Vp:").replace("F:", "Fp:").replace("V has", "Vp has")
    with pytest.raises(proxyvis.Error) as e:
        call(V, F)
    assert e.value.exit_code == 2
    assert text in e.value.message, e.value.message


@pytest.mark.parametrize("V, F", [
    (TET_V.astype(np.float32), TET_F.astype(np.int64)),
    (np.asfortranarray(TET_V), np.asfortranarray(TET_F)),
    (TET_V.astype(np.int16), TET_F.astype(np.uint8)),
    (np.repeat(TET_V, 2, axis=0)[::2], TET_F),  # a strided view
    (TET_V.tolist(), TET_F.tolist()),
    (TET_V.astype(">f8"), TET_F.astype(">i4")),  # big-endian
])
def test_convertible_arrays_are_accepted(tmp_path, V, F):
    path = tmp_path / "tet.ply"
    proxyvis.save_mesh(str(path), V, F)
    V2, F2, report = proxyvis.load_mesh(str(path))
    np.testing.assert_array_equal(V2, TET_V)
    np.testing.assert_array_equal(F2, TET_F)
    assert report["closed"]
    report = proxyvis.check(V, F, TET_V * 5 - 1, TET_F, rays=500)
    assert report["exact"] == "contains" and report["counts"]["HM"] == 0
