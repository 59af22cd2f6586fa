"""The add-on without the Python module (docs/blender.md): its "Module Path" preference names a
folder without proxyvis, so it runs the programs proxy-gen and proxy-check of "Programs Folder"
and says so; the proxies, checks and refusals are the same as with the module (and as
proxy-gen's on the same triangles, byte for byte); a cancelled job stops the running program
at once and adds nothing.

blender -b --factory-startup --python tests/blender/test_fallback.py -- --zip Z --bin B
--data D --work W"""
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support as t  # noqa: E402


def test(a):
    t.step("install the add-on; Module Path without the module; Programs Folder = build/bin")
    addon = t.install_addon(a.zip)
    assert "proxyvis" not in sys.modules
    prefs = t.prefs()
    prefs.module_path = os.path.join(a.work, "no-module-here")
    prefs.programs_folder = a.bin
    backend, notes = addon.backend.resolve(prefs)
    t.expect_equal(backend.name, "programs", "backend")
    assert "proxyvis" not in sys.modules
    assert any("module not importable" in n for n in notes), notes
    what, where = backend.describe()
    t.expect_equal(os.path.realpath(where), os.path.realpath(a.bin), "programs folder")
    t.clear_scene()
    C = bpy.context

    t.step("OBJ: spot, rotated -> outside proxy at 150 faces with the programs")
    spot = t.import_one(bpy.ops.import_scene.obj, "spot",
                        filepath=os.path.join(a.data, "spot_triangulated.obj"), split_mode="OFF")
    spot.rotation_euler = (0.5, 0.0, 0.25)
    t.select_only(spot)
    t0 = time.monotonic()
    assert bpy.ops.proxyvis.make_proxy(kind="outside", max_faces=150, method="wrap",
                                       offset=0.002) == {"FINISHED"}
    t.step(f"make_proxy: {time.monotonic() - t0:.1f} s")
    proxy = bpy.data.objects["spot-occludee"]
    t.expect_equal(proxy["proxyvis_backend"], "programs", "backend property")
    V, F = t.applied_triangles(spot)
    t.compare_with_programs(proxy, V, F, a.work, a.bin, "spot",
                            ["--kind", "outside", "--max-faces", 150, "--method", "wrap",
                             "--offset", 0.002])

    t.step("check with the programs; an edit breaks the claim")
    t.select_only(proxy)
    assert bpy.ops.proxyvis.check() == {"FINISHED"}
    t.expect_equal((proxy["proxyvis_check_class"], proxy["proxyvis_check_holds"]),
                   ("outside", True), "check")
    for v in proxy.data.vertices:
        v.co *= 0.9
    proxy.data.update()
    assert bpy.ops.proxyvis.check() == {"FINISHED"}
    t.expect_equal(proxy["proxyvis_check_holds"], False, "holds after the edit")
    t.expect_equal(tuple(proxy.color), (1.0, 0.0, 0.0, 1.0), "red")

    t.step("refusal: proxy-gen's text")
    teapot = t.import_one(bpy.ops.import_scene.obj, "teapot",
                          filepath=os.path.join(a.data, "teapot.obj"), split_mode="OFF")
    V, F = t.applied_triangles(teapot)
    src = os.path.join(a.work, "teapot.ply")
    t.write_ply(src, V, F)
    _, err = t.run(a.bin, "proxy-gen", src, "--kind", "inside", "-o",
                   os.path.join(a.work, "never.ply"), "-q", expect_code=2)
    expected = "teapot: " + t.error_text(err, "proxy-gen", src)
    t.select_only(teapot)
    n = len(bpy.data.objects)
    try:
        bpy.ops.proxyvis.make_proxy(kind="inside")
        raise AssertionError("make_proxy did not refuse")
    except RuntimeError as e:
        assert expected in str(e), f"refusal:\n{e}\nexpected:\n{expected}"
    t.expect_equal(len(bpy.data.objects), n, "objects after the refusal")

    t.step("cancel: the running proxy-gen is stopped at once; nothing is added")
    t.select_only(spot)
    items = [addon.jobs.Item(spot.name, *addon.meshes.world_triangles(
        spot, C.evaluated_depsgraph_get()), "")]
    job = addon.jobs.ProxyJob(backend, items, addon.jobs.Settings(kind="outside", max_faces=60))
    job.start()
    deadline = time.monotonic() + 30
    while job.progress == 0.0 and time.monotonic() < deadline:  # proxy-gen's --progress lines
        time.sleep(0.02)
    progress, status, _ = job.snapshot()
    assert 0.0 < progress < 1.0 and "spot:" in status, (progress, status)
    t0 = time.monotonic()
    job.cancel()
    job.wait(30)
    stopped = time.monotonic() - t0
    assert not job.alive() and stopped < 5.0, f"stopped after {stopped:.1f} s"
    created, messages = job.finish(C)
    t.expect_equal((created, messages, len(bpy.data.objects)), ([], [], n), "after cancel")
    t.step(f"cancelled at {100 * progress:.0f} % ({status}); stopped in {stopped:.2f} s")


a = t.arguments()
t.main(lambda: test(a))
