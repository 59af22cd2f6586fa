# Type stub of the proxyvis module (apps/python; docs/python.md), copied beside the built module.
from typing import Any, Literal, Optional, Tuple

import numpy as np
import numpy.typing as npt

__version__: str

Vertices = npt.NDArray[np.float64]  # n x 3
Faces = npt.NDArray[np.int32]  # m x 3
ArrayLike = npt.ArrayLike  # converted when not float64 / int32 C-contiguous

class Error(Exception):
    """What the programs print ("FILE: WHAT; WHY (TODO)") and the exit code they return:
    1 a check failed, 2 bad input or settings, 3 an output cannot be written."""

    message: str
    exit_code: int
    def __init__(self, message: str, exit_code: int = 2) -> None: ...

def load_mesh(
    path: str,
    self_intersections: bool = False,
    mesh: Optional[str] = None,
    node: Optional[str] = None,
) -> Tuple[Vertices, Faces, dict[str, Any]]:
    """Loads a mesh file; returns V, F and mesh-info's validation report."""

def save_mesh(
    path: str,
    V: ArrayLike,
    F: ArrayLike,
    draco_bits: int = 0,
    compress: Literal["none", "draco", "meshopt"] = "none",
    ascii: bool = False,
) -> None:
    """Writes V, F atomically in the format of the extension (.obj .ply .off .drc .gltf .glb)."""

def proxy(
    V: ArrayLike,
    F: ArrayLike,
    kind: Literal["outside", "inside", "general"] = "outside",
    method: Optional[
        Literal["wrap", "hull", "convex-parts", "erode", "qem", "cgal-sms", "meshopt"]
    ] = None,
    max_faces: Optional[int] = None,
    ratio: Optional[float] = None,
    threads: int = 0,
    seed: int = 0,
    quiet: bool = True,
    *,
    alpha: Optional[float] = None,
    offset: Optional[float] = None,
    parts: Optional[int] = None,
    budget: Literal["hard", "soft"] = "hard",
    max_seconds: float = 600.0,
    min_faces: int = 12,
    erosion: Optional[float] = None,
    voxel: Optional[float] = None,
    clearance: Optional[float] = None,
    clearance_ulps: Optional[float] = None,
    fill_holes: bool = False,
) -> Tuple[Vertices, Faces, dict[str, Any]]:
    """proxy-gen on arrays: the proxy's V, F and proxy-gen's JSON report as a dict."""

def check(
    V: ArrayLike,
    F: ArrayLike,
    Vp: ArrayLike,
    Fp: ArrayLike,
    rays: int = 1000000,
    distribution: Literal["sphere", "scene"] = "sphere",
    seed: int = 0,
    expect: Optional[Literal["outside", "inside", "general"]] = None,
    precision: Literal["float", "double", "both"] = "both",
    threads: int = 0,
    quiet: bool = True,
) -> dict[str, Any]:
    """proxy-check on arrays: proxy-check's JSON report of the pair as a dict."""
