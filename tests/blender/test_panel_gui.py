"""The add-on's panel in Blender's user interface, under Xvfb (docs/blender.md): the sidebar tab
"proxyvis" drawn, a job started from it (the modal operator with its timer: the panel shows the
progress bar and the cancel button while proxy-gen runs in a thread), cancelled (nothing added),
started again and finished (the proxy added, its proof on the panel), and a screenshot of the
3D view with the panel.

xvfb-run -a -s "-screen 0 1280x800x24" blender --factory-startup --enable-event-simulate
--python tests/blender/test_panel_gui.py -- --zip Z --bin B --data D --work W [--screenshot PNG]

--enable-event-simulate: Blender then takes input only from the script (Window.event_simulate),
which clicks the sidebar's tab "proxyvis" as a user would."""
import os
import sys
import time
import traceback

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import support as t  # noqa: E402

a = t.arguments()
bpy.context.preferences.view.show_splash = False
T0 = time.monotonic()
TIMEOUT = 240.0
state = {"drawn": 0, "tries": 0}


def fail():
    traceback.print_exc()
    sys.stderr.flush()
    os._exit(1)


def view3d():
    win = bpy.context.window_manager.windows[0]
    area = next(a for a in win.screen.areas if a.type == "VIEW_3D")
    region = next(r for r in area.regions if r.type == "WINDOW")
    sidebar = next(r for r in area.regions if r.type == "UI")
    return win, area, region, sidebar


def override():
    win, area, region, _ = view3d()
    return bpy.context.temp_override(window=win, area=area, region=region, screen=win.screen)


def steps():
    """The test as a generator: each yield waits that many seconds (Blender draws meanwhile)."""
    addon = t.install_addon(a.zip)
    panel_cls = addon.panel.PROXYVIS_PT_panel
    draw = panel_cls.draw

    def counting_draw(self, context):
        state["drawn"] += 1
        draw(self, context)
    panel_cls.draw = counting_draw
    t.clear_scene()
    spot = t.import_one(bpy.ops.import_scene.obj, "spot",
                        filepath=os.path.join(a.data, "spot_triangulated.obj"), split_mode="OFF")
    spot.rotation_euler = (1.5708, 0.0, 0.6)
    t.select_only(spot)
    win, area, region, sidebar = view3d()
    area.spaces.active.show_region_ui = True
    with override():
        bpy.ops.view3d.view_selected()
    yield 0.5

    t.step("switch the sidebar to the tab proxyvis (a click on its tab)")
    # The tabs stand on the sidebar's right edge; a click goes down the strip until the panel
    # draws (Blender 3.4 has no Python setting for a region's active tab).
    _, _, _, sidebar = view3d()
    x = sidebar.x + sidebar.width - 10
    for y in range(sidebar.y + sidebar.height - 10, sidebar.y, -12):
        state["drawn"] = 0
        area.tag_redraw()
        yield 0.2
        if state["drawn"]:
            break
        state["tries"] += 1
        win.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
        win.event_simulate(type="LEFTMOUSE", value="PRESS", x=x, y=y)
        win.event_simulate(type="LEFTMOUSE", value="RELEASE", x=x, y=y)
    assert state["drawn"], "the panel was never drawn"
    t.step(f"the tab after {state['tries']} clicks")
    win.event_simulate(type="MOUSEMOVE", value="NOTHING", x=region.x + 20, y=region.y + 20)

    t.step("start a job from the panel's operator; the panel shows progress and Cancel")
    settings = bpy.context.scene.proxyvis
    settings.max_faces = 60  # what the panel shows; its button passes it so
    with override():
        assert bpy.ops.proxyvis.make_proxy("INVOKE_DEFAULT", kind="outside",
                                           max_faces=60) == {"RUNNING_MODAL"}
    job = addon.jobs.current
    assert job is not None and job.alive()
    yield 0.5
    wm = bpy.context.window_manager
    assert job.alive(), "the job ended too soon to be cancelled"
    assert wm.proxyvis_status.startswith("spot: "), wm.proxyvis_status
    with override():
        bpy.ops.screen.screenshot_area(filepath=os.path.join(a.work, "running.png"))
    t.step("cancel")
    with override():
        assert bpy.ops.proxyvis.cancel() == {"FINISHED"}
    while addon.jobs.current is not None:
        yield 0.1
    assert "spot-occludee" not in bpy.data.objects, "a cancelled job added its proxy"
    assert not [o for o in bpy.data.objects if o.name != "spot"], "objects after cancel"

    t.step("again, to the end")
    settings.max_faces = 200
    with override():
        assert bpy.ops.proxyvis.make_proxy("INVOKE_DEFAULT", kind="outside",
                                           max_faces=200) == {"RUNNING_MODAL"}
    t0 = time.monotonic()
    while addon.jobs.current is not None:
        yield 0.1
    t.step(f"the job took {time.monotonic() - t0:.1f} s in the modal operator")
    proxy = bpy.data.objects["spot-occludee"]
    t.expect_equal(proxy["proxyvis_class"], "outside", "class")
    t.expect_equal(proxy.parent, spot, "parent")
    t.select_only(proxy)
    with override():
        assert bpy.ops.proxyvis.check() == {"FINISHED"}
    proxy.display_type = "WIRE"  # the original shows through it in the screenshot
    yield 0.3
    state["drawn"] = 0
    area.tag_redraw()
    yield 0.5
    assert state["drawn"], "the panel is not drawn"
    if a.screenshot:
        with override():
            bpy.ops.screen.screenshot_area(filepath=a.screenshot)
        t.step(f"screenshot: {a.screenshot}")
    print(f"PASS test_panel_gui.py in {time.monotonic() - T0:.1f} s", flush=True)


gen = steps()


def tick():
    try:
        if time.monotonic() - T0 > TIMEOUT:
            raise TimeoutError(f"not done after {TIMEOUT} s")
        return next(gen)
    except StopIteration:
        bpy.ops.wm.quit_blender()
        return None
    except BaseException:  # noqa: BLE001
        fail()


bpy.app.timers.register(tick, first_interval=1.0)
