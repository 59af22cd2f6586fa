"""Blender side of the add-on: an object's triangles as Blender evaluates them, proxy objects
with their proof as custom properties, and the red mark of a broken claim."""
import hashlib
import json

import bpy
import numpy as np

COLLECTION = "proxyvis proxies"
BROKEN_MATERIAL = "proxyvis claim broken"
PREFIX = "proxyvis_"
# The types whose evaluated geometry is a mesh (modifiers, curves' bevels, text).
GEOMETRY_TYPES = {"MESH", "CURVE", "SURFACE", "META", "FONT"}
# The engines' names of a proxy (docs/gltf.md): by the class the proxy was proved to have.
SUFFIX = {"inside": "-occonly", "outside": "-occludee"}


def proxy_name(original_name, proxy_class):
    return original_name + SUFFIX.get(proxy_class, "-lod")


def is_proxy(obj):
    return PREFIX + "class" in obj.keys()


def world_triangles(obj, depsgraph, matrix=None):
    """The triangles of `obj` as Blender evaluates them: modifiers applied (evaluated depsgraph),
    in world space (its world matrix applied by Blender itself, as Apply > All Transforms does),
    polygons split into Blender's loop triangles. Returns (V float32 n x 3, F int32 m x 3).
    `matrix` replaces the world matrix (None: obj's evaluated matrix_world)."""
    if obj.mode == "EDIT":
        obj.update_from_editmode()
    ob_eval = obj.evaluated_get(depsgraph)
    mesh = ob_eval.to_mesh()
    try:
        mesh.transform(ob_eval.matrix_world if matrix is None else matrix)
        mesh.calc_loop_triangles()
        V = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
        mesh.vertices.foreach_get("co", V)
        F = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
        mesh.loop_triangles.foreach_get("vertices", F)
    finally:
        ob_eval.to_mesh_clear()
    return V.reshape(-1, 3), F.reshape(-1, 3)


def source_sha256(V, F):
    """SHA-256 of the triangles given to proxy-gen: the float32 vertices (little-endian, x y z per
    vertex) followed by the int32 vertex indices of the triangles."""
    h = hashlib.sha256()
    h.update(np.ascontiguousarray(V, dtype="<f4").tobytes())
    h.update(np.ascontiguousarray(F, dtype="<i4").tobytes())
    return h.hexdigest()


def proxy_collection(scene):
    coll = bpy.data.collections.get(COLLECTION)
    if coll is None:
        coll = bpy.data.collections.new(COLLECTION)
    if coll.name not in scene.collection.children.keys():
        scene.collection.children.link(coll)
    return coll


def _mesh_from_arrays(name, V, F):
    mesh = bpy.data.meshes.new(name)
    V = np.ascontiguousarray(V, dtype=np.float32).reshape(-1, 3)
    F = np.ascontiguousarray(F, dtype=np.int32).reshape(-1, 3)
    mesh.vertices.add(len(V))
    mesh.vertices.foreach_set("co", V.ravel())
    mesh.loops.add(3 * len(F))
    mesh.loops.foreach_set("vertex_index", F.ravel())
    mesh.polygons.add(len(F))
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(F), 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(F), 3, dtype=np.int32))
    mesh.update(calc_edges=True)
    return mesh


def _set(obj, key, value):
    if value is None:
        if PREFIX + key in obj.keys():
            del obj[PREFIX + key]
    else:
        obj[PREFIX + key] = value


def set_check_properties(obj, check):
    """HH'/HM'/MH'/MM' counts of a check with the 95 % upper bounds of the HM' and MH' rates."""
    counts = check.get("counts", {})
    intervals = check.get("intervals", {})
    _set(obj, "check_rays", check.get("rays"))
    _set(obj, "check_seed", check.get("seed"))
    for c in ("HH", "HM", "MH", "MM"):
        _set(obj, c, counts.get(c))
    _set(obj, "HM_rate_upper_95", intervals.get("HM", {}).get("hi"))
    _set(obj, "MH_rate_upper_95", intervals.get("MH", {}).get("hi"))
    _set(obj, "sampled_class", check.get("sampled_class"))
    _set(obj, "exact", check.get("exact"))
    _set(obj, "check_report", json.dumps(check, sort_keys=True))


def checked_class(check):
    """The class the exact check proves (outside: contains; inside: contained; else general), in
    both readings when there are two."""
    exact, double = check.get("exact"), check.get("exact_double")
    if double is not None and double != exact:
        return "general"
    return {"contains": "outside", "contained": "inside"}.get(exact, "general")


def create_proxy(context, original, Vp, Fp, report, check, backend, sha):
    """The proxy as a new object in the collection "proxyvis proxies", parented to `original`
    (it keeps its world position: the vertices are world coordinates), named after the proved
    class, with the proof as custom properties. Replaces an earlier proxy of the same name."""
    cls = report.get("class") or "general"
    name = proxy_name(original.name, cls)
    old = bpy.data.objects.get(name)
    if old is not None and is_proxy(old) and old.parent == original:
        old_mesh = old.data
        bpy.data.objects.remove(old)
        if old_mesh.users == 0:
            bpy.data.meshes.remove(old_mesh)
    mesh = _mesh_from_arrays(name, Vp, Fp)
    obj = bpy.data.objects.new(name, mesh)
    proxy_collection(context.scene).objects.link(obj)
    obj.parent = original
    obj.matrix_parent_inverse = original.matrix_world.inverted()
    # Where the original was: while it stays there (and the proxy is not moved) the proxy's
    # vertices are its world coordinates as proxy-gen wrote them (operators._proxy_matrix).
    obj[PREFIX + "parent_matrix"] = [x for row in original.matrix_world for x in row]
    hausdorff = report.get("hausdorff") or {}
    props = {
        "class": cls,
        "kind": report.get("kind"),
        "verified": bool(report.get("verified")),
        "method": report.get("method"),
        "faces": report.get("faces"),
        "volume_ratio": report.get("volume_ratio"),
        "hausdorff_original_to_proxy": hausdorff.get("original_to_proxy"),
        "hausdorff_proxy_to_original": hausdorff.get("proxy_to_original"),
        "hausdorff_diagonal": hausdorff.get("diagonal"),
        "containment": (report.get("checks") or {}).get("containment"),
        "source_sha256": sha,
        "backend": backend,
        "report": json.dumps(report, sort_keys=True),
    }
    for key, value in props.items():
        _set(obj, key, value)
    set_check_properties(obj, check)
    holds = cls == "general" or (checked_class(check) == cls and check.get("ok", True))
    _set(obj, "check_class", checked_class(check))
    _set(obj, "check_holds", holds)
    mark(obj, holds)
    return obj


def _broken_material():
    mat = bpy.data.materials.get(BROKEN_MATERIAL)
    if mat is None:
        mat = bpy.data.materials.new(BROKEN_MATERIAL)
        mat.diffuse_color = (1.0, 0.0, 0.0, 1.0)
    return mat


def mark(obj, holds):
    """Red (viewport display color and an object-linked red material in slot 1) where the claim
    no longer holds; back to the mesh's own materials when it holds."""
    if holds:
        obj.color = (1.0, 1.0, 1.0, 1.0)
        for slot in obj.material_slots:
            if slot.link == "OBJECT" and slot.material and slot.material.name == BROKEN_MATERIAL:
                slot.material = None
                slot.link = "DATA"
        return
    obj.color = (1.0, 0.0, 0.0, 1.0)
    if not obj.material_slots:
        obj.data.materials.append(None)
    slot = obj.material_slots[0]
    slot.link = "OBJECT"
    slot.material = _broken_material()
