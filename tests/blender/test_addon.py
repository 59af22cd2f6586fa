"""The add-on in a real Blender, with the Python module (docs/blender.md): installed from
build/blender/proxyvis_blender.zip; an OBJ (data/spot_triangulated.obj, with a transform and a
modifier) and a glTF (data/bunny.off written as .glb by the module) imported with Blender's
importers; bpy.ops.proxyvis.make_proxy's proxies equal proxy-gen's on the same triangles (written
from Blender's own Convert + Apply Transforms), byte for byte; bpy.ops.proxyvis.check finds the
class, and a broken claim after an edit turns the proxy red; a non-manifold object gets
proxy-gen's refusal text; a cancelled job adds nothing.

blender -b --factory-startup --python tests/blender/test_addon.py -- --zip Z --bin B --data D
--work W --module build/python"""
import math
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support as t  # noqa: E402


def test(a):
    t.step("install the add-on from the zip")
    addon = t.install_addon(a.zip)
    backend, notes = addon.backend.resolve(t.prefs())
    t.expect_equal(backend.name, "module", f"backend ({notes})")
    sys.path.insert(0, a.module)
    import proxyvis  # the same module, for the glTF file
    t.clear_scene()
    C = bpy.context

    t.step("OBJ: spot with a transform and a Decimate modifier -> outside proxy, 200 faces")
    spot = t.import_one(bpy.ops.import_scene.obj, "spot",
                        filepath=os.path.join(a.data, "spot_triangulated.obj"), split_mode="OFF")
    spot.location = (0.25, -0.5, 0.125)
    spot.rotation_euler = (0.3, -0.2, 0.9)
    spot.scale = (1.5, 1.25, 1.5)
    mod = spot.modifiers.new("decimate", "DECIMATE")
    mod.ratio = 0.5
    t.select_only(spot)
    t0 = time.monotonic()
    assert bpy.ops.proxyvis.make_proxy(kind="outside", max_faces=200) == {"FINISHED"}
    t.step(f"make_proxy: {time.monotonic() - t0:.1f} s")
    proxy = bpy.data.objects["spot-occludee"]
    t.expect_equal(proxy.parent, spot, "parent")
    t.expect_equal([c.name for c in proxy.users_collection], ["proxyvis proxies"], "collection")
    V, F = t.applied_triangles(spot)
    t.expect_equal(len(F), 2928, "the Decimate modifier's triangles (5,856 / 2)")
    report, _ = t.compare_with_programs(proxy, V, F, a.work, a.bin, "spot", ["--kind", "outside",
                                                                        "--max-faces", 200])
    t.expect_equal(report["input"]["faces"], 2928, "proxy-gen's input faces")
    t.expect_equal(proxy["proxyvis_class"], "outside", "class")
    t.expect_equal(proxy["proxyvis_backend"], "module", "backend property")
    # Where the proxy is: at the original's world position (its parent inverse undoes the
    # parent's matrix), following it from now on.
    assert all(abs(x - (1.0 if i % 5 == 0 else 0.0)) < 1e-5
               for i, x in enumerate(v for row in proxy.matrix_world for v in row))

    t.step("glTF: the bunny written by the module, imported -> inside at 2 %, general at 300")
    V0, F0, _ = proxyvis.load_mesh(os.path.join(a.data, "bunny.off"))
    glb = os.path.join(a.work, "bunny.glb")
    proxyvis.save_mesh(glb, V0, F0)
    # Shading "SMOOTH": the default ("NORMALS") fails in Debian 12's Blender 3.4.1 with Debian's
    # NumPy 1.24 (the importer uses np.bool, removed in NumPy 1.24).
    bunny = t.import_one(bpy.ops.import_scene.gltf, "bunny", filepath=glb,
                         import_shading="SMOOTH")
    t.select_only(bunny)
    t0 = time.monotonic()
    assert bpy.ops.proxyvis.make_proxy(kind="inside", ratio=2.0) == {"FINISHED"}
    assert bpy.ops.proxyvis.make_proxy(kind="general", max_faces=300) == {"FINISHED"}
    t.step(f"make_proxy x2: {time.monotonic() - t0:.1f} s")
    V, F = t.applied_triangles(bunny)
    t.expect_equal(len(F), len(F0), "the glTF's triangles")
    inside = bpy.data.objects["bunny-occonly"]
    t.compare_with_programs(inside, V, F, a.work, a.bin, "bunny-inside",
                            ["--kind", "inside", "--ratio", 0.02])
    lod = bpy.data.objects["bunny-lod"]
    t.compare_with_programs(lod, V, F, a.work, a.bin, "bunny-general",
                            ["--kind", "general", "--max-faces", 300])
    t.expect_equal(lod["proxyvis_faces"], 300, "general faces")

    t.step("a second run replaces the proxy of the same name")
    assert bpy.ops.proxyvis.make_proxy(kind="general", max_faces=300) == {"FINISHED"}
    t.expect_equal(sorted(o.name for o in bunny.children), ["bunny-lod", "bunny-occonly"],
                   "children")

    t.step("check: the unedited proxy is outside; its counts are proxy-check's")
    counts = {c: proxy["proxyvis_" + c] for c in ("HH", "HM", "MH", "MM")}
    t.select_only(proxy)
    assert bpy.ops.proxyvis.check() == {"FINISHED"}
    t.expect_equal(proxy["proxyvis_check_class"], "outside", "check class")
    t.expect_equal(proxy["proxyvis_check_holds"], True, "check holds")
    t.expect_equal(proxy["proxyvis_source_changed"], False, "source changed")
    t.expect_equal({c: proxy["proxyvis_" + c] for c in counts}, counts, "counts")
    t.expect_equal(tuple(proxy.color), (1.0, 1.0, 1.0, 1.0), "color")

    t.step("check after an edit: proxy shrunk by 10 % about its centre -> claim broken, red")
    co = [v.co.copy() for v in proxy.data.vertices]
    centre = sum(co, co[0] * 0) / len(co)
    for v, c in zip(proxy.data.vertices, co):
        v.co = centre + (c - centre) * 0.9
    proxy.data.update()
    assert bpy.ops.proxyvis.check() == {"FINISHED"}
    t.expect_equal(proxy["proxyvis_check_holds"], False, "check holds after the edit")
    assert proxy["proxyvis_check_class"] != "outside"
    assert proxy["proxyvis_HM"] > 0, "a shrunk outside proxy lets rays through: HM' > 0"
    t.expect_equal(tuple(proxy.color), (1.0, 0.0, 0.0, 1.0), "color")
    t.expect_equal(proxy.material_slots[0].material.name, "proxyvis claim broken", "material")
    t.expect_equal(tuple(proxy.material_slots[0].material.diffuse_color), (1.0, 0.0, 0.0, 1.0),
                   "material color")

    t.step("undo the edit -> holds again, no longer red")
    for v, c in zip(proxy.data.vertices, co):
        v.co = c
    proxy.data.update()
    t.select_only(spot)  # the original selected: its proxies are checked
    assert bpy.ops.proxyvis.check() == {"FINISHED"}
    t.expect_equal(proxy["proxyvis_check_holds"], True, "holds after undoing")
    t.expect_equal(proxy["proxyvis_check_class"], "outside", "class after undoing")
    t.expect_equal(tuple(proxy.color), (1.0, 1.0, 1.0, 1.0), "color after undoing")
    t.expect_equal(proxy.material_slots[0].material, None, "material after undoing")

    t.step("the original moved: the proxy follows and still contains it")
    spot.location.x += 2.0
    spot.rotation_euler.z += math.radians(30)
    C.view_layer.update()
    assert bpy.ops.proxyvis.check() == {"FINISHED"}
    t.expect_equal(proxy["proxyvis_check_holds"], True, "holds after moving the original")
    t.expect_equal(proxy["proxyvis_source_changed"], True, "the original's triangles moved")

    t.step("refusals: non-manifold objects get proxy-gen's text, and no object")
    teapot = t.import_one(bpy.ops.import_scene.obj, "teapot",
                          filepath=os.path.join(a.data, "teapot.obj"), split_mode="OFF")
    fin = bpy.data.objects.new("fin", bpy.data.meshes.new("fin"))
    fin.data.from_pydata(
        [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1),
         (0.5, -1, 0.5)], [],
        [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7),
         (0, 1, 8)])  # a cube with a fin on one edge: 3 faces at that edge
    C.scene.collection.objects.link(fin)
    for obj in (teapot, fin):
        V, F = t.applied_triangles(obj)
        src = os.path.join(a.work, f"{obj.name}.ply")
        t.write_ply(src, V, F)
        _, err = t.run(a.bin, "proxy-gen", src, "--kind", "inside", "--max-faces", 100,
                       "-o", os.path.join(a.work, "never.ply"), "-q", expect_code=2)
        expected = f"{obj.name}: " + t.error_text(err, "proxy-gen", src)
        n = len(bpy.data.objects)
        t.select_only(obj)
        try:
            bpy.ops.proxyvis.make_proxy(kind="inside", max_faces=100)
            raise AssertionError(f"{obj.name}: make_proxy did not refuse")
        except RuntimeError as e:
            assert expected in str(e), f"refusal:\n{e}\nexpected:\n{expected}"
        t.expect_equal(len(bpy.data.objects), n, "objects after a refusal")
        print(f"   {expected[:110]}...")

    t.step("cancel: a job cancelled while it runs adds no object")
    t.select_only(spot)
    n = len(bpy.data.objects)
    items = [addon.jobs.Item(spot.name, *addon.meshes.world_triangles(
        spot, C.evaluated_depsgraph_get()), "")]
    job = addon.jobs.ProxyJob(backend, items, addon.jobs.Settings(kind="outside", max_faces=100))
    job.start()
    time.sleep(0.3)
    assert job.alive(), "the job ended before it was cancelled"
    job.cancel()
    job.wait(120)
    created, messages = job.finish(C)
    t.expect_equal((created, messages, len(bpy.data.objects)), ([], [], n), "after cancel")
    # The operator after a cancelled job: works again.
    assert bpy.ops.proxyvis.make_proxy(kind="outside", max_faces=200) == {"FINISHED"}


a = t.arguments()
t.main(lambda: test(a))
